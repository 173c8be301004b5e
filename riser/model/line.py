"""The line: its cross-sections (:class:`LineType`, scene table ``[line_types.NAME]``) and
the lengths of them from the bottom end to the hang-off (:class:`Segment`,
``[[segments]]``). SI units; each field's range, unit and meaning is its spec
(:mod:`riser.spec`), checked on construction.

The plausible ranges are wide enough for any real riser and narrow enough to catch unit
slips (mm instead of m, kN instead of N, GPa instead of Pa).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..spec import Part, Spec, check_fields, part_error, spec

#: the longest segment a scene may hold [m]
MAX_SEGMENT_LENGTH = 5.0e4
#: the largest diameter [m]
MAX_DIAMETER = 5.0
#: the largest density of a material or contents [kg/m3] (tungsten is 19300)
MAX_DENSITY = 25000.0
#: the largest distributed load: weight, buoyancy [N/m]
MAX_LINE_LOAD = 1.0e5
#: the largest stiffness EA [N], EI or GJ [N m2]
MAX_STIFFNESS = 1.0e14
#: the range of Young's and the shear modulus [Pa]
MODULUS = (1.0e6, 1.0e13)
#: the range of a wall's yield and tensile strength [Pa] (10 MPa to 5 GPa: MPa typed as Pa
#: and Pa typed as kPa both fall outside)
MATERIAL_STRENGTH = (1.0e7, 5.0e9)

#: the largest axial (internal) damping BA [N s] (1e14: EA's own bound times 1 s)
MAX_AXIAL_DAMPING = 1.0e14
#: the longest time constant BA / EA [s] of the axial damping: 10 s damps every axial mode
#: above 0.02 Hz beyond critical (a structure's is below 0.01 s: MoorDyn's default 0.8 of
#: critical on 2.5 m segments of Lowe and Langley's jumper is 1.1 ms); N s typed as kN s
#: on such a line stays inside, a BA typed for the wrong line type or in the wrong unit
#: by 1e4 does not
MAX_DAMPING_TIME = 10.0

#: the largest minimum bend radius [m] (a flexible's MBR is metres; 1 km typed as mm
#: falls outside)
MAX_BEND_RADIUS = 1000.0

BORE = "wall_thickness or inner_diameter"


@dataclass(frozen=True)
class LineType(Part):
    """Cross-section and material of a line: a pipe, a cable, a chain, a jumper.

    ``name`` is its key in ``[line_types]``. A section is given by its properties (mass
    per length, EA, EI: a cable, a chain, a flexible pipe) or, in a file, by its wall and
    material (:data:`FILE_KEYS`: a steel pipe). ``inner_diameter`` is None when the
    section is given by its properties alone (only contents need the bore);
    ``axial_stiffness`` is None when not given (only an inextensible model may omit it);
    ``hydro_diameter`` None means the outer diameter; ``submerged_weight`` [N/m, positive
    down], when given, replaces m g - rho_w g pi D^2 / 4.
    """

    name: str
    outer_diameter: float = spec(gt=0.0, le=MAX_DIAMETER, unit="m",
                                 doc="outer diameter: displacement (buoyancy) diameter")
    inner_diameter: float | None = spec(optional=True, ge=0.0, unit="m", also="< outer_diameter",
                                        default_doc="not set (no bore)",
                                        doc="bore (or give wall_thickness); needed by "
                                            "contents and youngs_modulus")
    mass_per_length: float = spec(gt=0.0, le=1.0e4, unit="kg/m",
                                  default_doc="required, or density with a bore",
                                  doc="mass of the line in air, without contents")
    axial_stiffness: float | None = spec(optional=True, gt=0.0, le=MAX_STIFFNESS, unit="N",
                                         default_doc="E A with youngs_modulus",
                                         doc="EA; required by the extensible model")
    bending_stiffness: float = spec(gt=0.0, le=MAX_STIFFNESS, unit="N m2",
                                    default_doc="E I with youngs_modulus, else required",
                                    doc="EI")
    torsional_stiffness: float = spec(gt=0.0, le=MAX_STIFFNESS, unit="N m2",
                                      default_doc="G 2I with shear_modulus, else "
                                                  "EI / (1 + poisson_ratio)",
                                      doc="GJ")
    axial_damping: float = spec(0.0, ge=0.0, le=MAX_AXIAL_DAMPING, unit="N s",
                                default_doc="0 (none)",
                                also=f"<= {MAX_DAMPING_TIME:g} s x axial_stiffness",
                                doc="internal axial damping BA (MoorDyn's BA): the axial "
                                    "force gains BA d(strain)/dt (Kelvin-Voigt)")
    drag_normal: float = spec(1.0, ge=0.0, le=10.0, doc="normal drag coefficient")
    drag_tangential: float = spec(0.0, ge=0.0, le=10.0, doc="tangential drag coefficient")
    added_mass: float = spec(1.0, ge=0.0, le=10.0, doc="added-mass coefficient")
    contents_density: float = spec(0.0, ge=0.0, le=MAX_DENSITY, unit="kg/m3",
                                   also=f"needs {BORE}",
                                   doc="density of the contents of the bore")
    hydro_diameter: float | None = spec(None, gt=0.0, le=MAX_DIAMETER, unit="m",
                                        default_doc="outer_diameter",
                                        doc="diameter of drag and added mass")
    submerged_weight: float | None = spec(None, ge=-MAX_LINE_LOAD, le=MAX_LINE_LOAD,
                                          unit="N/m", default_doc="m g - rho_w g pi D^2 / 4",
                                          doc="weight of the empty line in water, "
                                              "positive down")
    max_strain: float = spec(0.01, gt=0.0, le=1.0,
                             doc="axial strain T/EA beyond which a result carries a warning")
    compression: bool = spec(True, "boolean", doc="false for a line that cannot carry "
                                                  "effective compression (chain, rope)")
    yield_strength: float | None = spec(None, gt=MATERIAL_STRENGTH[0],
                                        le=MATERIAL_STRENGTH[1], unit="Pa",
                                        also="<= tensile_strength",
                                        doc="SMYS of the wall: [design] checks, the "
                                            "bend check SMYS / E, the bending_strain "
                                            "warning")
    tensile_strength: float | None = spec(None, gt=MATERIAL_STRENGTH[0],
                                          le=MATERIAL_STRENGTH[1], unit="Pa",
                                          doc="SMTS of the wall: DNV's check")
    minimum_bend_radius: float | None = spec(None, gt=0.0, le=MAX_BEND_RADIUS, unit="m",
                                             default_doc="not set (steel: SMYS / E)",
                                             doc="the least bend radius of a flexible "
                                                 "pipe or cable (its datasheet's MBR): the "
                                                 "bend check kappa x MBR "
                                                 "(bend_utilisation), the bend_radius "
                                                 "warning")

    def __post_init__(self) -> None:
        check_fields(self)
        error = part_error(self)
        d = self.inner_diameter
        if d is not None:
            check_bore(self.outer_diameter, d, error)
        fy, fu = self.yield_strength, self.tensile_strength
        if fy is not None and fu is not None and fy > fu:
            raise error("yield_strength", f"must be <= tensile_strength {fu:g} Pa (SMYS "
                        f"above SMTS), got {fy:g}")
        ea, ba = self.axial_stiffness, self.axial_damping
        if ea is not None and ba > MAX_DAMPING_TIME * ea:
            raise error("axial_damping", f"must be <= {MAX_DAMPING_TIME:g} s x axial_stiffness "
                        f"= {MAX_DAMPING_TIME * ea:g} N s (BA / EA is the damping's time "
                        f"constant), got {ba:g}")
        if self.contents_density > 0.0 and d is None:
            raise error("contents_density", "needs inner_diameter or wall_thickness (the "
                        "bore that holds the contents)")


def check_bore(outer_diameter: float, inner_diameter: float, error) -> None:
    """The bore is inside the pipe: raise ``error('inner_diameter', message)`` unless
    inner_diameter < outer_diameter [m]."""
    if not inner_diameter < outer_diameter:
        raise error("inner_diameter", f"must be < {outer_diameter:g} m, got {inner_diameter:g}")


#: the default Poisson's ratio of a wall (the reader's GJ = EI / (1 + nu))
POISSON_RATIO = 0.3
#: keys of ``[line_types.NAME]`` that are no field: the wall and the material, from which
#: the reader derives the section (mass_per_length = density A, EA = E A, EI = E I,
#: GJ = G 2I or EI / (1 + poisson_ratio))
FILE_KEYS = {
    "wall_thickness": Spec(gt=0.0, unit="m", also="<= outer_diameter / 2", optional=True,
                           doc="wall thickness (or give inner_diameter)"),
    "density": Spec(gt=0.0, le=MAX_DENSITY, unit="kg/m3", optional=True,
                    doc=f"density of the wall material (needs {BORE}; or give "
                        "mass_per_length)"),
    "youngs_modulus": Spec(ge=MODULUS[0], le=MODULUS[1], unit="Pa", optional=True,
                           doc=f"Young's modulus (needs {BORE}): EA and EI"),
    "poisson_ratio": Spec(ge=0.0, le=0.5, default_doc=f"{POISSON_RATIO:g}",
                          doc="Poisson's ratio: GJ = EI / (1 + nu) without shear_modulus"),
    "shear_modulus": Spec(gt=0.0, le=MODULUS[1], unit="Pa", optional=True,
                          doc=f"shear modulus (needs {BORE}): GJ = G 2I"),
}


@dataclass(frozen=True)
class Segment(Part):
    """A length of one line type, ordered from the bottom end to the hang-off.

    ``weight_scale`` is a factor on the submerged weight (e.g. -1 for Wang et al.'s
    buoyancy section w_e = -w_r).
    """

    line_type: str = spec(kind="string", doc="name of a [line_types] table")
    length: float = spec(gt=0.0, le=MAX_SEGMENT_LENGTH, unit="m", doc="unstretched length")
    buoyancy: float = spec(0.0, ge=-MAX_LINE_LOAD, le=MAX_LINE_LOAD, unit="N/m",
                           doc="extra uplift of buoyancy modules")
    submerged_weight: float | None = spec(None, ge=-MAX_LINE_LOAD, le=MAX_LINE_LOAD,
                                          unit="N/m", default_doc="the line type's",
                                          doc="override of the submerged weight, "
                                              "positive down")
    weight_scale: float = spec(1.0, ge=-100.0, le=100.0,
                               doc="factor on the submerged weight")
    hydro_diameter: float | None = spec(None, gt=0.0, le=MAX_DIAMETER, unit="m",
                                        default_doc="the line type's",
                                        doc="diameter of drag and added mass")
    label: str = spec("", "string", doc="free text naming the segment in reports")
