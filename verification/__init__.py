"""Cross-checks, paper reproductions, reports and the command line of the riser suite.

The Python entry points, imported when first used (``import verification`` loads no
solver)::

    from verification import resolve, solve_scene, compare, write_comparison, run_modes
    scene = resolve("scr-steel")                  # a built-in name or a scene file
    res = solve_scene(scene, "bvp")               # a riser.results.result.SolveResult
    comp = compare(scene)                         # both methods on the same model
    write_comparison(comp, "out/scr-steel")       # agreement.csv, report.md, plots

Layout (ARCHITECTURE.md): the modules here are the pipeline (one way to run a method on a
scene), quantities read off profiles, the catalog of built-in scenes and the regression
store; the folders hold one concern each: ``comparison/``, ``studies/``, ``sweeps/``,
``peers/``, ``bench/``, ``runtime/``, ``report/`` and ``cli/``.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

if TYPE_CHECKING:                 # the names below, for readers and type checkers
    from .catalog import resolve
    from .comparison.modes import run_modes
    from .comparison.static.protocol import Comparison, compare
    from .comparison.static.report import write as write_comparison
    from .pipeline import solve_scene, vfife_equivalent

#: facade name -> (module, attribute)
_FACADE = {
    "resolve": ("verification.catalog", "resolve"),
    "solve_scene": ("verification.pipeline", "solve_scene"),
    "vfife_equivalent": ("verification.pipeline", "vfife_equivalent"),
    "compare": ("verification.comparison.static.protocol", "compare"),
    "Comparison": ("verification.comparison.static.protocol", "Comparison"),
    "write_comparison": ("verification.comparison.static.report", "write"),
    "run_modes": ("verification.comparison.modes", "run_modes"),
}
__all__ = ["resolve", "solve_scene", "vfife_equivalent", "compare", "Comparison",
           "write_comparison", "run_modes"]


def __getattr__(name: str):
    if name in _FACADE:
        module, attr = _FACADE[name]
        return getattr(importlib.import_module(module), attr)
    raise AttributeError(f"module 'verification' has no attribute {name!r}")
