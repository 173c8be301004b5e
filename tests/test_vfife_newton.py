"""Newton's finish of the VFIFE statics (vfife/newton.py) and the BVP's pruned Newton
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
from vfife import newton


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
