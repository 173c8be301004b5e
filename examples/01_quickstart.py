"""Quickstart: solve one riser with both methods, compare them, plot tension and moment.

    python examples/01_quickstart.py [OUT.png] [SCENE]

OUT.png: the plot (default: riser-verify-quickstart.png in the system's temporary
folder). SCENE: a built-in scene name (``riser-verify scenes`` lists them) or a scene
``.toml`` path; default ``scr-steel``, a steel catenary riser in 1000 m of water with both
ends fixed in space, so that both methods solve exactly the same scene. (A scene in a Wang
form, e.g. ``wang2014-baseline``, is solved by ``solve_scene(scene, "bvp")`` in its own
paper model, inextensible on a rigid seabed, while ``"vfife"`` solves its fixed-ends
conversion: the two curves then also differ by the model. ``compare`` always solves the
matched model; see verification/pipeline.py.)

Prints, per method, the hang-off tension [N], the touchdown (lift-off) tension [N] and the
largest bending moment [N m], then the agreement rows of the comparison protocol and its
verdict. Runs in a few seconds (the first run also compiles the VFIFE kernels, cached).
"""

import sys
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")                       # write files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

from verification.catalog import resolve  # noqa: E402
from verification.comparison.static.protocol import compare  # noqa: E402
from verification.pipeline import solve_scene  # noqa: E402

out = Path(sys.argv[1] if len(sys.argv) > 1
           else Path(tempfile.gettempdir()) / "riser-verify-quickstart.png")
scene = resolve(sys.argv[2] if len(sys.argv) > 2 else "scr-steel")   # a frozen Scene

fig, (ax_t, ax_m) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
for method, style in (("bvp", "-"), ("vfife", "--")):
    res = solve_scene(scene, method)         # a SolveResult: how it ended is res.status
    if not res.converged:
        sys.exit(f"{method}: {res.status.value}: {res.message}")
    p, sm = res.profile, res.summary()       # Profile arrays along s; summary(): features
    print(f"{method}: {res.message} ({res.wall_time_s:.2f} s)")
    for key, unit in (("hang_off_tension", "N"), ("tdp_tension", "N"), ("max_moment", "N m")):
        print(f"  {key} = {sm[key]} {unit}")
    ax_t.plot(p.s, p.tension / 1e3, style, label=method)  # effective tension [N] -> kN
    ax_m.plot(p.s, p.moment / 1e3, style, label=method)   # moment magnitude [N m] -> kN m

comp = compare(scene, paper_model=False)     # the protocol: both methods, same model
print(comp.frame().to_string(index=False))   # quantity, bvp, vfife, abs_diff, ..., pass
print("agreement:", "pass" if comp.passed else "FAIL")

ax_t.set_ylabel("effective tension [kN]")
ax_m.set_ylabel("bending moment [kN m]")
ax_m.set_xlabel("arc length s from the bottom end [m]")
ax_t.set_title(scene.title or scene.name)
ax_t.legend()
out.parent.mkdir(parents=True, exist_ok=True)
fig.savefig(out, dpi=120, bbox_inches="tight")
print(f"plot: {out}")
