"""One load case of a sweep: solved in a worker, its files written by the process that
submitted it.

:func:`run_case` is what a worker runs (a local process or a Dask worker on another
machine): it touches no file, validates the case's scene from its parsed TOML, solves it
with each method as ``riser-verify solve`` would, and returns a plain record (JSON types
and lists of floats), so that the same code gives the same numbers on any engine and
needs no shared file system. :func:`write_case` stores a record in the case's own folder
(``cases/NNNN/``: ``scene.toml``, ``case.json``, and per method ``METHOD/summary.json``
and, when it converged, ``METHOD/profile.csv`` and ``METHOD/profile.npz``); ``case.json`` is written last, under a temporary name renamed into
place, so that its presence means the case finished (the resume test of
:func:`read_case`). A case that raised an unexpected error records status ``error`` and
is run again by the next sweep; the methods' own statuses (converged, refused,
not_converged, ...) are final.

The method agreement of a case is the protocol of ``riser-verify compare``
(:func:`verification.comparison.static.agreement.agreement`: the same rows, tolerances and bases) on the two
profiles, assessed when both converged on the same continuum model (``SolveResult.model``):
a Wang-form scene's BVP solves its paper model when the VFIFE cannot, and then the
difference is a model difference, not a defect.
"""

from __future__ import annotations

import json
import os
import socket
import time
import traceback
from pathlib import Path

import numpy as np

from riser.errors import SceneError, SolveFailed
from riser.results.profile import OPTIONAL_COLUMNS, Profile, summarize, write_json
from verification.runtime.interrupts import reraise_interrupt

#: the scalar summary quantities kept per method (riser.results.profile.summarize's names)
SUMMARY_KEYS = ("hang_off_tension", "hang_off_angle_deg", "max_tension", "max_tension_s",
                "min_tension", "max_moment", "max_moment_s", "max_shear", "tdp_x",
                "tdp_tension", "span", "length", "max_lateral_offset", "max_lateral_offset_s")
#: the design checks' summary quantities kept per method when the scene makes them
#: ([design]'s utilisation, a line type's bend limit; riser.design.verdicts)
DESIGN_KEYS = ("max_utilisation", "max_utilisation_s", "max_bend_utilisation",
               "max_bend_utilisation_s")
#: the agreement rows copied into cases.csv, besides the worst row: their rel_diff (over
#: the row's basis), and for the touchdown its difference in metres (its tolerance is a
#: length, not a fraction)
AGREEMENT_KEYS = ("configuration", "tension", "moment", "hang_off_tension", "max_moment")
AGREEMENT_DIFF_KEYS = ("tdp_x",)
_FIELDS = ("s", "x", "y", "z", "theta", "tension", "moment", "shear", "curvature")
ERROR = "error"


def _profile_lists(p: Profile) -> dict:
    out = {name: np.asarray(getattr(p, name), float).tolist() for name in _FIELDS}
    out["tdp_s"] = p.tdp_s
    for name in OPTIONAL_COLUMNS:
        v = getattr(p, name)
        out[name] = None if v is None else v.tolist()
    return out


def profile_of(d: dict) -> Profile:
    """The :class:`Profile` of a record's lists (:func:`_profile_lists`)."""
    return Profile(**{name: np.asarray(d[name], float) for name in _FIELDS},
                   tdp_s=d["tdp_s"],
                   **{name: None if d.get(name) is None else np.asarray(d[name], float)
                      for name in OPTIONAL_COLUMNS})


def _solve(scene, method: str) -> tuple[dict, object]:
    from verification.pipeline import solve_scene
    t0 = time.perf_counter()
    try:
        res = solve_scene(scene, method)
    except SceneError as exc:                     # bad input for this method: refused
        return {"status": "refused", "message": str(exc), "warnings": [],
                "wall_time_s": time.perf_counter() - t0}, None
    except SolveFailed as exc:
        return {"status": exc.status.value, "message": str(exc), "warnings": [],
                "wall_time_s": time.perf_counter() - t0}, None
    rec = {"status": res.status.value, "message": res.message, "warnings": list(res.warnings),
           "wall_time_s": res.wall_time_s, "model": dict(res.model)}
    if res.converged and res.profile is not None:
        sm = summarize(res.profile)
        rec["summary"] = {k: sm.get(k) for k in SUMMARY_KEYS}
        rec["summary"].update({k: sm[k] for k in DESIGN_KEYS if sm.get(k) is not None})
        rec["profile"] = _profile_lists(res.profile)
        full = res.summary()
        if "design_fails" in full:              # a design check was made (riser.design.verdicts)
            rec["design_fails"] = list(full["design_fails"])
    return rec, res


def _agreement(scene, results: dict) -> dict:
    from verification.comparison.static.agreement import agreement, unresolved_bending
    from verification.quantities import reference_depth
    b, v = results.get("bvp"), results.get("vfife")
    if b is None or v is None or not b.converged or not v.converged:
        return {"assessed": False, "reason": "a method did not converge"}
    if dict(b.model) != dict(v.model):
        return {"assessed": False, "reason": f"different models: bvp {dict(b.model)}, "
                f"vfife {dict(v.model)}"}
    depth = reference_depth(scene, b.summary())
    bending = unresolved_bending(scene, b.profile, v.info["element_length"])
    rows = agreement(b.profile, v.profile, depth, moment_reason=bending,
                     ends=scene.ends, points=[a.s for a in scene.attachments], scene=scene)
    keep = ("quantity", "bvp", "vfife", "diff", "rel_diff", "tolerance", "pass", "at_s",
            "basis_label", "tol_label", "note")
    rows = [{k: (r.get(k).item() if isinstance(r.get(k), np.generic) else r.get(k))
             for k in keep} for r in rows]
    # rows shown but not judged (pass None: a moment the mesh cannot resolve) are left out
    ratios = [(abs(r["diff"]) / r["tolerance"] if r["tolerance"] else
               (0.0 if r["pass"] else float("inf")), r["quantity"])
              for r in rows if r["diff"] is not None and r["pass"] is not None]
    worst = max(ratios) if ratios else (float("nan"), "")
    return {"assessed": True, "passed": all(r["pass"] is not False for r in rows), "rows": rows,
            "worst_ratio": worst[0], "worst_quantity": worst[1]}


def run_case(spec: dict) -> dict:
    """Solve one case. ``spec``: ``index``, ``digest``, ``scene`` (the parsed scene TOML),
    ``methods``. Never raises: an unexpected error becomes status ``error`` with its
    reason. Plain arguments and result, so that any worker process can run it."""
    from riser.io.scene_file import scene_from_dict
    t0 = time.perf_counter()
    rec = {"index": spec["index"], "digest": spec["digest"], "methods": {},
           "worker": f"{socket.gethostname()}:{os.getpid()}"}
    try:
        scene = scene_from_dict(spec["scene"], f"case {spec['index']}")
        results = {}
        for method in spec["methods"]:
            rec["methods"][method], results[method] = _solve(scene, method)
        if {"bvp", "vfife"} <= set(spec["methods"]):
            rec["agreement"] = _agreement(scene, results)
    except Exception as exc:                  # the case fails, never the sweep
        reraise_interrupt(exc)                # but Ctrl-C in this process (Numba) stops it
        where = traceback.extract_tb(exc.__traceback__)[-1]
        reason = (f"{type(exc).__name__}: {exc} (at {Path(where.filename).name}:"
                  f"{where.lineno})")
        for method in spec["methods"]:
            rec["methods"].setdefault(method, {"status": ERROR, "message": reason,
                                               "warnings": []})
            if rec["methods"][method].get("status") is None:
                rec["methods"][method]["status"] = ERROR
        rec["error"] = reason
    rec["wall_time_s"] = time.perf_counter() - t0
    return rec


def error_record(spec: dict, reason: str) -> dict:
    """The record of a case whose worker failed outside :func:`run_case` (a worker killed,
    a lost connection)."""
    return {"index": spec["index"], "digest": spec["digest"], "error": reason,
            "methods": {m: {"status": ERROR, "message": reason, "warnings": []}
                        for m in spec["methods"]}, "wall_time_s": None}


def case_folder(out: Path, index: int) -> Path:
    return Path(out) / "cases" / f"{index:04d}"


def write_case(out: Path, record: dict, scene_text: str | None = None) -> None:
    """Write a case's files into its own folder; ``case.json`` last (atomically).
    ``scene_text``: the case's scene file (``scene.toml``: ``riser-verify compare`` or
    ``solve`` reruns the case alone)."""
    folder = case_folder(out, record["index"])
    folder.mkdir(parents=True, exist_ok=True)
    if scene_text is not None:
        (folder / "scene.toml").write_text(scene_text)
    profiles = {m: d.get("profile") for m, d in record["methods"].items()}
    meta = {**record, "methods": {m: {k: v for k, v in d.items() if k != "profile"}
                                  for m, d in record["methods"].items()}}
    for method, m in meta["methods"].items():
        sub = folder / method
        sub.mkdir(exist_ok=True)
        prof = profiles[method]
        if prof is not None:
            profile_of(prof).write_csv(sub / "profile.csv")
            np.savez(sub / "profile.npz", **{k: np.asarray(v, float) for k, v in prof.items()
                                             if v is not None})
        else:
            for stale in ("profile.csv", "profile.npz"):
                (sub / stale).unlink(missing_ok=True)
        write_json({"method": method, **m}, sub / "summary.json")
    tmp = folder / "case.json.tmp"
    write_json(meta, tmp)
    os.replace(tmp, folder / "case.json")


def read_case(out: Path, index: int, digest: str) -> dict | None:
    """The finished record of case ``index`` with these inputs, else None (never run, run
    with other inputs, or ended in an unexpected error: run it again). Its profiles are
    read back from ``profile.npz`` (full precision)."""
    path = case_folder(out, index) / "case.json"
    try:
        rec = json.loads(path.read_text())
    except (OSError, ValueError):
        return None
    if rec.get("digest") != digest or "error" in rec:
        return None
    for method, m in rec["methods"].items():
        if m.get("status") == "converged":
            npz = case_folder(out, index) / method / "profile.npz"
            try:
                with np.load(npz) as z:
                    prof = {k: z[k] for k in z.files}
            except (OSError, ValueError):
                return None
            prof["tdp_s"] = float(prof["tdp_s"]) if "tdp_s" in prof else None
            m["profile"] = prof
    return rec
