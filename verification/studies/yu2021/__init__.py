"""Reproduction of Yu, Zhao, Zhang et al. (2021), lazy-wave flexible riser
(``riser-verify reproduce yu2021``): :mod:`.cases` (the static cases A1-A4, the gap, the
buoyancy loss, the current, the moved-up hang-off; the report) and :mod:`.dynamics` (the
heave of the hang-off)."""

from .cases import STUDY

__all__ = ["STUDY"]
