"""Large-deformation inextensible beam boundary-value solver (Wang et al. 2014) on solve_bvp."""

from .solver import solve

__all__ = ["solve"]
