"""The slug case of Liu et al. (2021) by two time domains: the VFIFE (vfife/flow.py) and the
ANCF with its ALE internal flow (ancf/flow.py), the same mathematical model (the effective
tension of the shape equations, the contents' gradient and Coriolis forces, the slug's mass
and weight moving with the flow) by two discretisations.

Both run the scene ``liu2021-scr`` with the paper's slug from the same static state's
definition (the slug frozen at t = 0) for :data:`DURATION` s of the paper's surge; the
response along s is read over the last :data:`WINDOW` s (a whole number of the surge's 9 s
and the slug's 32 s periods, after 72 s of start):

- ``tension_amp``: (max - min) / 2 of the effective tension [N] at each node;
- ``moment_max``: the largest bending moment [N m]; ``moment_amp``: its (max - min) / 2;
- ``disp_amp``: the in-plane displacement amplitude [m], |((max - min) / 2 of x, of y)|;
- ``moment_slug``, ``tension_slug``: the amplitude of the moment [N m] and tension [N] at
  the slug's frequency U / L_s (the slug's own response; the surge's lines fall on other
  bins of the window).

Each quantity q(s) is compared as the largest difference along s over its largest value,
e = max |q_ancf - q_vfife| / max |q_vfife|. Tolerance, measured: each method's own change
between its default run and a coarser one (elements 2x longer; the ANCF's step 2x longer
too, the VFIFE's step follows its elements), e_vfife + e_ancf, with the coarse run
interpolated linearly onto the default nodes: the difference of two converging methods is
bounded by the sum of their discretisation errors, and a halving's change bounds the
finer run's error (first order or better). A quantity passes when e <= its tolerance.
"""

from __future__ import annotations

import dataclasses
import math
import time
from pathlib import Path

import numpy as np
import pandas as pd

from verification.pipeline import solve_scene
from verification.report.figures import new_figure, save
from verification.report.markdown import md_table, pct

from .analysis import amplitude_at, window

#: [s] the runs' length: one common period of the surge and the slug (288 s) after 72 s
DURATION = 360.0
#: [s] the window the response is read over (the surge's 9 s x 32, the slug's 32 s x 9)
WINDOW = 288.0
#: the coarser runs: element length x this (and the ANCF's steps per period / this)
COARSEN = 2.0
METHODS = ("vfife", "ancf")
QUANTITIES = {
    "tension_amp": ("tension amplitude (max - min) / 2", "kN", 1e-3),
    "moment_max": ("largest moment", "kN m", 1e-3),
    "moment_amp": ("moment amplitude (max - min) / 2", "kN m", 1e-3),
    "disp_amp": ("in-plane displacement amplitude", "m", 1.0),
    "tension_slug": ("tension at the slug frequency", "kN", 1e-3),
    "moment_slug": ("moment at the slug frequency", "kN m", 1e-3),
}
CSV_COLUMNS = ("quantity", "unit", "vfife_max", "ancf_max", "rel_diff", "vfife_change",
               "ancf_change", "tolerance", "verdict")


@dataclasses.dataclass
class AlongS:
    """One run's response along s over the window: s (n,) [m] and the quantities of the
    module docstring (n,) each; the run's wall time [s], its time step [s] and elements."""

    method: str
    s: np.ndarray
    values: dict
    wall: float
    time_step: float
    elements: int


def method_scene(scene, method: str, coarse: bool):
    """``scene`` for ``method``'s default run, or its coarser one (the ANCF's step too)."""
    if coarse and method == "ancf":
        st = scene.ancf
        return scene.replace(ancf=dataclasses.replace(
            st, steps_per_period=max(8, int(round(st.steps_per_period / COARSEN)))))
    return scene


def along_s(res, method: str, length: float, f_slug: float, wall: float) -> AlongS:
    """The quantities along s of a converged dynamic result over its last ``length`` s."""
    st = res.dynamics.states
    t = np.asarray(st["t"], float)
    dt = float(t[1] - t[0])
    sel = window(t, t[-1] + dt, length)
    T = np.asarray(st["tension"], float)[sel]
    M = np.asarray(st["moment"], float)[sel]
    x = np.asarray(st["x"], float)[sel]
    ax = 0.5 * (x[:, :, 0].max(axis=0) - x[:, :, 0].min(axis=0))
    ay = 0.5 * (x[:, :, 1].max(axis=0) - x[:, :, 1].min(axis=0))
    n = T.shape[1]
    vals = {"tension_amp": 0.5 * (T.max(axis=0) - T.min(axis=0)),
            "moment_max": M.max(axis=0),
            "moment_amp": 0.5 * (M.max(axis=0) - M.min(axis=0)),
            "disp_amp": np.hypot(ax, ay),
            "tension_slug": np.array([amplitude_at(T[:, j], dt, f_slug) for j in range(n)]),
            "moment_slug": np.array([amplitude_at(M[:, j], dt, f_slug) for j in range(n)])}
    info = res.info
    return AlongS(method, np.asarray(st["s"], float), vals, wall,
                  float(info.get("dynamic_time_step", math.nan)), int(info.get("elements", n - 1)))


def solve_runs(scene, log, element_length: float | None = None,
               duration: float = DURATION, length: float = WINDOW) -> dict:
    """{(method, 'default' | 'coarse'): AlongS or None} of the slug ``scene`` (its
    [dynamics] shortened to ``duration`` s by the caller); ``element_length`` the default
    runs' [m] (None: each method's scene setting)."""
    fl = scene.internal_flow
    f_slug = fl.speed / fl.slug_length
    out = {}
    for method in METHODS:
        h0 = element_length or getattr(scene, method).element_length
        for level in ("default", "coarse"):
            coarse = level == "coarse"
            sc = method_scene(scene, method, coarse)
            t0 = time.perf_counter()
            res = solve_scene(sc, method, element_length=h0 * (COARSEN if coarse else 1.0))
            wall = time.perf_counter() - t0
            if not res.converged or res.dynamics is None:
                log(f"liu2021: {method} {level} failed ({res.status.value}): {res.message}")
                out[(method, level)] = None
                continue
            log(f"liu2021: slug by {method} ({level}, {h0 * (COARSEN if coarse else 1):g} m "
                f"elements) in {wall:.1f} s")
            out[(method, level)] = along_s(res, method, length, f_slug, wall)
    return out


def rel_diff(ref: AlongS, other: AlongS, key: str) -> float:
    """max |other - ref| / max |ref| of quantity ``key`` along s, ``other`` interpolated
    linearly onto ``ref``'s nodes."""
    a = ref.values[key]
    b = np.interp(ref.s, other.s, other.values[key])
    return float(np.max(np.abs(b - a)) / max(float(np.max(np.abs(a))), 1e-300))


def compare(runs: dict) -> pd.DataFrame | None:
    """The rows of the comparison (CSV_COLUMNS), None when a run is missing."""
    if any(r is None for r in runs.values()):
        return None
    v, a = runs[("vfife", "default")], runs[("ancf", "default")]
    rows = []
    for key, (_, unit, scale) in QUANTITIES.items():
        e = rel_diff(v, a, key)
        cv = rel_diff(v, runs[("vfife", "coarse")], key)
        ca = rel_diff(a, runs[("ancf", "coarse")], key)
        tol = cv + ca
        rows.append((key, unit, float(np.max(v.values[key])) * scale,
                     float(np.max(a.values[key])) * scale, e, cv, ca, tol,
                     "pass" if e <= tol else "FAIL"))
    return pd.DataFrame(rows, columns=CSV_COLUMNS)


def figure(runs: dict, out: Path) -> None:
    """methods.png: each quantity along s by both methods (default and coarse)."""
    if any(r is None for r in runs.values()):
        return
    fig, ax = new_figure(3, 2, (12, 11))
    styles = {("vfife", "default"): ("C0", "-"), ("vfife", "coarse"): ("C0", ":"),
              ("ancf", "default"): ("C3", "--"), ("ancf", "coarse"): ("C3", ":")}
    for k, (key, (label, unit, scale)) in enumerate(QUANTITIES.items()):
        a = ax[k // 2, k % 2]
        for (m, level), r in runs.items():
            c, ls = styles[(m, level)]
            a.plot(r.s, r.values[key] * scale, color=c, ls=ls, lw=1.0,
                   label=f"{m.upper()} {level} ({r.elements} elements)")
        a.set_title(label, fontsize=9)
        a.set_xlabel("arc length from the anchor s [m]")
        a.set_ylabel(f"[{unit}]")
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    save(fig, out / "methods.png")


def report_lines(frame: pd.DataFrame | None, runs: dict, scene) -> list[str]:
    """The report's section on the two methods."""
    fl = scene.internal_flow
    head = ["## The slug by two methods: VFIFE and ANCF (ALE internal flow)", "",
            f"The slug case (eta {fl.density_amplitude:g}, L_s {fl.slug_length:g} m, U "
            f"{fl.speed:g} m/s) by the VFIFE and by the ANCF, whose internal flow is Liu et "
            "al.'s arbitrary Lagrangian-Eulerian description on its own elements "
            "(ancf/flow.py): the same mathematical model as the VFIFE's (the contents' "
            "gradient and Coriolis forces, the slug's mass and weight moving along the line, "
            "the effective tension in the shape equations; docs/theory.md), two "
            f"discretisations. Each runs {DURATION:g} s of the surge from its own static state "
            f"(the slug frozen at t = 0); the response along s over the last {WINDOW:g} s "
            "(whole surge and slug periods). Difference: the largest along s over the "
            "quantity's largest value; tolerance: the sum of each method's change from its "
            f"default run to one with elements {COARSEN:g}x longer (the ANCF's time step "
            f"{COARSEN:g}x longer too; the VFIFE's step follows its elements), measured here.",
            ""]
    if frame is None:
        failed = [f"{m} {lv}" for (m, lv), r in runs.items() if r is None]
        return head + [f"Runs that did not converge: {', '.join(failed)}; no comparison.", ""]
    rows = []
    for r in frame.itertuples():
        rows.append((QUANTITIES[r.quantity][0], r.unit, f"{r.vfife_max:.4g}",
                     f"{r.ancf_max:.4g}", pct(r.rel_diff, 2), pct(r.vfife_change, 2),
                     pct(r.ancf_change, 2), pct(r.tolerance, 2), r.verdict))
    npass = int((frame.verdict == "pass").sum())
    v, a = runs[("vfife", "default")], runs[("ancf", "default")]
    lines = head + [
        md_table(["quantity along s", "unit", "VFIFE largest", "ANCF largest",
                  "difference", "VFIFE change", "ANCF change", "tolerance", "verdict"], rows),
        "",
        f"Agreement: {npass} of {len(frame)} quantities within their measured tolerance. "
        f"Default runs: VFIFE {v.elements} elements, step {v.time_step:.3g} s (explicit); "
        f"ANCF {a.elements} elements, step {a.time_step:.3g} s (implicit, "
        f"{scene.ancf.integrator}).", "",
        "![the slug's response along s by both methods](methods.png)", ""]
    return lines


def index_text(frame: pd.DataFrame | None) -> str:
    """The index's words on the two methods."""
    if frame is None:
        return "VFIFE vs ANCF: not run"
    worst = frame.loc[(frame.rel_diff / frame.tolerance).idxmax()]
    ok = bool((frame.verdict == "pass").all())
    return (f"VFIFE vs ANCF (slug): {int((frame.verdict == 'pass').sum())}/{len(frame)} along s "
            f"within measured tolerance, worst {pct(worst.rel_diff, 2)} ({worst.quantity}, "
            f"tol. {pct(worst.tolerance, 2)})" + ("" if ok else " FAIL"))
