"""What acts on the line: the current and seabed, waves, the vessel and its motion, the
dynamic run, internal flow."""
