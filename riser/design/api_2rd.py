"""API RP 2RD (1998) Sec. 4.4: the allowable von Mises stress of a metallic riser pipe.

    sigma_vm <= C_f C_a sigma_y,   C_a = 2/3,

sigma_vm the von Mises stress of the principal stresses (axial with bending, hoop, radial:
:mod:`riser.design.wall`), sigma_y the SMYS and C_f the design case factor of the load
class (its Table 2): operating 1.0, extreme 1.2, temporary 1.2, survival 1.5, test 1.35.
The utilisation is sigma_vm / (C_f C_a sigma_y). SI: [Pa].
"""

from __future__ import annotations

import numpy as np

#: C_a, the basic allowable stress factor
C_A = 2.0 / 3.0
#: C_f by load class (API RP 2RD Table 2)
C_F = {"operating": 1.0, "extreme": 1.2, "temporary": 1.2, "survival": 1.5, "test": 1.35}


def allowable(design, wall) -> np.ndarray:
    """C_f C_a sigma_y [Pa] at the wall's stations."""
    return C_F[design.load_class] * C_A * wall.yield_strength


def utilisation(design, wall, von_mises) -> np.ndarray:
    """sigma_vm / (C_f C_a sigma_y) of von Mises stresses [Pa]."""
    return np.asarray(von_mises, float) / allowable(design, wall)
