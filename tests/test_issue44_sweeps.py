"""Issue 44 (a), (b): a sweep validates every case as the methods would before running it.

(a) a varied (or set) key that cannot change what a sweep case solves (its static
    equilibrium) is refused before running, one line naming the key, exit 2; the keys
    refused are shown to be inert by solving with and without them (the same profile bit
    for bit), and keys that do matter stay accepted;
(b) a case whose tensioner pulls less than the line weighs is refused before running, as a
    plain ``solve`` of that case is; the limit is the submerged weight computed here from
    the section (closed form).
"""

from __future__ import annotations

import copy
import math
import tomllib

import numpy as np
import pytest

import bvp
import vfife
from riser.errors import SceneError
from riser.io.scene_file import scene_from_dict
from verification.catalog import builtin_paths
from verification.cli import main
from verification.sweeps import inert
from verification.sweeps.file import load_sweep


def _write(tmp_path, text: str, name: str = "s.toml"):
    f = tmp_path / name
    f.write_text(text)
    return f


def _base(name: str) -> dict:
    return tomllib.loads(builtin_paths()[name].read_text())


# ============================================================ (a) keys with no effect
INERT_CASES = {   # key, two values that would differ, base, methods
    "a wave height": ("environment.waves.trains[0].height", [2.0, 4.0],
                      "scr-steel-fatigue", ["bvp", "vfife"]),
    "a wave train": ("environment.waves.trains",
                     [[{"height": 2.0, "period": 10.0}], [{"height": 4.0, "period": 10.0}]],
                     "scr-steel", ["bvp"]),
    "an RAO table": ("vessel.raos[0].heave", [[0.0, 0.1, 0.4, 0.9], [0.0, 0.2, 0.5, 1.0]],
                     "scr-steel-fatigue", ["bvp", "vfife"]),
    "the vessel's lever arm": ("vessel.hang_off_on_vessel", [[30.0, -10.0, 0.0],
                                                             [40.0, -10.0, 0.0]],
                               "scr-steel-fatigue", ["bvp"]),
    "a fatigue S-N curve": ("design.fatigue.scf", [1.0, 1.2], "scr-steel-fatigue", ["bvp"]),
    "the dynamic time step": ("vfife.time_step", [0.001, 0.002], "scr-steel", ["vfife"]),
    "a method not run": ("vfife.element_length", [1.0, 2.0], "scr-steel", ["bvp"]),
    "the analytic's model, not run": ("analytic.model", ["composite", "catenary"],
                                      "scr-steel", ["bvp", "vfife"]),
}


@pytest.mark.parametrize("what", list(INERT_CASES))
def test_a_key_that_cannot_change_a_static_case_is_refused_naming_it(tmp_path, what):
    key, values, base, methods = INERT_CASES[what]
    f = _write(tmp_path, f'base = "{base}"\nmethods = {methods!r}\n'.replace("'", '"')
               + "[[vary]]\n" + f'key = "{key}"\nvalues = {_toml(values)}\n')
    with pytest.raises(SceneError) as exc:
        load_sweep(f)
    line = str(exc.value)
    assert "\n" not in line and "vary[0].key" in line and repr(key) in line, line
    assert "cannot change what a sweep solves" in line, line


def _toml(values) -> str:
    """A TOML array of numbers, strings, arrays or inline tables."""
    def one(v):
        if isinstance(v, dict):
            return "{" + ", ".join(f"{k} = {one(x)}" for k, x in v.items()) + "}"
        if isinstance(v, list):
            return "[" + ", ".join(one(x) for x in v) + "]"
        if isinstance(v, str):
            return f'"{v}"'
        return repr(float(v))
    return one(values)


def test_a_set_key_with_no_effect_is_refused_too_and_the_cli_says_one_line(tmp_path, capsys):
    f = _write(tmp_path, 'base = "scr-steel"\nmethods = ["bvp"]\n[set]\n'
               '"vessel.heading_deg" = 10.0\n[[vary]]\nkey = "ends.hang_off"\n'
               'values = [[1460.0, 1000.0], [1470.0, 1000.0]]\n')
    out = tmp_path / "out"
    assert main(["sweep", str(f), "--out", str(out), "--jobs", "1"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and 'set."vessel.heading_deg"' in err[0], err
    assert not (out / "cases").exists()                  # refused before anything ran


def _solve_both(method, base: str, key_values: dict, element_length=None):
    """The static profile of ``base`` (dynamics dropped, as a sweep does) and of it with
    ``key_values`` changed in its parsed TOML."""
    d = _base(base)
    d.pop("dynamics", None)
    if element_length is not None:
        d.setdefault("vfife", {})["element_length"] = element_length
    changed = copy.deepcopy(d)
    for path, value in key_values.items():
        node = changed
        *head, last = path
        for step in head:
            node = node[step]
        node[last] = value
    return [method.solve(scene_from_dict(x, "t")).profile for x in (d, changed)]


def _doubled_raos(raos: list) -> list:
    out = copy.deepcopy(raos)
    for t in out:
        for dof in ("surge", "heave", "pitch"):
            t[dof] = [2.0 * v for v in t[dof]]
    return out


def test_the_refused_keys_indeed_leave_the_static_solution_unchanged():
    # the independent check of the list: the waves, the vessel and the fatigue table of a
    # scene that has all three changed, both methods solve the same static state bit for
    # bit (a key that entered statics would move some digit of the tension)
    d = _base("scr-steel-fatigue")
    trains = copy.deepcopy(d["environment"]["waves"].get("trains"))
    changes = {("vessel", "hang_off_on_vessel"): [45.0, -12.0, 3.0],
               ("vessel", "raos"): _doubled_raos(d["vessel"]["raos"]),
               ("design", "fatigue", "scf"): 2.0}
    if trains:
        trains[0]["height"] *= 1.5
        changes[("environment", "waves", "trains")] = trains
    if "spectrum" in d["environment"]["waves"]:
        changes[("environment", "waves", "spectrum", "hs")] = \
            d["environment"]["waves"]["spectrum"]["hs"] * 0.5
    for key in inert.STATIC_INERT:
        assert any(".".join(p).startswith(key) for p in changes) or key.startswith("vfife"), key
    a, b = _solve_both(bvp, "scr-steel-fatigue", changes)
    assert np.array_equal(a.tension, b.tension) and np.array_equal(a.x, b.x)
    # the VFIFE's dynamic-only settings (coarse 10 m elements: 2 s a solve)
    a, b = _solve_both(vfife, "scr-steel-fatigue", {
        ("vfife", "time_step"): 0.01, ("vfife", "rotational_inertia_scale_dynamics"): 1.0},
        element_length=10.0)
    assert np.array_equal(a.tension, b.tension) and np.array_equal(a.y, b.y)


@pytest.mark.parametrize("base, methods, key, values", [
    ("scr-steel", ["bvp", "vfife"], "vfife.element_length", [5.0, 10.0]),
    ("wang2014-baseline", ["vfife"], "bvp.tolerance", [1e-6, 1e-5]),   # its conversion
    ("scr-steel-fatigue", ["bvp"], "design.safety_class", ["normal", "high"]),
], ids=["vfife setting, vfife run", "bvp setting, vfife converts", "design column"])
def test_keys_that_change_a_case_stay_accepted(tmp_path, base, methods, key, values):
    # a design key changes the utilisation column every method writes, a bvp setting the
    # BVP solve the VFIFE's conversion of a touchdown-form scene starts from
    f = _write(tmp_path, f'base = "{base}"\nmethods = {_toml(methods)}\n[[vary]]\n'
               f'key = "{key}"\nvalues = {_toml(values)}\n')
    assert len(load_sweep(f).cases) == 2


# ============================================================ (b) the methods' own checks
def _ttr_weight() -> float:
    """The submerged weight [N] of ttr-steel's line, from its section (closed form: steel
    ring weight minus the displaced water of the outer diameter; the bore is empty of
    contents and not flooded unless the scene says so, as riser.model.sections models it)."""
    d = _base("ttr-steel")
    lt = d["line_types"]["steel"]
    od, wt, rho_s = lt["outer_diameter"], lt["wall_thickness"], lt["density"]
    scene = scene_from_dict(copy.deepcopy(d), "t")
    g, rho_w = scene.gravity, scene.water_density
    ring = math.pi / 4 * (od ** 2 - (od - 2 * wt) ** 2)
    per_m = ring * rho_s * g - math.pi / 4 * od ** 2 * rho_w * g
    return per_m * sum(seg["length"] for seg in d["segments"])


def test_a_tensioner_below_the_line_weight_is_refused_before_running(tmp_path, capsys):
    w = _ttr_weight()
    f = _write(tmp_path, 'base = "ttr-steel"\n[[vary]]\nkey = "ends.tensioner.top_tension"\n'
               f"values = [{1.6e6!r}, {0.99 * w!r}]\n")
    with pytest.raises(SceneError) as exc:
        load_sweep(f)
    line = str(exc.value)
    assert "case 1 (" in line and "ends.tensioner.top_tension" in line, line
    said = float(line.split("attachments ")[1].split(" N")[0])
    assert said == pytest.approx(w, rel=1e-5), line        # printed to 6 digits
    out = tmp_path / "out"
    assert main(["sweep", str(f), "--out", str(out), "--jobs", "1"]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
    assert not (out / "cases").exists()
    # a plain solve of that case is refused the same way (exit 2)
    d = _base("ttr-steel")
    d["ends"]["tensioner"]["top_tension"] = 0.99 * w
    from riser.io.toml_text import dumps
    case = _write(tmp_path, dumps(d), "case.toml")
    assert main(["solve", str(case), "--method", "bvp", "--out", str(tmp_path / "o")]) == 2
    # and just above the weight the case is valid (the limit is the weight, not a margin)
    f2 = _write(tmp_path, 'base = "ttr-steel"\n[[vary]]\nkey = "ends.tensioner.top_tension"\n'
                f"values = [{1.01 * w!r}]\n", "ok.toml")
    assert len(load_sweep(f2).cases) == 1


def test_an_element_too_coarse_for_the_vfife_is_refused_before_running(tmp_path):
    # scr-steel's line is ~1,800 m: 1000 m elements leave fewer than the fewest allowed
    f = _write(tmp_path, 'base = "scr-steel"\n[[vary]]\nkey = "vfife.element_length"\n'
               'values = [2.0, 1000.0]\n')
    with pytest.raises(SceneError) as exc:
        load_sweep(f)
    assert "case 1 (" in str(exc.value) and "vfife.element_length: must be <=" in str(exc.value)
