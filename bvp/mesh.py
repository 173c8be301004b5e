"""A clustered mesh on the unit interval: the starting mesh of each piece of the line
(bvp/beam/layout.py) and of the modal analysis's pieces (bvp/modal/modes.py)."""

from __future__ import annotations

import numpy as np


def clustered_mesh(n: int, beta: float = 0.75) -> np.ndarray:
    """n nodes on [0, 1], clustered towards both ends where the bending boundary layers
    (width sqrt(EI/T)) sit at touchdown, joints and hang-off.

    A blend of a uniform and a Chebyshev-Lobatto distribution:
    tau = (1 - beta) xi + beta (1 - cos(pi xi)) / 2, xi uniform; beta in [0, 1).
    """
    xi = np.linspace(0.0, 1.0, n)
    return (1.0 - beta) * xi + beta * 0.5 * (1.0 - np.cos(np.pi * xi))
