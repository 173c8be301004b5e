"""The two dynamic methods in waves (issue 33): the frequency domain about the BVP static
state against the VFIFE's time domain on the Lowe and Langley jumper (built-in scenes
verification/scenes/waves/jumper-*.toml), a regular wave by the first harmonics and an
irregular sea by the standard deviations; negative controls; bad input (one line, exit 2).
"""

from __future__ import annotations

import pytest

from riser.errors import SceneError
from riser.physics.waves import WaveTrain
from verification.catalog import resolve
from verification.comparison.dynamic.protocol import compare_dynamics
from verification.comparison.sea.protocol import compare_sea


def _rows(rows) -> dict:
    return {r["quantity"]: r for r in rows}


@pytest.fixture(scope="module")
def regular():
    return compare_dynamics(resolve("jumper-wave"))


def test_regular_wave_first_harmonics_agree(regular):
    """The issue's bounds at a small wave (H 0.5 m): first-harmonic tension within 1 %
    (the protocol's 0.5 % at the hang-off, 1 % of the peak along s) and the moment
    (curvature x EI) within 2 % of its peak (the protocol judges 1 %). Measured: hang-off
    tension +0.21 %, along s -0.64 %, moment -0.55 %, phase -0.07 deg."""
    r = _rows(regular.results[0].rows)
    assert regular.passed, [q for q in r.values() if q["pass"] is False]
    assert abs(r["hang_off_tension_amplitude"]["rel_diff"]) <= 0.01
    assert abs(r["tension_amplitude"]["rel_diff"]) <= 0.01
    assert abs(r["moment_amplitude"]["rel_diff"]) <= 0.02


def test_a_wave_without_its_inertia_in_one_method_fails(regular):
    """Negative control: the VFIFE's wave with half the height against the FD's full one
    fails the hang-off tension by far (the comparison can fail: ~50 %)."""
    def half(sc):
        tr = sc.waves.trains[0]
        return sc.replace(waves=sc.waves.replace(trains=(tr.replace(height=0.5 * tr.height),)))
    comp = compare_dynamics(resolve("jumper-wave"), static=regular.static,
                            vfife_modifier=half)
    r = _rows(comp.results[0].rows)["hang_off_tension_amplitude"]
    assert r["pass"] is False and abs(r["rel_diff"]) > 0.4


def test_irregular_sea_standard_deviation_agrees():
    """A JONSWAP sea (Hs 2 m, Tp 10 s) of 40 components (a shorter repeat period than the
    built-in's 100: 133 s): the hang-off tension's std within the issue's 5 % over one
    repeat period (measured +1.2 % with 60 components; the drag's stochastic against its
    nonlinear form, the transient and the discretisations)."""
    sc = resolve("jumper-sea")
    sc = sc.replace(waves=sc.waves.replace(spectrum=sc.waves.spectrum.replace(components=40)))
    comp = compare_sea(sc)
    r = _rows(comp.rows)["hang_off_tension_std"]
    assert comp.passed and abs(r["rel_diff"]) <= 0.05, r
    assert comp.record_s == pytest.approx(2 * 3.141592653589793 / comp.fd.d_omega)


@pytest.mark.parametrize("argv, words", [
    (["compare", "jumper-sea", "--dynamics", "--amplitudes", "0.1"], "not with an irregular"),
    (["compare", "jumper-sea", "--dynamics", "--peer", "moordyn"], "--peer"),
])
def test_sea_cli_bad_input_is_one_line_exit_2(run_cli, tmp_path, argv, words):
    code, out, err = run_cli(argv + ["--out", str(tmp_path / "o")])
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and words in lines[0], err


def test_several_trains_are_refused_by_the_harmonic_comparison():
    sc = resolve("jumper-wave")
    two = sc.waves.replace(trains=sc.waves.trains + (WaveTrain(0.5, 8.0),))
    with pytest.raises(SceneError, match="one regular train"):
        compare_dynamics(sc.replace(waves=two))
