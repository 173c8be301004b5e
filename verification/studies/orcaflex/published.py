"""Public OrcaFlex models with OrcaFlex's own static results, imported and solved by both
methods (the reproduction of issue 51).

The models are three of Orcina's example models (A01 "Catenary riser", A01 "Lazy wave
riser", line "10\\" Lazy Wave Distributed", judged against tolerances; A01 "Steep wave
riser", line "10\\" Steep Wave1", in a current across its plane, reported), saved as
OrcaFlex 11.6b text data files in the public repository vamseeachanta/digitalmodel, whose OrcFxAPI script ran OrcaFlex's statics
on them and wrote the results (docs/references.md, "OrcaFlex example models"). The
fixtures in ``tests/data/orcaflex/`` hold their parts this suite reads, written by hand
(``SOURCES.md``).

Each is imported with ``--statics`` (the models' Dean stream wave is not the suite's Airy
wave, and their drag coefficient is a table against Reynolds number, constant up to Re
= 2.4e5 where the current's flow stays: the import carries it as that constant in statics)
and solved by the BVP and the VFIFE on the imported scene without seabed friction:
OrcaFlex's statics apply its friction "as laid" (an elastic slip from the as-laid
position, shear stiffness 100 kN/m/m2), which the suite's statics do not model (the BVP
has no friction; the VFIFE's relaxation would follow its own path). What that changes is
the tension along the grounded length, which OrcaFlex's own results bound: its anchor
tension exceeds its minimum tension by 0.8 % (catenary) and 34 % (lazy wave, where the
minimum is at the hog bend, not on the seabed).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from riser.io.orcaflex.scene_from_model import import_model
from riser.model.scene import Scene
from verification.pipeline import solve_scene

FIXTURES = Path(__file__).resolve().parents[3] / "tests" / "data" / "orcaflex"


@dataclass(frozen=True)
class Published:
    """One public model: its fixture, its line, OrcaFlex's static results [kN, kN m] and
    where they are published, and the tolerances of the comparison (relative)."""

    name: str
    fixture: str
    line: str
    results: dict                 # quantity -> OrcaFlex's value (kN, kN m)
    source: str
    tolerance: dict | None        # quantity -> relative tolerance of both methods; None:
    #                               reported, not judged (a difference not explained)


#: OrcaFlex's quantity -> the suite's summary key
QUANTITIES = {"end_a_tension": ("hang_off_tension", "kN"),
              "end_b_tension": ("bottom_tension", "kN"),
              "min_tension": ("min_tension", "kN"),
              "max_bending_moment": ("max_moment", "kN m")}

#: the tolerances (relative), for both methods. The top tension is the grounded length's
#: tension plus the weight and the current's drag over the height: friction moves the
#: touchdown's tension by at most OrcaFlex's own T_B - T_min (0.8 % of T_B, 0.07 % of the
#: top's), so 0.2 % holds it with the mesh's error (0.01 %); the anchor tension (End B)
#: carries the friction itself: 1 % (catenary: T_B - T_min = 0.84 %) and 2 % (lazy wave,
#: whose grounded length is shorter but whose OrcaFlex statics holds more of it); the
#: minimum tension 0.5 %; the peak moment at the touchdown or the sag bend converges at
#: second order in the mesh (OrcaFlex's own mesh study: 9.354, 9.464, 9.502 kN m at 2, 1
#: and the model's 0.5 m segments), 1 %.
TOLERANCES = {"end_a_tension": 0.002, "end_b_tension": 0.01, "min_tension": 0.005,
              "max_bending_moment": 0.01}

def _results(folder: str) -> str:
    """Where the repository publishes a model's OrcaFlex statics."""
    return (f"vamseeachanta/digitalmodel: docs/domains/orcaflex/library/tier2_fast/{folder}/"
            "validation/results.json (OrcaFlex 11.6b statics)")


MODELS = (
    Published(
        "a01-catenary-riser", "a01-catenary-riser.yml", "Catenary Hose",
        {"end_a_tension": 132.37869525651703, "end_b_tension": 11.875170402569715,
         "min_tension": 11.775708628084125, "max_bending_moment": 9.501998999632983},
        _results("a01_catenary_riser"),
        TOLERANCES),
    Published(
        "a01-lazy-wave-riser", "a01-lazy-wave-riser.yml", '10" Lazy Wave Distributed',
        {"end_a_tension": 90.6551275004462, "end_b_tension": 18.195378030056734,
         "min_tension": 13.551898570174892, "max_bending_moment": 10.77631905062216},
        _results("a01_lazy_wave_riser"),
        {**TOLERANCES, "end_b_tension": 0.02}),
    # reported, not judged: the current (0.5 m/s at 75 deg) crosses the line's plane; the
    # top and anchor tensions agree (0.03 %, 0.5 %), the least tension and the peak
    # moment differ by -1.7 % and +1.3 %, in the direction of a larger current effect in
    # OrcaFlex (the suite's own sensitivity: the current moves them by 0.9 % and 2.2 %);
    # the cause is not found (docs/orcaflex.md)
    Published(
        "a01-steep-wave-riser", "a01-steep-wave-riser.yml", '10" Steep Wave1',
        {"end_a_tension": 87.30346144882958, "end_b_tension": 36.569102878819606,
         "min_tension": 8.995584311912097, "max_bending_moment": 14.220530884606884},
        _results("a01_steep_wave_riser"),
        None),
)


def imported(model: Published) -> tuple[Scene, list[str]]:
    """The model's line imported (``--statics``), without seabed friction (see the module
    docstring), and the import's notes."""
    _, scene, notes = import_model(FIXTURES / model.fixture, line=model.line,
                                   name=model.name, statics=True)
    if scene.seabed is not None and scene.seabed.friction:
        scene = scene.replace(seabed=scene.seabed.replace(friction=0.0))
    return scene, notes


def solve(model: Published) -> tuple[Scene, list[dict], dict]:
    """The imported scene, one row per quantity (OrcaFlex's value, each method's, their
    relative differences and the tolerance) and the results by method."""
    scene, _ = imported(model)
    rows = []
    results = {m: solve_scene(scene, m).require() for m in ("bvp", "vfife")}
    for q, (key, unit) in QUANTITIES.items():
        ref = model.results[q]
        row = {"model": model.name, "quantity": q, "unit": unit, "orcaflex": ref}
        for m, res in results.items():
            value = res.summary()[key] / 1000.0
            row[m] = value
            row[f"{m}_rel_diff"] = (value - ref) / abs(ref)
        if model.tolerance is None:
            row["tolerance"] = float("nan")
            row["pass"] = "reported"
        else:
            row["tolerance"] = model.tolerance[q]
            row["pass"] = all(abs(row[f"{m}_rel_diff"]) <= row["tolerance"]
                              for m in results)
        rows.append(row)
    return scene, rows, results
