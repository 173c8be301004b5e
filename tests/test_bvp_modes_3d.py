"""The BVP's modes about a 3D static state: the rod linearised, in- and out-of-plane
coupled (bvp/modal/rod_family.py).

Independent sources: the planar families of bvp/modal/equations.py (derived by hand, a
different state and code) for a planar state solved as the rod, which the coupled family
must reproduce; the static rod's own solution (its states' derivatives must be the rod
equations written anew in rod_family.rod_rhs, under the static load it records); the
VFIFE's coupled modes (tests/test_modes_3d_compare.py).
"""

from __future__ import annotations

import numpy as np
import pytest
from builders import catenary, scene, small_pipe

from bvp.modal.equations import FAMILIES, build_pieces
from bvp.modal.modes import solve_modes
from bvp.modal.rod_family import (IF1, IF2, IM1, IM2, IPH, IT, ITH, IY, IZ, ROD_FAMILY,
                                  rod_pieces, rod_rhs, static_load)
from bvp.solver import solve
from riser.results.modes import COUPLED
from verification.catalog import resolve


def _cross_current(speed: float) -> dict:
    """The catenary of builders.catenary under a uniform current across its plane."""
    return scene(catenary(line_type=small_pipe(bending_stiffness=1.0e5),
                          environment={"current": {"heights": [0.0, 60.0],
                                                   "speeds": [speed, speed],
                                                   "heading_deg": 90.0}}))


def test_about_a_planar_state_the_coupled_matrices_are_the_hand_derived_families():
    # the planar catenary solved as the 3D rod: at every point the complex-step
    # linearisation of the rod (A + omega^2 B, 10 x 10) must be the two hand-derived
    # families of bvp/modal/equations.py (built from the same static profile): the in-plane
    # block equal, the out-of-plane block equal after the change of state w = dz,
    # psi = dphi, B = dM2, Q = T dphi - dF2 (r = P v: A_r = (P' + P A_o) P^-1), the blocks
    # between them zero. Both from the same profile, splined under different names (kappa
    # and F signed by slopes there, M1 / EI and F1 here), and the change of state holds
    # T' (here the spline's derivative, in the rod's row the equations' right-hand side:
    # they differ by the static solution's residual): equal to ~3e-6 of a row's largest
    # entry (measured); 1e-5. A wrong or missing term (a dead-load turning term, the
    # -EI kappa^2 psi of a tilted rod) is O(1) of its row
    sc = scene(catenary(line_type=small_pipe(bending_stiffness=1.0e5)))
    st = solve(sc, three_d=True)
    assert st.converged
    rod = rod_pieces(sc, st.profile, st.solver_state)
    flat = build_pieces(sc, st.profile, dead_drag=True)
    assert [(p.s0, p.s1, p.contact) for p in rod] == [(p.s0, p.s1, p.contact) for p in flat]
    oop = [IZ, IPH, IM2, IF2]
    for pr, pf in zip(rod, flat):
        s = np.linspace(pr.s0, pr.s1, 23)[1:-1]
        A, B = ROD_FAMILY.matrices(pr, s)
        Ai, Bi = FAMILIES["in_plane"].matrices(pf, s)
        Ao, Bo = FAMILIES["out_of_plane"].matrices(pf, s)
        T, dT = pr.spl["T"](s), pr.spl["T"](s, 1)
        for j in range(s.size):
            P = np.eye(4)
            P[3] = [0.0, T[j], 0.0, -1.0]
            dP = np.zeros((4, 4))
            dP[3, 1] = dT[j]
            Pi = np.linalg.inv(P)
            want = {"in A": (A[:6, :6, j], Ai[:, :, j]), "in B": (B[:6, :6, j], Bi[:, :, j]),
                    "out A": (A[np.ix_(oop, oop)][:, :, j], (dP + P @ Ao[:, :, j]) @ Pi),
                    "out B": (B[np.ix_(oop, oop)][:, :, j], P @ Bo[:, :, j] @ Pi)}
            for name, (got, ref) in want.items():
                scale = np.maximum(np.max(np.abs(ref), axis=1, keepdims=True), 1e-300)
                assert np.max(np.abs(got - ref) / scale) < 1e-5, (name, pr.s0, s[j], got, ref)
            assert np.max(np.abs(A[:6, oop, j])) + np.max(np.abs(A[oop, :6, j])) < 1e-9 * \
                np.max(np.abs(A[:, :, j]))


@pytest.mark.slow
def test_the_coupled_family_of_a_planar_state_is_the_two_planar_families():
    # scr-steel solved as the 3D rod (its state stays in plane): the coupled family's 8
    # lowest modes are the 8 lowest of the two planar families merged (in- and out-of-plane
    # interleave there), each purely in or out of plane. Both refined to solve_bvp's 1e-6:
    # the frequencies converge to ~1e-9 (bvp/modal/modes.py; measured 4e-9); 1e-7 leaves
    # rounding room. ~10 s
    sc = resolve("scr-steel")
    planar = solve_modes(sc, count=8)
    coupled = solve_modes(sc, count=4, static=solve(sc, three_d=True))
    assert planar.converged and coupled.converged, (planar.message, coupled.message)
    assert {m.plane for m in coupled.modes} == {COUPLED} and len(coupled.modes) == 8
    merged = np.sort([m.frequency_hz for m in planar.modes])[:8]
    got = np.array([m.frequency_hz for m in coupled.modes])
    assert np.max(np.abs(got / merged - 1.0)) < 1e-7, (got, merged)
    shares = np.array(coupled.info["out_of_plane_share"])
    assert np.all(np.minimum(shares, 1.0 - shares) < 1e-6), shares
    assert 0 < np.sum(shares > 0.5) < 8               # both families among them


def test_the_static_rod_satisfies_the_equations_linearised():
    # the rod's static state under a current across its plane (a 3D state): the splines'
    # derivative of each state against rod_rhs at the state under the recorded static load
    # (weight, seabed, the drag columns): the equations the linearisation differentiates,
    # written anew, and the load it holds dead. A cubic spline's derivative on the profile's
    # stations is accurate to ~1e-4 of a state's range here; a drag column off by its
    # normal part (the cross flow) is ~1e-1
    sc = _cross_current(0.5)
    st = solve(sc)
    assert st.converged and st.solver_state is not None
    assert np.max(np.abs(st.profile.z)) > 1.0            # the current moves it out of plane
    worst = {}
    for pc in rod_pieces(sc, st.profile, st.solver_state):
        s = np.linspace(pc.s0, pc.s1, 41)[1:-1]
        v = {k: f(s) for k, f in pc.spl.items()}
        q = static_load(pc, v)
        f = rod_rhs(v["th"], v["ph"], v["M1"], v["M2"], v["F1"], v["F2"], v["T"], q,
                    pc.EI, pc.inv_EA)
        for key, i in (("y", IY), ("th", ITH), ("ph", IPH), ("M1", IM1), ("M2", IM2),
                       ("F1", IF1), ("F2", IF2), ("T", IT)):
            span = np.ptp(st.solver_state.columns[key]) or 1.0
            err = np.max(np.abs(pc.spl[key](s, 1) - f[i])) * (pc.s1 - pc.s0) / span
            worst[key] = max(worst.get(key, 0.0), float(err))
    assert max(worst.values()) < 1e-2, worst


@pytest.mark.slow
def test_a_small_cross_current_moves_the_modes_by_its_square():
    # the catenary (EI 1e5 N m2) under 0.01 m/s across its plane: the drag (5e-3 N/m against
    # a weight of 100 N/m) perturbs the static state at first order out of plane, the
    # frequencies at second order (the state's symmetry z -> -z): they stay within 1e-4 of
    # the still-water ones, while the state is 3D and the family coupled. At 0.5 m/s they
    # move by tens of per cent (the drag turns the line and raises its tension): the
    # control that the comparison can see a change. ~5 s
    still = solve_modes(scene(catenary(line_type=small_pipe(bending_stiffness=1.0e5))),
                        count=6)
    f0 = np.sort([m.frequency_hz for m in still.modes])[:4]
    got = {}
    for speed in (0.01, 0.5):
        res = solve_modes(_cross_current(speed), count=2)
        assert res.converged and {m.plane for m in res.modes} == {COUPLED}, res.message
        got[speed] = np.array([m.frequency_hz for m in res.modes])
    assert np.max(np.abs(got[0.01] / f0 - 1.0)) < 1e-4, (got[0.01], f0)
    assert np.max(np.abs(got[0.5] / f0 - 1.0)) > 0.05, (got[0.5], f0)
