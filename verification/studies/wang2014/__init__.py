"""Reproduction of Wang, Duan & Tian (2014) Table 2 (``riser-verify reproduce wang2014``):
:mod:`.table2` (the forward, inverse and as-printed runs, the VFIFE of the same model and
the report) and :mod:`.agreement` (each VFIFE - BVP difference against its tolerance)."""

from .table2 import STUDY

__all__ = ["STUDY"]
