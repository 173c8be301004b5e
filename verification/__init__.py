"""Cross-checks, paper reproductions, reports and the command line of the riser suite."""
