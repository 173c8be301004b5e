"""Newton's finish of the VFIFE statics (vfife/statics/newton.py) and the BVP's pruned Newton
matrices (bvp/collocation.py), issue 36.

References: the BVP of the same scene (the comparison's tolerances), the relaxation's own
residual, scipy's unpruned solve.
"""

from __future__ import annotations

import numpy as np
import pytest

import bvp
import vfife
from bvp.collocation import unpruned
from verification.catalog import resolve
from vfife.statics import newton


@pytest.mark.parametrize("name", ["scr-steel", "yu2021-a3"])
def test_newton_finishes_every_mesh_down_to_a_quarter_metre(name):
    # the relaxation runs on the coarse 10 m mesh only (the same steps at every element
    # length): each finer mesh is Newton's, a few iterations; the 0.25 m result within
    # the comparison's tolerances of the BVP (hang-off tension 1e-4 of itself: measured
    # 2e-8 on scr-steel; the relaxation's stop had left 6e-6)
    sc = resolve(name)
    b = bvp.solve(sc).require()
    steps = set()
    for h in (1.0, 0.25):
        v = vfife.solve(sc, element_length=h).require()
        steps.add(v.info["steps"])
        stages = v.info["static_stages"]
        assert all("newton_iterations" in st for st in stages[1:]), stages
        assert max(st["newton_iterations"] for st in stages[1:]) <= 8
        assert v.info["static_newton_failed"] is None
    assert len(steps) == 1
    assert v.profile.tension[-1] == pytest.approx(b.profile.tension[-1], rel=1e-4)


def test_the_residual_newton_reads_is_the_relaxations():
    # out_of_balance reads the kernels' forces off one step from rest with unit masses;
    # the relaxation's own residual (the largest nodal out-of-balance force the kernel
    # measures in a step, its squared norm R) of the same state at rest is the same
    # number: the same kernels, the forces computed before the step moves anything (to
    # the rounding of the velocity's division, 1e-12 relative)
    sc = resolve("scr-steel").replace(**{"vfife.expert.static_newton": False})
    model = vfife.solve(sc, element_length=2.0).require().solver_state
    F, _ = newton.out_of_balance(model)
    model.V[:] = 0.0
    model.W[:] = 0.0
    _, res, _, _, _ = model.run(1, 1e-6, 0.0, tol_f=0.0, tol_m=0.0)
    assert float(np.max(np.hypot(F[0], F[1]))) == pytest.approx(res, rel=1e-9)


@pytest.mark.parametrize("name", ["scr-steel", "yu2021-a3", "mooring-clump-weight"])
def test_pruned_newton_matrices_give_the_same_solution(name):
    # pruning the explicit zeros changes SuperLU's pivot order, not the matrix: the same
    # converged solution to the rounding of the factorisation (measured 0 to 8e-9 of
    # the largest moment over the compare scenes)
    sc = resolve(name)
    a = bvp.solve(sc).require()
    with unpruned():
        b = bvp.solve(sc).require()
    assert a.info["nodes"] == b.info["nodes"]
    for key in ("x", "y", "tension", "moment"):
        ref = np.asarray(getattr(b.profile, key))
        got = np.interp(b.profile.s, a.profile.s, getattr(a.profile, key))
        assert float(np.max(np.abs(got - ref))) <= 1e-7 * max(float(np.max(np.abs(ref))),
                                                              1.0), key


@pytest.mark.parametrize("name", ["scr-steel-current-45", "yu2021-a3-current-90"])
def test_newton_finishes_a_line_in_a_cross_current(name):
    # out of plane: x, y, z and two rotations a node. Each finer mesh in a few
    # iterations; the equilibrium within the comparison's tolerances of the BVP and
    # closer to it than the relaxation's stop: hang-off tension measured 0.17 N from the
    # BVP's on both (2e-7 and 1.2e-6 of itself), the relaxation's 7.2 N and 2.6 N; the
    # bound 1e-5 of itself lies between (the relaxation fails it on both)
    sc = resolve(name)
    b = bvp.solve(sc).require()
    v = vfife.solve(sc).require()
    assert v.info["kernel"] == "3d" and v.info["static_newton_failed"] is None
    stages = v.info["static_stages"]
    assert all(st["newton_iterations"] is not None and st["newton_iterations"] <= 8
               for st in stages[1:]), stages
    assert v.profile.tension[-1] == pytest.approx(b.profile.tension[-1], rel=1e-5)
    r = vfife.solve(sc.replace(**{"vfife.expert.static_newton": False})).require()
    assert abs(r.profile.tension[-1] - b.profile.tension[-1]) > \
        10.0 * abs(v.profile.tension[-1] - b.profile.tension[-1])
    # the out-of-plane excursion, the quantity the current makes: the same to 1e-4 of it
    assert float(np.max(np.abs(v.profile.z))) == pytest.approx(
        float(np.max(np.abs(b.profile.z))), rel=1e-4)


def test_the_3d_residual_is_the_planar_one_on_a_planar_state():
    # the 3D kernels read the same forces and the moment about z on a planar state (z = 0,
    # directors in the plane): out_of_balance of both paths agree to round-off (1e-9 of the
    # largest force), the out-of-plane rows zero
    from vfife.statics.equilibrium import solve_static
    sc = resolve("scr-steel").replace(**{"vfife.expert.static_newton": False})
    planar, _ = solve_static(sc, 2.0, sc.vfife.static_tolerance, True)
    m3, _ = solve_static(sc, 2.0, sc.vfife.static_tolerance, False)
    assert planar.planar and not m3.planar
    m3.X[:], m3.D[:] = planar.X, planar.D
    F2, M2 = newton.out_of_balance(planar)
    F3, M3 = newton.out_of_balance(m3)
    scale = float(np.max(np.abs(F2)))
    assert np.max(np.abs(F3[:2] - F2)) <= 1e-9 * scale
    assert np.max(np.abs(F3[2])) <= 1e-9 * scale and np.max(np.abs(M3[:2])) <= 1e-9 * scale
    assert np.max(np.abs(M3[2] - M2)) <= 1e-9 * scale
