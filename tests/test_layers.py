"""The layering of ARCHITECTURE.md, checked on the source: what each package may import,
which folder of ``verification/`` may import which, what may sit at the top of
``verification/``, no import cycle (function-local imports included), nothing imports the
CLI, the concept folders of the packages (no folder above 16 modules, a lower folder never
importing a higher one), and every method reached through its registry
(``verification/methods.py``)."""

from __future__ import annotations

import ast
import inspect
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("riser", "bvp", "vfife", "analytic", "ancf", "verification")
#: package -> project packages it may import (ARCHITECTURE.md)
ALLOWED = {"riser": set(), "bvp": {"riser"}, "vfife": {"riser"}, "analytic": {"riser"},
           "ancf": {"riser"}, "verification": {"riser", "bvp", "vfife", "analytic", "ancf"}}
#: the folders of verification/ -> the folders of verification/ they may import ("core":
#: the modules at its top, the pipeline, quantities, catalog and regression store). The
#: runtime and the report helpers import nothing of verification; the comparison never a
#: peer, a study or a sweep; studies and sweeps not each other; only the command line
#: imports the peers; nothing imports the command line (test_nothing_imports_the_cli).
FOLDER_ALLOWED = {
    "runtime": {"runtime"},
    "report": {"report"},
    "core": {"core"},
    "comparison": {"core", "comparison", "runtime", "report"},
    "studies": {"core", "comparison", "runtime", "report", "studies"},
    "sweeps": {"core", "comparison", "runtime", "report", "sweeps"},
    "peers": {"core", "comparison", "runtime", "report", "peers"},
    "bench": {"core", "runtime", "report", "bench"},
    "cli": {"core", "comparison", "runtime", "report", "studies", "sweeps", "peers", "bench",
            "cli"},
    "facade": {"core", "comparison"},
}
#: the only modules at the top of verification/ (the rest lives in a folder of its concern)
TOP_MODULES = {"__init__.py", "pipeline.py", "methods.py", "quantities.py", "catalog.py",
               "regress.py"}
#: the method registry: the one module of verification/ that imports a method's entry points
REGISTRY = ROOT / "verification" / "methods.py"
#: modules side by side in one folder at most (``__init__.py`` not counted): beyond it a
#: newcomer no longer finds a concept from ``ls``; a folder is split by concept
MAX_MODULES_PER_FOLDER = 16
#: the Numba kernels take their arrays one by one (their own rule, issue 45)
KERNELS = "vfife/kernels.py"
#: the concept folders of a package -> the folders beside them they never import (ARCHITECTURE.md,
#: "The tree"): the lower never reaches up. riser: the field specs and errors at the top,
#: physics (what acts on the line) < model (the line and the scene composing it all) <
#: results; bvp: the planar beam < the 3D rod < the modes (about the beam's or the rod's
#: static state) < the frequency domain; vfife:
#: the dynamic run and the modes never import the statics (the statics' Newton uses the
#: tangent of modal/); the comparisons: static, dynamic < sea
CONCEPT_FORBIDDEN = {
    "riser.physics": {"riser.model", "riser.results", "riser.io"},
    "riser.model": {"riser.results", "riser.io"},
    "bvp.beam": {"bvp.rod", "bvp.modal", "bvp.frequency"},
    "bvp.rod": {"bvp.modal", "bvp.frequency"},
    "bvp.modal": {"bvp.frequency"},
    "vfife.dynamics": {"vfife.statics", "vfife.modal"},
    "vfife.modal": {"vfife.statics", "vfife.dynamics"},
    "vfife.statics": {"vfife.dynamics"},
    "ancf.dynamics": {"ancf.statics"},
    "ancf.statics": {"ancf.dynamics"},
    "verification.comparison.static": {"verification.comparison.dynamic",
                                       "verification.comparison.sea"},
    "verification.comparison.dynamic": {"verification.comparison.static",
                                        "verification.comparison.sea"},
    "verification.comparison.nonlinear": {"verification.comparison.static",
                                          "verification.comparison.dynamic",
                                          "verification.comparison.sea"},
}


def modules() -> dict[str, Path]:
    """Dotted module name -> file, for every module of the project packages."""
    out = {}
    for pkg in PACKAGES:
        for p in sorted((ROOT / pkg).rglob("*.py")):
            parts = list(p.relative_to(ROOT).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join(parts)] = p
    return out


def imports_of(name: str, path: Path, known: set[str]) -> set[str]:
    """Project modules imported anywhere in ``path`` (module level or inside functions)."""
    is_pkg = path.name == "__init__.py"
    base = name.split(".") if is_pkg else name.split(".")[:-1]
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        targets = []
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            head = base[:len(base) - node.level + 1] if node.level else []
            mod = ".".join(head + ([node.module] if node.module else []))
            targets = [mod] + [f"{mod}.{a.name}" for a in node.names]
        for t in targets:
            while t and t not in known:       # 'pkg.mod.func' -> 'pkg.mod'
                t = t.rpartition(".")[0]
            if t and t != name:
                found.add(t)
    return found


def graph() -> dict[str, set[str]]:
    mods = modules()
    return {n: imports_of(n, p, set(mods)) for n, p in mods.items()}


def folder(module: str) -> str:
    """The folder of a verification module (see FOLDER_ALLOWED)."""
    parts = module.split(".")
    if len(parts) == 1:
        return "facade"
    return parts[1] if parts[1] in FOLDER_ALLOWED else "core"


def folder_violations(g: dict[str, set[str]]) -> list[str]:
    """Imports between folders of verification/ that FOLDER_ALLOWED does not allow (a
    module's import of its own package's __init__ is not an edge between folders)."""
    bad = []
    for a, deps in g.items():
        if not a.startswith("verification"):
            continue
        for b in deps:
            if b.startswith("verification") and b != "verification":
                if folder(b) not in FOLDER_ALLOWED[folder(a)]:
                    bad.append(f"{a} ({folder(a)}) imports {b} ({folder(b)})")
    return bad


def test_the_scan_sees_imports():
    # the checker must be able to fail: it finds known edges, relative and absolute,
    # at module level and inside functions
    g = graph()
    assert "verification.pipeline" in g["verification.cli.solve"]        # in a function
    assert "verification.comparison.static.agreement" in g["verification.comparison.static.protocol"]
    assert "riser.errors" in g["riser.model.scene"]
    assert "vfife.kernels" in g["vfife.model"]


def test_the_folder_rules_can_fail():
    # each rule of the issue, broken on purpose, is reported
    broken = {"verification.comparison.static.protocol": {"verification.peers.moordyn.column"},
              "verification.runtime.engine": {"verification.pipeline"},
              "verification.report.figures": {"verification.comparison.formatting"},
              "verification.studies.compare": {"verification.sweeps.run"},
              "verification.sweeps.case": {"verification.studies.stress"},
              "verification.studies.stress": {"verification.peers.moordyn"},
              "verification.pipeline": {"verification.cli.common"}}
    assert len(folder_violations(broken)) == len(broken)
    assert folder_violations({"verification.cli.compare": {"verification.peers"}}) == []


def test_folders_of_verification_import_as_allowed():
    bad = folder_violations(graph())
    assert not bad, bad


def test_only_the_named_modules_sit_at_the_top_of_verification():
    top = {p.name for p in (ROOT / "verification").glob("*.py")}
    assert top == TOP_MODULES
    folders = {p.name for p in (ROOT / "verification").iterdir()
               if p.is_dir() and (p / "__init__.py").exists()}
    assert folders == set(FOLDER_ALLOWED) - {"core", "facade"}


def test_packages_import_only_lower_layers():
    bad = [f"{a} imports {b}" for a, deps in graph().items() for b in deps
           if b.split(".")[0] != a.split(".")[0]
           and b.split(".")[0] not in ALLOWED[a.split(".")[0]]]
    assert not bad, bad


def test_the_riser_model_never_imports_its_file_formats():
    # riser/io reads and writes the model; a model module never imports a format (the
    # package riser/__init__.py, the facade, re-exports the reader)
    bad = [f"{a} imports {b}" for a, deps in graph().items()
           if a.startswith("riser.") and not a.startswith("riser.io")
           for b in deps if b == "riser.io" or b.startswith("riser.io.")]
    assert not bad, bad


def test_no_method_imports_the_design_checks():
    # the design checks post-process every method's result alike, once, after the solve
    # (verification/methods.py: after_design); a method importing them would run them
    # inside its own solve again
    bad = [f"{a} imports {b}" for a, deps in graph().items()
           if a.split(".")[0] in ("bvp", "vfife", "analytic", "ancf")
           for b in deps if b == "riser.design" or b.startswith("riser.design.")]
    assert not bad, bad


def test_nothing_imports_the_cli():
    bad = [a for a, deps in graph().items()
           if not a.startswith("verification.cli")
           and any(d == "verification.cli" or d.startswith("verification.cli.") for d in deps)]
    assert not bad, bad


def test_no_import_cycle():
    g = graph()
    # a package imports its own modules (its __init__ re-exports): an edge from a package
    # to its submodule is not a cycle of modules, so drop package -> own submodule edges
    g = {a: {b for b in deps if not b.startswith(a + ".")} for a, deps in g.items()}
    state: dict[str, int] = {}
    cycles = []

    def visit(n, stack):
        state[n] = 1
        stack.append(n)
        for m in sorted(g[n]):
            if state.get(m) == 1:
                cycles.append(stack[stack.index(m):] + [m])
            elif m not in state:
                visit(m, stack)
        stack.pop()
        state[n] = 2

    for n in sorted(g):
        if n not in state:
            visit(n, [])
    assert not cycles, [" -> ".join(c) for c in cycles]


def test_no_folder_holds_more_than_16_modules():
    crowded = {}
    for pkg in PACKAGES:
        for d in [ROOT / pkg, *(q for q in (ROOT / pkg).rglob("*") if q.is_dir())]:
            n = len([q for q in d.glob("*.py") if q.name != "__init__.py"])
            if n > MAX_MODULES_PER_FOLDER:
                crowded[str(d.relative_to(ROOT))] = n
    assert not crowded, crowded


def concept_violations(g: dict[str, set[str]]) -> list[str]:
    """Imports from a concept folder into a folder beside it that CONCEPT_FORBIDDEN names."""
    def inside(module: str, folder_name: str) -> bool:
        return module == folder_name or module.startswith(folder_name + ".")
    return [f"{a} imports {b}" for a, deps in g.items() for b in deps
            for low, high in CONCEPT_FORBIDDEN.items()
            if inside(a, low) and any(inside(b, h) for h in high)]


def test_concept_folders_never_import_a_higher_one():
    assert concept_violations({"riser.physics.waves": {"riser.model.scene"},
                               "bvp.beam.problem": {"bvp.frequency.harmonic"},
                               "vfife.dynamics.run": {"vfife.statics.equilibrium"}}) != []
    bad = concept_violations(graph())
    assert not bad, bad


# ------------------------------------------------------------------ the method registry
def registry_entries(source: str) -> tuple[set[str], set[tuple[str, str]]]:
    """What the registry's source wraps: the method packages it imports (``import bvp``)
    and the entry points it imports by name (``from bvp.modal.modes import solve_modes``: the
    pair (module, name))."""
    packages, entries = set(), set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            packages |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            packages.add(node.module.split(".")[0])
            entries |= {(node.module, a.name) for a in node.names}
    # the standard library and the shared layer are not methods
    packages = {p for p in packages if p not in sys.stdlib_module_names} - {"riser",
                                                                              "verification"}
    return packages, {(m, n) for m, n in entries if m.split(".")[0] in packages}


def registry_bypasses(sources: dict[str, str], packages: set[str],
                      entries: set[tuple[str, str]]) -> list[str]:
    """Imports in ``sources`` (module name -> source) that reach a method's entry point
    without the registry: a method package itself (``import bvp``, ``from bvp import
    solve``), a module holding an entry point (``import vfife.modal.modes``, ``from bvp import
    modes``) or an entry point by name (``from bvp.frequency.harmonic import solve_harmonic``). A
    method's other modules (its internals: mesh, bench, time step) are not entries."""
    entry_modules = {m for m, _ in entries}
    bad = []
    for name, src in sources.items():
        for node in ast.walk(ast.parse(src)):
            got = []
            if isinstance(node, ast.Import):
                got = [a.name for a in node.names
                       if a.name in packages or a.name in entry_modules]
            elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
                for a in node.names:
                    by_name = (node.module, a.name) in entries
                    of_package = node.module in packages and (
                        a.name == "solve" or f"{node.module}.{a.name}" in entry_modules)
                    if by_name or of_package:
                        got.append(f"{node.module}.{a.name}")
            bad += [f"{name} imports {g}" for g in got]
    return bad


def _verification_sources() -> dict[str, str]:
    return {n: p.read_text() for n, p in modules().items()
            if n.startswith("verification") and p != REGISTRY}


def test_the_registry_wraps_every_method_and_its_entry_points_exist():
    # the packages and entry points the registry's wrappers import are the methods of
    # the suite's layering, and each entry point is there (a renamed function fails here,
    # not in the middle of a study)
    import importlib
    packages, entries = registry_entries(REGISTRY.read_text())
    assert packages == ALLOWED["verification"] - {"riser"}
    from verification.methods import METHODS
    assert set(METHODS) == packages            # one registry line per method package
    for module, name in entries:
        assert callable(getattr(importlib.import_module(module), name)), (module, name)
    for m in METHODS.values():             # each line's solve imports its own package
        code = inspect.unwrap(m.solve).__code__      # under the design checks' wrapper
        assert m.name in code.co_names, (m.name, code.co_names)


def test_a_method_added_in_a_fixture_is_found_and_an_import_around_it_fails():
    # a fourth method registered the registry's way is found, and a module of
    # verification/ that imports its solver (or its modes) directly is reported, while
    # reading one of its internals is not
    registry = REGISTRY.read_text() + (
        "\n\ndef _ancf_solve(scene, **overrides):\n    import ancf\n"
        "    return ancf.solve(scene, **overrides)\n\n\n"
        "def _ancf_modes(scene, count=10, **kwargs):\n"
        "    from ancf.modal import solve_modes\n    return solve_modes(scene, count)\n")
    packages, entries = registry_entries(registry)
    assert "ancf" in packages and ("ancf.modal", "solve_modes") in entries
    around = {"verification.studies.x": "import ancf\n",
              "verification.studies.y": "from ancf import solve\n",
              "verification.studies.z": "from ancf.modal import solve_modes as m\n",
              "verification.studies.w": "import ancf.modal\n",
              "verification.studies.v": "def f():\n    from ancf import modal\n"}
    assert len(registry_bypasses(around, packages, entries)) == len(around)
    inside = {"verification.studies.u": "from ancf.mesh import build_mesh\n"}
    assert registry_bypasses(inside, packages, entries) == []


def test_verification_reaches_the_methods_only_through_the_registry():
    packages, entries = registry_entries(REGISTRY.read_text())
    bad = registry_bypasses(_verification_sources(), packages, entries)
    assert not bad, bad


def test_no_method_dispatch_by_import_module():
    # importlib.import_module dispatch is what the registry replaced: no reader and no
    # layer test could follow it (the facade's lazy names, the studies' and peers'
    # registries import modules of verification/, not methods)
    for n, p in modules().items():
        src = p.read_text()
        for node in ast.walk(ast.parse(src)):
            if (isinstance(node, ast.Call) and getattr(node.func, "attr", "") == "import_module"
                    and node.args and isinstance(node.args[0], ast.Constant)):
                assert node.args[0].value.split(".")[0] not in ALLOWED["verification"], n


def parameter_counts(source: str) -> dict[str, int]:
    """Function name -> how many parameters it takes (positional, keyword-only, *args,
    **kwargs), for every function of ``source``."""
    out = {}
    for n in ast.walk(ast.parse(source)):
        if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef)):
            a = n.args
            out[n.name] = (len(a.posonlyargs) + len(a.args) + len(a.kwonlyargs)
                           + (a.vararg is not None) + (a.kwarg is not None))
    return out


def test_no_function_outside_the_kernels_takes_more_than_30_parameters():
    # a long argument list is a contract nobody can read (issue 45); the Numba kernels
    # take their arrays one by one (vfife/kernels.py, its own rule: grouped arrays only
    # at the same speed in the bench). The counter must see a long list:
    assert parameter_counts("def f(a, b, *c, d=1, **e): pass") == {"f": 5}
    long = {f"{p.relative_to(ROOT)}:{name}": k for p in modules().values()
            if p.relative_to(ROOT).as_posix() != KERNELS
            for name, k in parameter_counts(p.read_text()).items() if k > 30}
    assert not long, long


def test_the_kernels_run_takes_its_arrays_grouped():
    # kernels.run took 68 positional arguments from a 70-attribute Model (issue 45); its
    # arrays now come in named groups (State, Line, Sea, Effects, Scratch, Flow, Ends),
    # measured at the same speed side by side (CHANGELOG.md, issue 45)
    counts = parameter_counts((ROOT / KERNELS).read_text())
    assert counts["run"] <= 16, counts["run"]
    from vfife import kernels
    groups = (kernels.State, kernels.Line, kernels.Sea, kernels.Effects, kernels.Scratch,
              kernels.Flow, kernels.Ends)
    fields = [f for g in groups for f in g._fields]
    assert len(fields) == len(set(fields))                  # one name per array
    assert "trib" in fields and "sband" not in (ROOT / KERNELS).read_text()
