"""MoorDyn as a peer column of a comparison (``riser-verify compare SCENE --peer moordyn``).

MoorDyn solves the scene's exported deck (:mod:`riser.io.moordyn.deck_from_scene`: the same EA, EI,
weight, drag and seabed per metre) with its own method: a lumped-mass line whose bending
acts through the angle between adjacent segments, joints between lines that are hinges,
and its own static solver (:mod:`verification.peers.moordyn.run`). Its profile is compared with
the BVP's by the protocol's own rows (:func:`verification.comparison.static.agreement.agreement`: at MoorDyn's
nodes, the BVP interpolated there, its tension through the same nodal average, since a
MoorDyn interior node also reports the mean of its two segments), outside the verdict and
against tolerances of its own, :data:`TOLERANCES`, each with its reason. On a 3D scene
(the BVP's 3D rod against MoorDyn's 3D deck) the protocol's 3D rows and ``lateral``
(:func:`lateral_rows`) are added.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from riser.results.profile import Profile
from verification.comparison.static.agreement import agreement
from verification.comparison.static.columns import ColumnResult, verdict_values
from verification.comparison.row import Row, Tolerance, Verdict
from verification.comparison.tolerances import base_name
from verification.pipeline import shifted
from verification.quantities import signed_moment
from verification.report.markdown import md_table

from . import FILES
from .run import IC_TIME, PeerRun, run

#: quantity -> (kind, value, reason). Kinds as verification/comparison/tolerances.py, plus ``of_h``:
#: a multiple of MoorDyn's segment length h. Each is the worst value measured at h = 10 m on
#: the two scenes where MoorDyn's hinges sit where the beam's moment is ~0 (scr-steel, one
#: line; wang2014-baseline, whose BVP moment at its two joints is below 1e-9 N m), times a
#: margin of about 3 (MoorDyn stops at a force residual up to 1 % of a node's weight). The
#: BVP's own error is four orders smaller. Where a hinge sits on a bending beam the rows
#: go outside, as they should: yu2021-a3 (six joints at 21-81 kN m) measured peak moment
#: -13.6 %, moment along the line 36 % of M_max, configuration 0.84 % of depth.
TOLERANCES = {
    "configuration": ("of_depth", 3.0e-4, "lumped masses 10 m apart and the static solver's "
                      "residual: measured 0.0021 % (SCR), 0.0084 % (Wang) of depth"),
    "configuration_rms": ("of_depth", 1.5e-4, "measured 0.0008 %, 0.0035 % of depth"),
    "tension": ("of_T_max", 1.5e-3, "segment tensions from the stretch of 10 m segments: "
                "measured 0.014 %, 0.048 % of T_max"),
    "moment": ("of_M_max", 0.075, "curvature from the angle between 10 m segments, which do "
               "not resolve the touchdown layer sqrt(EI/T) ~ 5 m: measured 1.7 %, 2.4 % of "
               "M_max; a hinge on a bending beam (M = 0 there) goes outside"),
    "hang_off_tension": ("rel", 6.0e-4, "the end-node force (MoorDyn's FairTen output) "
                         "against the BVP's T(L): measured -0.0075 %, -0.021 %"),
    "hang_off_angle_deg": ("abs", 0.1, "the last segment's direction, h/2 below the "
                           "hang-off: measured -0.035, -0.023 deg"),
    "tdp_x": ("of_h", 0.5, "the lift-off between two nodes: measured -2.6, -2.3 m at h = 10 m"),
    "tdp_tension": ("of_T_max", 1.0e-3, "as the tension: measured 0.011 %, 0.024 % of T_max"),
    "crest_height": ("of_depth", 3.0e-4, "as the configuration: measured 0.0027 % (Wang)"),
    "sag_height": ("of_depth", 3.0e-4, "as the configuration: measured 0.0076 % (Wang)"),
    "crest_s": ("of_h", 0.1, "a vertex between nodes h apart: measured 0.21 m (Wang)"),
    "sag_s": ("of_h", 0.1, "a vertex between nodes h apart: measured 0.13 m (Wang)"),
    "max_moment": ("of_M_max", 1.0e-2, "the peak at 10 m nodes: measured 0.06 %, 0.21 %"),
    "max_moment_s": ("of_h", 1.0, "a peak between nodes h apart: measured 4.3, 3.5 m"),
    # 3D rows (the protocol's, and ``lateral`` of this column): measured at h = 10 m on
    # hard-out-of-plane-current against the BVP's 3D solution (2900 m, three sections,
    # 62 m of lateral excursion); each as the planar row it is a component or a point of
    "lateral": ("of_depth", 3.0e-4, "the lateral offset at the same s, a component of the "
                "configuration: measured 0.013 % of depth"),
    "max_lateral_offset": ("of_depth", 3.0e-4, "as the configuration: measured -0.013 %"),
    "crest_lateral": ("of_depth", 3.0e-4, "as the configuration: measured -0.013 %"),
    "sag_lateral": ("of_depth", 3.0e-4, "as the configuration: measured -0.013 %"),
    "tdp_lateral": ("of_h", 0.1, "the lift-off between two nodes times the lateral slope "
                    "there: measured -0.27 m"),
    "moment_out_of_plane": ("of_M_max", 0.075, "as the moment: measured 2.5 % of M_max, at "
                            "a hinge between sections"),
    "max_moment_out_of_plane": ("of_M_max", 1.0e-2, "as the peak moment: measured -0.015 %"),
}

PEER_COLUMNS = ("quantity", "unit", "bvp", "vfife", "moordyn", "diff", "rel_diff",
                "tolerance", "pass", "reason", "reference")


def reference(comp) -> tuple[Profile, Profile]:
    """The BVP's profile MoorDyn is compared with, as the verdict (in 3D too: the BVP
    solves a 3D scene as its 3D rod): (in the scene's arc length, in the solved scene's,
    from which MoorDyn's joints start)."""
    bp = comp.bvp.profile
    return shifted(bp, comp.s_shift), bp


def lateral_rows(ref: Profile, md: Profile, depth: float) -> list[Row]:
    """MoorDyn's row ``lateral``, when both profiles carry the lateral offset (a row of
    the BVP and MoorDyn, no value of either: a difference along s): the largest difference
    of the lateral offset at MoorDyn's nodes (the BVP interpolated there). The protocol's
    own 3D rows (the out-of-plane moment, the lateral excursion, ...) come with
    :func:`~verification.comparison.static.agreement.agreement`."""
    if ref.lateral is None or md.lateral is None:
        return []
    lo, hi = max(ref.s[0], md.s[0]), min(ref.s[-1], md.s[-1])
    sel = (md.s >= lo - 1e-9) & (md.s <= hi + 1e-9)
    d = md.lateral[sel] - np.interp(md.s[sel], ref.s, ref.lateral)
    i = int(np.argmax(np.abs(d)))
    return [Row("lateral", {"bvp": None, "moordyn": None}, "m", float(d[i]),
                float(d[i]) / depth, Tolerance(None, depth, "depth"),
                at_s=float(md.s[sel][i]))]


def tolerance(row: Row, h: float) -> tuple[float | None, str, str]:
    """(absolute tolerance, label, reason) of MoorDyn's row ``row`` at segment length h."""
    entry = TOLERANCES.get(base_name(row["quantity"]))
    if entry is None:
        return None, "", "not assessed"
    kind, value, why = entry
    if kind == "abs":
        return value, f"{value:g} {row['unit']}", why
    if kind == "of_h":
        return value * h, f"{value:g} h = {value * h:g} m", why
    basis = row.get("basis")
    if kind == "rel":
        basis = abs(row["bvp"]) if row.get("bvp") is not None else None
    if not basis:
        return None, "", why
    label = {"of_depth": "depth", "of_T_max": "T_max", "of_M_max": "M_max", "rel": "itself"}
    if kind != "rel" and row.get("basis_label"):     # a floor in place of T_max, M_max
        label[kind] = row["basis_label"]
    return value * basis, f"{100 * value:g} % of {label[kind]}", why


class MoorDynColumn:
    """MoorDyn's column of ``compare --peer moordyn`` (a :class:`~verification.comparison.
    columns.Column`): MoorDyn on the scene's exported deck, segments of ``segment_length``
    [m], its static solver bounded by ``ic_time`` [s] of pseudo-time."""

    name = "moordyn"
    label = "MoorDyn (nodes)"
    style = {"ls": "none", "marker": ".", "ms": 2.5}
    forces = ("tension", "moment")            # MoorDyn reports no shear
    files = FILES

    def __init__(self, segment_length: float = 10.0, ic_time: float = IC_TIME):
        self.segment_length = segment_length
        self.ic_time = ic_time

    def solve(self, comp, folder: Path, progress=None) -> ColumnResult:
        """Run MoorDyn on ``comp.scene`` (its deck and log into ``folder``); its rows against
        the BVP (:func:`reference`) with this column's own tolerances, and the end-segment
        tension beside."""
        rp, start = reference(comp)
        peer = run(comp.scene, folder, segment_length=self.segment_length,
                   profile=start, ic_time=self.ic_time, progress=progress)
        if peer.profile is None:
            return ColumnResult(self, peer, note=peer.message, ok=peer.converged)
        vf = {r.quantity: r for r in comp.rows}
        # the scene's floors of the relative rows' bases (issue 44: round-off never FAILs)
        own = agreement(rp, peer.profile, comp.depth, nodal=True,
                        scene=comp.matched_scene, names=("bvp", self.name))
        rows = []
        have = {r.quantity for r in own}
        extra = [r for r in lateral_rows(rp, peer.profile, comp.depth)
                 if r.quantity not in have]
        for r in own + extra:
            # this column's own tolerance (its segments, not the VFIFE's elements); the
            # VFIFE's value of the verdict row beside
            tol, label, why = tolerance(r, self.segment_length)
            v = vf[r.quantity].value("vfife") if r.quantity in vf else None
            basis = r.tolerance.basis_label if r.tolerance is not None else ""
            rows.append(r.replace(
                values={"bvp": r.value("bvp"), self.name: r.value(self.name), "vfife": v},
                tolerance=Tolerance(tol, None, basis, label, why),
                verdict=Verdict.of(None if tol is None or r.diff is None
                                   else bool(abs(r.diff) <= tol)), note=""))
        b, seg = float(rp.tension[-1]), peer.info["hang_off_end_segment_tension"]
        rows.append(Row("hang_off_segment_tension", {"bvp": b, self.name: seg, "vfife": None},
                        "N", seg - b, (seg - b) / b,
                        Tolerance(None, None, "itself", "", "the last segment's tension "
                                  "(GetLineFairTen), half a segment below the end: shown, "
                                  "not assessed")))
        return ColumnResult(self, peer, peer.profile,
                            verdict_values(comp.rows, own, self.name), rows,
                            note=peer.message, ok=peer.converged)

    def markdown(self, comp, res: ColumnResult, heading: str = "#") -> list[str]:
        return moordyn_markdown(comp, res, heading)

    def write(self, comp, res: ColumnResult, out: Path) -> None:
        write(comp, res, out)

    def console(self, res: ColumnResult) -> list[str]:
        return summary_lines(res)

    def files_note(self) -> str:
        return "`moordyn_rel_diff` MoorDyn's"


def hinge_moments(comp, peer: PeerRun) -> list[tuple[float, float]]:
    """(s, the BVP's moment) at each joint between MoorDyn lines: where MoorDyn's hinge
    has 0."""
    if peer.files is None:
        return []
    bp, _ = reference(comp)
    m = signed_moment(bp)
    return [(s0 - peer.files.s_shift, float(np.interp(s0 - peer.files.s_shift, bp.s, m)))
            for s0, _ in peer.files.export.line_span[1:]]


def moordyn_markdown(comp, res: ColumnResult, heading: str = "#") -> list[str]:
    """The report's MoorDyn section."""
    peer = res.result
    info = peer.info
    h = info.get("segment_length")
    lines = ["", f"{heading}# MoorDyn (peer column), not part of the verdict", "",
             f"MoorDyn {_version()} solved the exported deck (`moordyn/deck.dat`, "
             f"{info.get('segments')} segments of about {h:g} m): {peer.status.value}, "
             f"{peer.message}."]
    if peer.profile is None:
        return lines
    if peer.profile.is_3d:
        why = (comp.matched_scene or comp.scene).out_of_plane(statics=True)
        lines += ["", f"The scene is 3D ({why[1]}): MoorDyn solved the 3D deck and "
                  "is compared with the BVP's 3D solution; the rows "
                  "of the lateral offset (from the vertical plane through the ends) and of "
                  "the out-of-plane moment are added. MoorDyn's moment vector at a node is "
                  "EI x GetLineNodeCurv about the axis q_{i-1} x q_i of its two segments "
                  "(MoorDyn outputs none)."]
    lines += [
        "",
        f"- Static solver: {info['ic_pseudo_time_s']:g} s of pseudo-time in "
        f"{info['ic_wall_s']:.1f} s of wall time, force residual "
        f"{100 * info['ic_force_residual']:.2g} % of a node's load (its submerged weight, "
        "or its drag in the current when larger).",
    ]
    if "settle_sim_s" in info:
        lines.append(f"- The current (not applied by MoorDyn's static solver) was then switched "
                     f"on and the line time-stepped until it stopped: {info['settle_sim_s']:g} "
                     f"s simulated, {info['settle_wall_s']:.1f} s of wall time, step "
                     f"{info['dynamic_step_s']:.3g} s.")
    lines += [
        f"- Tension compared at the hang-off: **the end-node force**, |GetLineNodeForce| of the "
        f"last node ({info['hang_off_end_node_force'] / 1e3:.3f} kN), the force on the vessel "
        "that MoorDyn's FairTen output channel writes; the end-segment tension "
        f"(GetLineFairTen, {info['hang_off_end_segment_tension'] / 1e3:.3f} kN) is half a "
        "segment lower on the line (row `hang_off_segment_tension`). Along the line: "
        "GetLineNodeTen (the mean of the two adjacent segments).",
        "- Moment = EI x GetLineNodeCurv, the curvature 4 sin(a/2)/(l1 + l2) from the angle a "
        "between adjacent segments; 0 at the pinned ends and at the joints between lines, "
        "which are hinges in MoorDyn.",
    ]
    hinges = hinge_moments(comp, peer)
    if hinges:
        lines.append("- BVP moment at the hinges (MoorDyn: 0): " + ", ".join(
            f"{m / 1e3:.3g} kN m at s = {s:.1f} m" for s, m in hinges) + ".")
    lines += ["", "Tolerances of this column, each with its reason: "
              "`verification/peers/moordyn/column.py`.", ""]
    rows = []
    for r in res.rows:
        rel = r.rel_diff
        rows.append((f"`{r.quantity}`", r.unit, _n(r.value("bvp")), _n(r.value("vfife")),
                     _n(r.value("moordyn")), _n(r.diff) + (f" at s = {r.at_s:.1f}"
                                                           if r.at_s is not None else ""),
                     "" if rel is None else f"{100 * rel:+.3g} %",
                     r.tolerance.label, {True: "yes", False: "**no**", None: "-"}[r.passed],
                     r.tolerance.reason))
    lines.append(md_table(["quantity", "unit", "BVP", "VFIFE", "MoorDyn", "MoorDyn - BVP",
                           "relative", "tolerance", "within", "reason"], rows))
    lines += ["", "Files: `moordyn/agreement.csv` (these rows), `moordyn/profile.csv` (MoorDyn's "
              "profile and the BVP interpolated at MoorDyn's nodes), `moordyn/deck.dat`, "
              "`moordyn/moordyn.log`.", ""]
    return lines


def write(comp, res: ColumnResult, out: Path) -> None:
    """moordyn/agreement.csv and moordyn/profile.csv (the deck and log are already there)."""
    import pandas as pd
    peer = res.result
    if peer is None or peer.profile is None:
        return
    d = Path(out) / "moordyn"
    d.mkdir(parents=True, exist_ok=True)
    pd.DataFrame([r.record(PEER_COLUMNS) for r in res.rows], columns=PEER_COLUMNS).to_csv(
        d / "agreement.csv", index=False, float_format="%.8g")
    p = peer.profile
    bp, _ = reference(comp)
    cols = {"s": p.s, "x": p.x, "y": p.y, "z": p.z, "tension": p.tension,
            "curvature": p.curvature, "moment": p.moment, "angle_deg": np.degrees(p.theta)}
    three_d = ("lateral", "moment_in_plane", "moment_out_of_plane")
    for c in three_d:
        if getattr(p, c) is not None:
            cols[c] = getattr(p, c)
    for c in ("tension", "moment") + three_d:
        if getattr(p, c) is not None and getattr(bp, c) is not None:
            cols[f"bvp_{c}"] = np.interp(p.s, bp.s, getattr(bp, c))
    pd.DataFrame(cols).to_csv(d / "profile.csv", index=False, float_format="%.10g")


def summary_lines(res: ColumnResult) -> list[str]:
    """The command line's lines on the MoorDyn column."""
    out = [f"  moordyn: {res.result.status.value}: {res.result.message}"]
    for r in res.rows:
        if r.passed is not None and r.diff is not None:
            out.append(f"    {'ok  ' if r.passed else 'OUT '} {r.quantity:<22} MoorDyn - "
                       f"BVP {r.diff:.6g} {r.unit} "
                       f"(tolerance {r.tolerance.label})")
    return out


def _n(v) -> str:
    if v is None:
        return ""
    return f"{v:.6g}"


def _version() -> str:
    try:
        from importlib.metadata import version
        return version("moordyn")
    except Exception:         # noqa: BLE001 - a version string only
        return "(version unknown)"
