"""A scatter diagram's fatigue as units of work on an engine (``riser-verify fatigue
SCENE``, ``reproduce design``'s unit ``fatigue``): each cell's frequency domain, and each
realisation of a cell's time domains, is a unit (:func:`run_unit`), run on this process,
local worker processes or a Dask cluster (:class:`~verification.runtime.engine.Engine`),
kept as it finishes and skipped by the next run (:mod:`verification.runtime.units`), then
assembled into the damage per year along the line (:func:`.fatigue.damage_per_year`).

**Units.** ``fd``: one per cell, the BVP static state and the frequency domain's sea
response, its spectral estimates (Dirlik, narrow band) at the VFIFE's stations (they do
not depend on the realisation's phases). ``td``: one per realisation of a cell run in the
time domain, :func:`.fatigue.run_sea_state`'s comparison (the FD about the BVP static
state, the VFIFE's record of one repeat period of the sea), the record estimates (the
VFIFE's rainflow, the FD's linear record of the same realisation) and, on the cells and
realisation chosen, the ANCF's rainflow on exactly the VFIFE's scene.

**Records of a design's length.** ``[design.fatigue] record_length`` [s]: each cell runs
``n = ceil(record_length / repeat period)`` realisations, each one repeat period of the
sea (the components orthogonal over it) after its own ramp and settling, the damage rate
the realisations' damage over their records; realisation ``k`` of a cell has the seed
:func:`cell_seed` of the scene's spectrum seed, the cell's Hs and Tp and ``k``: the cells
each have their own phases, derived from the cell alone (not from the order the cells
are listed, run or finished in), so every engine runs the same seas. Without it, each
cell runs one repeat period with the scene's own seed (every cell the same phases, as
the suite did before). The first half of the realisations (``ceil(n / 2)``) gives the
damage with half the record: the convergence with record length.

**Screening.** With a ``share`` (``fatigue --share``, default :data:`DEFAULT_SHARE`) the
frequency domain runs first on every cell; at the governing stations (the FD's worst in
the touchdown zone and the hang-off) the cells are taken in order of their share of the
FD's damage per year until they carry ``share`` of it, and the union over the stations
runs in the time domain (``share`` None, ``--all``: every cell). The ANCF runs on
``ancf_cells`` of them (the largest FD shares at the touchdown; None: all), on the first
realisation, judged against the VFIFE's same realisation. A cell left to the frequency
domain enters a record estimate's total by its FD damage scaled by that estimate's ratio
to the FD over the cells it ran (:func:`.fatigue.damage_per_year`).

**Files** (``out``): ``cells/NNNN/fd.json`` and ``cells/NNNN/td-K.json`` (K from 1), each
with the digest of its inputs (:func:`unit_digest`: the cell's scene without the scatter
diagram and the verdict's keys, the realisation and its seed, the element length, the
ANCF); the same command again skips the units done (a unit whose inputs changed, or that
failed, runs again). A unit that fails is reported with its reason after the others ran
(:class:`~riser.errors.SolveFailed`: exit 1).
"""

from __future__ import annotations

import math
import os
import socket
import struct
import time
import traceback
from dataclasses import asdict
from pathlib import Path

import numpy as np

from riser.errors import SceneError, SolveFailed, UnsupportedSceneError
from riser.results.result import Status
from verification.comparison.sea.protocol import compare_sea, repeat_period
from verification.methods import method
from verification.pipeline import vfife_equivalent
from verification.runtime.engine import Engine
from verification.runtime.interrupts import reraise_interrupt
from verification.runtime.units import (clear_stale, digest, read_record, run_units,
                                        write_record)

from .fatigue import (ANCF, ESTIMATES, REFERENCE, SECONDS_PER_YEAR, TOUCHDOWN_ZONE,
                      RunFigures, ScatterFatigue, SeaStateFatigue, damage_per_year,
                      estimates_of, fd_utilisation, figures_of, record_rates,
                      require_fatigue, run_ancf, sea_state_scene, spectral_rates)

#: the share of the FD's damage at the governing stations the time domains' cells carry
#: (``fatigue --share``)
DEFAULT_SHARE = 0.90
#: the record estimates: run on a cell's realisations in the time domain
RECORD_ESTIMATES = ("rainflow_vfife", "rainflow_fd")
#: the layout of a unit's record (a change of meaning: a new number, and every unit runs
#: again)
FORMAT = 1
#: relative costs of the units, for the estimate of the time and the schedule (longest
#: first): a cell's FD (static, sea response, spectral estimates) 1, a realisation in the
#: VFIFE (its FD again, the ramp, settling and record) 3, with the ANCF 12 (measured on
#: scr-steel-fatigue at 50 components, 2 m: 32, 85 and ~350 CPU s)
WEIGHTS = {"fd": 1.0, "td": 3.0, "ancf": 12.0}


def cell_seed(base: int, hs: float, tp: float, k: int) -> int:
    """The seed of realisation ``k`` of the cell (``hs`` [m], ``tp`` [s]) of a scene whose
    spectrum's seed is ``base``: NumPy's SeedSequence of the four (the floats by their
    exact bits), 63 bits. The same on every machine and engine, whatever the order of the
    cells."""
    bits = [int.from_bytes(struct.pack("<d", float(x)), "little") for x in (hs, tp)]
    state = np.random.SeedSequence([int(base), *bits, int(k)]).generate_state(1, np.uint64)
    return int(state[0] >> np.uint64(1))


def realisations(scene, cell) -> int:
    """How many realisations of one repeat period the cell runs: ceil(record_length /
    repeat period), 1 without ``[design.fatigue] record_length``."""
    length = scene.design.fatigue.record_length
    if length is None:
        return 1
    return max(1, math.ceil(length / repeat_period(sea_state_scene(scene, cell)) - 1e-9))


def seeds(scene, cell) -> tuple[int, ...]:
    """The seeds of the cell's realisations (:func:`cell_seed`); () without
    ``record_length`` (one realisation, the scene's own seed)."""
    if scene.design.fatigue.record_length is None:
        return ()
    base = scene.waves.spectrum.seed
    return tuple(cell_seed(base, cell.hs, cell.tp, k) for k in range(realisations(scene,
                                                                                 cell)))


def seeded(scene, cell, seed: int | None):
    """The cell's sea-state scene, its spectrum's seed ``seed`` (None: the scene's)."""
    sc = sea_state_scene(scene, cell)
    if seed is None:
        return sc
    return sc.replace(waves=sc.waves.replace(spectrum=sc.waves.spectrum.replace(seed=seed)))


def _neutral(scene):
    """``scene`` without what does not change a unit's numbers: its name, title and
    provenance, the scatter diagram, the record length and the verdict's keys (a unit's
    digest)."""
    d = scene.design
    f = d.fatigue.replace(sea_states=(), record_length=None, design_fatigue_factor=1.0)
    return scene.replace(name="unit", title="", provenance="",
                         design=d.replace(design_life=None, fatigue=f))


def unit_digest(spec: dict) -> str:
    """The digest of a unit's inputs (see the module docstring)."""
    return digest(FORMAT, spec["kind"], repr(_neutral(spec["scene"])),
                  spec.get("realisation"), spec.get("seed"), spec["element_length"],
                  spec.get("ancf", False), spec.get("realisations"))


# ------------------------------------------------------------------ the units
def _plain(x):
    """JSON types of numpy values (floats round-trip exactly)."""
    if isinstance(x, dict):
        return {str(k): _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, np.ndarray):
        return [_plain(v) for v in x.tolist()]
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.floating):
        return float(x)
    return x


def _fd(spec: dict, progress) -> dict:
    """A cell's FD unit: statics, the sea response, the spectral estimates."""
    now = progress or (lambda message, fraction=None: None)
    matched = vfife_equivalent(spec["scene"]).scene
    h = spec["element_length"] or matched.vfife.element_length
    now("bvp: static state")
    static = method("bvp").solve(matched)
    if not static.converged:
        raise SolveFailed("bvp", static.status, f"bvp statics: {static.message}")
    now("frequency domain: the sea's components, drag linearised stochastically")
    t0 = time.perf_counter()
    fd = method("bvp").sea(matched, static=static)
    if fd.status is Status.REFUSED:
        raise UnsupportedSceneError(fd.message)
    if not fd.converged:
        raise SolveFailed("bvp", fd.status, f"frequency domain (sea): {fd.message}")
    from vfife.mesh import build_mesh                # the VFIFE's stations (its mesh)
    s = build_mesh(matched, h).s
    now("frequency domain: spectral fatigue along the line")
    rates = spectral_rates(matched, fd, s)
    return {"s": s, "rates": rates, "tdp_s": static.profile.tdp_s,
            "fd_wall_s": time.perf_counter() - t0, "element_length": h}


def _td(spec: dict, progress) -> dict:
    """A realisation's time-domain unit: the sea comparison (FD and VFIFE), the record
    estimates, the figures of the reports, the ANCF when asked."""
    cmp = compare_sea(spec["scene"], element_length=spec["element_length"],
                      progress=progress)
    s, rates, record = record_rates(cmp)
    fig = figures_of(cmp)
    fig.fd_max_utilisation = fd_utilisation(cmp, record * spec.get("realisations", 1))
    out = {"s": s, "rates": rates, "record_s": record, "tdp_s": cmp.static.profile.tdp_s,
           "figures": asdict(fig)}
    if spec.get("ancf"):
        rate, wall, info = run_ancf(cmp, s, progress)
        out["rates"][ANCF] = rate
        out["ancf_wall_s"], out["ancf_info"] = wall, info
    return out


def run_unit(spec: dict, progress=None) -> dict:
    """Run one unit (``spec``: :func:`plan`'s); never raises but for Ctrl-C: an error
    becomes the record's ``error`` (its kind and one line). Plain arguments and result, so
    that any worker process runs it."""
    t0, c0 = time.perf_counter(), time.process_time()
    rec = {"kind": spec["kind"], "cell": spec["cell"], "realisation": spec.get("realisation"),
           "seed": spec.get("seed"), "digest": spec["digest"],
           "worker": f"{socket.gethostname()}:{os.getpid()}"}
    try:
        rec.update(_fd(spec, progress) if spec["kind"] == "fd" else _td(spec, progress))
    except Exception as exc:                  # the unit fails, not the run
        reraise_interrupt(exc)                # but Ctrl-C in this process (Numba) stops it
        where = traceback.extract_tb(exc.__traceback__)[-1]
        first = (str(exc).strip().splitlines() or ["no reason given"])[0]
        rec["error"] = (f"{type(exc).__name__}: {first} (at {Path(where.filename).name}:"
                        f"{where.lineno})")
        rec["error_kind"] = type(exc).__name__
        rec["message"] = str(exc)
    rec["wall_s"] = time.perf_counter() - t0
    rec["cpu_s"] = time.process_time() - c0      # this process's CPU (one BLAS thread)
    return _plain(rec)


# ------------------------------------------------------------------ plan, store
def _spec(scene, c: int, cell, kind: str, element_length, k=None, seed=None, n=1,
          ancf=False) -> dict:
    spec = {"kind": kind, "cell": c, "hs": cell.hs, "tp": cell.tp,
            "scene": seeded(scene, cell, seed), "element_length": element_length}
    if kind == "td":
        spec.update({"realisation": k, "seed": seed, "realisations": n, "ancf": ancf})
    spec["digest"] = unit_digest(spec)
    return spec


class Store:
    """The units' records: in ``out/cells/NNNN/`` (None: in memory only)."""

    def __init__(self, out):
        self.folder = None if out is None else Path(out) / "cells"
        self.memory: dict = {}

    def path(self, spec) -> Path:
        name = "fd.json" if spec["kind"] == "fd" else f"td-{spec['realisation'] + 1}.json"
        return self.folder / f"{spec['cell']:04d}" / name

    def key(self, spec):
        return spec["cell"], spec["kind"], spec.get("realisation")

    def get(self, spec) -> dict | None:
        rec = self.memory.get(self.key(spec))
        if rec is not None and rec.get("digest") == spec["digest"] and "error" not in rec:
            return rec
        if self.folder is None:
            return None
        rec = read_record(self.path(spec), spec["digest"])
        if rec is not None:
            self.memory[self.key(spec)] = rec
        return rec

    def put(self, spec, rec: dict) -> None:
        self.memory[self.key(spec)] = rec
        if self.folder is not None:
            write_record(self.path(spec), rec)

    def tidy(self, cells: int, realisations: list[int]) -> None:
        """Remove the folders of cells beyond ``cells`` and the realisations beyond each
        cell's count (an earlier, longer run)."""
        if self.folder is None or not self.folder.exists():
            return
        clear_stale(self.folder, cells)
        for c, n in enumerate(realisations):
            for p in (self.folder / f"{c:04d}").glob("td-*.json"):
                k = p.stem[3:]
                if k.isdigit() and int(k) > n:
                    p.unlink()


def _line(spec, rec, cells: int) -> str:
    what = (f"cell {spec['cell'] + 1}/{cells} (Hs {spec['hs']:g} m, Tp {spec['tp']:g} s)")
    if "error" in rec:
        return f"{what} {spec['kind']}: FAILED: {rec['error']}"
    if spec["kind"] == "fd":
        return f"{what} frequency domain: {rec['wall_s']:.1f} s"
    fig = rec["figures"]
    part = (f"realisation {spec['realisation'] + 1}/{spec['realisations']}: "
            if spec["realisations"] > 1 else "")
    ancf = f", ancf {rec['ancf_wall_s']:.0f} s" if "ancf_wall_s" in rec else ""
    return (f"{what} {part}time domain: vfife {fig['vfife_wall_s']:.0f} s{ancf}, "
            f"{rec['wall_s']:.0f} s in all")


def _run(engine, specs, store: Store, progress, cells: int, done_before: int,
         total: int) -> list[dict]:
    """Run the specs not in the store; the failed units' records."""
    todo = [s for s in specs if store.get(s) is None]
    resumed = len(specs) - len(todo)
    todo.sort(key=lambda s: -_weight(s))          # longest first
    failed = []
    earlier = [store.get(s)["wall_s"] / _weight(s) for s in specs if store.get(s) is not None
               and isinstance(store.get(s).get("wall_s"), (int, float))]

    def keep(i, res):
        spec = todo[i]
        if isinstance(res, BaseException):
            res = {"kind": spec["kind"], "cell": spec["cell"], "digest": spec["digest"],
                   "error": f"the worker failed: {type(res).__name__}: {res}",
                   "error_kind": type(res).__name__, "message": str(res), "wall_s": None}
        store.put(spec, res)
        if "error" in res:
            failed.append((spec, res))
        return _line(spec, res, cells), (None if "error" in res else res["wall_s"])

    def written():
        return done_before + sum(1 for s in specs if store.get(s) is not None)

    run_units(engine, run_unit, todo, keep, progress=progress,
              names=[_name(s) for s in todo], noun="unit", each="a unit of weight 1",
              weights=[_weight(s) for s in todo], earlier=earlier, resumed=resumed,
              total=total, written=written, unit_progress=True)
    if failed:
        spec, rec = failed[0]
        status = Status.NOT_CONVERGED
        raise SolveFailed("fatigue", status,
                          f"{len(failed)} of {len(specs)} unit(s) failed; the first: cell "
                          f"{spec['cell'] + 1} (Hs {spec['hs']:g} m, Tp {spec['tp']:g} s) "
                          f"{spec['kind']}: {rec['message'] or rec['error']} (the units "
                          "done are kept; rerun to retry the failed ones)")
    return [store.get(s) for s in specs]


def _weight(spec) -> float:
    if spec["kind"] == "fd":
        return WEIGHTS["fd"]
    return WEIGHTS["ancf"] if spec.get("ancf") else WEIGHTS["td"]


def _name(spec) -> str:
    if spec["kind"] == "fd":
        return f"fatigue-cell-{spec['cell']:04d}-fd"
    return f"fatigue-cell-{spec['cell']:04d}-td-{spec['realisation'] + 1}"


# ------------------------------------------------------------------ screening
def screen(states: list[SeaStateFatigue], share: float | None, ancf_cells: int | None,
           ancf: bool = True) -> dict:
    """Which cells run in the time domain (see the module docstring): at the governing
    stations of the FD's damage per year (Dirlik), ``touchdown`` (its worst in the
    touchdown zone) and ``hang_off``, each cell's share; the cells in order of share
    until ``share`` is reached at each station (every cell with ``share`` None); the ANCF's
    cells among them. Returns ``share``, ``stations`` (name -> s [m]), ``shares`` (name ->
    one share per cell), ``cells`` (the time domains', sorted), ``ancf_cells``."""
    s = states[0].s
    per = [st.probability * np.interp(s, st.s, st.rates[REFERENCE]) for st in states]
    total = sum(per)
    tdp = states[0].tdp_s
    zone = np.flatnonzero((s >= tdp + TOUCHDOWN_ZONE[0]) & (s <= tdp + TOUCHDOWN_ZONE[1]))
    where = {"touchdown": int(zone[np.argmax(total[zone])]), "hang_off": len(s) - 1}
    shares = {name: [float(p[j] / total[j]) if total[j] > 0 else 0.0 for p in per]
              for name, j in where.items()}
    chosen: set[int] = set()
    for name in where:
        if share is None:
            chosen |= set(range(len(states)))
            break
        order = sorted(range(len(states)), key=lambda c: (-shares[name][c], c))
        got = 0.0
        for c in order:
            chosen.add(c)
            got += shares[name][c]
            if got >= share - 1e-12:
                break
    cells = sorted(chosen)
    by_td = sorted(cells, key=lambda c: (-shares["touchdown"][c], c))
    take = len(cells) if ancf_cells is None else min(ancf_cells, len(cells))
    return {"share": share, "stations": {k: float(s[j]) for k, j in where.items()},
            "shares": shares, "cells": cells,
            "ancf_cells": sorted(by_td[:take]) if ancf else []}


# ------------------------------------------------------------------ assembly
def _mean(recs: list[dict], e: str) -> np.ndarray:
    """A record estimate's damage rate over the realisations ``recs``: their damage over
    their records (one realisation: its rate as it is)."""
    if len(recs) == 1:
        return np.asarray(recs[0]["rates"][e], float)
    damage = sum(np.asarray(r["rates"][e], float) * r["record_s"] for r in recs)
    return damage / sum(r["record_s"] for r in recs)


def _figures(recs: list[dict]) -> RunFigures:
    """A cell's figures over its realisations: the first's, the largest utilisation and
    the touchdown's travel over all, the walls summed."""
    figs = [RunFigures(**r["figures"]) for r in recs]
    first = figs[0]
    info = dict(first.info)
    u = [f.info.get("dynamic_max_utilisation") for f in figs]
    if all(x is not None for x in u):
        k = int(np.argmax(u))
        info["dynamic_max_utilisation"] = u[k]
        info["dynamic_max_utilisation_s"] = figs[k].info.get("dynamic_max_utilisation_s")
    lo = [f.info.get("dynamic_min_touchdown_s") for f in figs]
    hi = [f.info.get("dynamic_max_touchdown_s") for f in figs]
    if all(x is not None for x in lo + hi):
        info["dynamic_min_touchdown_s"], info["dynamic_max_touchdown_s"] = min(lo), max(hi)
    fd_u = first.fd_max_utilisation
    return RunFigures(info, first.ramp_s, first.settle_s, first.element_length,
                      sum(f.fd_wall_s for f in figs), sum(f.vfife_wall_s for f in figs),
                      first.fd_hang_off_tension_std,
                      float(np.mean([f.vfife_hang_off_tension_std for f in figs])),
                      None if fd_u is None else tuple(fd_u))


def cell_state(cell, fd: dict, tds: list[dict], seeds_: tuple) -> SeaStateFatigue:
    """A cell's :class:`SeaStateFatigue` from its FD unit's record and its realisations'
    (``tds``, in order; empty: not run in the time domain)."""
    s = np.asarray(tds[0]["s"] if tds else fd["s"], float)
    fd_s = np.asarray(fd["s"], float)
    same = fd_s.shape == s.shape and bool(np.all(fd_s == s))
    spectral = {e: (np.asarray(fd["rates"][e], float) if same else
                    np.interp(s, fd_s, np.asarray(fd["rates"][e], float)))
                for e in ("dirlik_fd", "narrow_band_fd")}
    rates, half, pair = {}, {}, {}
    if tds:
        for e in RECORD_ESTIMATES:
            rates[e] = _mean(tds, e)
    rates.update(spectral)
    ancf_wall, ancf_info = None, {}
    with_ancf = [r for r in tds if ANCF in r["rates"]]
    if with_ancf:
        rates[ANCF] = _mean(with_ancf, ANCF)
        ancf_wall = sum(r["ancf_wall_s"] for r in with_ancf)
        ancf_info = dict(with_ancf[0]["ancf_info"])
        if len(with_ancf) < len(tds):
            pair["rainflow_vfife"] = _mean(with_ancf, "rainflow_vfife")
    if len(tds) > 1:
        h = math.ceil(len(tds) / 2)
        half = {e: _mean(tds[:h], e) for e in RECORD_ESTIMATES}
    record = sum(r["record_s"] for r in tds) if tds else 0.0
    wall = fd["wall_s"] + sum(r["wall_s"] for r in tds)
    return SeaStateFatigue(cell.hs, cell.tp, cell.probability, s, rates, record,
                           _figures(tds) if tds else None, wall, fd["tdp_s"], ancf_wall,
                           ancf_info, tuple(seeds_), half, pair)


def _fd_state(cell, fd: dict) -> SeaStateFatigue:
    return cell_state(cell, fd, [], ())


def run_scatter(scene, element_length: float | None = None, progress=None,
                ancf: bool = True, *, engine: Engine | None = None, out=None,
                share: float | None = None, ancf_cells: int | None = None) -> ScatterFatigue:
    """The scatter diagram's fatigue (the module docstring): ``engine`` (open; default this
    process), ``out`` (the folder of the units' records, resumed; None: kept in memory),
    ``share`` (screening; None: every cell in the time domains), ``ancf`` (the ANCF's
    column at all) on ``ancf_cells`` cells (None: every time-domain cell). ``progress``: a
    :class:`~verification.runtime.progress.Progress`, or None. Raises
    :class:`~verification.runtime.units.Interrupted` on Ctrl-C (the units written kept),
    :class:`SolveFailed` when a unit failed (after the others ran)."""
    require_fatigue(scene)
    engine = engine or Engine(1)
    if ancf_cells == 0:                     # no ANCF at all: nothing waits for the FD
        ancf, ancf_cells = False, None
    cells = scene.design.fatigue.sea_states
    h = element_length
    store = Store(out)
    seed_lists = [seeds(scene, c) for c in cells]
    counts = [max(1, len(x)) for x in seed_lists]
    store.tidy(len(cells), counts)
    t0 = time.perf_counter()
    fd_specs = [_spec(scene, c, cell, "fd", h) for c, cell in enumerate(cells)]

    def td_specs(chosen, with_ancf):
        out_ = []
        for c in chosen:
            sl = seed_lists[c] or (None,)
            for k, sd in enumerate(sl):
                out_.append(_spec(scene, c, cells[c], "td", h, k, sd, len(sl),
                                  ancf=(c in with_ancf and k == 0)))
        return out_

    if share is None and (not ancf or ancf_cells is None):
        # every unit known at once: one batch, longest first (no stage waits for another)
        every = list(range(len(cells)))
        tds = td_specs(every, set(every) if ancf else set())
        recs = _run(engine, fd_specs + tds, store, progress, len(cells), 0,
                    len(fd_specs) + len(tds))
        fds, td_recs = recs[:len(fd_specs)], recs[len(fd_specs):]
        fd_states = [_fd_state(cell, r) for cell, r in zip(cells, fds)]
        _require_touchdown(scene, fd_states)
        scr = screen(fd_states, None, None, ancf)
    else:                                   # the FD first, then the cells it chose
        fds = _run(engine, fd_specs, store, progress, len(cells), 0, len(fd_specs))
        fd_states = [_fd_state(cell, r) for cell, r in zip(cells, fds)]
        _require_touchdown(scene, fd_states)
        scr = screen(fd_states, share, ancf_cells, ancf)
        if progress is not None:
            progress.log(screen_line(scr, len(cells)))
        tds = td_specs(scr["cells"], set(scr["ancf_cells"]))
        td_recs = _run(engine, tds, store, progress, len(cells), len(fd_specs),
                       len(fd_specs) + len(tds))
    by_cell: dict[int, list] = {}
    for spec, rec in zip(tds, td_recs):
        by_cell.setdefault(spec["cell"], []).append(rec)
    states = [cell_state(cell, fds[c], by_cell.get(c, []), seed_lists[c])
              for c, cell in enumerate(cells)]
    first = next(st for st in states if st.comparison is not None)
    s = first.s
    present = [e for e in (*ESTIMATES, ANCF) if any(e in st.rates for st in states)]
    per_year, formed = damage_per_year(states, s, present)
    half = {}
    if any(st.half_rates for st in states):
        half, _ = damage_per_year(states, s, [e for e in present if e in RECORD_ESTIMATES],
                                  half=True)
    res = ScatterFatigue(scene, states, s, per_year, first.comparison.element_length, formed,
                         scr, half)
    res.run = {"engine": engine.describe(), "workers": engine.workers(),
               "units": len(fd_specs) + len(tds), "wall_s": time.perf_counter() - t0,
               "record_length": scene.design.fatigue.record_length,
               "realisations": counts}
    return res


def _require_touchdown(scene, states) -> None:
    if states[0].tdp_s is None:
        raise UnsupportedSceneError(f"{scene.source}: the static line does not touch the "
                                    "seabed: the fatigue by two methods reports the "
                                    "touchdown zone and the hang-off")


def screen_line(scr: dict, cells: int) -> str:
    """The console line of the screening's choice."""
    st = scr["stations"]
    if scr["share"] is None:
        return (f"every cell in the time domains ({cells}; the ANCF on "
                f"{len(scr['ancf_cells'])})")
    return (f"screening: {len(scr['cells'])} of {cells} cell(s) carry "
            f"{100 * scr['share']:.0f} % of the frequency domain's damage at the touchdown "
            f"(s = {st['touchdown']:.1f} m) and the hang-off (s = {st['hang_off']:.1f} m): "
            f"the time domains run on them (the ANCF on {len(scr['ancf_cells'])})")


def estimates_run(result: ScatterFatigue) -> dict:
    """Per estimate the cells (indices) it ran."""
    return {e: [k for k, st in enumerate(result.states) if e in st.rates]
            for e in estimates_of(result.per_year)}
