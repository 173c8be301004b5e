"""The ANCF time domain: one implicit step (integrator.py), the run (run.py)."""
