"""The irregular-sea comparison: the frequency domain's stochastic response against the VFIFE."""
