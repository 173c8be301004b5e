"""Modes about a static state in an in-plane current: both methods linearise the same
model, the static drag frozen as a dead load (``bvp/modal/modes.py``, ``vfife/modal/tangent.py``).

The VFIFE's tangent has no drag term (a constant nodal force has no stiffness); the BVP's
equations are written in the frame that turns with the line, where a dead load's
components turn: d(q.n) = -(q.t) dtheta, d(q.t) = (q.n) dtheta. Without the drag's share
of these terms (-f_t dtheta in dF', -f_n dtheta in dT') the BVP's drag turned with the
line and the methods differed by up to 1.5 % in plane, whatever the mesh.

The scene: a light dynamic power cable (OD 0.2 m, 40 kg/m, EI 1e4 N m2, EA 5e8 N,
C_Dn 1.2) in 200 m of water, a uniform in-plane current of 1 m/s towards the hang-off.
Measured (3 modes per plane, VFIFE / BVP - 1):

- suspended (anchor 50 m above the seabed), 2 m elements: without current -0.007, -0.012,
  -0.023 % in plane, -0.003 to -0.014 % out of plane; with the current -0.007, -0.013,
  -0.024 % and -0.003 to -0.014 % (1 m elements: all within 0.007 %); the drag's terms
  left out: -0.46, -0.30, -0.19 % in plane, out of plane unchanged.
- on the seabed (k = 1e5 N/m2, 88 m grounded), 2 m elements: with the current -0.06,
  -0.07, -0.08 %; the drag's terms left out -1.55, -0.88, -0.51 %. Here the VFIFE's lumped
  springs resolve the touchdown to one element (a boundary layer (EI/k)^(1/4) = 0.56 m):
  at 1, 0.5, 0.25, 0.125 m elements the first mode differs by -0.077, +0.084, +0.044,
  +0.020 % (without current -0.002, -0.072, +0.034, -0.005 %), O(h) and not monotone
  (where the touchdown falls between two nodes).
"""

from __future__ import annotations

import numpy as np
import pytest

import bvp.modal.modes
import vfife.modal.modes
from bvp.modal.equations import FAMILIES, Piece, build_pieces
from bvp.solver import solve as bvp_solve
from riser.io.scene_file import scene_from_dict
from verification.comparison.modes import pair_rows

#: suspended cable: the largest |difference| without current at 2 m elements is 0.023 %
#: (in-plane mode 3, the VFIFE's O(h^2) discretisation); with the current the same. Twice
#: that, a tenth of the difference the drag's terms make.
TOL_SUSPENDED = 5e-4
#: grounded cable: the VFIFE's touchdown is resolved to one element, 0.08 % at 2 m
#: (and up to 0.11 % without current at 0.5 to 2 m elements); a sixth of the 1.5 % the
#: drag's terms make on the first mode.
TOL_GROUNDED = 2.5e-3
COUNT = 3


def cable(speed: float, *, grounded: bool = False):
    """The light power cable, 2 m VFIFE elements; ``grounded``: anchored on the seabed
    (400 m of line, 88 m on the seabed at 1 m/s) instead of 50 m above it (340 m)."""
    d = {"name": "power-cable",
         "environment": {"water_depth": 200.0, "water_density": 1025.0},
         "line_types": {"cable": {"outer_diameter": 0.2, "mass_per_length": 40.0,
                                  "axial_stiffness": 5e8, "bending_stiffness": 1e4,
                                  "drag_normal": 1.2, "drag_tangential": 0.0,
                                  "added_mass": 1.0}},
         "seabed": {"stiffness": 1e5},
         "segments": [{"line_type": "cable", "length": 400.0 if grounded else 340.0}],
         "ends": {"anchor": [0.0, 0.0 if grounded else 50.0], "hang_off": [280.0, 200.0]},
         "vfife": {"element_length": 2.0}}
    if speed:
        d["environment"]["current"] = {"heights": [0.0, 200.0], "speeds": [speed, speed]}
    return scene_from_dict(d, "test")


def rows_of(scene):
    b = bvp.modal.modes.solve_modes(scene, COUNT)
    v = vfife.modal.modes.solve_modes(scene, COUNT)
    assert b.converged and v.converged, (b.message, v.message)
    rows = pair_rows(b, v)
    assert len(rows) == 2 * COUNT
    return rows


def without_drag_terms(monkeypatch):
    """The BVP's pieces built without the dead drag (its frame terms left out)."""
    monkeypatch.setattr(bvp.modal.modes, "build_pieces",
                        lambda scene, profile, **kw: build_pieces(scene, profile))


def worst(rows, plane=None):
    return max(abs(r["rel_diff"]) for r in rows if plane in (None, r["plane"]))


@pytest.fixture(scope="module")
def suspended_rows():
    return rows_of(cable(1.0))


def test_suspended_cable_in_current_agrees(suspended_rows):
    assert worst(suspended_rows) <= TOL_SUSPENDED, suspended_rows
    assert all(r["mac"] >= 0.9999 for r in suspended_rows)


def test_current_adds_no_disagreement(suspended_rows):
    # mode by mode the difference is the no-current one (the discretisation's) to 0.003 %
    still = rows_of(cable(0.0))
    for a, b in zip(suspended_rows, still):
        assert (a["plane"], a["mode"]) == (b["plane"], b["mode"])
        assert abs(a["rel_diff"] - b["rel_diff"]) <= 3e-5, (a, b)


def test_without_the_drag_terms_the_methods_differ(suspended_rows, monkeypatch):
    """Negative control: the drag's frame terms left out of the BVP, the in-plane modes
    miss by 0.2 to 0.46 %; out of plane nothing changes (a dead in-plane load has no
    term there)."""
    without_drag_terms(monkeypatch)
    rows = rows_of(cable(1.0))
    assert worst(rows, "in_plane") > 4 * TOL_SUSPENDED, rows
    for a, b in zip(rows, suspended_rows):
        if a["plane"] == "out_of_plane":
            assert a.value("bvp") == b.value("bvp")
        else:
            assert abs(a["rel_diff"]) > abs(b["rel_diff"]) + 1e-3


def test_grounded_cable_in_current(monkeypatch):
    rows = rows_of(cable(1.0, grounded=True))
    assert worst(rows) <= TOL_GROUNDED, rows
    without_drag_terms(monkeypatch)
    bad = rows_of(cable(1.0, grounded=True))
    assert worst(bad, "in_plane") > 5 * TOL_GROUNDED, bad


def test_tangential_drag_term(monkeypatch):
    """The -f_t dtheta term: with an exaggerated tangential drag (C_Dt 0.3: f_t up to 97
    N/m, f_n up to 110 N/m, the weight 77 N/m) the suspended cable agrees as without
    current (measured -0.003 to -0.024 %); with f_t left out of the BVP's frame terms
    in-plane mode 2 misses by 0.38 %."""
    scene = cable(1.0).replace(**{"line_types.cable.drag_tangential": 0.3})
    rows = rows_of(scene)
    assert worst(rows) <= TOL_SUSPENDED, rows
    static = Piece.static

    def without_f_t(self, s):
        out = static(self, s)
        out["f_t"] = np.zeros_like(out["f_t"])
        return out

    monkeypatch.setattr(Piece, "static", without_f_t)
    bad = rows_of(scene)
    assert worst(bad, "in_plane") > 4 * TOL_SUSPENDED, bad


def test_frame_terms_are_the_static_load_as_a_dead_load():
    """The BVP's dtheta column holds the whole static load q (weight, seabed, drag) as a
    dead load: A[dF, dtheta] = -(q.t) and A[dT, dtheta] = -(q.n), with q read off the
    static solution's own balance, q.n = F' - T kappa and q.t = -(T' + F kappa)."""
    scene = cable(1.0, grounded=True)
    static = bvp_solve(scene)
    assert static.converged
    fam = FAMILIES["in_plane"]
    dth, dF, dT = 2, 4, 5
    drag_max = 0.0
    for pc in build_pieces(scene, static.profile, dead_drag=True):
        s = np.linspace(pc.s0, pc.s1, 801)[1:-1]
        st = pc.static(s)
        A, _ = fam.matrices(pc, s)
        qn = pc.spl["F"](s, 1) - st["T"] * st["kappa"]
        qt = -(pc.spl["T"](s, 1) + st["F"] * st["kappa"])
        scale = abs(pc.w) + float(np.max(np.abs(st["f_n"])))
        assert np.max(np.abs(A[dF, dth] + qt)) <= 1e-3 * scale
        assert np.max(np.abs(A[dT, dth] + qn)) <= 1e-3 * scale
        drag_max = max(drag_max, float(np.max(np.abs(st["f_n"]))))
    assert drag_max > 0.3 * abs(pc.w)          # the drag is a good part of the load


def test_free_vibration_refuses_a_current():
    # released without its drag the static state in a current is no equilibrium
    with pytest.raises(ValueError, match="current"):
        vfife.modal.modes.free_vibration(cable(1.0))
