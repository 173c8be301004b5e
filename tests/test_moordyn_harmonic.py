"""MoorDyn as a dynamic third opinion (verification/peers/moordyn/harmonic.py): the
built-in steel catenary riser (2000 m in 1000 m of water) heaved at its hang-off by 0.5 m
at 12 s, MoorDyn at 10 m segments against the VFIFE at its own mesh (1 m), first
harmonics over the four periods after the one-period ramp.

Needs the optional package ``moordyn`` (``pip install -e '.[moordyn]'``); skipped with
that reason without it. About 15 s: MoorDyn's statics ~4 s and 60 s of motion ~2 s, the
VFIFE ~6 s.
"""

from __future__ import annotations

import numpy as np
import pytest

moordyn = pytest.importorskip("moordyn", reason="the optional extra [moordyn] is not installed")

from riser.physics.dynamics import Dynamics, TopMotion  # noqa: E402
from riser.errors import SceneError  # noqa: E402
from verification.catalog import resolve  # noqa: E402
from verification.comparison.harmonics import fit  # noqa: E402
from verification.peers.moordyn.harmonic import first_harmonics, run_harmonic  # noqa: E402
from verification.pipeline import solve_scene  # noqa: E402

PERIOD = 12.0        # s
AMPLITUDE = 0.5      # m, heave (scene axis y)


@pytest.fixture(scope="module")
def heave(tmp_path_factory):
    """(scene, MoorDyn run, VFIFE result): 4 periods after a one-period ramp, outputs
    every period / 40 (the VFIFE's states too, for the tension along s)."""
    scene = resolve("scr-steel").replace(dynamics=Dynamics(
        duration=5 * PERIOD, output_interval=PERIOD / 40, save_states=True,
        top_motion=TopMotion(axis="y", amplitude=AMPLITUDE, period=PERIOD)))
    folder = tmp_path_factory.mktemp("moordyn")
    run = run_harmonic(scene, folder, segment_length=10.0)
    assert (folder / "moordyn.log").exists() and (folder / "deck.dat").exists()
    return scene, run, solve_scene(scene, "vfife")


def test_run_samples_and_moves_the_hang_off_along_scene_y(heave):
    """The samples: every period / 40 from 0 to the duration; s from the bottom end at
    the 10 m nodes; the hang-off node (scene coordinates) moves by the prescribed d(t)
    along y only (the deck's MoorDyn Z), exactly at the samples."""
    _, run, _ = heave
    assert run["stable"], run["message"]
    k = 5 * 40 + 1
    assert run["t"].shape == (k,) and run["t"][-1] == pytest.approx(5 * PERIOD)
    np.testing.assert_allclose(np.diff(run["t"]), PERIOD / 40, rtol=1e-9)
    assert run["s"][0] == 0.0 and run["s"][-1] == pytest.approx(2000.0) and len(run["s"]) == 201
    assert run["tension"].shape == (k, 201) and run["position"].shape == (k, 201, 3)
    np.testing.assert_array_equal(run["hang_off_tension"], run["tension"][:, -1])
    top = run["position"][:, -1, :] - np.array([1500.0, 1000.0, 0.0])
    np.testing.assert_allclose(top[:, 1], run["hang_off_displacement"], atol=1e-9)
    np.testing.assert_allclose(top[:, [0, 2]], 0.0, atol=1e-9)
    assert abs(top[:, 1]).max() == pytest.approx(AMPLITUDE, rel=1e-3)
    assert run["statistics_from"] == pytest.approx(PERIOD)       # the end of the ramp
    assert run["time_step"] > 0 and run["wall_s"] > 0
    # the static start: MoorDyn's force residual within 1 % of a node's weight, no node
    # sunk into the seabed by more than 1 cm (w / k = 5 mm)
    assert run["static_force_residual"] <= 0.01
    assert (run["position"][0, :, 1] >= -0.01).all()


def test_first_harmonic_of_hang_off_tension_against_the_vfife(heave):
    """MoorDyn's first-harmonic hang-off tension against the VFIFE's.

    Measured (MoorDyn 2.7.2, 10 m segments; VFIFE 1 m): amplitude 23,391 N against
    23,537 N (-0.62 %), phase 69.87 against 70.01 deg, mean 842,258 against 842,208 N.
    MoorDyn's hang_off_tension is the end-node force (its FairTen output), which leaves
    out the end node's inertia (h/2 of line accelerated with the hang-off: ~50 N here);
    with it (``hang_off_force``) 23,443 N (-0.40 %). The rest is the sea surface (the
    hang-off sits at it and rises 0.5 m out of it: with the surface 10 m higher the
    support force meets the VFIFE's to 0.06 %) and MoorDyn's lumped 10 m segments
    (the end-node force at 5 m: 23,429 N). Tolerances about twice the measured
    differences: 1.25 % on the amplitude, 0.8 % on the support force, 0.3 deg on the
    phase, 0.012 % on the mean (measured 0.006 %).
    """
    scene, run, vf = heave
    assert run["stable"], run["message"]
    assert vf.converged, vf.message
    md = first_harmonics(run, PERIOD)
    ts = vf.dynamics.timeseries
    ref = fit(ts["time"], ts["hang_off_tension"], PERIOD, scene.dynamics.statistics_from)
    assert md["periods"] == ref.periods == 4
    assert md["hang_off_tension_amplitude"] == pytest.approx(float(ref.amplitude), rel=0.0125)
    assert abs(md["hang_off_tension_phase_deg"] - np.degrees(float(ref.phase))) < 0.3
    assert md["hang_off_tension_mean"] == pytest.approx(float(ref.mean), rel=1.2e-4)
    assert md["hang_off_force_amplitude"] == pytest.approx(float(ref.amplitude), rel=0.008)


def test_tension_along_s_against_the_vfife(heave):
    """The first harmonic of the tension along s at MoorDyn's interior nodes (the mean of
    its two segments' tensions) against the VFIFE's nodal tension (its states)
    interpolated there; the end nodes are the end-node forces, checked above.

    Measured: amplitude within 0.146 % of the largest amplitude (the worst at s = 1990 m,
    where the sea surface differs; 0.05-0.08 % elsewhere), phase within 0.14 deg, mean
    within 0.006 % of the largest tension. Tolerances twice that: 0.3 %, 0.3 deg, 0.012 %.
    """
    scene, run, vf = heave
    md = first_harmonics(run, PERIOD)
    st = vf.dynamics.states
    ref = fit(st["t"], np.asarray(st["tension"]).T, PERIOD, scene.dynamics.statistics_from)
    s = run["s"][1:-1]
    amp = np.interp(s, st["s"], ref.amplitude)
    phase = np.degrees(np.interp(s, st["s"], np.unwrap(ref.phase)))
    mean = np.interp(s, st["s"], ref.mean)
    md_phase = np.degrees(np.angle(fit(run["t"], run["tension"][:, 1:-1].T, PERIOD,
                                       run["statistics_from"]).first))
    assert np.max(np.abs(md["tension_amplitude"][1:-1] - amp)) < 3e-3 * np.max(amp)
    assert np.max(np.abs(md_phase - phase)) < 0.3
    assert np.max(np.abs(md["tension_mean"][1:-1] - mean)) < 1.2e-4 * np.max(mean)


def _short(axis: str):
    """scr-steel moved along ``axis`` for 6 s (a 3 s ramp), for the checks below."""
    return resolve("scr-steel").replace(dynamics=Dynamics(duration=6.0, top_motion=TopMotion(
        axis=axis, amplitude=0.5, period=12.0, ramp_time=3.0)))


@pytest.mark.parametrize("axis", ["x", "z"])
def test_surge_and_sway_move_the_hang_off_along_their_scene_axis(axis, tmp_path):
    """The deck's MoorDyn (X, Y, Z) = (x, -z, y - depth): a motion along scene x or z
    moves the hang-off node along that scene axis only, by +d(t) (20 m segments, 6 s)."""
    run = run_harmonic(_short(axis), tmp_path, segment_length=20.0)
    assert run["stable"], run["message"]
    k = "xyz".index(axis)
    top = run["position"][:, -1, :] - np.array([1500.0, 1000.0, 0.0])
    assert run["hang_off_displacement"].max() > 0.4
    np.testing.assert_allclose(top[:, k], run["hang_off_displacement"], atol=1e-9)
    np.testing.assert_allclose(np.delete(top, k, axis=1), 0.0, atol=1e-9)


def test_moordyn_error_is_unstable_with_the_samples_so_far(tmp_path, monkeypatch):
    """MoorDyn raising RuntimeError mid-run: 'stable' False, the message says after which
    time, the samples taken until then kept (here: t = 0 to 0.3 s)."""
    step = moordyn.Step

    def failing(system, x, v, t, dt):
        if t >= 0.45:
            raise RuntimeError("simulated MoorDyn failure")
        return step(system, x, v, t, dt)

    monkeypatch.setattr(moordyn, "Step", failing)
    run = run_harmonic(_short("y"), tmp_path, segment_length=20.0)
    assert not run["stable"] and "after t = 0.3 s" in run["message"]
    assert "simulated MoorDyn failure" in run["message"]
    np.testing.assert_allclose(run["t"], [0.0, 0.3])
    assert run["tension"].shape == (2, 101)


def test_a_time_series_motion_is_refused():
    scene = resolve("scr-steel").replace(dynamics=Dynamics(duration=10.0, top_motion=TopMotion(
        axis="y", times=(0.0, 10.0), displacements=(0.0, 1.0))))
    with pytest.raises(SceneError, match="harmonic top motion"):
        run_harmonic(scene, "unused")
