"""The end conditions of the linearised line (modes, bvp/modal/modes.py), as rows of a linear
form on an end's state: each row ((state, coefficient), ...) says sum(c_i y_i) = 0 there.

In plane, states (dx, dy, dtheta, dM, dF, dT); out of plane (w, psi, B, Q)
(bvp/modal/equations.py). SI units; s from the bottom end.

- pinned in place: dx = dy = 0, dM = 0; w = 0, B = 0;
- clamped (a clamped joint, or ``[vfife] clamped_ends``): dtheta = 0 instead of dM = 0;
  psi = 0 instead of B = 0;
- a flex joint of stiffness k [N m/rad] (riser/model/ends.py: M(L) = -k (theta - theta_0) at
  the hang-off, M(0) = +k (theta - theta_0) at the anchor): dM + k dtheta = 0 at the top,
  dM - k dtheta = 0 at the bottom; isotropic, so out of plane B + k psi = 0 (top), B - k
  psi = 0 (bottom): B = EI psi' pairs with psi as M = EI theta' with theta (the energy
  1/2 int EI psi'^2 and its boundary term B dpsi);
- a free anchor: no force and no moment, dT = dF = dM = 0; Q = 0, B = 0;
- a tensioner at the top: dx = 0 and w = 0; the line's vertical end force P_y = T sin
  theta - F cos theta follows the tensioner, dP_y = -k_t dy:
  sin(theta) dT + (T cos theta + F sin theta) dtheta - cos(theta) dF + k_t dy = 0, with
  the static theta, T, F at the top.
"""

from __future__ import annotations

import numpy as np

from riser.model.ends import FixedEnds
from riser.model.scene import Scene

IN_PLANE = {"dx": 0, "dy": 1, "dtheta": 2, "dM": 3, "dF": 4, "dT": 5}
OUT_OF_PLANE = {"w": 0, "psi": 1, "B": 2, "Q": 3}


def as_rows(states) -> tuple:
    """Rows of ``states`` held at zero (each its own row, coefficient 1)."""
    return tuple(((int(i), 1.0),) for i in states)


def modal_ends(scene: Scene, plane: str, top_static: dict | None = None) -> tuple:
    """(bottom rows, top rows) of the family ``plane`` of ``scene``; ``top_static``: the
    static theta [rad], T [N], F [N] at the top (needed with a tensioner)."""
    e = scene.ends
    clamped = tuple(scene.vfife.clamped_ends)
    inp = plane == "in_plane"
    ix = IN_PLANE if inp else OUT_OF_PLANE
    disp = ("dx", "dy") if inp else ("w",)
    rot, mom = ("dtheta", "dM") if inp else ("psi", "B")
    out = []
    for end, name, sign in (("anchor", "bottom", -1.0), ("hang_off", "top", 1.0)):
        joint = e.joint(end) if isinstance(e, FixedEnds) else None
        kind = "clamped" if name in clamped else (joint.kind if joint else "pinned")
        if kind == "free":
            rows = as_rows([ix[k] for k in (("dT", "dF", "dM") if inp else ("Q", "B"))])
            out.append(rows)
            continue
        rows = list(as_rows([ix[k] for k in disp]))
        if kind == "clamped":
            rows.append(((ix[rot], 1.0),))
        elif kind == "spring":
            rows.append(((ix[mom], 1.0), (ix[rot], sign * joint.rotational_stiffness)))
        else:
            rows.append(((ix[mom], 1.0),))
        if name == "top" and isinstance(e, FixedEnds) and e.tensioner is not None and inp:
            th, T, F = top_static["theta"], top_static["T"], top_static["F"]
            c, sn = float(np.cos(th)), float(np.sin(th))
            rows[1] = ((ix["dT"], sn), (ix["dtheta"], T * c + F * sn), (ix["dF"], -c),
                       (ix["dy"], e.tensioner.stiffness))
        out.append(tuple(rows))
    return tuple(out)
