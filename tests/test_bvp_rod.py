"""The BVP's 3D rod (bvp/rod/equations.py, bvp/rod/problem.py): its analytic Jacobian
against finite differences, its reduction to the planar equations on every built-in
planar scene, its symmetries (a hang-off out of the anchor's plane, a current reversed
across the plane) and its refusals."""

from __future__ import annotations

import numpy as np
import pytest

import bvp
from bvp.collocation import unpruned
from bvp.rod.equations import IF2, IM2, IPH, IZ, NROD
from bvp.rod.problem import build_rod_problem
from riser.physics.environment import Current
from riser.errors import SceneError
from verification.catalog import builtin_paths, resolve
from verification.comparison.static.protocol import compare

from builders import line, pipe, scene

REL_STEP = 1.0e-6


# ------------------------------------------------------------------ the Jacobian
def _state(prob, rng, tau):
    """The problem's lifted starting guess with the out-of-plane states switched on
    (phi ~ 0.3 rad, M2 and F2 of the size of M1 and F1, z of metres), perturbed by 1 %:
    no entry of the Jacobian is then trivially zero."""
    Y = prob.guess(tau)
    nb = prob.model.n_block
    for b in range(nb):
        o = b * NROD
        Y[o + IPH] = 0.3 * np.sin(3.0 * tau + b)
        Y[o + IM2] = 0.5 * np.cos(2.0 * tau) * (np.abs(Y[o + 3]).max() + 1.0)
        Y[o + IF2] = 0.5 * np.sin(5.0 * tau) * (np.abs(Y[o + 4]).max() + 1.0)
        Y[o + IZ] = 0.01 * np.sin(tau)
    rms = np.sqrt(np.mean(Y ** 2, axis=1, keepdims=True)) + 1e-3
    Y = Y + 0.01 * rms * rng.standard_normal(Y.shape)
    for b in range(nb):                     # heights away from the seabed's kink y = 0
        y = Y[b * NROD + 1]
        Y[b * NROD + 1] = np.where(np.abs(y) < 1e-3, np.sign(y + 1e-12) * 1e-3, y)
    return Y


JAC_CASES = {
    # a turning current (drag in every direction), a dead load, the contact-zone split
    # (two blocks, the lift-off point as the parameter)
    "scr-turning-dead": lambda: (resolve("scr-steel").replace(current=Current(
        heights=(0.0, 500.0, 1000.0), speeds=(0.3, 0.6, 1.0),
        headings_deg=(30.0, 60.0, 100.0))), (10.0, -5.0, 20.0)),
    # joints and their blends, a hang-off out of the plane
    "yu-a3-offset": lambda: (resolve("yu2021-a3-current-45").replace(
        **{"ends.hang_off": (613.42, 500.0, 50.0)}), None),
    # the hang-off-angle form's free first length (d rhs / dp on the line block)
    "wang-form": lambda: (resolve("wang2014-current-1p5").replace(current=Current(
        heights=(0.0,), speeds=(1.0,), heading_deg=60.0)), None),
}


def _worst(m, tau, Y, p) -> tuple[float, float]:
    """(worst discrepancy of d rhs/dY, of d rhs/dp) between the analytic Jacobian and
    central differences (see test_rod_jacobian_matches_central_differences)."""
    J, Jp = m.jac(tau, Y, p)
    f0 = m.rhs(tau, Y, p)
    S = np.abs(f0) + np.einsum("ijk,jk->ik", np.abs(J), np.abs(Y))
    worst = 0.0
    for j in range(Y.shape[0]):
        h = REL_STEP * np.maximum(1.0, np.abs(Y[j]))
        Yp, Ym = Y.copy(), Y.copy()
        Yp[j] += h
        Ym[j] -= h
        fd = (m.rhs(tau, Yp, p) - m.rhs(tau, Ym, p)) / (2.0 * h)
        err = np.abs(fd - J[:, j]) / (np.abs(J[:, j]) + S / np.maximum(1.0, np.abs(Y[j]))
                                      + 1e-300)
        worst = max(worst, float(err.max()))
    worst_p = 0.0
    if Jp is not None:
        hp = REL_STEP * max(1.0, abs(p[0]))
        fd = (m.rhs(tau, Y, p + hp) - m.rhs(tau, Y, p - hp)) / (2.0 * hp)
        worst_p = float((np.abs(fd - Jp[:, 0]) / (np.abs(Jp[:, 0]) + S + 1e-300)).max())
    return worst, worst_p


def _case(case):
    sc, dead = JAC_CASES[case]()
    prob = build_rod_problem(sc, True, dead)
    tau = np.linspace(0.013, 0.987, 37)
    return prob.model, tau, _state(prob, np.random.default_rng(7), tau), prob.guess_p * 1.01


@pytest.mark.parametrize("case", sorted(JAC_CASES))
def test_rod_jacobian_matches_central_differences(case):
    # Each column j is differenced with h_j = 1e-6 max(1, |Y_j|); central differences err
    # by ~h^2 |f'''| (truncation) plus ~eps |terms| / h (round-off, 2e-10 of the terms a
    # row sums), so an entry is compared relative to |J_ij| + S_i / max(1, |Y_j|) (S_i the
    # size of row i's terms, as in tests/test_bvp_jacobian.py) and must be within 1e-6
    # (measured worst 7e-7 on random states); a wrong or missing term is an O(1e-2 .. 1)
    # discrepancy on this scale (the negative control below).
    worst, worst_p = _worst(*_case(case))
    assert worst < 1e-6 and worst_p < 1e-6, (worst, worst_p)


def test_a_wrong_term_is_seen_by_the_jacobian_check(monkeypatch):
    # negative control: drop the phi derivative of the frame's turning term of M2'
    # (-M1^2 tan(phi)/EI) from the Jacobian; the check must see it far above its 1e-6
    m, tau, Y, p = _case("scr-turning-dead")
    honest = type(m).terms_jac

    def wrong(self, u, C, linear):
        J = honest(self, u, C, linear)
        J[IM2, IPH] = 0.0
        return J

    monkeypatch.setattr(type(m), "terms_jac", wrong)
    worst, _ = _worst(m, tau, Y, p)
    assert worst > 1e-2, worst


# ------------------------------------------------------------------ the planar limit
#: planar built-in scenes the planar BVP solves (hard-flexible: 1.3 s planar, 3 s as the
#: rod; the slow set)
PLANAR = [n for n, p in builtin_paths().items()
          if n not in ("liu2021-scr", "hard-buoyancy-loss", "hard-current-neg2p5")
          and resolve(n).is_planar and getattr(resolve(n).ends, "plain", True)
          and not resolve(n).attachments]
#: the planar built-ins with end conditions (joints, a tensioner, a free end, point
#: attachments): the rod holds its ends pinned and has no point loads, so it refuses them
HELD = [n for n in builtin_paths() if not getattr(resolve(n).ends, "plain", True)
        or resolve(n).attachments]


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.slow)
                                  if n == "hard-flexible" else n for n in PLANAR])
def test_rod_gives_the_planar_solution_on_every_planar_builtin(name):
    # The rod's extra rows vanish identically at phi = M2 = F2 = 0 with no load across the
    # plane, and its first six are the planar equations term for term: the two solves
    # take the same Newton path on the same mesh (same node count), so they agree to
    # round-off (measured <= 5e-13 of the largest value, hard-flexible; 1e-16 on most).
    # 1e-9 is far below the solver tolerance (1e-3 of the scaled residual) and far above
    # round-off: an equation that differs shows at the solver tolerance's level.
    sc = resolve(name)
    with unpruned():      # the same Newton path: scipy's own factorisation for both
        a, b = bvp.solve(sc), bvp.solve(sc, three_d=True)
    assert a.converged and b.converged, (a.message, b.message)
    assert a.info["nodes"] == b.info["nodes"]
    pa, pb = a.profile, b.profile
    for key in ("x", "y", "tension", "moment"):
        ref = np.asarray(getattr(pa, key))
        got = np.interp(pa.s, pb.s, getattr(pb, key))
        scale = max(float(np.max(np.abs(ref))), 1.0)
        assert float(np.max(np.abs(got - ref))) <= 1e-9 * scale, key
    assert float(np.max(np.abs(pb.lateral))) <= 1e-9 * max(float(np.ptp(pa.x)), 1.0)
    assert b.info["formulation"].startswith("3d rod")


@pytest.mark.parametrize("name", HELD)
def test_the_rod_refuses_end_conditions_it_does_not_hold(name):
    res = bvp.solve(resolve(name), three_d=True)
    assert res.status.value == "refused", res.message


# ------------------------------------------------------------------ symmetries
def test_a_hang_off_out_of_plane_without_current_is_the_planar_line_rotated():
    # no load across the plane of the ends: the line lies in that plane, the planar
    # solution of the same horizontal distance rotated about the vertical through the
    # anchor (to round-off: the rod solves it in its plane's frame)
    base = resolve("yu2021-a3")
    dx, dz = 613.42 * np.cos(np.radians(20.0)), 613.42 * np.sin(np.radians(20.0))
    rot = bvp.solve(base.replace(**{"ends.hang_off": (dx, 500.0, dz)}))
    flat = bvp.solve(base)
    assert rot.converged and flat.converged
    pr, pf = rot.profile, flat.profile
    xi = np.hypot(pr.x, pr.z)
    assert np.allclose(np.interp(pf.s, pr.s, xi), pf.x, atol=1e-6)
    assert np.allclose(np.interp(pf.s, pr.s, pr.tension), pf.tension, rtol=1e-9)
    assert float(np.max(np.abs(pr.lateral))) < 1e-9
    assert np.allclose(np.arctan2(pr.z[1:], pr.x[1:]), np.radians(20.0), atol=1e-9)


def test_a_current_reversed_across_the_plane_mirrors_the_line():
    # heading h and -h: the same line mirrored in the plane z = 0 (tension and moment
    # magnitude equal, lateral offset and out-of-plane moment of opposite sign)
    base = resolve("scr-steel-current-45")
    a = bvp.solve(base)
    b = bvp.solve(base.replace(**{"environment.current.heading_deg": -45.0}))
    pa, pb = a.profile, b.profile
    assert np.allclose(pb.lateral, -np.interp(pb.s, pa.s, pa.lateral), atol=1e-7)
    assert np.allclose(pb.tension, np.interp(pb.s, pa.s, pa.tension), rtol=1e-8)
    assert np.allclose(pb.moment_out_of_plane, -np.interp(pb.s, pa.s, pa.moment_out_of_plane),
                       atol=1e-6 * np.max(pa.moment))


def test_a_turning_profile_of_one_heading_is_the_single_heading_current():
    # headings_deg all equal: the same velocity at every height as heading_deg (the
    # components interpolated, exact for one direction), so the same solution
    base = resolve("scr-steel-current-90")
    cur = base.current
    one = bvp.solve(base)
    many = bvp.solve(base.replace(current=Current(heights=cur.heights, speeds=cur.speeds,
                                                  headings_deg=(90.0,) * 3)))
    assert np.allclose(np.interp(one.profile.s, many.profile.s, many.profile.lateral),
                       one.profile.lateral, atol=1e-6)


# ------------------------------------------------------------------ bad input, refusals
def test_a_heading_list_of_the_wrong_length_is_one_line():
    with pytest.raises(SceneError, match="headings_deg: must have as many entries as "
                                         "heights"):
        scene(line(150.0, (0.0, 0.0), (100.0, 60.0), line_type=pipe(),
                   environment={"water_depth": 100.0, "current": {
                       "heights": [0.0, 100.0], "speeds": [0.5, 1.0],
                       "headings_deg": [0.0, 45.0, 90.0]}}))


def test_heading_and_headings_together_are_refused():
    with pytest.raises(SceneError, match="not both"):
        scene(line(150.0, (0.0, 0.0), (100.0, 60.0), line_type=pipe(),
                   environment={"water_depth": 100.0, "current": {
                       "heights": [0.0, 100.0], "speeds": [0.5, 1.0], "heading_deg": 10.0,
                       "headings_deg": [0.0, 45.0]}}))


@pytest.mark.parametrize("heading", [-361.0, 400.0])
def test_a_heading_outside_a_turn_is_refused(heading):
    with pytest.raises(SceneError, match=r"headings_deg\[1\]: must be"):
        scene(line(150.0, (0.0, 0.0), (100.0, 60.0), line_type=pipe(),
                   environment={"water_depth": 100.0, "current": {
                       "heights": [0.0, 100.0], "speeds": [0.5, 1.0],
                       "headings_deg": [0.0, heading]}}))


def test_a_hang_off_on_the_anchor_is_refused():
    with pytest.raises(SceneError, match=r"hang_off\[0\]: must be >= anchor\[0\]"):
        scene(line(150.0, (0.0, 20.0, 5.0), (0.0, 20.0, 5.0), line_type=pipe()))


def test_a_rigid_seabed_form_under_a_cross_current_at_the_seabed_is_refused():
    # Wang's touchdown form keeps the grounded line straight on a frictionless rigid
    # seabed: a current across it there has no equilibrium of that form
    sc = resolve("wang2014-current-1p5").replace(
        **{"environment.current.heading_deg": 90.0})
    res = bvp.solve(sc)
    assert res.status.value == "refused" and "frictionless seabed" in res.message


def test_three_d_false_refuses_a_3d_scene():
    res = bvp.solve(resolve("scr-steel-current-90"), three_d=False)
    assert res.status.value == "refused" and "heading_deg" in res.message


@pytest.mark.slow
def test_a_strong_cross_current_is_reached_by_continuation_and_agrees_with_the_vfife():
    # Yu's A3 lazy wave under 0.75 m/s at the seabed to 2.5 m/s at the surface across its
    # plane: the cold start fails, the continuation from the in-plane loads to the full
    # cross loads (bvp/strategy.py) reaches it, its buoyant arch pushed ~300 m sideways.
    # Against the VFIFE at the default 1 m: the configuration within the protocol's 0.02 %
    # of depth and the largest lateral excursion within its row's tolerance (the same
    # 0.02 % of depth; measured below).
    sc = resolve("yu2021-a3").replace(current=Current(heights=(0.0, 500.0),
                                                      speeds=(0.75, 2.5), heading_deg=90.0))
    comp = compare(sc, paper_model=False, columns=())
    assert "continuation in cross loads" in comp.bvp.info["strategy"]
    rows = {r["quantity"]: r for r in comp.rows}
    assert rows["max_lateral_offset"]["bvp"] > 250.0
    for q in ("configuration", "max_lateral_offset", "tension", "hang_off_tension"):
        assert rows[q]["pass"], (q, rows[q]["abs_diff"], rows[q]["tolerance"])
