"""The VFIFE's dynamic run from its static state: the time loop, its records and the wave loads."""
