"""Design checks of a line with a wall: the ``[design]`` table, the stresses in the wall,
the code checks (DNV-ST-F201's combined loading, API RP 2RD's allowable von Mises) and
fatigue (DNV-RP-C203 S-N curves, rainflow counting, spectral damage).

These are post-processing definitions applied to every method's results alike (as the
profile's columns are), not physics a method solves: each method reports its tension,
moments and positions; the functions here turn them into stresses and utilisations.
"""
