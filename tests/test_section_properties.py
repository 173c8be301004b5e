"""Line types from section properties (issue 13): a cable, a jumper and a chain given as
OD + mass per length + EA + EI (+ submerged weight, hydrodynamic diameter) without any wall
dimension load, derive the right section inputs, and solve with both methods."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from scipy.optimize import fsolve

from riser.errors import SceneError
from riser.io.scene_file import load_scene, parse_scene
from riser.model.sections import segment_properties
from verification.pipeline import solve_scene

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "scenes"
NAMES = ("power-cable", "flexible-jumper", "chain-mooring")


def scene(name):
    return load_scene(EXAMPLES / f"{name}.toml")


@pytest.mark.parametrize("name", NAMES)
def test_section_without_wall_dimension(name):
    # protects: OD + mass + EA + EI alone is a complete line type (no bore needed)
    sc = scene(name)
    (lt,) = sc.line_types.values()
    assert lt.inner_diameter is None
    (p,) = segment_properties(sc)
    # closed forms of the section inputs (docs/scene-files.md): the weight in water is the
    # sheet's when given, else m g - rho g pi D^2 / 4 on the displacement diameter; drag
    # and added mass act on the hydrodynamic diameter
    g, rho = sc.gravity, sc.water_density
    w = (lt.submerged_weight if lt.submerged_weight is not None else
         lt.mass_per_length * g - rho * g * math.pi / 4 * lt.outer_diameter ** 2)
    Dh = lt.hydro_diameter or lt.outer_diameter
    assert p.weight == pytest.approx(w, rel=1e-12)
    assert p.drag_normal_coef == pytest.approx(0.5 * rho * Dh * lt.drag_normal, rel=1e-12)
    assert p.added_mass == pytest.approx(lt.added_mass * rho * math.pi / 4 * Dh ** 2, rel=1e-12)
    assert (p.EA, p.EI) == (lt.axial_stiffness, lt.bending_stiffness)


@pytest.mark.parametrize("name", NAMES)
def test_both_methods_solve_and_agree(name):
    # protects: the section-property scenes solve with both methods (1 m elements to keep
    # the test fast; the scenes' own finer lengths are for the moment peaks). Tolerance:
    # the compare protocol's hang-off tension row, 1e-4 relative (verification/comparison/tolerances.py)
    sc = scene(name)
    b = solve_scene(sc, "bvp")
    v = solve_scene(sc, "vfife", element_length=1.0)
    assert b.converged and v.converged, (b.message, v.message)
    tb, tv = b.summary()["hang_off_tension"], v.summary()["hang_off_tension"]
    assert tv == pytest.approx(tb, rel=1e-4)


def test_chain_matches_elastic_catenary():
    # protects: a chain from its MoorDyn-style properties against the closed-form elastic
    # catenary with a frictionless grounded part (horizontal tension H, suspended length
    # Ls). Tolerance 5e-4: the models differ by the chain's small EI (boundary layer
    # sqrt(EI/H) ~ 0.1 m) and the elastic seabed's ~1 cm penetration; measured 0.6e-4
    # (hang-off) and 1.2e-4 (touchdown tension H) for the BVP
    sc = scene("chain-mooring")
    lt = sc.line_types["chain"]
    w = lt.mass_per_length * sc.gravity - sc.water_density * sc.gravity * math.pi / 4 * \
        lt.outer_diameter ** 2
    L, EA = sc.total_length, lt.axial_stiffness
    xf, zf = sc.ends.hang_off

    def equations(v):
        H, Ls = v
        x = (L - Ls) + H / w * math.asinh(w * Ls / H) + H * L / EA
        z = H / w * (math.sqrt(1 + (w * Ls / H) ** 2) - 1) + w * Ls ** 2 / (2 * EA)
        return [x - xf, z - zf]

    H, Ls = fsolve(equations, [1e5, 400.0], xtol=1e-12)
    sm = solve_scene(sc, "bvp").summary()
    assert sm["hang_off_tension"] == pytest.approx(math.hypot(H, w * Ls), rel=5e-4)
    assert sm["tdp_tension"] == pytest.approx(H, rel=5e-4)


BASE = """
name = "t"
[environment]
water_depth = 500.0
[line_types.c]
outer_diameter = 0.2
{keys}
[[segments]]
line_type = "c"
length = 800.0
[ends]
anchor = [0.0, 0.0]
hang_off = [500.0, 450.0]
"""


@pytest.mark.parametrize("keys,key,words", [
    # the bore is needed only by what uses it, and the message says so
    ("mass_per_length = 50.0\naxial_stiffness = 1e9\nbending_stiffness = 1e4\n"
     "contents_density = 800.0", "contents_density", ["needs inner_diameter"]),
    ("density = 7850.0\naxial_stiffness = 1e9\nbending_stiffness = 1e4", "density",
     ["needs wall_thickness or inner_diameter", "mass_per_length"]),
    ("mass_per_length = 50.0\nyoungs_modulus = 2e11", "youngs_modulus",
     ["needs wall_thickness", "axial_stiffness"]),
    ("axial_stiffness = 1e9\nbending_stiffness = 1e4", "mass_per_length", ["required"]),
    ("mass_per_length = 50.0\naxial_stiffness = 1e9\nbending_stiffness = 1e4\n"
     "max_strain = 0.0", "max_strain", ["must be > 0"]),
    ("mass_per_length = 50.0\naxial_stiffness = 1e9\nbending_stiffness = 1e4\n"
     "compression = 1", "compression", ["true or false"]),
])
def test_what_needs_the_bore_says_so(keys, key, words):
    with pytest.raises(SceneError) as exc:
        parse_scene(BASE.format(keys=keys), "t.toml")
    assert exc.value.key == f"line_types.c.{key}"
    for word in words:
        assert word in str(exc.value)


def test_contents_with_a_bore_add_weight():
    # protects: contents need the bore, and add rho_c g pi d^2 / 4 to the weight in water
    keys = ("mass_per_length = 50.0\nsubmerged_weight = 300.0\ninner_diameter = 0.1\n"
            "axial_stiffness = 1e9\nbending_stiffness = 1e4\ncontents_density = 800.0")
    sc = parse_scene(BASE.format(keys=keys), "t.toml")
    (p,) = segment_properties(sc)
    assert p.weight == pytest.approx(300.0 + 800.0 * sc.gravity * math.pi / 4 * 0.01, rel=1e-12)
