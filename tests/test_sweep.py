"""``riser-verify sweep``: the sweep file, the cases, the run with resume, the tables and
report, and the engine they run on (verification/sweeps/, verification/runtime/engine.py,
verification/cli/sweep.py).

Every number is checked against a source the sweep does not compute itself: the sweep
file parsed with ``tomllib`` (the file contract), an independent solve of each case's
scene through ``verification.pipeline.solve_scene`` (what ``riser-verify solve`` runs),
the compare protocol (``verification.comparison.static.agreement.agreement``) on those profiles, the
profiles interpolated at the envelope's stations, and a physical ordering (a vessel
farther from the anchor pulls the catenary tighter: higher hang-off tension).

Speed: one real sweep of the built-in ``scr-steel`` (2000 m steel catenary in 1000 m of
water, each method < 1 s) with 2 hang-off offsets, run once for the module
(:func:`swept`); the resume tests rerun copies of its folder (0 or 1 case each); one more
2-case sweep makes a case fail, one reruns the module's sweep with ``--jobs 2``; the
bad-input tests only validate. About 20 s on 2 cores with Numba's cache warm.
"""

from __future__ import annotations

import contextlib
import csv
import io
import json
import math
import os
import re
import shutil
import tomllib
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from riser.errors import SceneError
from riser.io.scene_file import load_scene
from riser.results.profile import summarize
from verification import cli
from verification.sweeps.file import SWEEP_DIR, load_sweep

#: the two vessel offsets of the module's sweep. At 1480 m the methods agree within the
#: protocol; at 1520 m its moment row was measured at 1.18 x its tolerance (the same in
#: `riser-verify compare` of that case's scene.toml): one pass and one FAIL, so both
#: branches of the agreement column are exercised. The tests never hard-code which is
#: which: they recompute the protocol on independent solves.
OFFSETS = ([1480.0, 1000.0], [1520.0, 1000.0])
#: the columns of cases.csv in the documented order (docs/sweeps.md, the docstring of
#: verification/sweeps/report.py): case, method, one column per vary key, ...
SUMMARY_COLUMNS = ["hang_off_tension", "hang_off_angle_deg", "max_tension", "max_tension_s",
                   "min_tension", "max_moment", "max_moment_s", "max_shear", "tdp_x",
                   "tdp_tension", "span", "length"]
#: the 3D figures after them (empty for a planar case)
LATERAL_COLUMNS = ["max_lateral_offset", "max_lateral_offset_s"]
AGREEMENT_ROWS = ["configuration", "tension", "moment", "hang_off_tension", "max_moment"]


def sweep_text(values=OFFSETS, key="ends.hang_off", methods=("bvp", "vfife"),
               base="scr-steel", extra="") -> str:
    return (f"base = {json.dumps(base)}\nmethods = {json.dumps(list(methods))}\n{extra}"
            f"[[vary]]\nkey = {json.dumps(key)}\nvalues = {json.dumps(list(values))}\n")


def write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


def main(argv) -> tuple[int, str, str]:
    """``riser-verify ARGV`` in this process: (exit code, stdout, stderr). Usable in a
    module-scoped fixture, where capsys is not."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main([str(a) for a in argv])
    return code, out.getvalue(), err.getvalue()


def read_csv(path: Path) -> tuple[list[str], list[dict]]:
    """Header and rows as text: values compared as written (Python's float() of a
    repr-written float is exact, so numbers are parsed where needed, never via pandas)."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        return list(reader.fieldnames), list(reader)


def num(text: str) -> float | None:
    return None if text == "" else float(text)


def without(rows: list[dict], *columns: str) -> list[dict]:
    return [{k: v for k, v in r.items() if k not in columns} for r in rows]


def case_json(out: Path, index: int) -> Path:
    return out / "cases" / f"{index:04d}" / "case.json"


# --------------------------------------------------------------------------- fixtures
@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    """One real sweep of scr-steel over OFFSETS, both methods, ``--jobs 1`` (~3 s)."""
    folder = tmp_path_factory.mktemp("sweep")
    f = write(folder / "offsets.toml", sweep_text())
    out = folder / "out"
    code, stdout, stderr = main(["sweep", f, "--out", out, "--jobs", "1"])
    header, rows = read_csv(out / "cases.csv")
    return SimpleNamespace(file=f, out=out, code=code, stdout=stdout, stderr=stderr,
                           sweep=load_sweep(f), header=header, rows=rows)


@pytest.fixture(scope="module")
def independent(swept):
    """Each case's scene solved by each method exactly as ``riser-verify solve`` does
    (``pipeline.solve_scene``), outside the sweep: {(case, method): SolveResult}."""
    from verification.pipeline import solve_scene
    out = {}
    for case in swept.sweep.cases:
        for method in ("bvp", "vfife"):
            res = solve_scene(case.scene, method)
            assert res.converged, res.message
            out[case.index, method] = res
    return out


@pytest.fixture
def resumable(swept, tmp_path):
    """A copy of the module sweep's output folder (modification times kept), to rerun
    into without touching the shared one."""
    out = tmp_path / "out"
    shutil.copytree(swept.out, out)
    return out


# ============================================================ 1. sweep file semantics
def test_product_order_first_vary_slowest(tmp_path):
    lengths = [2000.0, 2050.0, 2100.0]
    f = write(tmp_path / "p.toml", sweep_text() + "[[vary]]\nkey = \"segments[0].length\"\n"
              f"values = {json.dumps(lengths)}\n")
    sw = load_sweep(f)
    # the product: 2 x 3 cases; case k takes hang-off k // 3 and length k % 3
    assert len(sw.cases) == len(OFFSETS) * len(lengths)
    for k, case in enumerate(sw.cases):
        assert case.index == k
        assert case.values == {"ends.hang_off": OFFSETS[k // 3],
                               "segments[0].length": lengths[k % 3]}
        # the validated Scene carries them (not only the record of the values)
        assert case.scene.ends.hang_off == tuple(OFFSETS[k // 3])
        assert case.scene.segments[0].length == lengths[k % 3]


def test_zip_on_a_vary_pairs_it_with_the_one_before(tmp_path):
    speeds = [[0.0, 0.5], [0.0, 1.0]]
    lengths = [2000.0, 2050.0, 2100.0]
    f = write(tmp_path / "z.toml", sweep_text(extra=(
        "[set]\n\"environment.current.heights\" = [0.0, 1000.0]\n"
        "\"environment.current.heading_deg\" = 0.0\n"))
        + f"[[vary]]\nkey = \"environment.current.speeds\"\nvalues = {json.dumps(speeds)}\n"
        "zip = true\n"
        f"[[vary]]\nkey = \"segments[0].length\"\nvalues = {json.dumps(lengths)}\n")
    sw = load_sweep(f)
    # hang-off and speeds form one dimension of 2 (paired), times 3 lengths: 6, not 12
    assert len(sw.cases) == 2 * 3
    for k, case in enumerate(sw.cases):
        i, j = divmod(k, 3)
        assert case.scene.ends.hang_off == tuple(OFFSETS[i])
        assert case.scene.current.speeds == tuple(speeds[i])          # paired with i
        assert case.scene.segments[0].length == lengths[j]


def test_top_level_zip_pairs_every_list(tmp_path):
    speeds = [[0.0, 0.5], [0.0, 1.0]]
    lengths = [2000.0, 2050.0]
    f = write(tmp_path / "zz.toml", "zip = true\n" + sweep_text(extra=(
        "[set]\n\"environment.current.heights\" = [0.0, 1000.0]\n"))
        + f"[[vary]]\nkey = \"environment.current.speeds\"\nvalues = {json.dumps(speeds)}\n"
        f"[[vary]]\nkey = \"segments[0].length\"\nvalues = {json.dumps(lengths)}\n")
    sw = load_sweep(f)
    assert len(sw.cases) == 2                    # one dimension: case i takes value i of each
    for i, case in enumerate(sw.cases):
        assert case.scene.ends.hang_off == tuple(OFFSETS[i])
        assert case.scene.current.speeds == tuple(speeds[i])
        assert case.scene.segments[0].length == lengths[i]


@pytest.mark.parametrize("top, item, bad", [
    ("zip = true\n", "", 2),          # top-level zip: vary[2] has 3 values, vary[0] 2
    ("", "zip = true\n", 1),          # zip on vary[1]: pairs it with vary[0]
])
def test_zip_of_unequal_lengths_names_the_vary(tmp_path, top, item, bad):
    lists = {1: [2000.0, 2050.0], 2: [0.01, 0.02]}
    lists[bad] = lists[bad] + [lists[bad][-1] * 1.1]
    f = write(tmp_path / "u.toml", top + sweep_text()
              + f"[[vary]]\nkey = \"segments[0].length\"\nvalues = {json.dumps(lists[1])}\n"
              + item
              + f"[[vary]]\nkey = \"bvp.tolerance\"\nvalues = {json.dumps(lists[2])}\n")
    with pytest.raises(SceneError) as err:
        load_sweep(f)
    assert err.value.key == f"vary[{bad}].values"
    assert "3 values" in err.value.message and "vary[0] has 2" in err.value.message


def test_set_applies_to_every_case_and_keeps_the_rest_of_the_base(tmp_path):
    from verification.catalog import resolve
    base = resolve("scr-steel")
    speeds = [[0.0, 0.0], [0.0, 0.5], [0.0, 1.0]]
    f = write(tmp_path / "s.toml", sweep_text(values=speeds, key="environment.current.speeds",
              extra=("[set]\n\"environment.current.heights\" = [0.0, 1000.0]\n"
                     "\"environment.current.heading_deg\" = 90.0\n"
                     "\"segments[0].length\" = 2050.0\n")))
    sw = load_sweep(f)
    assert len(sw.cases) == 3
    assert sw.fixed == {"environment.current.heights": [0.0, 1000.0],
                        "environment.current.heading_deg": 90.0, "segments[0].length": 2050.0}
    for case, v in zip(sw.cases, speeds):
        s = case.scene
        assert s.current.speeds == tuple(v)
        assert s.current.heights == (0.0, 1000.0) and s.current.heading_deg == 90.0
        assert s.segments[0].length == 2050.0
        # keys neither set nor varied are the base scene's
        assert s.water_depth == base.water_depth == 1000.0
        assert s.ends == base.ends and s.line_types == base.line_types
    # distinct inputs, distinct digests (the resume key)
    assert len({c.digest for c in sw.cases}) == 3


def test_builtin_yu2021_a3_envelope_against_its_file():
    """The example sweep: its lists read with tomllib (the file, not the reader), the
    cases expected from the documented rule (docs/sweeps.md: product, first slowest, zip =
    one dimension)."""
    path = SWEEP_DIR / "yu2021-a3-envelope.toml"
    data = tomllib.loads(path.read_text())
    vary = {v["key"]: v["values"] for v in data["vary"]}
    hang, speeds = vary["ends.hang_off"], vary["environment.current.speeds"]
    buoy = vary["segments[1].buoyancy"]
    assert vary["segments[3].buoyancy"] == vary["segments[5].buoyancy"] == buoy   # zipped
    sw = load_sweep("yu2021-a3-envelope")
    assert sw.builtin and sw.base == "yu2021-a3" and sw.methods == ("bvp", "vfife")
    assert len(sw.cases) == len(hang) * len(speeds) * len(buoy) == 24
    for k, case in enumerate(sw.cases):
        i, rest = divmod(k, len(speeds) * len(buoy))
        j, b = divmod(rest, len(buoy))
        s = case.scene
        assert s.ends.hang_off == tuple(hang[i])
        assert s.current.speeds == tuple(speeds[j])
        assert s.current.heights == tuple(data["set"]["environment.current.heights"])
        assert s.current.heading_deg == data["set"]["environment.current.heading_deg"]
        for seg in (1, 3, 5):
            assert s.segments[seg].buoyancy == buoy[b]
        assert s.dynamics is None                  # a sweep solves statics


def test_set_cannot_bring_dynamics_back(tmp_path):
    f = write(tmp_path / "d.toml", sweep_text(extra="[set]\n\"dynamics.duration\" = 0.5\n"))
    try:
        sw = load_sweep(f)
    except SceneError as exc:                      # refused, as vary refuses it ...
        assert "dynamics" in str(exc)
        return
    assert all(c.scene.dynamics is None for c in sw.cases)   # ... or dropped


def test_set_with_unquoted_dotted_keys_keeps_the_base_environment(tmp_path):
    f = write(tmp_path / "q.toml", sweep_text(
        values=[[0.0, 0.5]], key="environment.current.speeds",
        extra="[set]\nenvironment.current.heights = [0.0, 1000.0]\n"))
    try:
        sw = load_sweep(f)
    except SceneError as exc:
        assert "set" in str(exc)
        return
    s = sw.cases[0].scene
    assert s.current.heights == (0.0, 1000.0)
    assert s.water_depth == 1000.0                 # scr-steel's, untouched by [set]


# ============================================================ 2. bad input, via the CLI
HANG = 'key = "ends.hang_off"\nvalues = [[1480.0, 1000.0]]\n'
BAD = {
    # name: (sweep file text, words the one line must contain)
    "unknown key": ('base = "scr-steel"\n[[vary]]\nkey = "ends.hang_of"\n'
                    'values = [[1480.0, 1000.0]]\n', ["case 0", "ends.hang_of", "unknown key"]),
    "unknown table": ('base = "scr-steel"\n[[vary]]\nkey = "foo.bar"\nvalues = [1.0]\n',
                      ["case 0", "foo", "unknown key"]),
    "index past the end": ('base = "scr-steel"\n[[vary]]\nkey = "segments[9].buoyancy"\n'
                           'values = [1.0]\n', ["vary[0].key", "segments[9]"]),
    "path through a value": ('base = "scr-steel"\n[[vary]]\nkey = "ends.hang_off.x"\n'
                             'values = [1.0]\n', ["vary[0].key", "ends.hang_off"]),
    "string for a number": ('base = "scr-steel"\n[[vary]]\nkey = "environment.water_depth"\n'
                            'values = [1000.0, "deep"]\n',
                            ["case 1", "environment.water_depth", "number"]),
    "scalar hang_off": ('base = "scr-steel"\n[[vary]]\nkey = "ends.hang_off"\n'
                        'values = [[1480.0, 1000.0], 1500.0]\n', ["case 1", "ends.hang_off"]),
    "4-element hang_off": ('base = "scr-steel"\n[[vary]]\nkey = "ends.hang_off"\n'
                           'values = [[1500.0, 1000.0, 0.0, 1.0]]\n',
                           ["case 0", "ends.hang_off", "2 or 3 entries"]),
    "empty values": ('base = "scr-steel"\n[[vary]]\nkey = "ends.hang_off"\nvalues = []\n',
                     ["vary[0].values", "empty"]),
    "missing values": ('base = "scr-steel"\n[[vary]]\nkey = "ends.hang_off"\n',
                       ["vary[0].values", "required"]),
    "unknown method": ('base = "scr-steel"\nmethods = ["fem"]\n[[vary]]\n' + HANG,
                       ["methods", "fem"]),
    "unknown base": ('base = "scr-steal"\n[[vary]]\n' + HANG, ["base", "scr-steal"]),
    "top-level unknown key": ('base = "scr-steel"\ncolour = 1\n[[vary]]\n' + HANG,
                              ["colour", "unknown key"]),
    "bad TOML": ('base = "scr-steel\n[[vary]]\n' + HANG, ["not valid TOML"]),
    "current without heights": ('base = "scr-steel"\n[[vary]]\n'
                                'key = "environment.current.speeds"\nvalues = [[0.0, 0.5]]\n',
                                ["case 0", "environment.current.heights"]),
}


def _refused(run_cli, argv, out: Path) -> str:
    """Exit 2, exactly one line on stderr (``error: ...``), nothing on stdout that claims a
    run, and no output folder: returns the line."""
    code, stdout, stderr = run_cli([str(a) for a in argv])
    assert code == 2, (stdout, stderr)
    lines = stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), stderr
    assert not out.exists(), "a refused sweep created its output folder"
    return lines[0]


@pytest.mark.parametrize("name", list(BAD))
def test_bad_sweep_file_is_one_line_exit_2_and_writes_nothing(run_cli, tmp_path, name):
    text, words = BAD[name]
    f = write(tmp_path / "bad.toml", text)
    out = tmp_path / "out"
    line = _refused(run_cli, ["sweep", f, "--out", out, "--jobs", "1"], out)
    assert str(f) in line                          # names the sweep file ...
    for w in words:                                # ... and the key (and case) at fault
        assert w in line, (w, line)


@pytest.mark.parametrize("options, words", [
    (["--jobs", "0"], ["--jobs", "got 0"]),
    (["--jobs", "2", "--scheduler", "tcp://127.0.0.1:1"], ["--jobs", "--scheduler"]),
])
def test_bad_options_are_one_line_exit_2(run_cli, swept, tmp_path, options, words):
    out = tmp_path / "out"
    line = _refused(run_cli, ["sweep", swept.file, "--out", out, *options], out)
    for w in words:
        assert w in line, (w, line)


def test_a_date_value_is_refused_naming_the_key(run_cli, tmp_path):
    f = write(tmp_path / "date.toml", 'base = "scr-steel"\n[[vary]]\n'
              'key = "environment.water_depth"\nvalues = [1979-05-27]\n')
    out = tmp_path / "out"
    line = _refused(run_cli, ["sweep", f, "--out", out, "--jobs", "1"], out)
    assert "case 0" in line and "environment.water_depth" in line


def test_a_refused_sweep_leaves_no_table_of_an_earlier_run(run_cli, resumable, tmp_path):
    assert (resumable / "cases.csv").exists() and (resumable / "report.md").exists()
    f = write(tmp_path / "bad.toml", BAD["unknown key"][0])
    code, _, _ = run_cli(["sweep", str(f), "--out", str(resumable), "--jobs", "1"])
    assert code == 2
    assert not (resumable / "cases.csv").exists()
    assert not (resumable / "report.md").exists()


# ============================================================ 3. a real run on scr-steel
def test_cases_csv_has_the_documented_columns_and_one_row_per_case_and_method(swept):
    assert swept.header == (["case", "method", "ends.hang_off", "status", "wall_time_s",
                             *SUMMARY_COLUMNS, *LATERAL_COLUMNS, "warnings", "agreement",
                             "agreement_note",
                             "worst_quantity", "worst_ratio",
                             *(f"{q}_rel_diff" for q in AGREEMENT_ROWS), "tdp_x_diff",
                             "message"])
    assert [(r["case"], r["method"]) for r in swept.rows] == [
        ("0", "bvp"), ("0", "vfife"), ("1", "bvp"), ("1", "vfife")]
    for r in swept.rows:
        # the varied value as JSON, as written in the sweep file
        assert json.loads(r["ends.hang_off"]) == OFFSETS[int(r["case"])]
        assert r["status"] == "converged"
        assert float(r["wall_time_s"]) > 0.0


def test_cases_csv_values_are_those_of_an_independent_solve(swept, independent):
    """The sweep solves exactly what ``solve`` solves: the same scene through the same
    deterministic code (BVP collocation, VFIFE relaxation with a fixed step sequence) in
    the same kind of process, so the numbers are the same to the last bits; rel 1e-12
    leaves room for nothing but a repr round trip (itself exact)."""
    for r in swept.rows:
        res = independent[int(r["case"]), r["method"]]
        sm = summarize(res.profile)
        assert num(r["hang_off_tension"]) == pytest.approx(sm["hang_off_tension"], rel=1e-12)
        assert num(r["max_moment"]) == pytest.approx(sm["max_moment"], rel=1e-12)
        for k in SUMMARY_COLUMNS:
            assert num(r[k]) == pytest.approx(sm[k], rel=1e-12, abs=1e-9), k
        assert r["message"] == res.message
        assert r["warnings"] == "; ".join(res.warnings)


def test_a_farther_vessel_gives_a_higher_hang_off_tension(swept):
    """Physics, not code: moving the hang-off away from the anchor lifts line off the
    seabed and raises the horizontal tension of the catenary, so the top tension grows
    (here by ~9 %, far above the methods' 1e-4 differences)."""
    for method in ("bvp", "vfife"):
        t = [num(r["hang_off_tension"]) for r in swept.rows if r["method"] == method]
        assert t[1] > 1.05 * t[0]


def test_agreement_columns_follow_the_compare_protocol(swept, independent):
    from verification.comparison.static.agreement import agreement
    for case in swept.sweep.cases:
        b, v = independent[case.index, "bvp"], independent[case.index, "vfife"]
        # reference depth of the protocol: the water depth (verification/quantities.py)
        rows = {r["quantity"]: r for r in agreement(b.profile, v.profile, 1000.0)}
        ratios = {q: abs(r["diff"]) / r["tolerance"] for q, r in rows.items()
                  if r["diff"] is not None}
        worst = max(ratios, key=ratios.get)
        passed = all(r["pass"] for r in rows.values())
        mine = [r for r in swept.rows if int(r["case"]) == case.index]
        assert len(mine) == 2
        assert without(mine, "method", "status", "wall_time_s", "message",
                       *SUMMARY_COLUMNS)[0] == without(
            mine, "method", "status", "wall_time_s", "message", *SUMMARY_COLUMNS)[1]
        r = mine[0]                                  # the same in both methods' rows
        assert r["agreement"] == ("pass" if passed else "FAIL")
        assert r["agreement_note"] == ""
        assert r["worst_quantity"] == worst
        assert num(r["worst_ratio"]) == pytest.approx(ratios[worst], rel=1e-12)
        assert (num(r["worst_ratio"]) <= 1.0) == passed   # every row within its tolerance
        for q in AGREEMENT_ROWS:
            assert num(r[f"{q}_rel_diff"]) == pytest.approx(rows[q]["rel_diff"], rel=1e-12), q
        assert num(r["tdp_x_diff"]) == pytest.approx(rows["tdp_x"]["diff"], rel=1e-12)
        # the case record keeps every row of the protocol
        rec = json.loads(case_json(swept.out, case.index).read_text())
        assert [x["quantity"] for x in rec["agreement"]["rows"]] == list(rows)


def test_exit_code_and_summary_lines(swept):
    failed = {r["case"] for r in swept.rows if r["agreement"] == "FAIL"}
    # no method failed (all converged above): exit 1 exactly when a case disagrees
    assert swept.code == (1 if failed else 0), swept.stdout + swept.stderr
    assert "ran 2 case(s)" in swept.stdout
    assert f"{len(failed)} case(s) where the methods disagree" in swept.stdout
    assert "skipped" not in swept.stdout             # a fresh folder: nothing to resume
    assert swept.stderr == ""


def _envelopes(out: Path) -> dict[str, dict[str, np.ndarray]]:
    header, rows = read_csv(out / "envelopes.csv")
    assert header == ["method", "s", "tension_min", "tension_max", "moment_min",
                      "moment_max", "cases", "tension_max_case", "moment_max_case"]
    env = {}
    for m in ("bvp", "vfife"):
        sub = [r for r in rows if r["method"] == m]
        env[m] = {k: np.array([float(r[k]) for r in sub]) for k in header[1:]}
    return env


def test_envelopes_bound_every_case(swept, independent):
    env = _envelopes(swept.out)
    for m, e in env.items():
        s = e["s"]
        # 0.5 m stations from the bottom end to the top of the 2000 m line
        assert s[0] == 0.0 and s[-1] == pytest.approx(2000.0, abs=1e-9)
        assert np.allclose(np.diff(s), 0.5, rtol=0, atol=1e-9)
        assert np.all(e["cases"] == 2)              # both cases reach every station
        T = np.array([np.interp(s, independent[i, m].profile.s, independent[i, m].profile.tension)
                      for i in (0, 1)])
        M = np.array([np.interp(s, independent[i, m].profile.s, independent[i, m].profile.moment)
                      for i in (0, 1)])
        # the same profiles interpolated the same way: the bounds hold exactly, and are
        # reached (the envelope is the pointwise min/max, not a looser bound); 1e-12
        # relative for the float text round trip (exact, in fact)
        tol_T, tol_M = 1e-12 * np.max(T), 1e-12 * np.max(M)
        assert np.all(e["tension_min"] <= T.min(axis=0) + tol_T)
        assert np.all(T.max(axis=0) <= e["tension_max"] + tol_T)
        assert np.allclose(e["tension_max"], T.max(axis=0), rtol=0, atol=tol_T)
        assert np.allclose(e["tension_min"], T.min(axis=0), rtol=0, atol=tol_T)
        assert np.allclose(e["moment_max"], M.max(axis=0), rtol=0, atol=tol_M)
        assert np.allclose(e["moment_min"], M.min(axis=0), rtol=0, atol=tol_M)
        assert np.array_equal(e["tension_max_case"], np.argmax(T, axis=0))


def test_envelope_peak_is_the_largest_case_tension(swept, independent):
    """max over stations of tension_max = the largest max_tension of cases.csv, within
    interpolation error: linear interpolation between nodes never exceeds the largest
    nodal tension, and a station lies within half a spacing (0.25 m) of any node, where
    the tension differs by at most max|dT/ds| x 0.25 m; summarize's max_tension may add a
    parabolic refinement between nodes, bounded by the same slope times a node spacing."""
    env = _envelopes(swept.out)
    for m, e in env.items():
        largest = max(num(r["max_tension"]) for r in swept.rows if r["method"] == m)
        slope = max(float(np.max(np.abs(np.diff(p.tension) / np.diff(p.s))))
                    for p in (independent[i, m].profile for i in (0, 1)))
        ds = max(float(np.max(np.diff(independent[i, m].profile.s))) for i in (0, 1))
        bound = slope * (0.25 + ds)
        assert abs(float(np.max(e["tension_max"])) - largest) <= bound
        assert bound < 1e-3 * largest                # and the bound itself is tight
        # the case of that peak is the case with the largest hang-off tension (a
        # catenary's tension is largest at its top)
        top = max((r for r in swept.rows if r["method"] == m),
                  key=lambda r: num(r["hang_off_tension"]))
        assert int(e["tension_max_case"][np.argmax(e["tension_max"])]) == int(top["case"])


def test_report_has_its_sections_and_names_the_worst_case(swept):
    text = (swept.out / "report.md").read_text()
    for section in ("## Worst case per quantity", "## Method agreement", "## Failures"):
        assert section in text
    failures = text.split("## Failures", 1)[1].split("\n## ", 1)[0]
    assert "None: every method converged in every case." in failures
    for m in ("bvp", "vfife"):
        top = max((r for r in swept.rows if r["method"] == m),
                  key=lambda r: num(r["hang_off_tension"]))
        kn = num(top["hang_off_tension"]) * 1e-3
        row = re.search(rf"^\| hang-off tension \| {m} \| (\d+) \| ([0-9.]+) kN \|", text, re.M)
        assert row is not None
        assert int(row.group(1)) == int(top["case"])
        assert float(row.group(2)) == pytest.approx(kn, rel=1e-5)   # printed to 6 digits
    # a disagreement is listed with its quantity, a passing case is not
    disagree = text.split("### Disagreements", 1)[1].split("\n## ", 1)[0]
    for r in swept.rows[::2]:
        listed = re.search(rf"^\| {r['case']} \| ", disagree, re.M) is not None
        assert listed == (r["agreement"] == "FAIL")


def test_each_case_folder_reruns_alone(swept):
    """cases/NNNN/scene.toml is the case as a scene file (docs/sweeps.md: `compare` reruns
    it)."""
    for case in swept.sweep.cases:
        folder = swept.out / "cases" / f"{case.index:04d}"
        again = load_scene(folder / "scene.toml")
        assert again.ends == case.scene.ends
        assert again.segments == case.scene.segments
        assert again.line_types == case.scene.line_types
        for m in ("bvp", "vfife"):
            assert (folder / m / "summary.json").exists()
            assert (folder / m / "profile.csv").exists()


# ============================================================ 4. resume
def test_a_rerun_skips_every_finished_case(resumable, swept):
    before = {i: case_json(resumable, i).stat().st_mtime_ns for i in (0, 1)}
    code, stdout, _ = main(["sweep", swept.file, "--out", resumable, "--jobs", "1"])
    assert code == swept.code
    assert "ran 0 case(s)" in stdout and "2 skipped" in stdout
    # no case was rewritten
    assert {i: case_json(resumable, i).stat().st_mtime_ns for i in (0, 1)} == before
    header, rows = read_csv(resumable / "cases.csv")
    assert header == swept.header
    # the records are read back from the case folders: the same table (wall_time_s too,
    # read back from case.json, but the contract only promises the results)
    assert without(rows, "wall_time_s") == without(swept.rows, "wall_time_s")


def test_a_changed_value_reruns_only_its_case(resumable, swept, tmp_path):
    changed = [OFFSETS[0], [1510.0, 1000.0]]
    f = write(tmp_path / "offsets.toml", sweep_text(values=changed))
    before = {i: case_json(resumable, i).stat().st_mtime_ns for i in (0, 1)}
    code, stdout, _ = main(["sweep", f, "--out", resumable, "--jobs", "1"])
    assert code in (0, 1)
    assert "ran 1 case(s)" in stdout and "1 skipped" in stdout
    assert case_json(resumable, 0).stat().st_mtime_ns == before[0]      # kept
    assert case_json(resumable, 1).stat().st_mtime_ns != before[1]      # solved again
    rec = json.loads(case_json(resumable, 1).read_text())
    assert rec["digest"] == load_sweep(f).cases[1].digest
    _, rows = read_csv(resumable / "cases.csv")
    assert without(rows[:2], "wall_time_s") == without(swept.rows[:2], "wall_time_s")
    assert [json.loads(r["ends.hang_off"]) for r in rows[2:]] == [changed[1]] * 2
    # and it is a new solution: a nearer vessel, a lower top tension than at 1520 m
    assert num(rows[2]["hang_off_tension"]) < num(swept.rows[2]["hang_off_tension"])


def test_a_case_that_ended_in_an_error_runs_again(resumable, swept):
    path = case_json(resumable, 1)
    rec = json.loads(path.read_text())
    rec["error"] = "RuntimeError: injected (a worker lost)"
    path.write_text(json.dumps(rec))
    code, stdout, _ = main(["sweep", swept.file, "--out", resumable, "--jobs", "1"])
    assert code == swept.code
    assert "ran 1 case(s)" in stdout and "1 skipped" in stdout
    assert "error" not in json.loads(path.read_text())
    _, rows = read_csv(resumable / "cases.csv")
    assert without(rows, "wall_time_s") == without(swept.rows, "wall_time_s")


# ============================================================ 5. failures
def test_a_failing_case_never_stops_the_others(run_cli, tmp_path):
    """[vfife] max_steps = 100: the relaxation needs ~6e4 steps from its catenary start
    on this scene (its message at the default says so), so it stops at the limit,
    not_converged, at solve time; the BVP ignores [vfife] settings. Newton's finish off
    (it finishes even an unconverged coarse start: vfife/statics/newton.py)."""
    f = write(tmp_path / "f.toml", sweep_text(
        values=[5_000_000, 100], key="vfife.max_steps",
        extra="[set]\n\"vfife.expert.static_newton\" = false\n"))
    out = tmp_path / "out"
    code, stdout, stderr = run_cli(["sweep", str(f), "--out", str(out), "--jobs", "1"])
    assert code == 1, stdout + stderr                # a method failed: exit 1
    _, rows = read_csv(out / "cases.csv")
    status = {(int(r["case"]), r["method"]): r for r in rows}
    assert status[0, "bvp"]["status"] == status[0, "vfife"]["status"] == "converged"
    assert status[1, "bvp"]["status"] == "converged"
    bad = status[1, "vfife"]
    assert bad["status"] == "not_converged"
    assert "100 steps" in bad["message"] and "max_steps" in bad["message"]
    assert bad["hang_off_tension"] == ""             # no numbers for a failed solve
    # the BVP of both cases is the same solve (max_steps is a VFIFE setting)
    assert status[1, "bvp"]["hang_off_tension"] == status[0, "bvp"]["hang_off_tension"]
    # the agreement of the failed case is not assessed, and says why
    assert bad["agreement"] == "" and "did not converge" in bad["agreement_note"]
    text = (out / "report.md").read_text()
    failures = text.split("## Failures", 1)[1].split("\n## ", 1)[0]
    assert re.search(r"^\| 1 \| vfife \| not_converged \| .*max_steps", failures, re.M)
    assert "| 0 |" not in failures
    # the envelope of the VFIFE holds the one case that converged
    env = _envelopes(out)
    assert np.all(env["vfife"]["cases"] == 1) and np.all(env["bvp"]["cases"] == 2)


@pytest.mark.parametrize("scene", [{"segments": "nonsense"}, None, {}])
def test_run_case_never_raises(scene):
    from verification.sweeps.case import run_case
    rec = run_case({"index": 7, "digest": "abc", "scene": scene, "methods": ["bvp", "vfife"]})
    assert rec["index"] == 7 and rec["digest"] == "abc"
    assert rec["error"]                                  # the reason, named
    for m in ("bvp", "vfife"):
        assert rec["methods"][m]["status"] == "error"
        assert rec["methods"][m]["message"] == rec["error"]
    json.dumps(rec)                                      # a plain record, as a worker returns


# ============================================================ 6. --jobs 2
def test_two_local_workers_give_the_same_table(swept, tmp_path):
    out = tmp_path / "out"
    code, stdout, _ = main(["sweep", swept.file, "--out", out, "--jobs", "2"])
    assert code == swept.code
    assert "2 local worker processes" in stdout
    header, rows = read_csv(out / "cases.csv")
    assert header == swept.header
    # same inputs through the same deterministic code in another process (one BLAS
    # thread there; the BVP's sparse LU and the VFIFE's kernels do not thread): the same
    # text, value for value, except one known rounding-level difference: this process may
    # run kernels Numba compiled afresh (a cold cache at the session's start) while the
    # workers load them from the cache, and the two give VFIFE results ~3e-9 apart
    # (measured: 15958.3726293 against 15958.3725783 N m). Numbers within 1e-7 relative
    # (of the value, or of 1 for the differences near 0) are taken as equal; the
    # tolerances they are judged by are 1e-4 and more. Text columns must be identical.
    a, b = without(rows, "wall_time_s"), without(swept.rows, "wall_time_s")
    assert len(a) == len(b)
    for ra, rb in zip(a, b):
        assert ra.keys() == rb.keys()
        for k in ra:
            try:
                x, y = float(ra[k]), float(rb[k])
            except ValueError:                         # text; the solver's message
                digits = re.compile(r"\d[\d.e+-]*")      # may quote a step count
                assert digits.sub("#", ra[k]) == digits.sub("#", rb[k]), k
                continue
            if k.endswith("_diff") or k == "worst_ratio":
                # a difference of two values each moved by ~3e-9 of itself moves by
                # ~3e-9 x value: ~1e-6 of a tolerance that is 0.5 % of the value
                assert x == pytest.approx(y, rel=1e-5, abs=1e-5), k
            elif k.endswith("_s"):
                # where a peak is: at a flat maximum a tiny change of the values moves
                # the vertex much more (measured 7e-5 m); 1 mm is 0.5 % of the 0.2 m the
                # protocol allows between the methods' peak locations
                assert x == pytest.approx(y, abs=1e-3), k
            else:
                assert x == pytest.approx(y, rel=1e-7, abs=1e-7), k
    # and the cases did run elsewhere: the records name the worker process
    pids = {json.loads(case_json(out, i).read_text())["worker"].rsplit(":", 1)[1]
            for i in (0, 1)}
    assert str(os.getpid()) not in pids
    mine = {json.loads(case_json(swept.out, i).read_text())["worker"].rsplit(":", 1)[1]
            for i in (0, 1)}
    assert mine == {str(os.getpid())}                    # --jobs 1: in this process


# ============================================================ 7. the engine
@pytest.mark.parametrize("jobs", [1, 2])
def test_engine_yields_every_unit_and_the_exception_of_one_that_raised(jobs):
    from verification.runtime.engine import Engine
    args = [(4.0,), (-1.0,), (9.0,), (2.25,)]
    with Engine(jobs=jobs) as engine:
        got = list(engine.map(math.sqrt, args))
    assert sorted(i for i, _ in got) == [0, 1, 2, 3]    # each unit once
    res = dict(got)
    assert isinstance(res[1], ValueError)               # sqrt(-1): math domain error
    assert (res[0], res[2], res[3]) == (2.0, 3.0, 1.5)  # exact squares: exact roots
