"""``riser-verify fatigue`` on every engine (issue 49): the same damage along s, bit for
bit, in this process (``--jobs 1``), on two local workers interrupted and resumed, and on
a local Dask cluster of two workers; the real units (the FD, the VFIFE) on a tiny
scatter diagram: scr-steel-fatigue's line at 20 m elements, 12 wave components, two
cells (``record_length`` 40 s: two realisations of the one at Tp 9 s, whose sea repeats
after 36 s, one at Tp 11 s), every cell in the time domains: five units.

Each run is a fresh ``riser-verify`` process (as a user's), after a first one that fills
Numba's cache: a kernel compiled afresh and the same kernel read from the cache give
VFIFE values ~3e-9 apart (docs/sweeps.md), which a cold cache would show here. The units'
records (``cells/NNNN/*.json``: the damage rates along s in full precision) and the
files of the damage along s must be equal. About 140 s in all (measured on 2 cores, another
run beside it).
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import pytest

from extras import needs_dask

ROOT = Path(__file__).resolve().parents[1]
CODE = "import sys\nfrom verification.cli import main\nsys.exit(main())\n"
pytestmark = pytest.mark.slow


def _scene(folder: Path, cells, record_length=40.0) -> Path:
    from riser.io.toml_text import dumps
    d = tomllib.loads((ROOT / "verification/scenes/design/scr-steel-fatigue.toml").read_text())
    d["name"] = "fatigue-engines"
    d["environment"]["waves"]["spectrum"]["components"] = 12
    d["vfife"] = {"element_length": 20.0}
    d["design"]["fatigue"]["points"] = 8
    if record_length is not None:
        d["design"]["fatigue"]["record_length"] = record_length
    d["design"]["fatigue"]["sea_states"] = [{"hs": h, "tp": t, "probability": p}
                                            for h, t, p in cells]
    path = folder / f"{d['name']}-{len(cells)}.toml"
    path.write_text(dumps(d))
    return path


def _argv(scene: Path, out: Path, *more) -> list[str]:
    return [sys.executable, "-c", CODE, "fatigue", str(scene), "--all", "--ancf-cells", "0",
            "--out", str(out), "-q", *more]


def _run(scene: Path, out: Path, *more) -> subprocess.CompletedProcess:
    p = subprocess.run(_argv(scene, out, *more), cwd=ROOT, capture_output=True, text=True,
                       timeout=300)
    assert p.returncode == 0, p.stderr[-2000:]
    return p


def _records(out: Path) -> dict:
    """The units' damage rates and records, by file."""
    keep = ("s", "rates", "record_s", "tdp_s", "seed", "digest")
    return {str(p.relative_to(out)): {k: v for k, v in json.loads(p.read_text()).items()
                                      if k in keep}
            for p in sorted((out / "cells").rglob("*.json"))}


def _same(a: Path, b: Path) -> None:
    ra, rb = _records(a), _records(b)
    assert list(ra) == list(rb) and len(ra) == 5            # 2 FD + 2 + 1 realisations
    for f in ra:
        assert ra[f] == rb[f], f
    for f in ("fatigue_along_s.csv", "stations.csv"):
        assert (a / f).read_text() == (b / f).read_text(), f


@pytest.fixture(scope="module")
def tiny(tmp_path_factory):
    base = tmp_path_factory.mktemp("fatigue-engines")
    scene = _scene(base, ((2.0, 9.0, 0.7), (4.0, 11.0, 0.3)))
    _run(_scene(base, ((3.0, 10.0, 1.0),), None), base / "prime", "--jobs", "1")   # the cache
    _run(scene, base / "jobs1", "--jobs", "1")
    return scene, base


def test_two_workers_interrupted_and_resumed_give_the_damage_of_one(tiny):
    scene, base = tiny
    out = base / "jobs2"
    p = subprocess.Popen(_argv(scene, out, "--jobs", "2"), cwd=ROOT, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:                                     # Ctrl-C once three units are written
        deadline = time.monotonic() + 240
        while p.poll() is None and time.monotonic() < deadline and \
                len(list(out.glob("cells/*/*.json"))) < 3:
            time.sleep(0.1)
        os.killpg(p.pid, signal.SIGINT)
        _, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
    written = len(list(out.glob("cells/*/*.json")))
    assert p.returncode == 130 and err.strip().splitlines() == [
        f"error: interrupted: {written} of 5 units written to {out}/cells; rerun the same "
        "command to resume"], err
    assert 3 <= written < 5
    again = _run(scene, out, "--jobs", "2")
    assert f"{written} of 5 unit(s) finished by an earlier run: skipped" in again.stdout
    _same(base / "jobs1", out)


@needs_dask
def test_a_dask_cluster_gives_the_damage_of_one_worker(tiny):
    from verification.runtime.dask_local import local_cluster
    scene, base = tiny
    with local_cluster(workers=2) as address:
        p = _run(scene, base / "dask", "--scheduler", address)
    assert "on Dask cluster at" in p.stdout
    _same(base / "jobs1", base / "dask")
