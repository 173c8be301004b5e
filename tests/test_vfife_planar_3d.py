"""The planar and the 3D kernel paths of the VFIFE agree on a planar scene (no
out-of-plane current or motion), statics and dynamics, with each branch of the kernels
switched on in turn: drag (a current in statics and dynamics, still-water drag in
dynamics), the sea surface (the line's top lifted through it), seabed friction (the
touchdown dragged sideways), internal flow (steady, and a slug).

How the path is chosen: :func:`vfife.solve` steps a scene with ``scene.is_planar`` through
the planar kernels (``*_2d`` in :mod:`vfife.kernels`, on rows x, y of the state); the
3D kernels are the general path. Both entry points below it take the choice explicitly,
:func:`vfife.statics.equilibrium.solve_static` (``planar``) and :func:`vfife.dynamics.run.run_dynamics`
(``planar``), so the 3D path of a planar scene is those calls with ``planar=False``; the
planar calls are checked to be what :func:`vfife.solve` runs. The dynamics of both paths
start from the same (planar) static state, so that their difference is the dynamics'.

Exact identity: on the 3D path the out-of-plane components (z, v_z, d_z and the in-plane
rotation rates w_x, w_y) stay exactly 0.0 (every out-of-plane force is a product with a
zero; the current's heading is 0 deg, whose sine is exactly 0; heading 180 deg would give
sin(pi) = 1.2e-16 and z ~ 1e-16).

Tolerances (round-off): the two paths evaluate the same formulas with z = 0 but in a
different order (fast-math contraction and vectorisation differ), so they differ by
round-off, which each step adds (relative 1e-16) and the damped, driven line carries over
the ~57,000-74,000 relaxation and ~4,500 dynamic steps. Measured (bench machine): static
positions and directors <= 7e-14 of the line length (of 1), static tensions, moments and
shears <= 1.2e-11 of their largest; dynamic positions <= 4.3e-14 of the line length,
velocities, tensions and moments <= 8.1e-10 of their largest, time series <= 6e-9 of each
column's largest (min_tension: its largest magnitude is small beside the forces whose
difference it is). Forces carry ~1e3 times the positions' relative round-off: the stretch
l - l0 is ~1e-3 of l here. POSITION_TOL = 1e-11 of the line length and TOL = 1e-6 of each
quantity's largest magnitude leave a margin of >= 150 for a CPU that rounds differently;
each branch's own effect on the same time series is >= 3.8e-2 (the control of each case:
the same run with the branch off), above BRANCH_EFFECT = 1e-3 = 1000 TOL, so a branch
that one path dropped or computed differently could not pass. The runs are short (10 s of
a 150 m line in 2 m elements, ~0.1 s each) and damped (drag or structural damping):
undamped, the line slapping the seabed is chaotic and round-off grows to O(1) within
~20 s.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest

import builders
import vfife
from vfife.dynamics.run import run_dynamics
from vfife.statics.equilibrium import solve_static

POSITION_TOL = 1e-11        # x line length; see the module docstring
TOL = 1e-6                  # x the quantity's largest magnitude
BRANCH_EFFECT = 1e-3        # a branch switched off changes its outputs by more than this
LENGTH = 150.0              # [m] of line, 2 m elements

LINE_TYPE = builders.small_pipe(drag_tangential=0.03)
NO_DRAG = {**LINE_TYPE, "drag_normal": 0.0, "drag_tangential": 0.0}
CONTENTS = {**LINE_TYPE, "contents_density": 800.0}
SWAY = {"axis": "x", "amplitude": 2.0, "period": 5.0}
HEAVE = {"axis": "y", "amplitude": 2.0, "period": 5.0}
CURRENT = {"heights": [0.0, 60.0], "speeds": [-0.2, -1.0], "heading_deg": 0.0}
STEADY = {"speed": 5.0}
SLUG = {"speed": 5.0, "slug": {"density_amplitude": 0.25, "slug_length": 20.0}}


def scr(*, line_type=LINE_TYPE, motion=SWAY, damping=0.0, **tables) -> dict:
    """:func:`builders.catenary` (150 m of line from an anchor on an elastic seabed to a
    hang-off at (100, 60) m) in 2 m elements; 10 s of top motion (default: sway, 2 m,
    5 s)."""
    return builders.catenary(line_type=line_type,
                             dynamics={"duration": 10.0, "output_interval": 0.5,
                                       "save_states": True, "damping": damping,
                                       "top_motion": motion},
                             vfife={"element_length": 2.0}, **tables)


def hanging(water_depth: float | None) -> dict:
    """120 m of line hanging from (0, 10) m to (100, 60) m, no seabed, heaved 2 m: with a
    water depth of 60.2 m its top element leaves the water for part of each period (the
    first free node reaches y = 60.35 m)."""
    env = {"water_depth": water_depth} if water_depth is not None else None
    return builders.line(120.0, (0.0, 10.0), (100.0, 60.0), line_type=LINE_TYPE,
                         submerged_weight=100.0, environment=env,
                         dynamics={"duration": 10.0, "output_interval": 0.5,
                                   "save_states": True, "top_motion": HEAVE},
                         vfife={"element_length": 2.0})


DEEP = {"water_depth": 100.0}        # [internal_flow] needs one; the line stays 40 m below
#: case: (scene, the effect its branch adds (None: no branch), the scene with it off)
CASES = {
    # no drag coefficients: no drag kernel; structural damping keeps it regular
    "no-drag": (scr(line_type=NO_DRAG, damping=0.2), None, None),
    "current-drag": (scr(environment={"current": CURRENT}), "current_drag", scr()),
    "still-water-drag": (scr(), "drag", scr(line_type=NO_DRAG)),
    "sea-surface": (hanging(60.2), "sea_surface", hanging(None)),
    "seabed-friction": (scr(seabed={"stiffness": 1e5, "friction": 0.1}), "seabed_friction",
                        scr()),
    "steady-flow": (scr(line_type=CONTENTS, environment=DEEP, internal_flow=STEADY),
                    "internal_flow", scr(line_type=CONTENTS, environment=DEEP)),
    "slug-flow": (scr(line_type=CONTENTS, environment=DEEP, internal_flow=SLUG), "slug_flow",
                  scr(line_type=CONTENTS, environment=DEEP, internal_flow=STEADY)),
}


def run(data: dict, planar: bool, static=None):
    """(static model, static info, dynamic model, dynamic info) of the scene ``data`` on
    one kernel path; the dynamics from ``static`` when given (else this path's own)."""
    scene = builders.scene(data)
    assert scene.is_planar
    # the two kernel paths' relaxations compared step for step: Newton's finish
    # (vfife/statics/newton.py) off
    scene = scene.replace(**{"vfife.expert.static_newton": False})
    vf = scene.vfife
    model, sinfo = solve_static(scene, vf.element_length, vf.static_tolerance, planar)
    end, dinfo = run_dynamics(scene, static if static is not None else model, planar)
    return model, sinfo, end, dinfo


def rel(a, b, scale: float) -> float:
    """max |a - b| / scale over the finite entries (the NaN patterns must match)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert np.array_equal(np.isnan(a), np.isnan(b))
    ok = ~np.isnan(a)
    return float(np.max(np.abs(a[ok] - b[ok]), initial=0.0)) / scale


def scale(*arrays) -> float:
    return max(float(np.nanmax(np.abs(np.asarray(x, float)), initial=0.0)) for x in arrays)


#: time-series columns of a value (the others: time, the prescribed hang-off, and the
#: nodes where the extremes are, min_tension_s and max_moment_s, which two nodes of nearly
#: equal value could swap on round-off; their values are compared)
VALUES = ("hang_off_tension", "touchdown_s", "touchdown_tension", "min_tension",
          "max_moment", "kinetic_energy")


def series_difference(a: dict, b: dict, columns=VALUES) -> float:
    """The largest difference between two runs' time series ``columns``, each relative to
    its largest magnitude."""
    return max(rel(a[k], b[k], max(scale(a[k]), 1e-300)) for k in columns)


@functools.cache
def paths(name: str):
    """(planar path, 3D path) of case ``name``, each (static model, static info, dynamic
    model, dynamic info); the 3D dynamics start from the planar static state."""
    data = CASES[name][0]
    planar = run(data, True)
    return planar, run(data, False, static=planar[0])


BRANCHED = [name for name, (_, effect, _) in CASES.items() if effect is not None]


@pytest.mark.parametrize("name", CASES)
def test_the_3d_path_stays_exactly_in_plane(name):
    _, (s3, _, d3, info3) = paths(name)
    for m in (s3, d3):
        assert not m.planar
        for row in (m.X[2], m.V[2], m.D[2], m.W[0], m.W[1]):
            assert np.all(row == 0.0)
    x = np.asarray(info3["states"]["x"])
    v = np.asarray(info3["states"]["v"])
    assert np.all(x[..., 2] == 0.0) and np.all(v[..., 2] == 0.0)
    assert np.all(np.asarray(info3["timeseries"]["hang_off_z"]) == 0.0)


@pytest.mark.parametrize("name", CASES)
def test_same_static_state(name):
    (sp, ip, _, _), (s3, i3, _, _) = paths(name)
    assert ip["status"] == i3["status"] == "converged", (ip["status"], i3["status"])
    assert sp.planar and not s3.planar
    # the same relaxation: the same number of steps to the same tolerance
    assert ip["steps"] == i3["steps"]
    assert rel(sp.X[:2], s3.X[:2], LENGTH) <= POSITION_TOL
    assert rel(sp.D[:2], s3.D[:2], 1.0) <= POSITION_TOL
    rp, r3 = sp.nodal_results(), s3.nodal_results()
    for q in ("tension", "moment", "shear"):
        assert rel(rp[q], r3[q], scale(rp[q])) <= TOL, q


@pytest.mark.parametrize("name", CASES)
def test_same_dynamic_time_series(name):
    effect = CASES[name][1]
    (_, _, dp, ip), (_, _, d3, i3) = paths(name)
    assert ip["status"] == i3["status"] == "ok", (ip["message"], i3["message"])
    assert ip["steps"] == i3["steps"] and ip["time_step"] == i3["time_step"]
    assert ip["effects"] == i3["effects"]
    if effect is not None:
        assert effect in ip["effects"]
    else:
        assert not {"drag", "current_drag"} & set(ip["effects"])
    ts_p, ts_3 = ip["timeseries"], i3["timeseries"]
    assert set(ts_p) == set(ts_3) and len(ts_p["time"]) == 21
    assert series_difference(ts_p, ts_3) <= TOL
    for k in ("time", "hang_off_x", "hang_off_y", "hang_off_z"):      # prescribed: copies
        np.testing.assert_array_equal(ts_p[k], ts_3[k], err_msg=k)
    for k, e in ip["envelope"].items():
        assert rel(e, i3["envelope"][k], max(scale(e), 1e-300)) <= TOL, k
    st_p, st_3 = ip["states"], i3["states"]
    assert rel(np.asarray(st_p["x"])[..., :2], np.asarray(st_3["x"])[..., :2],
               LENGTH) <= POSITION_TOL
    for k in ("v", "tension", "moment"):
        assert rel(st_p[k], st_3[k], max(scale(st_p[k]), 1e-300)) <= TOL, k
    assert rel(dp.X[:2], d3.X[:2], LENGTH) <= POSITION_TOL


@pytest.mark.parametrize("name", BRANCHED)
def test_the_branch_matters_far_above_the_tolerance(name):
    # the same run with the branch off differs by >= BRANCH_EFFECT: the branch is live in
    # these runs, and the tolerance could not hide it
    _, effect, off = CASES[name]
    (_, _, _, ip), _ = paths(name)
    _, _, _, info_off = run(off, True)
    assert effect in ip["effects"] and effect not in info_off["effects"]
    assert series_difference(ip["timeseries"], info_off["timeseries"]) >= BRANCH_EFFECT


@pytest.mark.parametrize("name", CASES)
def test_the_planar_path_is_what_solve_runs(name):
    # vfife.solve picks the planar kernels for these scenes and gives bit for bit the
    # time series of the planar path's calls above
    (_, _, _, ip), _ = paths(name)
    res = vfife.solve(builders.scene(CASES[name][0]).replace(
        **{"vfife.expert.static_newton": False}))          # as the paths above (run)
    assert res.converged, res.message
    assert res.info["kernel"] == "planar"
    for k, v in ip["timeseries"].items():
        np.testing.assert_array_equal(np.asarray(res.dynamics.timeseries[k], float),
                                      np.asarray(v, float), err_msg=k)
