"""The VFIFE's cost against the mesh (``riser-verify bench``, bench.json
``vfife_scaling``; issue 36): the static solve's wall time at element lengths 2, 1, 0.5
and 0.25 m on given scenes with its fitted exponent in the element count, and the planar
kernel's time per element-step against a copy-only loop over the same arrays measured in
the same run (how near the kernel is to the machine's data-movement limit).
"""

from __future__ import annotations

import math
import time

import numpy as np
from numba import njit

from .model import Model
from .solver import solve
from .timestep import choose_step, critical_steps

#: the element lengths [m] of the statics' scaling
LENGTHS = (2.0, 1.0, 0.5, 0.25)


def fitted_exponent(counts, walls) -> float:
    """The slope of log(wall) against log(count) (least squares)."""
    return float(np.polyfit(np.log(np.asarray(counts, float)),
                            np.log(np.asarray(walls, float)), 1)[0])


def statics_scaling(scene, lengths=LENGTHS) -> dict:
    """Rows (element length, elements, wall [s], Newton's share [s], converged, hang-off
    tension [N]) of the static solve at ``lengths``, and the fitted exponent of the wall
    in the element count (the compile excluded: the solver's own wall)."""
    rows = []
    for h in lengths:
        res = solve(scene, element_length=h)
        stages = res.info.get("static_stages", [])
        newton = sum(s["wall_s"] for s in stages if "newton_iterations" in s)
        rows.append({"element_length": h, "elements": int(res.info["elements"]),
                     "wall_s": float(res.wall_time_s), "newton_s": float(newton),
                     "relaxation_steps": int(res.info["steps"]),
                     "converged": bool(res.converged),
                     "hang_off_tension": (float(res.profile.tension[-1])
                                          if res.profile is not None else None)})
    ne = [r["elements"] for r in rows]
    return {"scene": scene.name, "rows": rows,
            "exponent": fitted_exponent(ne, [r["wall_s"] for r in rows]),
            "newton_exponent": (fitted_exponent(ne, [r["newton_s"] for r in rows])
                                if all(r["newton_s"] > 0.0 for r in rows) else None)}


@njit(cache=True)
def _copy_pass(nsteps, src, dst):
    """A step's data movement without its arithmetic: every row of ``src`` (the arrays
    the planar step reads) read and written to ``dst`` (k, n), nsteps times."""
    k, n = src.shape
    for _ in range(nsteps):
        for j in range(k):
            for i in range(n):
                dst[j, i] = src[j, i]
    return dst[0, 0]


def kernel_over_copy(scene, static: Model, nsteps: int = 2000) -> dict:
    """The planar kernel's time per element-step on ``static``'s mesh and a copy-only loop
    over as many arrays of the node count (the planar node and element passes touch
    ~24 per-node rows), best of 3 each, side by side."""
    m = Model(scene, static.mesh, rot_scale=1.0, added_mass=True, planar=True)
    m.X[:] = static.X
    m.D[:] = static.D
    dt, _ = choose_step(critical_steps(static.mesh, rot_scale=1.0, tension=1e6,
                                       added_mass=True), 0.8)
    m.run(10, dt, 0.0)
    n = static.mesh.n
    src = np.random.default_rng(0).random((24, n))
    dst = np.empty_like(src)
    _copy_pass(2, src, dst)
    best_k = best_c = math.inf
    for _ in range(3):
        t0 = time.perf_counter()
        m.run(nsteps, dt, 0.0)
        best_k = min(best_k, time.perf_counter() - t0)
        t0 = time.perf_counter()
        _copy_pass(nsteps, src, dst)
        best_c = min(best_c, time.perf_counter() - t0)
    per = nsteps * static.mesh.ne
    return {"kernel_ns": best_k / per * 1e9, "copy_ns": best_c / per * 1e9,
            "kernel_over_copy": best_k / best_c, "rows_copied": int(src.shape[0])}


def scaling_lines(record: dict) -> list[str]:
    """Console lines of the bench's ``vfife_scaling``."""
    lines = ["VFIFE statics against the mesh (wall s; Newton's share; relaxation steps on "
             "the coarse meshes):"]
    for sc in record["statics"]:
        cells = ", ".join(f"{r['element_length']:g} m {r['wall_s']:.2f} s "
                          f"({r['newton_s']:.2f})" for r in sc["rows"])
        lines.append(f"  {sc['scene']}: {cells}; exponent in elements "
                     f"{sc['exponent']:.2f}" + (f" (Newton {sc['newton_exponent']:.2f})"
                                                if sc["newton_exponent"] is not None
                                                else ""))
    k = record["kernel"]
    lines.append(f"  planar kernel {k['kernel_ns']:.2f} ns / element-step against a copy of "
                 f"{k['rows_copied']} rows {k['copy_ns']:.2f} ns: x{k['kernel_over_copy']:.2f}")
    return lines
