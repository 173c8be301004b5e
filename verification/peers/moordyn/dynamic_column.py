"""MoorDyn's third opinion on a dynamic comparison (``compare SCENE --dynamics --peer
moordyn``): the same ramped harmonic motion of the hang-off, or in a comparison driven by
a regular wave the same sea (:mod:`.waves`: the scene's components, the vessel moving the
hang-off), at the sweep's smallest
amplitude, driven through MoorDyn's Coupled point (:mod:`.harmonic`), its first harmonic
against the frequency domain's and the VFIFE's. Outside the verdict, with its own
tolerance (:data:`TOLERANCE`).

File: ``moordyn/dynamic_agreement.csv`` (quantity, moordyn, fd, vfife, moordyn_vs_fd,
moordyn_vs_vfife, tolerance, within); units N and deg.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from verification.comparison.dynamic.rows import wrap_deg
from verification.comparison.row import Row, Tolerance, Verdict
from verification.comparison.dynamic.protocol import ORBIT, RAMP_PERIODS, SETTLE_PERIODS, dynamic_scene
from verification.report.markdown import md_table, pct

#: MoorDyn's tolerance: its 10 m segments lump the line's inertia at the nodes, its end
#: node's force leaves out that node's inertia, and it has no bending stiffness in the
#: VFIFE's form; measured on scr-steel (0.5 m heave, 12 s) 0.62 % below the VFIFE's
#: hang-off tension amplitude (0.06 % with the sea surface above the hang-off), 0.15 %
#: of the peak along s: 2 % leaves room for a coarser deck, a defect of 5 % fails.
TOLERANCE = 0.02
#: its segment length [m]
SEGMENT_LENGTH = 10.0
FILES = ("moordyn/dynamic_agreement.csv",)


def dynamic(dc, out, progress=None) -> tuple[str, list[str]]:
    """Run MoorDyn on the smallest amplitude of ``dc`` into ``out``/moordyn; write its
    CSV and return its report section (Markdown) and its console lines."""
    from .harmonic import first_harmonics, run_harmonic
    if not dc.matched.statics_planar:      # the first harmonics it is read against are planar
        why = ("not run: its first harmonic is read against the frequency domain's about a "
               "planar static state, and this scene's is 3D")
        return (f"\n## MoorDyn (third opinion, not in the verdict)\n\nMoorDyn {why}.\n",
                [f"  moordyn: {why}"])
    if dc.axis == ORBIT:                   # its coupled point is driven along one axis
        why = "not run: its harmonic run drives the hang-off along one axis, not an orbit"
        return (f"\n## MoorDyn (third opinion, not in the verdict)\n\nMoorDyn {why}.\n",
                [f"  moordyn: {why}"])
    r0 = dc.results[0]
    if progress:
        progress(f"moordyn: amplitude {r0.amplitude:g} m")
    scene = dynamic_scene(dc.matched, dc.axis, r0.amplitude, dc.period,
                          r0.vf.get("settle_periods", SETTLE_PERIODS),
                          r0.vf.get("ramp_periods", RAMP_PERIODS))
    folder = Path(out) / "moordyn"
    folder.mkdir(parents=True, exist_ok=True)
    sea = scene.waves is not None and scene.dynamics.top_motion is None
    if sea:      # a wave-driven comparison: the same components (WaveKin 7), the vessel
        from .waves import run_waves                        # moving the hang-off
        run = run_waves(scene, folder, segment_length=SEGMENT_LENGTH,
                        profile=dc.static.profile,
                        sample=scene.dynamics.output_interval)
    else:
        run = run_harmonic(scene, folder, segment_length=SEGMENT_LENGTH,
                           profile=dc.static.profile)
    if not run.get("stable", True):
        why = run.get("message", "unstable")
        return (f"\n## MoorDyn (third opinion, not in the verdict)\n\nMoorDyn stopped: "
                f"{why}\n", [f"  moordyn: stopped: {why}"])
    h = first_harmonics(run, dc.period)
    s = np.asarray(run["s"])
    fd_top = complex(r0.fd.amplitudes["tension"][-1])
    vf_top = complex(r0.vf["tension"].first[-1])
    fd_along = np.abs(r0.fd.at("tension", s))
    vf_along = np.interp(s, r0.vf["s"], r0.vf["tension"].amplitude)
    md_along = np.asarray(h["tension_amplitude"])
    inner = slice(1, -1)                     # the end nodes' force is not T(s)
    peak = float(np.max(fd_along))
    rows = [
        _row("hang_off_tension_amplitude", h["hang_off_tension_amplitude"], abs(fd_top),
             abs(vf_top), relative=True),
        _row("hang_off_tension_phase_deg", h["hang_off_tension_phase_deg"],
             float(np.degrees(np.angle(fd_top))), float(np.degrees(np.angle(vf_top))),
             relative=False),
        _along_row(md_along, fd_along, vf_along, inner, peak)]
    pd.DataFrame([{"quantity": r.quantity, "moordyn": r.value("moordyn"), "fd": r.value("fd"),
                   "vfife": r.value("vfife"), "moordyn_vs_fd": _vs_fd(r),
                   "moordyn_vs_vfife": r["moordyn_vs_vfife"], "tolerance": r.tolerance.value,
                   "within": r.passed} for r in rows]).to_csv(
        folder / "dynamic_agreement.csv", index=False, float_format="%.8g")
    table = md_table(["quantity", "MoorDyn", "FD", "VFIFE", "MoorDyn vs FD",
                      "MoorDyn vs VFIFE", "tolerance", "within"],
                     [(f"`{r.quantity}`", r.value("moordyn"), r.value("fd"), r.value("vfife"),
                       _fmt(r, _vs_fd(r)), _fmt(r, r["moordyn_vs_vfife"]),
                       r.tolerance.value, "yes" if r.passed else "**no**") for r in rows])
    lines = [f"  moordyn (not in the verdict): {r.quantity} {_fmt(r, _vs_fd(r))} vs "
             f"the FD ({'within' if r.passed else 'OUTSIDE'} its {r.tolerance.value:g})"
             for r in rows]
    return ("\n## MoorDyn (third opinion, not in the verdict)\n\n"
            f"MoorDyn-C, {SEGMENT_LENGTH:g} m segments, "
            + (f"the same sea (the scene's components summed by its WaveKin 7, wave "
               f"amplitude {r0.amplitude:g} m; {run['ramp']}; its elevation within "
               f"{run['sea_elevation_difference']:.1g} m of the scene's"
               + ("" if scene.waves.stretching == "wheeler" else
                  f"; MoorDyn stretches by Wheeler, the scene's '{scene.waves.stretching}' "
                  "stretching is not represented")
               + "), the hang-off's motion given at every MoorDyn step" if sea else
               f"the same ramped motion at {r0.amplitude:g} m, the hang-off given at every "
               "MoorDyn step") + "; its first "
            "harmonic over the same window (`moordyn/dynamic_agreement.csv`; tension "
            "along s at the interior nodes; its tolerance "
            f"{TOLERANCE:.0%}: {TOLERANCE_REASON}). Wall time "
            f"{run.get('wall_s', float('nan')):.1f} s.\n\n" + table + "\n", lines)


TOLERANCE_REASON = ("lumped 10 m segments, the end node's force without its inertia, no "
                    "bending stiffness in the VFIFE's form; measured 0.6 % on scr-steel")


def _row(name, md, fd, vf, relative: bool) -> Row:
    """MoorDyn's value against the FD's (relative, or in deg for a phase), the VFIFE's
    beside (``moordyn_vs_vfife``)."""
    if relative:
        a, b = md / fd - 1.0, md / vf - 1.0
    else:
        a, b = wrap_deg(md - fd), wrap_deg(md - vf)
    tol = TOLERANCE if relative else 1.0
    return Row(name, {"fd": fd, "moordyn": md, "vfife": vf}, "" if relative else "deg",
               None if relative else a, a if relative else None,
               Tolerance(tol, None, "of the FD's" if relative else "", "",
                         TOLERANCE_REASON, relative=relative),
               Verdict.of(bool(abs(a) <= tol)),
               extra={"moordyn_vs_vfife": b})


def _along_row(md_along, fd_along, vf_along, inner, peak: float) -> Row:
    """The tension amplitude along s (interior nodes): the largest difference over the
    FD's peak."""
    a = float(np.max(np.abs(md_along - fd_along)[inner]) / peak)
    return Row("tension_amplitude_along_s",
               {"fd": peak, "moordyn": float(np.max(md_along[inner])),
                "vfife": float(np.max(vf_along[inner]))}, "", None, a,
               Tolerance(TOLERANCE, None, "of the FD's peak", "", TOLERANCE_REASON,
                         relative=True), Verdict.of(bool(abs(a) <= TOLERANCE)),
               extra={"moordyn_vs_vfife": float(np.max(np.abs(md_along - vf_along)[inner])
                                                / peak)})


def _vs_fd(r: Row) -> float:
    """MoorDyn against the FD: the relative difference, or the phase's in deg."""
    return r.rel_diff if r.tolerance.relative else r.diff


def _fmt(r: Row, v: float) -> str:
    return f"{v:+.3f} deg" if r.quantity.endswith("_deg") else pct(v)
