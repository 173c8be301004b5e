"""The dynamic comparison: the frequency domain against the VFIFE under a harmonic drive."""
