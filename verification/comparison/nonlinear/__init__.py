"""The VFIFE against the ANCF in the nonlinear time domain (``compare SCENE --time-domain``):
the protocol (:mod:`.protocol`), the stations (:mod:`.stations`), the measured tolerances
(:mod:`.tolerances`) and the report (:mod:`.report`)."""
