"""The BVP's analytic Jacobian (``BeamModel.jac``) against central differences of its
right-hand side (``BeamModel.rhs``): d rhs/dY and d rhs/dp, for every kind of term.

solve_bvp takes ``jac`` on trust: a wrong entry does not give a wrong solution (the
residual is the rhs's), but slow or failed Newton iterations, i.e. spurious "did not
converge" results. So each term is checked here, in the model the solver builds
(``bvp.beam.problem.build_problem``) for built-in scenes:

- (a) the inextensible Wang form without current (and the extensible one);
- (b) Morison drag, planar: a uniform current, a sheared one (dV/dy) and one that
  reverses with height (V = 0 along the line);
- (c) the extensible line on the unilateral Winkler seabed, with nodes in contact
  (y < 0) and nodes above it;
- (d) the free-length parameter p (the d rhs/dp block): the hang-off-angle form, the
  rigid seabed with the anchor on it, the contact-zone split;
- (e) the contact-zone split form (linear spring in block 0, the lift-off point s_L = p
  entering the zone block and the line block's first piece with opposite signs);
- (f) the joints' blends (bvp/beam/layout.py): nodes inside every gap and at its two ends,
  where the coefficients of two pieces mix, and d rhs/dp where piece 0 mixes with
  piece 1.

The state: the solver's own starting guess on 24 nodes of each piece of the line plus five
in every joint's gap (t_j - g, - g/2, 0, + 0.3 g, + g), perturbed (fixed seed) by 1 % of
each state component's RMS, so that no entry is trivially zero (the guess has
theta = M = F = 0 on the seabed), the heights by 1 % of
themselves (the line lying on the seabed, y = -w/k ~ -4 mm, stays in contact) and the free
length(s) by 1 %. The rhs is smooth except at a few kinks where the analytic Jacobian is one
branch's (bvp/beam/equations.py): the unilateral reaction k max(-y, 0) at y = 0, the
piecewise-linear current V(y) at its given heights, and the drag s|s| (C1 but not C2) at
zero relative velocity (V = 0, or theta a multiple of pi/2). A difference stencil across
a kink measures an average of two branches (an O(1) mismatch at y = 0, see
``test_a_stencil_across_the_seabed_kink_is_not_the_jacobian``; O(h) for s|s|), so the state
is moved two difference steps away from every kink (``_away_from_kinks``); nowhere else.

Tolerance. Each column j is differenced with the step h_j = 1e-6 max(1, |Y_j|) (the state
is scaled to O(1), bvp/beam/problem.py). Central differences err by h^2/6 |f'''| (truncation,
~2e-13 relative for terms that vary on O(1) scales of the scaled state: trigonometric,
polynomial, piecewise-linear V) plus ~eps |terms of f_i| / h (round-off, eps/h = 2.2e-10
relative to the size of the terms summed in f_i, which can cancel). So the discrepancy of
entry (i, j) is measured relative to |J_ij| + S_i / max(1, |Y_j|), with S_i the size of the
terms of f_i (|f_i| + sum_j |J_ij Y_j|, a term linear in Y_j being J_ij Y_j), and must be
at most TOL = 1e-7: 380x the measured worst case (2.6e-10), while a wrong or missing term
is an O(1e-4 .. 1) discrepancy (the negative controls below measure each term's size on
this scale).
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import pytest

from bvp.beam.equations import IF, ITH, IY, NSTATE
from bvp.beam.problem import build_problem
from riser.model.scene import FixedEnds, HangOffAngleEnds, Seabed
from verification.catalog import resolve

REL_STEP = 1.0e-6      # relative difference step per component (see the module docstring)
TOL = 1.0e-7           # largest discrepancy allowed (module docstring)
KINK_STEPS = 2.0       # distance kept from a kink, in difference steps (stencil: +-1)
NODES = 24


# ------------------------------------------------------------------ the scenes
def _wang_hang_off_angle(name):
    # the inverse form (b) of test_bvp: hang-off height and angle given, the suspended
    # length of the first segment the unknown p
    return resolve(name).replace(ends=HangOffAngleEnds(hang_off_height=1586.3,
                                                       hang_off_angle_deg=78.88))


def _wang_rigid_seabed():
    # fixed ends with the anchor 300 m ahead on a rigid seabed: the touchdown (suspended
    # length of the first segment) is the unknown p (as in test_bvp)
    sc = resolve("wang2014-baseline")
    segs = list(sc.segments)
    segs[0] = dataclasses.replace(segs[0], length=690.0)
    return sc.replace(segments=tuple(segs), seabed=Seabed(1e5),
                      ends=FixedEnds(anchor=(-300.0, 0.0), hang_off=(1625.0, 1586.3)),
                      model={"axial": "inextensible", "seabed": "rigid"})


# id -> (scene builder, split, features the built model must have). The features are
# asserted, so that a change of the problem set-up cannot quietly drop a term from the check.
CASES = {
    "wang-inextensible": (lambda: resolve("wang2014-baseline"), True, {"joints"}),
    "wang-extensible": (lambda: resolve("wang2014-baseline").replace(
        model={"axial": "extensible"}), True, {"extensible", "joints"}),
    "wang-current-1p5": (lambda: resolve("wang2014-current-1p5"), True, {"drag", "joints"}),
    "wang-hang-off-angle": (lambda: _wang_hang_off_angle("wang2014-baseline"), True,
                            {"free_length", "joints"}),
    "wang-current-hang-off-angle": (lambda: _wang_hang_off_angle("wang2014-current-1p5"),
                                    True, {"drag", "free_length", "joints"}),
    "wang-rigid-seabed-anchor": (_wang_rigid_seabed, True, {"free_length", "joints"}),
    "yu2021-a2-sheared-unilateral": (lambda: resolve("yu2021-a2-sheared"), False,
                                     {"extensible", "drag", "shear", "seabed", "joints"}),
    "yu2021-a2-sheared-contact-zone": (lambda: resolve("yu2021-a2-sheared"), True,
                                       {"extensible", "drag", "shear", "seabed",
                                        "free_length", "split", "joints"}),
    "yu2021-a3-unilateral": (lambda: resolve("yu2021-a3"), False,
                             {"extensible", "seabed", "joints"}),
    "yu2021-a3-contact-zone": (lambda: resolve("yu2021-a3"), True,
                               {"extensible", "seabed", "free_length", "split", "joints"}),
    "scr-steel-unilateral": (lambda: resolve("scr-steel"), False, {"extensible", "seabed"}),
    "scr-steel-contact-zone": (lambda: resolve("scr-steel"), True,
                               {"extensible", "seabed", "free_length", "split"}),
    "current-reversing-unilateral": (lambda: resolve("hard-current-reversing"), False,
                                     {"extensible", "drag", "shear", "seabed", "joints"}),
}


def _features(model) -> set[str]:
    out = set()
    if model.extensible:
        out.add("extensible")
    if model.speed is not None and model.drag_factor != 0.0:
        out.add("drag")
        if np.any(model.speed_gradient(np.linspace(-10.0, 3000.0, 301)) != 0.0):
            out.add("shear")
    if model.k_seabed > 0.0:
        out.add("seabed")
    if model.free_first_length:
        out.add("free_length")
    if model.split_first:
        out.add("split")
    if model.layout.n > 1:
        out.add("joints")
    return out


def _kink_heights(scene, model) -> tuple[np.ndarray, np.ndarray]:
    """Heights y [m] where the rhs has a kink: (the seabed's, y = 0, in the unilateral
    block; the current's: the given heights of a piecewise-linear current, where dV/dy
    jumps, and those where V changes sign, in every block)."""
    ys = []
    cur = scene.current
    if cur is not None and len(cur.heights) > 1:
        h, v = np.asarray(cur.heights, float), np.asarray(cur.speeds, float)
        ys += list(h)
        for a, b, va, vb in zip(h, h[1:], v, v[1:]):
            if va * vb < 0.0:
                ys.append(a - va * (b - a) / (vb - va))
    return np.asarray([0.0] if model.k_seabed > 0.0 else []), np.asarray(ys)


def _away_from_kinks(Y, model, kinks):
    """Move y and theta at least KINK_STEPS difference steps away from every kink (in the
    unilateral block: the contact zone of the split form is linear in y)."""
    n, m = model.n_block, Y.shape[1]
    u = Y.reshape(n, NSTATE, m)          # a view: edits Y

    def push(row, kinks):
        for kink in kinks:
            margin = KINK_STEPS * REL_STEP * np.maximum(1.0, np.abs(row))
            d = row - kink
            close = np.abs(d) < margin
            row[close] = kink + np.where(d[close] >= 0.0, 1.0, -1.0) * margin[close]

    for k in range(n):
        zone = model.split_first and k == 0
        ks = kinks[1] if zone else np.concatenate(kinks)
        push(u[k, IY], ks / model.scale[IY])
        if model.speed is not None:      # V_n = -V sin(theta), V_t = V cos(theta)
            push(u[k, ITH], np.arange(-4, 5) * (np.pi / 2))
    return Y


def _gap_nodes(model) -> np.ndarray:
    """Five nodes in each joint's blend gap: its two ends, inside it and its middle."""
    lay = model.layout
    g = lay.gap
    return np.concatenate([t + g * np.array([-1.0, -0.5, 0.0, 0.3, 1.0])
                           for t in lay.edges[1:-1]]) if lay.n > 1 else np.zeros(0)


@functools.lru_cache(maxsize=None)
def _case(case_id):
    """(scene, problem, tau, Y, p): the perturbed starting guess of the case."""
    build, split, _ = CASES[case_id]
    scene = build()
    prob = build_problem(scene, split)
    model = prob.model
    rng = np.random.default_rng(20240611)
    e = model.layout.edges
    tau = np.union1d(np.concatenate([np.linspace(a, b, NODES) for a, b in zip(e, e[1:])]),
                     _gap_nodes(model))
    m = tau.size
    u = prob.guess(tau).reshape(model.n_block, NSTATE, m)
    rms = np.sqrt(np.mean(u ** 2, axis=(0, 2)))
    noise = rng.standard_normal(u.shape)
    v = u + 1e-2 * rms[None, :, None] * noise
    # heights relative to themselves: the line lying on the seabed (y = -w/k, mm) stays in
    # contact, the suspended part above it
    v[:, IY] = u[:, IY] * (1.0 + 1e-2 * noise[:, IY])
    Y = v.reshape(-1, m)
    Y = _away_from_kinks(Y, model, _kink_heights(scene, model))
    p = prob.guess_p * (1.0 + 1e-2 * rng.standard_normal(prob.guess_p.shape))
    return scene, prob, tau, Y, p


# ------------------------------------------------------------------ the comparison
def central_differences(model, tau, Y, p):
    """(d rhs/dY (6n, 6n, m), d rhs/dp (6n, k, m)) by central differences. The rhs at a
    node depends on that node's state only, so column j is differenced at all nodes at
    once."""
    n6, m = Y.shape
    dY = np.empty((n6, n6, m))
    for j in range(n6):
        h = REL_STEP * np.maximum(1.0, np.abs(Y[j]))
        Yp, Ym = Y.copy(), Y.copy()
        Yp[j] += h
        Ym[j] -= h
        dY[:, j] = (model.rhs(tau, Yp, p) - model.rhs(tau, Ym, p)) / (Yp[j] - Ym[j])
    dp = np.empty((n6, p.size, m))
    for k in range(p.size):
        h = REL_STEP * max(1.0, abs(p[k]))
        pp, pm = p.copy(), p.copy()
        pp[k] += h
        pm[k] -= h
        dp[:, k] = (model.rhs(tau, Y, pp) - model.rhs(tau, Y, pm)) / (pp[k] - pm[k])
    return dY, dp


def discrepancy(J, J_fd, P, P_fd, f, Y, p):
    """Largest |J - J_fd| of the dY and dp blocks, each entry relative to |J_fd_ij| +
    S_i / max(1, |x_j|) (module docstring); only differenced values enter the scale, so
    a wrong analytic entry cannot enlarge its own tolerance. Returns (dY, dp) maxima (dp:
    0.0 without parameters)."""
    S = np.abs(f) + np.sum(np.abs(J_fd * Y[None, :, :]), axis=1)
    if p.size:
        S = S + np.sum(np.abs(P_fd * p[None, :, None]), axis=1)
    yscale = np.abs(J_fd) + S[:, None, :] / np.maximum(1.0, np.abs(Y))[None, :, :]
    d_y = float(np.max(np.abs(J - J_fd) / yscale))
    if not p.size:
        return d_y, 0.0
    pscale = np.abs(P_fd) + S[:, None, :] / np.maximum(1.0, np.abs(p))[None, :, None]
    return d_y, float(np.max(np.abs(P - P_fd) / pscale))


def _check(model, tau, Y, p, jac_model=None):
    """discrepancy() of ``jac_model``'s analytic Jacobian (default: the model's own)
    against the differences of ``model``'s rhs."""
    J, P = (jac_model or model).jac(tau, Y, p)
    J_fd, P_fd = central_differences(model, tau, Y, p)
    return discrepancy(J, J_fd, P, P_fd, model.rhs(tau, Y, p), Y, p)


# ------------------------------------------------------------------ the checks
@pytest.mark.parametrize("case_id", list(CASES))
def test_analytic_jacobian_matches_central_differences(case_id):
    # measured (seed above): dY 8e-11 .. 1.4e-10, dp 4e-11 .. 2.6e-10 (TOL 1e-7)
    _, prob, tau, Y, p = _case(case_id)
    model = prob.model
    assert _features(model) == CASES[case_id][2]
    m = tau.size
    if model.k_seabed > 0.0:
        # both branches of the unilateral law are exercised (nodes in contact and above the
        # seabed), or in the split form the linear spring in the contact zone, below y = 0
        y = Y.reshape(model.n_block, NSTATE, -1)[:, IY] * model.scale[IY]
        zone, rest = y[:1] if model.split_first else y[:0], y[-1:]
        assert np.sum(rest > 0.0) >= 3
        if model.split_first:
            assert np.sum(zone < 0.0) >= m - 1              # y(s_L) = 0 is the guess's
        else:
            assert np.sum(rest < 0.0) >= 3, np.sum(rest < 0.0)
    d_y, d_p = _check(model, tau, Y, p)
    assert d_y <= TOL, d_y
    assert d_p <= TOL, d_p
    _, P = model.jac(tau, Y, p)
    assert (P is not None) == model.free_first_length
    lay = model.layout
    if lay.n > 1:
        # the gap nodes see blended coefficients: at a joint's middle they are the mean of
        # the two pieces' (a check at the gaps that ran on pure coefficients would not
        # test the blend)
        C = model.coefficients(tau, p)[-1][0]
        for j, t in enumerate(lay.edges[1:-1]):
            i = int(np.argmin(np.abs(tau - t)))
            left, right = (model.coefficients(np.array([t - 2 * lay.gap, t + 2 * lay.gap]),
                                              p)[-1][0]).T
            assert np.allclose(C[:, i], 0.5 * (left + right), rtol=1e-9, atol=0.0)
    if model.free_first_length:
        # d rhs/dp: nonzero on piece 0 and in the gap of joint 1, zero beyond it
        line = P[(model.n_block - 1) * NSTATE:, 0]
        t1 = lay.edges[1]
        assert np.all(line[:, tau >= t1 + lay.gap] == 0.0)
        assert np.any(line[:, tau < t1] != 0.0)
        if lay.n > 1:
            assert np.any(line[:, (tau > t1 - lay.gap) & (tau < t1 + lay.gap)] != 0.0)
    if model.split_first:
        # the lift-off point moves the end of the contact zone and the start of the rest
        # of the first segment: both blocks are nonzero
        assert np.any(P[:NSTATE] != 0.0) and np.any(P[NSTATE:2 * NSTATE] != 0.0)


# Negative controls: the same comparison must fail when a term is left out of the analytic
# Jacobian (the Jacobian of a model without that term, against the differences of the model
# with it). Required margin: 100 TOL, i.e. every term is at least 1e-5 on the scale of the
# check and a missing or wrong one cannot hide below the tolerance.
def _without(model, feature):
    if feature == "drag":
        return dataclasses.replace(model, speed=None, speed_gradient=None)
    if feature == "shear":
        return dataclasses.replace(model, speed_gradient=lambda y: np.zeros_like(y))
    if feature == "seabed":
        return dataclasses.replace(model, k_seabed=0.0)
    if feature == "extensible":
        return dataclasses.replace(model, EA=np.full(model.n_seg, np.inf),
                                   layout=model.layout)
    raise AssertionError(feature)


CONTROLS = [(c, f) for c, (_, _, feats) in CASES.items() for f in sorted(feats)
            if f in ("drag", "shear", "seabed", "extensible")]


@pytest.mark.parametrize("case_id,feature", CONTROLS, ids=[f"{c}-no-{f}" for c, f in CONTROLS])
def test_a_missing_term_is_detected(case_id, feature):
    _, prob, tau, Y, p = _case(case_id)
    d_y, _ = _check(prob.model, tau, Y, p, jac_model=_without(prob.model, feature))
    assert d_y > 100.0 * TOL, d_y


@pytest.mark.parametrize("case_id", [c for c, (_, _, f) in CASES.items() if "free_length" in f])
def test_a_wrong_length_derivative_is_detected(case_id):
    # d rhs/dp off by 1e-5 of itself (or, in the split form, the rest of the first segment
    # not shortened as the contact zone grows) fails the dp check
    _, prob, tau, Y, p = _case(case_id)
    model = prob.model
    J, P = model.jac(tau, Y, p)
    J_fd, P_fd = central_differences(model, tau, Y, p)
    f = model.rhs(tau, Y, p)
    assert discrepancy(J, J_fd, P * (1.0 + 1e-5), P_fd, f, Y, p)[1] > 10.0 * TOL
    if model.split_first:
        Q = P.copy()
        Q[NSTATE:2 * NSTATE] = 0.0
        assert discrepancy(J, J_fd, Q, P_fd, f, Y, p)[1] > 1e3 * TOL


def test_one_wrong_entry_is_detected():
    # a single entry off by 1e-5 of its scale, or an entry that should be zero (dx'/dx)
    # made nonzero, at one node: the comparison reports it
    _, prob, tau, Y, p = _case("wang-current-1p5")
    model = prob.model
    J, P = model.jac(tau, Y, p)
    J_fd, P_fd = central_differences(model, tau, Y, p)
    f = model.rhs(tau, Y, p)
    assert discrepancy(J, J_fd, P, P_fd, f, Y, p)[0] <= TOL
    node = int(np.searchsorted(tau, 0.5 * (model.layout.edges[2] + 1.0)))   # segment 2
    bad = J.copy()
    bad[IF, ITH, node] *= 1.0 + 1e-5                                        # dF'/dtheta
    assert 10.0 * TOL < discrepancy(bad, J_fd, P, P_fd, f, Y, p)[0] <= 1e-5
    bad = J.copy()
    bad[0, 0, node] = 1e-5 * np.max(np.abs(J[0, :, node]))
    assert discrepancy(bad, J_fd, P, P_fd, f, Y, p)[0] > 10.0 * TOL


@pytest.mark.parametrize("case_id", ["wang-hang-off-angle", "yu2021-a3-contact-zone"])
def test_a_jacobian_without_the_blend_is_detected(case_id):
    # the Jacobian of the same pieces with a 1000x narrower gap (so the gap nodes see one
    # piece's pure coefficients) against the differences of the blended model: the gap
    # nodes report it; and d rhs/dp left out inside the gap of joint 1 (measured 1.2 and
    # 5.1, 0.87 and 0.89: O(1), against TOL 1e-7)
    from bvp.beam.layout import Layout
    _, prob, tau, Y, p = _case(case_id)
    model = prob.model
    lay = model.layout
    sharp = dataclasses.replace(model, layout=Layout(lay.edges, lay.gap * 1e-3))
    assert _check(model, tau, Y, p, jac_model=sharp)[0] > 100.0 * TOL
    J, P = model.jac(tau, Y, p)
    J_fd, P_fd = central_differences(model, tau, Y, p)
    f = model.rhs(tau, Y, p)
    t1 = lay.edges[1]
    Q = P.copy()
    Q[:, :, (tau > t1 - lay.gap) & (tau < t1 + lay.gap)] = 0.0
    assert discrepancy(J, J_fd, Q, P_fd, f, Y, p)[1] > 100.0 * TOL


def test_a_stencil_across_the_seabed_kink_is_not_the_jacobian():
    # why the states keep away from kinks: with the node where the rest of the first
    # segment leaves the seabed (y = 0 exactly, unilateral) left at the kink, the
    # difference measures the mean of the slopes -k and 0 of k max(-y, 0), the analytic
    # Jacobian one branch: an O(1) discrepancy, which is the law's, not an error
    _, prob, tau, Y, p = _case("scr-steel-contact-zone")
    model = prob.model
    Y = Y.copy()
    Y[NSTATE + IY, 0] = 0.0
    assert _check(model, tau, Y, p)[0] > 0.1
