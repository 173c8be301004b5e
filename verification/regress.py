"""Regression store: summaries of every built-in scene, both methods, compared on each run.

``riser-verify regress`` solves every built-in scene and compares a fixed set of summary
quantities with ``verification/regression/<scene>.json``; ``--update`` rewrites the store
(the explicit regenerate switch). A difference names the scene, the method and the
quantity. VFIFE runs at a coarse element length (``REGRESSION_ELEMENT_LENGTH``) to keep the
check fast; it guards against changes, not accuracy (that is the comparison protocol's job).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

from .catalog import SCENE_DIR, builtin_paths, resolve
from .pipeline import solve_scene

STORE = Path(__file__).parent / "regression"
REGRESSION_ELEMENT_LENGTH = 5.0      # m
QUANTITIES = ("hang_off_tension", "hang_off_angle_deg", "hang_off_x", "hang_off_height",
              "tdp_x", "tdp_tension", "max_tension", "max_moment", "max_shear",
              "max_lateral_offset")            # the last: 3D scenes only (None in plane)
# Relative tolerances: the BVP is deterministic to its collocation tolerance (1e-6) and
# re-meshing noise; VFIFE is deterministic too, and 1e-4 sits between its run-to-run
# round-off (none) and its relaxation error at the default tolerances (the cost study
# measures ~1e-5 of the hang-off tension and up to ~2e-4 of the touchdown tension and peak
# moment). So the store is a change detector: a change of the relaxation path (damping,
# fictitious inertia) moves the sensitive quantities by up to their relaxation error and
# needs `riser-verify regress --update`, with the reason in the commit.
RTOL = {"bvp": 1.0e-5, "vfife": 1.0e-4}
ATOL = {"hang_off_angle_deg": 1e-4, "tdp_x": 1e-2, "hang_off_x": 1e-3, "hang_off_height": 1e-3,
        "max_lateral_offset": 1e-3}


def regression_scenes() -> list[str]:
    """The built-in scenes of the store: every scene except the hard cases (those are the
    stress suite's, `riser-verify stress`)."""
    return [n for n, p in builtin_paths().items() if p.parent == SCENE_DIR]


def snapshot(name: str, methods=("bvp", "vfife")) -> dict:
    """Solve built-in scene ``name`` with each method (statics) and keep the regression
    quantities."""
    scene = resolve(name).replace(dynamics=None)
    out = {"scene": name, "vfife_element_length": REGRESSION_ELEMENT_LENGTH}
    for m in methods:
        res = solve_scene(scene, m, element_length=REGRESSION_ELEMENT_LENGTH)
        sm = res.summary()
        entry = {"converged": res.converged}
        if res.converged:
            entry.update({q: sm.get(q) for q in QUANTITIES})
            entry["crest_heights"] = [c["height"] for c in sm["crests"]]
            entry["sag_heights"] = [c["height"] for c in sm["sags"]]
        out[m] = entry
    return out


def diff(stored: dict, now: dict) -> list[str]:
    """Human-readable differences ('scene: method.quantity: stored X, now Y ...')."""
    lines = []
    name = stored.get("scene", "?")
    for m in ("bvp", "vfife"):
        a, b = stored.get(m), now.get(m)
        if a is None and b is None:
            continue
        if a is None or b is None:
            lines.append(f"{name}: {m}: present in only one of stored/now")
            continue
        if a.get("converged") != b.get("converged"):
            lines.append(f"{name}: {m}.converged: stored {a.get('converged')}, now {b.get('converged')}")
            continue
        for q in QUANTITIES + ("crest_heights", "sag_heights"):
            va, vb = a.get(q), b.get(q)
            if isinstance(va, list) or isinstance(vb, list):
                if len(va or []) != len(vb or []):
                    lines.append(f"{name}: {m}.{q}: stored {len(va or [])} entries, now {len(vb or [])}")
                    continue
                pairs = list(zip(va, vb))
            else:
                pairs = [(va, vb)]
            for x, y in pairs:
                if x is None and y is None:
                    continue
                if x is None or y is None:
                    lines.append(f"{name}: {m}.{q}: stored {x}, now {y}")
                    continue
                tol = max(RTOL[m] * abs(x), ATOL.get(q, 0.0))
                if not math.isclose(x, y, rel_tol=0.0, abs_tol=tol):
                    rel = (y - x) / abs(x) if x else float("inf")
                    lines.append(f"{name}: {m}.{q}: stored {x:.10g}, now {y:.10g} "
                                 f"(rel {rel:+.2e}, tolerance {tol:.3g})")
    return lines


def run(update: bool = False, names: list[str] | None = None, log=print) -> list[str]:
    """Compare (or with ``update`` rewrite) the store; returns the difference lines."""
    STORE.mkdir(exist_ok=True)
    problems = []
    for name in names or regression_scenes():
        now = snapshot(name)
        path = STORE / f"{name}.json"
        if update or not path.exists():
            path.write_text(json.dumps(now, indent=2) + "\n")
            log(f"{name}: {'updated' if update else 'created (no stored summary yet)'}")
            continue
        d = diff(json.loads(path.read_text()), now)
        problems += d
        log(f"{name}: {'ok' if not d else f'{len(d)} difference(s)'}")
    return problems
