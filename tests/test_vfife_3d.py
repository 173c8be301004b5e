"""The VFIFE in 3D: a current that turns with height, a hang-off out of the anchor's
plane, a uniform dead load of fixed direction (:func:`vfife.solve` ``dead_load``), and the
3D profile columns (``lateral``, ``moment_out_of_plane``).

Each case is checked against an independent statement of the same line:
- a turning profile is the single-heading profile it spells differently (headings all
  equal, or reversed by 180 deg with the speed's sign), and its nodal current is
  :meth:`riser.physics.environment.Current.velocity` (numpy's interpolation, not the kernel's);
- a line whose hang-off is out of the anchor's plane is the planar line (same horizontal
  distance, planar kernels) rotated about the vertical through the anchor: the seabed,
  gravity and a current along the line's plane do not care about the heading;
- a catenary between two ends at one height under its weight w plus a sideways dead load
  q hangs in the plane tilted by atan(q / w) about its chord, as the planar catenary of
  weight sqrt(w^2 + q^2) (a separate planar solve) rotated about that chord.

Tolerances. Round-off (``POSITION_TOL``, ``TOL``, as in tests/test_vfife_planar_3d.py):
where the two runs start from the same shape up to a rotation and meet the same loads,
they take the same number of relaxation steps and differ by round-off only (measured:
positions <= 1.7e-15 of the line length, tensions <= 1.5e-11 and moments, shears <=
2.1e-12 of their largest; a start or load that were not exactly rotated would stop at
another step and differ by ~1e-7). The 3D case leaves the 150 m line 9-13 m off its plane
and the turning current changes its positions by far more than these tolerances.
Relaxation tolerance (the dead load, whose 3D run swings out of its vertical start while
the planar run does not, so their paths differ): each run stops with at most
``creep_tolerance`` (1e-5) of the line length of displacement, ``tension_tolerance``
(1e-5) of the largest tension and ``moment_tolerance`` (5e-4) of the largest moment still
to come, so two runs agree to twice those (measured 1.9e-7, 9.5e-8 and 6.2e-7: margins of
100 and more; the dead load moves the line 15 m sideways, 0.13 of its length).

The runs are short (a 150 m or 120 m line in 2 m elements, 0.03-0.4 s each).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import builders
import vfife
from riser.model.frame import LinePlane, out_of_plane_columns
from vfife import kernels
from vfife.solver import warm_up
from vfife.statics.equilibrium import solve_static

POSITION_TOL = 1e-11        # x line length: round-off (module docstring)
TOL = 1e-6                  # x the quantity's largest magnitude: round-off
LENGTH = 150.0              # [m] of line of builders.catenary
PSI_DEG = 35.0              # [deg] heading of the rotated line's plane
ANCHOR = (5.0, 0.0, -3.0)   # [m] the rotated line's anchor (off the origin on purpose)


def cat(current: dict | None = None, ends: dict | None = None) -> dict:
    """:func:`builders.catenary` (150 m from an anchor on the seabed to a hang-off at
    (100, 60) m) in 2 m elements, with a ``current`` table and other ``ends``."""
    data = builders.catenary(vfife={"element_length": 2.0},
                             environment={"current": current} if current else None)
    if ends is not None:
        data["ends"] = ends
    return data


def rotated_ends() -> dict:
    """The ends of :func:`cat` turned by PSI_DEG about the vertical through ANCHOR."""
    psi = math.radians(PSI_DEG)
    xa, ya, za = ANCHOR
    return {"anchor": list(ANCHOR),
            "hang_off": [xa + 100.0 * math.cos(psi), 60.0, za + 100.0 * math.sin(psi)]}


_SOLVED: dict = {}


def solve(key: str, data: dict, dead_load=None):
    """The VFIFE solve of the scene ``data`` with ``dead_load``, once per ``key`` (a key
    names one scene and load throughout this module)."""
    if key not in _SOLVED:
        res = vfife.solve(builders.scene(data), dead_load=dead_load)
        assert res.converged, (key, res.message)
        _SOLVED[key] = res
    return _SOLVED[key]


def rel(a, b, scale: float) -> float:
    return float(np.max(np.abs(np.asarray(a, float) - np.asarray(b, float)))) / scale


def assert_same_values(p, q):
    """Tension, moment and shear of profiles p and q equal to TOL of p's largest."""
    for name in ("tension", "moment", "shear"):
        a, b = getattr(p, name), getattr(q, name)
        assert rel(a, b, float(np.max(np.abs(a)))) <= TOL, name


# ------------------------------------------------------------------ a current turning with depth
SINGLE_90 = {"heights": [0.0, 60.0], "speeds": [0.3, 1.0], "heading_deg": 90.0}
REVERSING_90 = {"heights": [0.0, 60.0], "speeds": [0.3, -1.0], "heading_deg": 90.0}
REVERSING_0 = {"heights": [0.0, 60.0], "speeds": [0.3, -1.0], "heading_deg": 0.0}
TURNING = {
    # headings all equal: the same profile (3D, the current profile path every step)
    "equal-90": ({"heights": [0.0, 60.0], "speeds": [0.3, 1.0], "headings_deg": [90.0, 90.0]},
                 SINGLE_90, "3d"),
    # 90 -> 270 deg: the z component reverses with height, as signed speeds along 90 deg
    "reversing-90-270": ({"heights": [0.0, 60.0], "speeds": [0.3, 1.0],
                          "headings_deg": [90.0, 270.0]}, REVERSING_90, "3d"),
    # 0 -> 180 deg: in plane, the planar kernels on the x components
    "planar-0-180": ({"heights": [0.0, 60.0], "speeds": [0.3, 1.0],
                      "headings_deg": [0.0, 180.0]}, REVERSING_0, "planar"),
}


@pytest.mark.parametrize("case", list(TURNING))
def test_turning_profile_is_the_single_heading_profile_it_spells(case):
    """A turning profile whose headings say what one heading with signed speeds says gives
    that profile's line to round-off (measured: equal-90 and planar-0-180 bit for bit,
    reversing-90-270 positions 1.2e-15 of the length, tension 1.5e-11: the x component
    of 270 deg is 1.8e-16 of the speed, not 0)."""
    turning, single, kernel = TURNING[case]
    a = solve(case, cat(turning))
    b = solve(case + "/single", cat(single))
    assert a.info["kernel"] == b.info["kernel"] == kernel
    p, q = a.profile, b.profile
    xyz = np.c_[p.x, p.y, p.z] - np.c_[q.x, q.y, q.z]
    assert float(np.max(np.abs(xyz))) <= POSITION_TOL * LENGTH
    assert_same_values(p, q)
    if kernel == "3d":      # it did leave the plane (the check is not of a planar line)
        assert float(np.max(np.abs(p.lateral))) > 5.0
        assert p.moment_out_of_plane is not None
    else:
        assert p.lateral is None and p.moment_out_of_plane is None


def test_turning_current_at_the_nodes_is_the_profile_interpolated_component_wise():
    """The kernels' nodal current of a profile turning with height (x components along
    cdir = e_x, z components in Uz, each by the branch-free :func:`vfife.kernels.
    current_pass`) equals :meth:`riser.physics.environment.Current.velocity` at the node heights
    (np.interp of each component; constant above the top height, 45 m, which the upper
    nodes pass) to round-off (1e-12 m/s). A single heading keeps Uz exactly zero."""
    cur = {"heights": [0.0, 20.0, 45.0], "speeds": [0.5, 1.0, 0.8],
           "headings_deg": [0.0, 45.0, 120.0]}
    res = solve("nodal", cat(cur))
    model = res.solver_state
    y = model.X[1].copy()
    assert float(np.max(y)) > 45.0
    model.run(1, 1e-9, 0.0)                 # the current pass runs on the heights y
    ux, uz = model.scene.current.velocity(y)
    assert model.turning and np.array_equal(model.cdir, [1.0, 0.0, 0.0])
    assert float(np.max(np.abs(model.U - ux))) <= 1e-12
    assert float(np.max(np.abs(model.Uz - uz))) <= 1e-12
    assert float(np.max(np.abs(uz))) > 0.5          # the z components are not trivial
    single = solve("equal-90/single", cat(SINGLE_90)).solver_state
    single.run(1, 1e-9, 0.0)
    assert not single.turning and not np.any(single.Uz)


# ------------------------------------------------------------------ a hang-off out of plane
ROTATED = {
    "no-current": (None, None),
    # a current along the line's plane: heading 0 in the planar scene, PSI in the rotated
    "current-in-plane": (REVERSING_0, {**REVERSING_0, "heading_deg": PSI_DEG}),
    "turning-in-plane": (REVERSING_0, {"heights": [0.0, 60.0], "speeds": [0.3, 1.0],
                                       "headings_deg": [PSI_DEG, PSI_DEG + 180.0]}),
}


@pytest.mark.parametrize("case", list(ROTATED))
def test_hang_off_out_of_plane_is_the_planar_line_rotated(case):
    """The line whose hang-off is out of the anchor's plane (its plane at PSI_DEG, the 3D
    kernels) is the planar line (planar kernels) turned about the vertical through the
    anchor: positions rotated, tension, moment and shear equal, no lateral offset and no
    out-of-plane moment, to round-off (measured: positions 1.7e-15 of the length, tension
    1.5e-11, moment 9e-13, lateral 3e-13 m, out-of-plane moment 4e-13 of the largest
    moment; the same number of relaxation steps). Its end nodes sit exactly on the ends."""
    planar_current, rotated_current = ROTATED[case]
    a = solve(case + "/planar", cat(planar_current))
    b = solve(case + "/rotated", cat(rotated_current, ends=rotated_ends()))
    assert a.info["kernel"] == "planar" and b.info["kernel"] == "3d"
    assert a.profile.lateral is None
    p, q = a.profile, b.profile
    psi = math.radians(PSI_DEG)
    expected = np.c_[ANCHOR[0] + p.x * math.cos(psi), p.y, ANCHOR[2] + p.x * math.sin(psi)]
    got = np.c_[q.x, q.y, q.z]
    assert float(np.max(np.abs(expected - got))) <= POSITION_TOL * LENGTH
    assert_same_values(p, q)
    assert float(np.max(np.abs(q.lateral))) <= POSITION_TOL * LENGTH
    assert float(np.max(np.abs(q.moment_out_of_plane))) <= TOL * float(np.max(p.moment))
    ends = b.solver_state.scene.ends
    assert tuple(got[0]) == ends.anchor_point and tuple(got[-1]) == ends.hang_off_point


def test_ends_at_one_nonzero_z_keep_the_planar_line():
    """Both ends at z = 7 m (a planar scene, the x-y plane shifted): the planar kernels,
    z = 7 m at every node, x and y bit for bit those of the ends at z = 0 (the planar
    kernels never touch z, and the start is the same catenary)."""
    shifted = solve("z7", cat(ends={"anchor": [0.0, 0.0, 7.0], "hang_off": [100.0, 60.0, 7.0]}))
    base = solve("no-current/planar", cat())
    assert shifted.info["kernel"] == "planar" and shifted.profile.lateral is None
    assert np.all(shifted.profile.z == 7.0)
    for name in ("x", "y", "tension", "moment"):
        assert np.array_equal(getattr(shifted.profile, name), getattr(base.profile, name))


# ------------------------------------------------------------------ a uniform dead load
W_LINE, Q_SIDE = 100.0, 60.0        # [N/m] submerged weight, sideways dead load (+z)
SPAN_Y = 50.0                       # [m] height of both ends


def hanging(weight: float) -> dict:
    """120 m of :func:`builders.small_pipe` of submerged ``weight`` [N/m] hanging between
    (0, 50) and (100, 50) m, no seabed, 2 m elements."""
    return builders.line(120.0, (0.0, SPAN_Y), (100.0, SPAN_Y),
                         line_type=builders.small_pipe(), submerged_weight=weight,
                         vfife={"element_length": 2.0})


def relaxation_bounds() -> tuple[float, float, float]:
    """Twice the relaxation's tolerances (module docstring): positions [x line length],
    tension and moment [x their largest]."""
    vf = builders.scene(hanging(W_LINE)).vfife
    return 2 * vf.creep_tolerance, 2 * vf.tension_tolerance, 2 * vf.moment_tolerance


def test_sideways_dead_load_tilts_the_catenary_about_its_chord():
    """Weight w down and a dead load q along +z: the line hangs in the plane through its
    (horizontal) chord tilted by atan(q / w) from the vertical, as the planar catenary of
    weight sqrt(w^2 + q^2) (the scene with the segment's submerged weight changed, solved
    on the planar kernels) turned about the chord: a sag d below the chord becomes
    (y, z) = (50 + d w / W, -d q / W). Tension and moment equal; ``lateral`` is z (the
    line's plane is the x-y plane) and the out-of-plane moment that of the turned planar
    moment vectors and tangents."""
    weight = math.hypot(W_LINE, Q_SIDE)
    a = solve("dead-z", hanging(W_LINE), (0.0, 0.0, Q_SIDE))
    scene = builders.scene(hanging(W_LINE))
    b = vfife.solve(scene.replace(**{"segments[0].submerged_weight": weight}))
    assert b.converged and b.info["kernel"] == "planar"
    assert a.info["kernel"] == "3d" and "dead_load" in a.effects
    pos_tol, t_tol, m_tol = relaxation_bounds()
    p, q = b.profile, a.profile
    d = p.y - SPAN_Y
    assert float(np.min(d)) < -25.0                 # a deep sag: a strong test of the tilt
    expected = np.c_[p.x, SPAN_Y + d * W_LINE / weight, -d * Q_SIDE / weight]
    assert float(np.max(np.abs(expected - np.c_[q.x, q.y, q.z]))) <= pos_tol * 120.0
    assert rel(q.tension, p.tension, float(np.max(p.tension))) <= t_tol
    assert rel(q.moment, p.moment, float(np.max(p.moment))) <= m_tol
    assert np.array_equal(q.lateral, q.z)

    c, s = W_LINE / weight, Q_SIDE / weight          # the turn about x: (0,-1,0) -> (0,-c,s)

    def turn(v):
        return np.c_[v[:, 0], c * v[:, 1] + s * v[:, 2], -s * v[:, 1] + c * v[:, 2]]

    planar = b.solver_state
    _, oop = out_of_plane_columns(LinePlane.of(scene), expected[:, 0], expected[:, 2],
                                  turn(planar.directors()),
                                  turn(-planar.nodal_results()["moment_vector"].T))
    assert float(np.max(np.abs(oop))) > 0.4 * float(np.max(p.moment))
    assert rel(q.moment_out_of_plane, oop, float(np.max(p.moment))) <= m_tol


def test_vertical_dead_load_is_more_weight():
    """A dead load (0, -dw, 0) on the planar kernels is the line of weight w + dw (the
    scene's segment weight changed): to the relaxation's tolerance (measured: positions
    4.8e-9 of the length, tension 2.6e-8)."""
    dw = 30.0
    a = solve("dead-y", hanging(W_LINE), (0.0, -dw, 0.0))
    b = solve("heavier", hanging(W_LINE + dw))
    assert a.info["kernel"] == "planar" and a.profile.lateral is None
    pos_tol, t_tol, m_tol = relaxation_bounds()
    p, q = b.profile, a.profile
    assert rel(np.c_[q.x, q.y, q.z], np.c_[p.x, p.y, p.z], 120.0) <= pos_tol
    assert rel(q.tension, p.tension, float(np.max(p.tension))) <= t_tol
    assert rel(q.moment, p.moment, float(np.max(p.moment))) <= m_tol


def test_in_plane_dead_load_planar_and_3d_kernels_agree():
    """A dead load (qx, qy, 0) on a planar scene: the planar kernels (what
    :func:`vfife.solve` runs) and the 3D kernels (``solve_static(planar=False)``) give
    the same line to round-off (the two paths of tests/test_vfife_planar_3d.py; z stays
    exactly 0 on the 3D path)."""
    # the two kernel paths' relaxations (Newton's finish off)
    scene = builders.scene(hanging(W_LINE)).replace(**{"vfife.expert.static_newton": False})
    load = (40.0, -20.0, 0.0)
    vf = scene.vfife
    mp, _ = solve_static(scene, vf.element_length, vf.static_tolerance, True, dead_load=load)
    m3, _ = solve_static(scene, vf.element_length, vf.static_tolerance, False, dead_load=load)
    assert mp.planar and not m3.planar and mp.use_dead and m3.use_dead
    assert not np.any(m3.X[2])
    assert rel(mp.X, m3.X, 120.0) <= POSITION_TOL
    tp, t3 = mp.nodal_results(), m3.nodal_results()
    for name in ("tension", "moment"):
        assert rel(tp[name], t3[name], float(np.max(np.abs(tp[name])))) <= TOL, name
    # the load did act: x moves by more than 1 m against the line without it
    plain = solve("no-dead", hanging(W_LINE)).profile
    assert float(np.max(np.abs(mp.X[0] - plain.x))) > 1.0


def test_dead_load_is_checked():
    """A dead load is three finite numbers; a z component is refused on the planar path."""
    scene = builders.scene(hanging(W_LINE))
    vf = scene.vfife
    with pytest.raises(ValueError, match="dead_load"):
        vfife.solve(scene, dead_load=(1.0, 2.0))
    with pytest.raises(ValueError, match="dead_load"):
        vfife.solve(scene, dead_load=(0.0, math.nan, 0.0))
    with pytest.raises(ValueError, match="planar"):
        solve_static(scene, vf.element_length, vf.static_tolerance, True,
                     dead_load=(0.0, 0.0, 1.0))


# ------------------------------------------------------------------ compilation
def test_warm_up_compiles_what_the_3d_solves_run():
    """:func:`vfife.solver.warm_up` compiles every argument-type combination of the solves
    above (a turning current, a hang-off out of plane, dead loads on both paths): they add
    no signature to any kernel (a new one would compile during a timed solve)."""
    warm_up()
    dispatchers = [getattr(kernels, n) for n in dir(kernels)
                   if hasattr(getattr(kernels, n), "signatures")]
    before = {d.__name__: len(d.signatures) for d in dispatchers}
    solve("reversing-90-270", cat(TURNING["reversing-90-270"][0]))
    solve("turning-in-plane/rotated", cat(ROTATED["turning-in-plane"][1], ends=rotated_ends()))
    solve("dead-z", hanging(W_LINE), (0.0, 0.0, Q_SIDE))
    solve("dead-y", hanging(W_LINE), (0.0, -30.0, 0.0))
    assert {d.__name__: len(d.signatures) for d in dispatchers} == before
