"""The results every method returns (profile, modes, harmonic response, dynamic result) and
their validity checks."""
