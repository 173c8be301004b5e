"""Reproduction of Kang, Zhang & Zhang (2015), J-lay pipeline, catenary against the
analytic, BVP and VFIFE solutions (``riser-verify reproduce kang2015``): :mod:`.cases`
(the cases and their solutions) and :mod:`.report` (tables, the eps scaling, figures)."""

from .cases import STUDY

__all__ = ["STUDY"]
