"""The result contract (riser/results/result.py) and the typed solver settings (riser/model/settings.py):
every run ends in a status, summary.json says which, the CLI maps it to its documented exit
code in one line, the stress suite reads the status (never the message), and a
programmatic setting is validated like the scene file's key."""

from __future__ import annotations

import json

import pytest

import bvp
import vfife
from riser.errors import SceneError
from riser.io.scene_file import parse_scene
from riser.results.result import SolveResult, Status
from riser.model.settings import BVPSettings, VFIFESettings
from verification import pipeline
from verification.catalog import resolve
from verification.studies import stress

# a small fixed-ends line: 300 m of 86.8 kg/m steel pipe hanging between (0, 0) and
# (200, 150) m, no seabed (fast for both methods)
SMALL = """\
name = "small"
[line_types.steel]
outer_diameter = 0.2032
inner_diameter = 0.165
mass_per_length = 86.8
axial_stiffness = 2.0e9
bending_stiffness = 1.0e7
[[segments]]
line_type = "steel"
length = 300.0
[ends]
anchor = [0.0, 0.0]
hang_off = [200.0, 150.0]
"""


# ------------------------------------------------------------------------- statuses
def test_status_exit_codes_and_meanings():
    # the documented exit codes: 0 converged, 2 refused (bad input), 1 every other way
    assert [s.exit_code for s in Status] == [0, 2, 1, 1, 1]
    assert all(s.meaning for s in Status)


def test_converged_result_carries_status_model_and_warnings(tmp_path):
    sc = parse_scene(SMALL)
    for res in (bvp.solve(sc), vfife.solve(sc, element_length=10.0)):
        assert res.status is Status.CONVERGED and res.converged
        assert res.model == {"axial": "extensible", "seabed": None}
        res.write(tmp_path / res.method)
        sm = json.loads((tmp_path / res.method / "summary.json").read_text())
        assert sm["status"] == "converged" and sm["converged"] is True
        assert sm["model"] == res.model and sm["warnings"] == res.warnings
    # residuals named for what they measure, never an ambiguous "residual"
    assert "collocation_residual" in bvp.solve(sc).info
    v = vfife.solve(sc, element_length=10.0)
    assert v.info["force_residual"] <= v.info["tolerance"] and "residual" not in v.info


def test_vfife_step_budget_is_not_converged():
    # 50 relaxation steps cannot settle a 300 m catenary: stopped at a limit, not diverged
    sc = parse_scene(SMALL)
    res = vfife.solve(sc.replace(vfife=sc.vfife.replace(max_steps=50)), element_length=10.0)
    assert res.status is Status.NOT_CONVERGED and res.profile is None
    assert "max_steps" in res.message


def test_vfife_time_step_above_critical_diverges():
    # a fixed relaxation step 50x the critical one blows up, and says so
    sc = parse_scene(SMALL)
    res = vfife.solve(sc.replace(vfife=sc.vfife.replace(static_time_step=0.05)),
                      element_length=10.0)
    assert res.status is Status.DIVERGED and res.profile is None


def test_bvp_node_cap_is_not_converged():
    # the Wang bending layer (sqrt(EI/T) ~ 3 m on 2,600 m) cannot meet 1e-10 on 100 nodes
    res = bvp.solve(resolve("wang2014-baseline"), tolerance=1e-10, max_nodes=100,
                    continuation=False)
    assert res.status is Status.NOT_CONVERGED and res.profile is None


def test_a_failed_result_never_holds_a_profile():
    res = SolveResult("bvp", "x", Status.DIVERGED, "blew up", profile=object())
    assert res.profile is None and not res.converged


def test_stress_reads_the_status_not_the_message(monkeypatch):
    # a message that used to be matched for "no equilibrium" decides nothing now
    fake = SolveResult("bvp", "small", Status.NOT_CONVERGED,
                       "the tension tends to zero, so probably no static equilibrium")
    monkeypatch.setattr(stress, "solve_scene", lambda scene, method, **kw: fake)
    row, _ = stress.run_one("hard-deep-scr", "bvp")
    assert row["outcome"] == "failed"
    fake = fake.replace(status=Status.NO_EQUILIBRIUM)      # results are frozen
    monkeypatch.setattr(stress, "solve_scene", lambda scene, method, **kw: fake)
    row, _ = stress.run_one("hard-deep-scr", "bvp")
    assert row["outcome"] == "no equilibrium"


# ------------------------------------------------------------------------- the CLI
def test_cli_element_length_override_is_validated(tmp_path, run_cli):
    # the CLI option goes through the scene key's range: 5000 m is refused, exit 2, one line
    code, out, err = run_cli(["solve", "scr-steel", "--method", "vfife",
                                      "--element-length", "5000", "--out",
                                      str(tmp_path / "o")])
    assert code == 2
    lines = err.splitlines()
    assert len(lines) == 1 and "error: command line: --element-length: must be <= 1000 m" in lines[0], err


def test_cli_unexpected_error_is_one_line(monkeypatch, tmp_path, run_cli):
    def boom(*a, **k):
        raise ZeroDivisionError("division by zero")
    monkeypatch.setattr(pipeline, "solve_scene", boom)
    code, out, err = run_cli(["solve", "scr-steel", "--out", str(tmp_path / "o")])
    assert code == 1
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: unexpected ZeroDivisionError")
    assert "Traceback" not in err


def test_cli_failed_solve_exits_1_with_its_status(tmp_path, run_cli):
    scene = tmp_path / "s.toml"
    scene.write_text(SMALL + "\n[vfife]\nmax_steps = 50\n")
    code, out, err = run_cli(["solve", str(scene), "--method", "vfife",
                                      "--element-length", "10", "--out", str(tmp_path / "o")])
    assert code == 1
    assert err.startswith("error: vfife on small: not_converged (") and err.count("\n") == 1
    sm = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert sm["status"] == "not_converged" and not (tmp_path / "o" / "profile.csv").exists()


# ------------------------------------------------------------------------- settings
def test_settings_defaults_are_the_scene_files():
    # a scene without [bvp]/[vfife] gets exactly the dataclass defaults
    sc = parse_scene(SMALL)
    assert sc.bvp == BVPSettings() and sc.vfife == VFIFESettings()
    assert (sc.vfife.element_length, sc.vfife.static_tolerance, sc.bvp.tolerance) == \
        (1.0, 1e-3, 1e-6)


def test_expert_table_is_read_and_validated():
    sc = parse_scene(SMALL + "\n[vfife.expert]\nstatic_damping = 5.0\ncreep_tolerance = 0\n")
    assert sc.vfife.static_damping == 5.0 and sc.vfife.creep_tolerance == 0.0
    with pytest.raises(SceneError, match=r"vfife\.expert\.static_damping: must be > 0"):
        parse_scene(SMALL + "\n[vfife.expert]\nstatic_damping = -1.0\n")
    with pytest.raises(SceneError, match=r"vfife\.expert\.dampin: unknown key"):
        parse_scene(SMALL + "\n[vfife.expert]\ndampin = 1.0\n")
    # an expert knob is not a [vfife] key
    with pytest.raises(SceneError, match=r"vfife\.static_damping: unknown key"):
        parse_scene(SMALL + "\n[vfife]\nstatic_damping = 5.0\n")


@pytest.mark.parametrize("change,message", [
    ({"element_length": 5000.0}, "vfife.element_length: must be <= 1000 m"),
    ({"static_damping": 0.0}, "vfife.expert.static_damping: must be > 0"),   # as the file
    ({"max_steps": 2.5}, "vfife.max_steps: must be an integer"),
    ({"clamped_ends": ("middle",)}, "vfife.clamped_ends[0]: must be one of"),
    ({"dampin": 1.0}, "vfife.dampin: unknown setting"),
])
def test_programmatic_settings_are_validated(change, message):
    with pytest.raises(SceneError) as exc:
        VFIFESettings().replace(**change)
    assert message in str(exc.value)


def test_bvp_override_is_validated():
    with pytest.raises(SceneError, match=r"bvp\.tolerance: must be <= 0\.1"):
        bvp.solve(parse_scene(SMALL), tolerance=0.5)


def test_every_registered_study_declares_its_own_name():
    # the registry names each study's module; the module's STUDY must answer to that name
    from verification.studies import STUDIES, study
    assert [study(n).name for n in STUDIES] == list(STUDIES)
