"""The BVP on one arc-length domain (bvp/beam/layout.py, bvp/beam/equations.py): the joints as mesh
points with a blended right-hand side across a tiny gap, runs of identical segments as
one piece, and the cost independent of the segment count.

Claims proved here:

- the blend is continuous, symmetric about the joint, and its integral over the gap is
  the sharp joint's exactly (so the solution outside the gap differs from the sharp
  joint's by O(g^2));
- the solution changes with the gap half-width g as g^2 and far below the collocation
  tolerance: g = 1e-8 vs the default 1e-7 changes nothing by more than 1e-9 (relative),
  and 1e-6 vs 1e-7 changes it ~100 x more than 1e-8 vs 1e-7 (measured on Yu's A3: x, y
  7e-14 .. 1e-11, theta 3e-12 .. 3e-10, tension 7e-13 .. 6e-11, moment 9e-12 .. 9e-10);
- a line cut into 100 identical sub-segments is the same problem as the uncut line (same
  nodes, same numbers), with a station at every joint;
- 53 segments with discrete buoyancy modules solve in one 6-state block with sharp joints
  (the slope of the tension jumps by the weight jump, from one station to the next).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import bvp
import bvp.beam.layout
from bvp.bench import discrete_modules, split_segments
from bvp.beam.layout import Layout
from bvp.beam.problem import build_problem
from verification.catalog import resolve


# ------------------------------------------------------------------ the layout itself
def test_the_blend_is_continuous_and_integrates_to_the_sharp_joint():
    lay = Layout.proportional([3.0, 1.0, 6.0], gap=1e-3)
    C = np.array([[2.0, -5.0, 7.0]])                     # one coefficient per piece
    for j, t in enumerate(lay.edges[1:-1], start=1):
        g = lay.gap
        tau = np.linspace(t - 2 * g, t + 2 * g, 4001)
        kl, kr, lam = lay.blend(tau)
        c = ((1.0 - lam) * C[:, kl] + lam * C[:, kr])[0]
        # continuous (linear inside the gap, constant outside: steps of at most one slope)
        assert np.max(np.abs(np.diff(c))) <= abs(C[0, j] - C[0, j - 1]) / 2000.0 * 1.0001
        # pure one side outside the gap, the mean at the joint
        assert c[0] == C[0, j - 1] and c[-1] == C[0, j]
        assert c[2000] == pytest.approx(0.5 * (C[0, j - 1] + C[0, j]), rel=1e-12)
        # the integral over the gap is the sharp joint's, g (C_left + C_right)
        inside = (tau >= t - g) & (tau <= t + g)
        assert np.trapezoid(c[inside], tau[inside]) == pytest.approx(
            g * (C[0, j - 1] + C[0, j]), rel=1e-9)


def test_the_starting_mesh_holds_a_node_pair_at_every_joint():
    lay = Layout.proportional([199.95, 66.7, 100.0, 66.7, 450.0])
    tau = lay.mesh(400)
    assert tau[0] == 0.0 and tau[-1] == 1.0 and np.all(np.diff(tau) > 0.0)
    for t in lay.edges[1:-1]:
        assert np.any(tau == t - lay.gap) and np.any(tau == t + lay.gap)
        assert not np.any((tau > t - lay.gap) & (tau < t + lay.gap))   # nothing inside
    assert np.all(lay.counts(0) == bvp.beam.layout.MIN_PIECE_NODES)
    assert lay.gap == bvp.beam.layout.GAP


def test_arc_length_and_tau_are_inverse():
    lay = Layout.proportional([10.0, 30.0, 60.0])
    L = np.array([12.0, 30.0, 60.0])                     # the first piece stretched
    tau = np.linspace(0.0, 1.0, 101)
    s = lay.s_of(tau, L, s0=5.0)
    assert s[0] == 5.0 and s[-1] == pytest.approx(5.0 + L.sum(), rel=1e-15)
    assert np.allclose(lay.tau_of(s, L, s0=5.0), tau, rtol=0.0, atol=1e-14)


# ------------------------------------------------------------------ the gap: O(g^2)
def _at_common_stations(a, b, names=("x", "y", "theta", "tension", "moment")):
    """Largest difference of the profiles at the stations they share, each relative to the
    line length (x, y) or the largest value of the quantity."""
    i = np.clip(np.searchsorted(b.s, a.s), 0, b.s.size - 1)
    same = np.abs(b.s[i] - a.s) < 1e-9
    assert same.sum() > 1000
    L = a.s[-1] - a.s[0]
    return {k: float(np.max(np.abs(getattr(b, k)[i[same]] - getattr(a, k)[same]))
                     / (L if k in ("x", "y") else np.max(np.abs(getattr(a, k)))))
            for k in names}


def test_the_gap_changes_the_solution_as_its_square_far_below_the_tolerance(monkeypatch):
    # Yu's A3 (7 segments, 6 weight jumps, the contact-zone form): solved with the gap
    # half-width 1e-6, 1e-7 (the default) and 1e-8 of the domain; every solve takes the
    # same path (same nodes), so the differences are the gap's alone
    scene = resolve("yu2021-a3")
    res = {}
    for g in (1e-6, 1e-7, 1e-8):
        monkeypatch.setattr(bvp.beam.layout, "GAP", g)
        res[g] = bvp.solve(scene)
        assert res[g].converged
    assert res[1e-6].info["nodes"] == res[1e-7].info["nodes"] == res[1e-8].info["nodes"]
    fine = _at_common_stations(res[1e-7].profile, res[1e-8].profile)
    coarse = _at_common_stations(res[1e-7].profile, res[1e-6].profile)
    for k in fine:
        # g -> g/10 from the default: far below the tolerance 1e-6 (measured <= 1e-11)
        assert fine[k] < 1e-9, (k, fine)
        # O(g^2): (1e-6^2 - 1e-7^2) / (1e-7^2 - 1e-8^2) = 100 (measured 90-110); an
        # O(g) error would give 10
        assert coarse[k] > 30.0 * fine[k], (k, coarse[k], fine[k])


# ------------------------------------------------------------------ identical segments
def test_identical_segments_are_one_piece_and_keep_their_stations():
    a3 = resolve("yu2021-a3")
    cut = split_segments(a3, 100)
    assert len(cut.segments) == 100
    assert build_problem(cut, True).model.n_seg == 7          # its 7 sections
    r7, r100 = bvp.solve(a3), bvp.solve(cut)
    assert r7.info["nodes"] == r100.info["nodes"]
    d = _at_common_stations(r7.profile, r100.profile)
    assert max(d.values()) < 1e-12, d               # the same problem, to round-off
    joints = np.cumsum([s.length for s in cut.segments])[:-1]
    gaps = np.min(np.abs(r100.profile.s[None, :] - joints[:, None]), axis=1)
    assert np.max(gaps) < 1e-9                       # a station at every joint


def test_the_first_segment_stays_apart_where_its_length_is_the_unknown():
    # hang-off height and angle: the suspended length of segments[0] is the parameter, so
    # an identical segments[1] is not merged into it (the warning compares with the file)
    sc = resolve("wang2014-baseline")
    segs = list(sc.segments)
    halves = [dataclasses.replace(segs[0], length=segs[0].length / 2)] * 2
    sc = sc.replace(segments=tuple(halves + segs[1:]))
    from riser.model.scene import HangOffAngleEnds
    inv = sc.replace(ends=HangOffAngleEnds(hang_off_height=1586.3, hang_off_angle_deg=78.88))
    prob = build_problem(inv, True)
    assert prob.model.n_seg == 4 and prob.model.free_first_length
    # and with fixed ends on an elastic seabed the two halves are one piece
    assert build_problem(sc, True).model.n_seg == 3


# ------------------------------------------------------------------ discrete modules
def test_a_lazy_wave_of_53_segments_has_sharp_joints():
    # Yu's A3 with its buoyancy as 26 discrete modules (4.7 m) and 25 gaps (11.1 m): 53
    # segments, 51 joints with a weight jump of 1,834 N/m; the former stacked form needed
    # 5.2 GB and failed (issue 29), this one solves in about a second in ~0.1 GB
    sc = discrete_modules(resolve("yu2021-a3"), 26)
    assert len(sc.segments) == 53
    r = bvp.solve(sc)
    assert r.converged, r.message
    assert r.info["equilibrium_residual"] < 1e-5
    p = r.profile
    w = np.array([s.length for s in sc.segments])
    from riser.model.sections import segment_properties
    weights = np.array([q.weight for q in segment_properties(sc)])
    joints = np.cumsum(w)[:-1]
    checked = 0
    for j, sj in enumerate(joints[1:-1], start=1):
        i = int(np.argmin(np.abs(p.s - sj)))
        if abs(p.s[i] - sj) > 1e-9 or i < 2 or i > p.s.size - 3:
            continue
        # no current: T' = w sin(theta) - F kappa; one-sided slopes on either side of the
        # joint (stations h = 0.05-0.5 m away: O(h T'') = O(h w kappa) error) carry the
        # weight of their own segment (measured: within 0.3 % of the jump, 1.4 kN/m)
        left = (p.tension[i] - p.tension[i - 1]) / (p.s[i] - p.s[i - 1])
        right = (p.tension[i + 1] - p.tension[i]) / (p.s[i + 1] - p.s[i])
        jump = (weights[j + 1] - weights[j]) * np.sin(p.theta[i])
        assert right - left == pytest.approx(jump, rel=0.02, abs=0.5)
        checked += 1
    assert checked >= 40


def test_cost_does_not_grow_with_the_segment_count():
    # nodes (the cost of every Newton step is linear in them, bvp/budget.py) of the lazy
    # wave with 1, 5, 25, 50 modules (3 .. 101 segments): measured 1282, 1814, 2414, 3345:
    # the joints' node pairs and the mesh the modules' own bending needs. The former
    # stacked form multiplied every node by (6 x segments)^2.
    nodes = [bvp.solve(discrete_modules(resolve("yu2021-a3"), m)).info["nodes"]
             for m in (1, 50)]
    assert nodes[1] < 4 * nodes[0], nodes


@pytest.mark.slow
def test_the_segment_count_scaling_table():
    # bvp.bench.segment_scaling, each solve in a fresh interpreter (the table
    # `riser-verify bench` writes): measured 100 / 3 segments of the same physics 1.0-1.3 x
    # the time, 101 / 3 segments with discrete modules 2.3-2.8 x (2.6 x the nodes), peak
    # RSS <= 0.17 GB; the bounds leave room for a loaded machine (each time is a single
    # ~0.1-0.7 s solve)
    from bvp.bench import scaling_lines, segment_scaling
    rec = segment_scaling(resolve("yu2021-a3"), resolve("wang2014-baseline"))
    print("\n".join(scaling_lines(rec)))
    for fam, r in rec.items():
        assert all(row["status"] == "converged" for row in r["rows"]), fam
        assert all(row["peak_rss_mb"] < 1500.0 for row in r["rows"]), fam
        limit = 3.0 if fam.startswith("same physics") else 6.0
        assert r["wall_ratio_last_over_first"] < limit, (fam, r)
