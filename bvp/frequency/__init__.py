"""The frequency domain about the BVP static state: harmonic hang-off motion, regular waves
and irregular seas."""
