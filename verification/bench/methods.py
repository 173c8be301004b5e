"""The methods' bench (``riser-verify bench``, ``reports/bench/bench.json``): the VFIFE
kernel per element-step for each effect and the solver on the Wang riser fixed at its
hang-off (:mod:`vfife.bench`), the ANCF's statics and dynamic run beside it on the same
riser and motion (:mod:`verification.bench.ancf`), the BVP on the Wang baseline, its
Table 2 batch and its cost against the segment count (:mod:`bvp.bench`), and the analytic
method against the BVP on the single-section scenes, each pair timed in the same run
(speed claims are ratios), and the VFIFE statics' cost against the mesh with its kernel
against a copy-only loop (:mod:`vfife.scaling`)."""

from __future__ import annotations

import json
from pathlib import Path

from riser.model.scene import Scene
from riser.model.transform import fixed_ends_scene
from verification.catalog import resolve

#: the Wang et al. (2014) scenes: the baseline and its currents (the BVP's Table 2 batch)
WANG_BASELINE = "wang2014-baseline"
WANG_CURRENTS = ("wang2014-current-neg1p5", "wang2014-current-neg0p75",
                 "wang2014-current-0p75", "wang2014-current-1p5")
#: the lazy wave of the BVP's segment-count table (cut finer, and as discrete modules)
LAZY_WAVE = "yu2021-a3"
#: the single-section scenes the bench times with the analytic method and the BVP
ANALYTIC_BENCH_SCENES = ("scr-steel", "kang2015-jlay")
#: the BVP's 3D rod against its planar solve (same solution) and on 3D scenes (issue 32)
ROD_PLANAR = ("scr-steel", "yu2021-a3", "wang2014-current-1p5")
ROD_3D = ("scr-steel-current-90", "yu2021-a3-current-90", "yu2021-a3-current-turning")
#: the design checks' cost (issue 34): a dynamic run of this scene with its [design] and
#: [design.fatigue] against the same run without, at DESIGN_ELEMENT_LENGTH [m] for
#: DESIGN_DURATION [s] (statistics from a third of it)
DESIGN_SCENE = "scr-steel-fatigue"
DESIGN_ELEMENT_LENGTH = 2.0
DESIGN_DURATION = 60.0
#: the scenes of the VFIFE statics' scaling with the mesh (issue 36)
SCALING_SCENES = ("scr-steel", "yu2021-a3")


def bench_scene() -> Scene:
    """The benchmark's scene: the Wang baseline fixed at the paper's hang-off point
    (1625.0, 1586.3) m with 300 m of line on the default seabed (also the scene of a peer's
    bench, ``bench --peer``)."""
    return fixed_ends_scene(resolve(WANG_BASELINE), (1625.0, 1586.3), 300.0)


def run(out: Path) -> dict:
    """Time the four methods; writes ``out/bench.json`` (and the VFIFE's files beside it)
    and returns its record."""
    from analytic.bench import median_times as analytic_times
    from bvp.bench import median_times as bvp_times
    from bvp.bench import run_bench as bvp_bench
    from vfife.bench import run_bench
    bench = run_bench(out, bench_scene())
    # the ANCF beside the VFIFE on the same riser and heave, in the same run (issue 46)
    from .ancf import run as ancf_bench
    bench["ancf"] = ancf_bench(bench_scene(), bench)
    bench["bvp"] = bvp_bench(resolve(WANG_BASELINE), [resolve(n) for n in WANG_CURRENTS])
    # the BVP's cost against the segment count (issue 29): same physics cut finer, and a
    # lazy wave's buoyancy as discrete modules; each solve in a fresh process
    from bvp.bench import segment_scaling
    bench["bvp_segments"] = segment_scaling(resolve(LAZY_WAVE), resolve(WANG_BASELINE))
    # the BVP's 3D rod against its planar solve on planar scenes, and on 3D ones (issue 32)
    from bvp.bench import rod_ratios
    bench["bvp_rod"] = rod_ratios([resolve(n) for n in ROD_PLANAR],
                                  [resolve(n) for n in ROD_3D])
    # the analytic method against the BVP on the same single-section scenes, side by side
    single = [resolve(n) for n in ANALYTIC_BENCH_SCENES]
    a_t, b_t = analytic_times(single), bvp_times(single)
    # the BVP against its solver before issue 36 on the compare study's scenes
    from bvp.bench import against_reference
    from verification.catalog import COMPARE_SCENES
    bench["bvp_reference"] = against_reference([resolve(n) for n in COMPARE_SCENES])
    bench["analytic"] = {n: {"analytic_s": a_t[n], "bvp_s": b_t[n], "bvp_over_analytic":
                             b_t[n] / a_t[n]} for n in a_t}
    bench["design"] = design_cost()
    # the VFIFE statics against the mesh and its kernel against a copy-only loop (issue 36)
    from verification.methods import method
    from vfife.scaling import kernel_over_copy, statics_scaling
    bench["vfife_scaling"] = {
        "statics": [statics_scaling(resolve(n)) for n in SCALING_SCENES],
        "kernel": kernel_over_copy(
            resolve(SCALING_SCENES[0]),
            method("vfife").solve(resolve(SCALING_SCENES[0])).solver_state)}
    (out / "bench.json").write_text(json.dumps(bench, indent=2) + "\n")
    return bench


def design_scenes() -> tuple:
    """The design bench's scenes: (the short run that compiles the kernels, the timed run
    of :data:`DESIGN_DURATION`). The scene's wave ramp (80 s) is longer than either run:
    each ramps its sea over the first third of its duration (a ramp longer than the run
    is refused, issue 44), the statistics start after it."""
    from riser.physics.dynamics import Dynamics
    base = resolve(DESIGN_SCENE)

    def run_of(duration: float):
        ramp = duration / 3.0
        return base.replace(dynamics=Dynamics(duration=duration, statistics_start=ramp),
                            **{"environment.waves.ramp_time": ramp})
    return run_of(1.0), run_of(DESIGN_DURATION)


def design_cost() -> dict:
    """Wall times [s] of one VFIFE dynamic run with the design checks (utilisation every
    sample, the fatigue record and its rainflow count) and without, side by side."""
    import time

    from verification.methods import method
    warm_up, base = design_scenes()
    # compile the kernels of the run with a short one: the runs below are timed alone
    method("vfife").solve(warm_up, element_length=8.0)
    walls = {}
    for key, scene in (("without", base.replace(design=None)), ("with", base)):
        t0 = time.perf_counter()        # the whole solve: the fatigue count follows the run
        method("vfife").solve(scene, element_length=DESIGN_ELEMENT_LENGTH).require()
        walls[key] = time.perf_counter() - t0
    return {"scene": DESIGN_SCENE, "element_length": DESIGN_ELEMENT_LENGTH,
            "duration_s": DESIGN_DURATION, "with_design_s": walls["with"],
            "without_design_s": walls["without"],
            "design_on_over_off": walls["with"] / walls["without"]}


def summary_lines(bench: dict) -> list[str]:
    """The console's lines on a bench record (the VFIFE table first)."""
    from vfife.bench import format_table
    lines = [format_table(bench)]
    if "ancf" in bench:
        from .ancf import summary_lines as ancf_lines
        lines.extend(ancf_lines(bench["ancf"]))
    for n, r in bench["analytic"].items():
        lines.append(f"analytic: {n} {1e3 * r['analytic_s']:.2f} ms a solve (median), BVP "
                     f"{r['bvp_s']:.3f} s: BVP / analytic = {r['bvp_over_analytic']:.0f}")
    b = bench["bvp"]
    lines.append(f"BVP: Wang baseline at tolerance 1e-6 {b['bvp_baseline_s']:.3f} s (median "
                 f"of {b['bvp_baseline_runs']}, target < 0.5 s); Table 2 batch of "
                 f"{b['bvp_table2_solves']} solves {b['bvp_table2_s']:.2f} s (target < 10 s)")
    if "bvp_segments" in bench:
        from bvp.bench import scaling_lines
        lines.extend(scaling_lines(bench["bvp_segments"]))
    if "bvp_rod" in bench:
        from bvp.bench import rod_lines
        lines.extend(rod_lines(bench["bvp_rod"]))
    if "bvp_reference" in bench:
        from bvp.bench import reference_lines
        lines.extend(reference_lines(bench["bvp_reference"]))
    if "vfife_scaling" in bench:
        from vfife.scaling import scaling_lines as vfife_scaling_lines
        lines.extend(vfife_scaling_lines(bench["vfife_scaling"]))
    if "design" in bench:
        d = bench["design"]
        lines.append(f"design checks on/off: {d['scene']} dynamic run ({d['duration_s']:g} s at "
                     f"{d['element_length']:g} m) {d['with_design_s']:.2f} / "
                     f"{d['without_design_s']:.2f} s = x{d['design_on_over_off']:.2f}")
    return lines
