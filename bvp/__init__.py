"""Large-deformation beam boundary-value solver (Wang et al. 2014; extensible, on an elastic
seabed, with current drag) on scipy.integrate.solve_bvp."""

from .solver import solve
from .modal import modes  # noqa: F401  (bvp.modal.modes.solve_modes: the modal analysis)

__all__ = ["solve"]
