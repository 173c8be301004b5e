"""An OrcaFlex line type -> a scene's ``[line_types.NAME]`` (see
:mod:`riser.io.orcaflex.scene_from_model` for the mapping).

Categories: ``General`` (the section's properties: OD, ID, mass per length, EA, EI) and
``Homogeneous pipe`` (OrcaFlex derives them from the wall's material: density, Young's
modulus, Poisson's ratio; the scene derives the same from ``density``,
``youngs_modulus``, ``poisson_ratio``). A drag coefficient that refers to variable data
(a table of Cd against Reynolds number) is carried only where it is one number for every
flow the import carries: a static scene (no waves) whose current's fastest speed gives a
Reynolds number within the table's first constant stretch (OrcaFlex holds a table
constant beyond its ends); otherwise it is refused.
"""

from __future__ import annotations

import math

from .text_file import Model, ModelError, get, number, table
from .units import Units


def _pair(value, src: str, item: str):
    """OrcaFlex's [x, y] (y ~: same as x) or a scalar: (x, y)."""
    if isinstance(value, list):
        if not value or len(value) > 3:
            raise ModelError(src, item, f"must be a value or a list of 2-3 values, got "
                             f"{value!r}")
        return value
    return [value]


def _variable(model: Model, kind: str, name: str, src: str, item: str) -> list[tuple]:
    """The rows (x, y) of the variable data table ``name`` of ``kind``."""
    vd = model.section("VariableData") or {}
    tables = get(vd, kind)
    if not isinstance(tables, list):
        raise ModelError(src, item, f"refers to variable data {name!r}, which the model's "
                         f"VariableData.{kind} does not hold")
    for t in tables:
        if isinstance(t, dict) and str(t.get("Name")) == name:
            rows = table(t, ("IndependentValue", "DependentValue"), src,
                         f"VariableData.{kind}[{name}]")
            if not rows:
                break
            return [(number(get(r, "IndependentValue"), src, item),
                     number(get(r, "DependentValue"), src, item)) for r in rows]
    raise ModelError(src, item, f"refers to variable data {name!r}, which is not in "
                     f"VariableData.{kind}")


def _drag_of_reynolds(model: Model, name: str, re_max: float | None, src: str,
                      item: str, notes: list[str]) -> float:
    """The constant Cd of the Reynolds-number table ``name`` for Reynolds numbers up to
    ``re_max`` (None: dynamics carried, every Reynolds number): refused unless constant."""
    rows = _variable(model, "Dragcoefficient", name, src, item)
    why = (f"refers to variable data {name!r}, a drag coefficient varying with Reynolds "
           "number; the suite's is one number")
    if re_max is None:
        raise ModelError(src, item, f"{why}, and the import carries waves (the flow "
                         "reaches every Reynolds number): set a constant Cd in OrcaFlex, "
                         "or import with --statics")
    first = rows[0][1]
    reach = 0.0
    for re_k, cd in rows:
        if cd != first:
            break
        reach = re_k
    if re_max > reach and any(cd != first for _, cd in rows):
        raise ModelError(src, item, f"{why}: the current reaches Re = {re_max:.4g}, beyond "
                         f"the table's constant Cd = {first:g} (to Re = {reach:.4g})")
    notes.append(f"Cd = {first:g} from the variable data {name!r}: constant up to Re = "
                 f"{reach:.4g}, and the current's fastest flow gives Re = {re_max:.4g} "
                 "(statics only: no waves carried)")
    return first


def contact_diameter(obj: dict, u: Units, src: str) -> float:
    """The line type's seabed contact diameter [m]: OuterContactDiameter, else OD."""
    name = str(obj.get("Name"))
    d = number(get(obj, "OuterContactDiameter"), src,
               f"LineTypes[{name}].OuterContactDiameter", allow_none=True)
    if d is None:
        d = number(get(obj, "OD"), src, f"LineTypes[{name}].OD")
    return d * u.length


def line_type(model: Model, obj: dict, u: Units, torsion: bool,
              re_max: float | None) -> tuple[dict, list[str]]:
    """The scene's line type table of the OrcaFlex line type ``obj`` and the comment
    lines saying how each value came; ``re_max``: the flow's largest Reynolds number per
    metre of diameter [1/m] (None: dynamics carried)."""
    src = model.source
    name = str(obj.get("Name"))
    it = f"LineTypes[{name}]"
    notes: list[str] = []
    cat = str(get(obj, "Category", default="General"))

    def num(key, allow_none=False):
        return number(get(obj, key), src, f"{it}.{key}", allow_none=allow_none)

    od = num("OD") * u.length
    idia = (num("ID", allow_none=True) or 0.0) * u.length
    out: dict = {"outer_diameter": od}
    if idia > 0.0:
        out["inner_diameter"] = idia
    if cat.lower() == "general":
        out["mass_per_length"] = num("MassPerUnitLength") * u.mass_per_length
        ea = get(obj, "EA", "EAx")
        if isinstance(ea, list):
            ea = ea[0] if ea else None
        if isinstance(ea, str) and not _is_number(ea):
            raise ModelError(src, f"{it}.EA", f"refers to {ea!r}: a nonlinear axial "
                             "stiffness is not carried (the scene's EA is one number)")
        out["axial_stiffness"] = number(ea, src, f"{it}.EA") * u.force
        ei = _pair(get(obj, "EI", "EIx"), src, f"{it}.EI")
        for k, v in enumerate(ei[:2]):
            if isinstance(v, str) and not _is_number(v):
                raise ModelError(src, f"{it}.EI", f"refers to {v!r}: a nonlinear bending "
                                 "stiffness is not carried")
        eix = number(ei[0], src, f"{it}.EI")
        eiy = number(ei[1], src, f"{it}.EI", allow_none=True) if len(ei) > 1 else None
        if eiy is not None and eiy != eix:
            raise ModelError(src, f"{it}.EI", f"x {eix:g} and y {eiy:g} differ: the scene's "
                             "section is round (one EI)")
        if eix == 0.0:
            raise ModelError(src, f"{it}.EI", "0 (a chain or rope without bending stiffness): "
                             "the suite's line is a beam and needs EI > 0")
        out["bending_stiffness"] = eix * u.ei
        notes.append("General line type: mass_per_length = MassPerUnitLength, "
                     "axial_stiffness = EA, bending_stiffness = EI, converted to SI")
        if torsion:
            out["torsional_stiffness"] = num("GJ") * u.ei
    elif cat.lower() == "homogeneous pipe":
        out["density"] = num("MaterialDensity") * u.density
        out["youngs_modulus"] = num("E") * u.force / u.length ** 2
        nu = num("PoissonRatio", allow_none=True)
        if nu is not None:
            out["poisson_ratio"] = nu
        if idia <= 0.0:
            raise ModelError(src, f"{it}.ID", "a homogeneous pipe needs its bore (ID > 0) "
                             "for the wall's area")
        for key in ("CoatingThickness", "LiningThickness"):
            v = get(obj, key)
            if v is not None and (not _is_number(v) or number(v, src, f"{it}.{key}") != 0.0):
                raise ModelError(src, f"{it}.{key}", f"{v!r}: a coated or lined pipe is not "
                                 "carried (the scene's wall is one material); give the line "
                                 "type as General (its OD, mass, EA, EI)")
        notes.append("Homogeneous pipe: density = MaterialDensity, youngs_modulus = E, "
                     "poisson_ratio = PoissonRatio; the scene derives mass, EA and EI from "
                     "the wall as OrcaFlex does")
        if torsion:
            notes.append("GJ: G = E / (2 (1 + nu)) of the wall, as OrcaFlex's")
    else:
        raise ModelError(src, f"{it}.Category", f"{cat!r}: only General and Homogeneous "
                         "pipe line types are read")
    # hydrodynamics: Cd and Ca as [normal x, normal y, axial] (a homogeneous pipe writes
    # them as Cdn, Cdz and Can, Caz)
    if get(obj, "Cd") is None and get(obj, "Cdn") is not None:
        obj = {**obj, "Cd": [get(obj, "Cdn"), None, get(obj, "Cdz", default=0.0)]}
    if get(obj, "Ca") is None and get(obj, "Can") is not None:
        obj = {**obj, "Ca": [get(obj, "Can"), None, get(obj, "Caz", default=0.0)]}
    for key in ("Cd", "Ca"):
        if get(obj, key) is None:
            raise ModelError(src, f"{it}.{key}", "not given: this import does not know "
                             "OrcaFlex's default here; give the coefficient")
    cd = _pair(get(obj, "Cd"), src, f"{it}.Cd")
    dn = number(get(obj, "NormalDragLiftDiameter"), src, f"{it}.NormalDragLiftDiameter",
                allow_none=True)
    dh = od if dn is None else dn * u.length
    cdn = cd[0]
    if isinstance(cdn, str) and not _is_number(cdn):
        cdn = _drag_of_reynolds(model, cdn, None if re_max is None else re_max * dh, src,
                                f"{it}.Cd", notes)
    cdn = number(cdn, src, f"{it}.Cd")
    cdy = cd[1] if len(cd) > 1 else None
    if cdy is not None and (not _is_number(cdy) or number(cdy, src, f"{it}.Cd") != cdn):
        raise ModelError(src, f"{it}.Cd", f"normal x {cd[0]!r} and y {cdy!r} differ: the "
                         "scene's drag is isotropic about the axis")
    cda = number(cd[2], src, f"{it}.Cd", allow_none=True) if len(cd) > 2 else 0.0
    cda = cda or 0.0
    da = number(get(obj, "AxialDragLiftDiameter"), src, f"{it}.AxialDragLiftDiameter",
                allow_none=True)
    da = od if da is None else da * u.length
    ca = _pair(get(obj, "Ca"), src, f"{it}.Ca")
    can = number(ca[0], src, f"{it}.Ca")
    cay = number(ca[1], src, f"{it}.Ca", allow_none=True) if len(ca) > 1 else None
    if cay is not None and cay != can:
        raise ModelError(src, f"{it}.Ca", f"normal x {can:g} and y {cay:g} differ: the "
                         "scene's added mass is isotropic about the axis")
    dynamic = re_max is None           # the scene carries waves (and dynamics)
    static_only: list[str] = []

    def dynamics_only(key: str, value, why: str) -> None:
        """An item that acts in dynamics only: refused when the scene carries them,
        noted otherwise."""
        if dynamic:
            raise ModelError(src, f"{it}.{key}", f"{value!r}: {why}")
        static_only.append(f"{key} {value!r}")

    caa = number(ca[2], src, f"{it}.Ca", allow_none=True) if len(ca) > 2 else 0.0
    if caa:
        dynamics_only("Ca", ca, f"axial added mass {caa:g}: the scene's added mass acts "
                      "normal to the line only")
    cm = get(obj, "Cm")
    cm = cm if isinstance(cm, list) else [cm]
    for c in cm:
        if c is not None and number(c, src, f"{it}.Cm") != 1.0 + can:
            dynamics_only("Cm", c, "an inertia coefficient other than 1 + Ca is not carried")
            break
    v = get(obj, "Cl")
    v = (v[0] if v else None) if isinstance(v, list) else v
    if v is not None and (not _is_number(v) or number(v, src, f"{it}.Cl") != 0.0):
        raise ModelError(src, f"{it}.Cl", f"{v!r}: lift is not modelled")
    for key, what in (("Cs", "slam entry"), ("Ce", "slam exit")):
        v = get(obj, key)
        v = (v[0] if v else None) if isinstance(v, list) else v
        if v is not None and (not _is_number(v) or number(v, src, f"{it}.{key}") != 0.0):
            dynamics_only(key, v, f"{what} is not modelled")
    if static_only:
        notes.append(f"not carried, acting in dynamics only (the scene is static): "
                     f"{'; '.join(static_only)}")
    for name, d in (("OD", od), ("NormalDragLiftDiameter", dh),
                    ("AxialDragLiftDiameter", da)):
        if not d > 0.0:
            raise ModelError(src, f"{it}.{name}", f"must be > 0, got {d:g} m")
    out["drag_normal"] = cdn
    out["drag_tangential"] = cda * da / dh
    out["added_mass"] = can * (od / dh) ** 2
    if dh != od:
        out["hydro_diameter"] = dh
        notes.append(f"hydro_diameter = NormalDragLiftDiameter {dh:.12g} m; added_mass = "
                     f"Ca {can:g} x (OD / D_h)^2 (OrcaFlex's added mass is on the "
                     "displaced area)")
    if da != dh or dh != od:
        notes.append(f"drag_tangential = axial Cd {cda:g} x D_axial {da:.12g} m / D_h "
                     f"{dh:.12g} m (OrcaFlex's axial drag acts on pi D_axial)")
    # what the scene cannot hold
    if str(get(obj, "CompressionIsLimited", default="No")).lower() in ("yes", "true") or \
            get(obj, "CompressionIsLimited") is True:
        raise ModelError(src, f"{it}.CompressionIsLimited", "Yes: a line that cannot take "
                         "compression is not modelled (the suite's line does)")
    exp = get(obj, "ExpansionTable")
    if exp is not None and str(exp).lower() != "none":
        raise ModelError(src, f"{it}.ExpansionTable", f"{exp!r}: thermal or pressure "
                         "expansion is not modelled")
    ray = get(obj, "RayleighDampingCoefficients")
    if ray is not None and str(ray).lower() != "(no damping)":
        raise ModelError(src, f"{it}.RayleighDampingCoefficients", f"{ray!r}: Rayleigh "
                         "structural damping is not carried")
    mbr = get(obj, "MinRadius")
    mbr = (mbr[0] if mbr else None) if isinstance(mbr, list) else mbr
    if mbr is not None and _is_number(mbr):
        r = number(mbr, src, f"{it}.MinRadius", allow_inf=True) * u.length
        if math.isfinite(r) and r > 0.0:
            out["minimum_bend_radius"] = r
            notes.append("minimum_bend_radius = MinRadius (the bend check)")
    com = get(obj, "CentreOfMass")
    if isinstance(com, list) and any(_is_number(c) and number(c, src, it) for c in com):
        raise ModelError(src, f"{it}.CentreOfMass", f"{com!r}: an offset centre of mass is "
                         "not modelled")
    left = [k for k in ("AllowableTension", "AllowableStress", "StressOD", "StressID")
            if get(obj, k) is not None]
    if left:
        notes.append(f"not carried (results limits and stress settings): {', '.join(left)}")
    return out, notes


def _is_number(v) -> bool:
    if isinstance(v, bool):
        return False
    if isinstance(v, (int, float)):
        return True
    if isinstance(v, str):
        try:
            float(v)
            return True
        except ValueError:
            return v.strip().lower() in ("infinity", "-infinity")
    return False
