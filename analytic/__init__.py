"""The analytic method: the extensible catenary in closed form with matched boundary
layers at the touchdown and at pinned ends (analytic/solver.py)."""

from .solver import effects_of, solve

__all__ = ["solve", "effects_of"]
