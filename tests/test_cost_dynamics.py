"""Cost study, dynamics: the sweep over element length and time-step factor, the errors
against the dynamic reference, ``dynamics.csv`` and one real (tiny) run.

The analysis is pinned on synthetic records whose exact values are known: a quantity
q(h, f) = q0 (1 + a h^2 + b (f h)^2) has the limit q0, order 2 in h and a step error
b (f h)^2, so the errors, the Richardson reference, the step-factor verdict and the
recommendation can be checked to rounding.
"""

from __future__ import annotations

import math

import pandas as pd
import pytest

import builders
import vfife
from verification.studies import cost
from verification.studies.cost import dynamics as dyn
from verification.studies.cost import dynamics_analysis as da
from verification.studies.cost import settings

LENGTHS = (10.0, 5.0, 2.0, 1.0)


def _run(h, f, amp, mom):
    """A completed run whose wall time is 1 / (f h^2), as elements x steps."""
    r = dyn.DynRun(dyn.DynSetting(h, f), times=[1.0 / (f * h * h)], converged=True,
                   message="dynamics completed", elements=int(100 / h),
                   time_step=1e-3 * f * h, steps=int(40 / (1e-3 * f * h)))
    r.amplitude, r.peak_moment = amp, mom
    return r


def _study(runs, f0=0.8):
    ds = dyn.DynStudy(runs, f0, "given")
    da.analyse(ds)
    return ds


def smooth_runs(a=5e-5, b=1e-6, step_factors=(0.95, 0.4)):
    """Amplitude 1000 (1 + a h^2 + b (f h)^2), peak moment 5e4 (1 - a h^2 / 2 + b (f h)^2)."""
    def q(h, f):
        return (1000.0 * (1 + a * h * h + b * (f * h) ** 2),
                5e4 * (1 - 0.5 * a * h * h + b * (f * h) ** 2))
    runs = [_run(h, 0.8, *q(h, 0.8)) for h in LENGTHS]
    runs += [_run(1.0, f, *q(1.0, f)) for f in step_factors]
    runs.append(_run(2.0, 0.4, *q(2.0, 0.4)))
    return runs


def test_errors_against_the_finest_run_are_exact():
    """Non-monotone amplitudes: no Richardson limit, the reference is the finest run at the
    smallest factor and every error is |q - q_ref| / q_ref."""
    amps = {10.0: 1010.0, 5.0: 995.0, 2.0: 1002.0, 1.0: 1000.5}
    moms = {10.0: 50100.0, 5.0: 49950.0, 2.0: 50030.0, 1.0: 50010.0}
    runs = [_run(h, 0.8, amps[h], moms[h]) for h in LENGTHS]
    runs.append(_run(1.0, 0.4, 1000.0, 5e4 + 9.0))
    ds = _study(runs)
    assert ds.ref_run is runs[-1]
    ref = ds.reference["amplitude"]
    assert ref["kind"] == "finest" and ref["value"] == 1000.0
    for r in runs:
        assert r.errors["amplitude"] == pytest.approx(abs(r.amplitude - 1000.0) / 1000.0,
                                                      rel=1e-12)
        assert r.errors["peak_moment"] == pytest.approx(abs(r.peak_moment - 50009.0) / 50009.0,
                                                        rel=1e-12)
    # uncertainty: the larger of the change from the scene's factor at 1 m (5e-4) and from
    # the next-coarser length (2 m, run at factor 0.8 only: 2 m vs 1 m at 0.8, 1.5e-3)
    assert ref["step_change"] == pytest.approx(5e-4)
    assert ref["mesh_change"] == pytest.approx(1.5e-3)
    assert ref["uncertainty"] == pytest.approx(1.5e-3)


def test_clean_convergence_gives_a_richardson_reference():
    runs = smooth_runs()
    ds = _study(runs)
    for q, q0 in (("amplitude", 1000.0), ("peak_moment", 5e4)):
        ref = ds.reference[q]
        assert ref["kind"] == "richardson", ref
        assert ref["richardson_lengths"] == [5.0, 2.0, 1.0]
        # the limit of the factor-0.8 sequence: q0 (1 + b 0.64 h^2 ...) is still h^2
        assert ref["value"] == pytest.approx(q0, rel=1e-9)
        assert ref["richardson_order"] == pytest.approx(2.0, abs=1e-6)
    r10 = runs[0]
    assert r10.errors["amplitude"] == pytest.approx(5e-5 * 100 + 1e-6 * 64, rel=1e-6)
    # the order in h: exactly 2 over the lengths above the step floor
    fit = ds.orders["amplitude"]
    assert fit["order"] == pytest.approx(2.0, abs=1e-6) and fit["points"] == list(LENGTHS)
    # the step factor: b (f h)^2 against a h^2, far below 10 % of the mesh error
    assert not ds.step_verdict["amplitude"]["matters"]
    rows = [r for r in ds.step if r["h"] == 1.0]
    assert {r["factor"] for r in rows} == {0.95, 0.8}
    row = next(r for r in rows if r["factor"] == 0.8)
    assert row["amplitude"] == pytest.approx(1e-6 * (0.64 - 0.16), rel=1e-6)
    # order in the time step from the three smallest factors at 1 m: 2
    (it,) = ds.dt_order["amplitude"]
    assert it["h"] == 1.0 and it["order"] == pytest.approx(2.0, abs=1e-4)


def test_a_step_error_that_matters_is_said_and_blocks_richardson():
    ds = _study(smooth_runs(b=5e-4))
    assert ds.step_verdict["amplitude"]["matters"]
    assert ds.reference["amplitude"]["kind"] == "finest"       # step change > 10 % of mesh


def test_recommendation_is_the_cheapest_run_within_the_accuracy():
    """Amplitude errors 5e-5 h^2 (+ 1e-6 (f h)^2, wall time 1/(f h^2)): 10 m 5e-3, 5 m
    1.3e-3, 2 m 2e-4, 1 m 5e-5; the reference (a Richardson limit) is uncertain by the
    1 m error, 5e-5, below every accuracy."""
    runs = smooth_runs()
    ds = _study(runs)
    recs = {r["target"]: r for r in da.recommendations(ds)}
    picks = {t: recs[t]["amplitude"] for t in (1e-2, 1e-3, 1e-4)}
    assert all(kind == "run" for kind, _ in picks.values())
    assert [(r.h, r.factor) for _, r in picks.values()] == [(10.0, 0.8), (2.0, 0.8),
                                                             (1.0, 0.95)]
    for t, (_, r) in picks.items():
        assert r is min((x for x in runs if x.errors["amplitude"] <= t),
                        key=lambda x: x.wall_s)
    kind, r = recs[1e-4]["both"]
    assert kind == "run" and max(r.errors.values()) <= 1e-4
    # coarser convergence: 1 m errs by 2e-4; with a (pretended) sharp reference, 0.01 % is
    # not reached, with a reference uncertain by more than the accuracy it is not judged
    ds = _study(smooth_runs(a=2e-4))
    ds.reference["amplitude"]["uncertainty"] = 1e-9
    recs = {r["target"]: r for r in da.recommendations(ds)}
    assert recs[1e-4]["amplitude"] == ("not reached", None)
    ds.reference["amplitude"]["uncertainty"] = 5e-3
    recs = {r["target"]: r for r in da.recommendations(ds)}
    assert recs[1e-3]["amplitude"] == ("uncertain", 5e-3)
    assert recs[1e-3]["both"][0] == "uncertain"
    assert recs[1e-2]["amplitude"][0] == "run"


def test_dynamics_csv_has_its_columns(tmp_path):
    ds = _study(smooth_runs())
    ds.runs.append(dyn.DynRun(dyn.DynSetting(0.5, 0.8), message="dynamics diverged"))
    ds.frame().to_csv(tmp_path / "dynamics.csv", index=False)
    df = pd.read_csv(tmp_path / "dynamics.csv")
    assert tuple(df.columns) == dyn.CSV_COLUMNS + dyn.CSV_EXTRA
    assert tuple(df.columns[:9]) == (
        "element_length", "time_step_factor", "time_step", "steps", "wall_s",
        "hang_off_tension_amplitude", "peak_moment", "err_amplitude", "err_peak_moment")
    assert df["reference"].sum() == 0             # a Richardson reference is no run
    assert not df["converged"].iloc[-1] and math.isnan(df["err_amplitude"].iloc[-1])


def hanging_surface_line():
    """A 240 m line hanging between two points 100 m and 150 m up, the top at the sea
    surface (water depth 150 m): the heave lifts its top out of the water."""
    return builders.scene(builders.line(
        240.0, (0.0, 100.0), (200.0, 150.0), name="surface-line",
        line_type=builders.pipe(drag_normal=1.0, drag_tangential=0.01, added_mass=1.0),
        environment={"water_depth": 150.0}))


def test_sweep_plan_fast_and_full():
    """Lengths at the scene's factor down to the finest within the budget, 0.95 and 0.4 at
    the finest, 0.4 at the next-coarser; --full adds 20 m, finer lengths and the step
    factors at 2 m; a hang-off at the surface is recognised."""
    sc = hanging_surface_line()
    assert dyn.surface_piercing(sc) == {"below": 0.0}
    fast = dyn.dynamic_settings(sc, "fast")
    f0 = sc.vfife.time_step_safety
    hs = [s.element_length for s in fast if s.factor == f0]
    assert hs == sorted(hs, reverse=True) and hs[0] == 10.0
    hmin = hs[-1]
    assert dyn.element_steps(sc, hmin, dyn.REFERENCE_FACTOR) <= dyn.BUDGET["fast"]
    assert {(s.element_length, s.factor) for s in fast if s.factor != f0} == {
        (hmin, 0.95), (hmin, 0.4), (hs[-2], 0.4)}
    full = dyn.dynamic_settings(sc, "full")
    keys = {(s.element_length, s.factor) for s in full}
    assert (20.0, f0) in keys and {(2.0, f) for f in dyn.ORDER_FACTORS} <= keys
    hmin_full = min(s.element_length for s in full)
    assert {(hmin_full, f) for f in (0.95, 0.6, 0.4)} <= keys and hmin_full <= hmin
    assert len(keys) == len(full)                              # no run twice
    # the budget cuts the sweep: a tiny budget keeps only the coarsest length
    assert [s.element_length for s in dyn.dynamic_settings(sc, "quick", (20.0, 10.0))
            if s.factor == f0] == [20.0, 10.0]
    assert "--full" not in settings.FAST_SWEEP and dyn.FULL_DYNAMICS in settings.FULL_ADDS


def test_a_real_tiny_dynamic_sweep(tmp_path):
    """The study with three dynamic runs on the surface line (20 and 10 m; ~2 s): the
    reference is the finest length at the smallest factor, the report has its section,
    dynamics.csv its rows, and the nodes that leave the water are counted."""
    S = settings.Setting
    st = cost.study(hanging_surface_line(), repeats=1, progress=False,
                    settings=[S("bvp", "tolerance", 1e-6, {"tolerance": 1e-6})],
                    dynamics=[(20.0, 0.8), (10.0, 0.8), (10.0, 0.4)])
    ds = st.dynamics
    assert all(r.converged for r in ds.runs), [r.message for r in ds.runs]
    assert ds.ref_run.setting == dyn.DynSetting(10.0, 0.4)
    assert ds.surface == {"below": 0.0}
    for r in ds.runs:
        assert r.amplitude > 0 and r.peak_moment > 0 and r.nodes_above_surface is not None
        assert r.steps == pytest.approx(dyn.DURATION / r.time_step, rel=1e-6)
    assert ds.runs[0].errors["amplitude"] == pytest.approx(
        abs(ds.runs[0].amplitude - ds.ref_run.amplitude) / ds.ref_run.amplitude)
    # half the factor, twice the steps
    assert ds.runs[2].steps == pytest.approx(2 * ds.runs[1].steps, rel=0.01)
    cost.write(st, tmp_path)
    df = pd.read_csv(tmp_path / "dynamics.csv")
    assert len(df) == 3 and df["reference"].tolist() == [False, False, True]
    text = (tmp_path / "report.md").read_text()
    assert "## Dynamics: accuracy and cost against element length and time-step factor" in text
    assert "### Recommendation (dynamics)" in text and "(dynamics_error.png)" in text
    assert (tmp_path / "dynamics_error.png").exists()


def test_failed_finest_run_at_the_scene_factor_falls_back_to_the_next_length():
    """When the finest length's run at the scene's factor failed (e.g. a blow-up), the
    reference's step uncertainty is its change from the next-larger factor that completed
    there, else the factor change at the next-coarser length."""
    runs = [r for r in smooth_runs(b=5e-4) if not (r.h == 1.0 and r.factor == 0.8)]
    ref = _study(runs).reference["amplitude"]
    q = {r.factor: r.amplitude for r in runs if r.h == 1.0}
    assert ref["kind"] == "finest" and (ref["step_at"], ref["step_factor"]) == (1.0, 0.95)
    assert ref["step_change"] == pytest.approx(abs(q[0.95] - q[0.4]) / q[0.4], rel=1e-9)
    runs = [r for r in runs if not (r.h == 1.0 and r.factor == 0.95)]
    ref = _study(runs).reference["amplitude"]
    assert ref["step_at"] == 2.0
    q = {r.factor: r.amplitude for r in runs if r.h == 2.0}
    assert ref["step_change"] == pytest.approx(abs(q[0.8] - q[0.4]) / ref["value"], rel=1e-9)


def test_a_node_in_air_loses_its_added_mass_and_part_of_its_stable_step():
    """The top free node's bending limit without added mass, over the limit with it, is
    sqrt(m / (m + m_a)): the dynamics takes its step without the added mass when the heave
    can bring nodes out of the water (Yu's flexible pipe: 0.75, so factor 0.8 blew up at
    0.25 m before), and with it when the line stays deep."""
    from riser.model.scene import Dynamics, TopMotion
    from vfife.dynamics.run import run_dynamics
    from vfife.mesh import build_mesh
    sc = hanging_surface_line()
    static = vfife.solve(sc, element_length=2.0)
    assert static.converged, static.message
    mesh = build_mesh(sc, 2.0)
    m, ma = mesh.lump(mesh.mass_pl)[-2], mesh.lump(mesh.added_pl)[-2]
    heave = Dynamics(duration=0.05, output_interval=0.05,      # the ramp within the run
                     top_motion=TopMotion(axis="y", amplitude=1.5, period=10.0,
                                          ramp_time=0.05))
    bending = {}
    for depth in (150.0, 1000.0):          # the top at the surface / 850 m below it
        s = sc.replace(water_depth=depth, dynamics=heave)
        _, info = run_dynamics(s, static.solver_state, True)
        bending[depth] = info["critical_steps"]["bending"]
    # one line type: the lumped m and m_a are in the same ratio at every node
    assert bending[150.0] / bending[1000.0] == pytest.approx(math.sqrt(m / (m + ma)),
                                                             rel=1e-12)