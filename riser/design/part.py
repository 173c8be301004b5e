"""The scene table ``[design]``: which code checks the line, with which factors, and how
its fatigue is assessed (``[design.fatigue]``, a scatter diagram of sea states in
``[[design.fatigue.sea_states]]``). The wall and the material (outer and inner diameter,
SMYS ``yield_strength``, SMTS ``tensile_strength``) are the line types'.

Codes (their formulas, clause by clause: :mod:`riser.design.dnv_f201`,
:mod:`riser.design.api_2rd`):

- ``dnv-st-f201``: the LRFD combined-loading criterion of DNV-OS-F201 (2010) Sec. 5 D 200
  (kept by DNV-ST-F201, 2018) with the safety class's resistance factor gamma_SC (Table
  5-3), the material factor gamma_m (Table 5-4) and the load-effect factors gamma_F,
  gamma_E (Table 5-2, load combination a); the functional load effect is the static
  state, the environmental one the dynamic part (the run's value minus the static);
- ``api-rp-2rd``: the von Mises stress against C_f C_a SMYS (API RP 2RD, 1998, Sec. 4.4,
  C_a = 2/3, C_f by the load class of its Table 2).

Fatigue verdict: with ``design_life`` [years] the fatigue life along the line is checked
against DFF x design_life (``[design.fatigue] design_fatigue_factor``;
:func:`riser.design.fatigue.fatigue_verdict`); without it the damage and the life are
reported and no verdict is given.

Pressures (gauge, [Pa]): outside the sea's rho_w g (h - y); inside the contents' design
pressure ``internal_pressure`` at the hang-off plus their hydrostatic head rho_c g
(y_top - y).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..errors import SceneError
from ..spec import Part, check_fields, part_error, spec
from .sn_curves import CURVE_NAMES, ENVIRONMENTS

CODES = ("dnv-st-f201", "api-rp-2rd")
SAFETY_CLASSES = ("low", "normal", "high")
#: API RP 2RD's load classes (its Table 2), each with its design case factor C_f
LOAD_CLASSES = ("operating", "extreme", "temporary", "survival", "test")
#: the scatter diagram's probabilities sum to 1 within this (a table of rounded entries)
PROBABILITY_SUM_TOLERANCE = 1e-3
#: the round-off allowed in comparing a length with a wall derived from the diameters
#: (a fraction of the outer diameter; float64 carries 1e-16 of it)
WALL_ROUND_OFF = 1e-9
FATIGUE = "fatigue"


def _own(value):
    """A fresh object equal to ``value``: a code-specific key's default, told from a value
    the input gave (equal, but another object) by identity, so that its type stays the
    plain float or str (see :meth:`Design.ignored_keys`)."""
    return "".join(list(value)) if isinstance(value, str) else float(str(value))


#: the defaults of the keys one code alone reads (each its own object, :func:`_own`)
CODE_DEFAULTS = {"safety_class": _own("normal"), "gamma_f": _own(1.1), "gamma_e": _own(1.3),
                 "gamma_m": _own(1.15), "alpha_u": _own(0.96), "alpha_fab": _own(1.0),
                 "ovality": _own(0.005), "corrosion_allowance": _own(0.0),
                 "load_class": _own("operating")}


#: the keys only one code's check reads (the other code ignores them)
CODE_KEYS = {"dnv-st-f201": ("safety_class", "gamma_f", "gamma_e", "gamma_m", "alpha_u",
                             "alpha_fab", "ovality", "corrosion_allowance"),
             "api-rp-2rd": ("load_class",)}


@dataclass(frozen=True)
class SeaState(Part):
    """One cell of a scatter diagram: the scene's wave spectrum at this Hs and Tp, for
    ``probability`` of the time."""

    hs: float = spec(gt=0.0, le=30.0, unit="m", doc="significant wave height")
    tp: float = spec(gt=1.0, le=40.0, unit="s", doc="spectral peak period")
    probability: float = spec(gt=0.0, le=1.0, doc="fraction of the time in this sea state")


@dataclass(frozen=True)
class Fatigue(Part):
    """``[design.fatigue]``: the S-N curve of the weld (DNV-RP-C203), its stress
    concentration, the points around the circumference, the design fatigue factor and the
    scatter diagram (``sea_states``, read from ``[[design.fatigue.sea_states]]``)."""

    sn_curve: str = spec("D", "string", choices=CURVE_NAMES,
                         doc="DNV-RP-C203 S-N curve class of the detail")
    environment: str = spec("seawater-cp", "string", choices=ENVIRONMENTS,
                            doc="S-N curve set: in air, in seawater with cathodic "
                                "protection, or free corrosion")
    scf: float = spec(1.0, ge=1.0, le=10.0, doc="stress concentration factor on the "
                                                 "nominal stress range")
    points: int = spec(16, "integer", ge=8, le=360,
                       doc="stress points equally spaced around the outer fibre")
    thickness: float | None = spec(None, gt=0.0, le=0.5, unit="m", default_doc="the wall's",
                                   doc="thickness of the S-N curve's thickness correction")
    design_fatigue_factor: float = spec(1.0, ge=1.0, le=100.0,
                                        doc="DFF: the fatigue life must reach DFF x [design] "
                                            "design_life")
    record_length: float | None = spec(None, gt=0.0, le=604800.0, unit="s",
                                       default_doc="one repeat period, the scene's seed",
                                       doc="time-domain record of each sea state (riser-verify "
                                           "fatigue): realisations of one repeat period, "
                                           "each cell its own seeds")
    sea_states: tuple[SeaState, ...] = field(default=())

    def __post_init__(self) -> None:
        check_fields(self)
        error = part_error(self)
        if isinstance(self.sea_states, list):
            object.__setattr__(self, "sea_states", tuple(self.sea_states))
        for i, cell in enumerate(self.sea_states):
            if not isinstance(cell, SeaState):
                raise error(f"sea_states[{i}]", f"must be a SeaState, got "
                            f"{type(cell).__name__}")
        if self.sea_states:
            total = sum(c.probability for c in self.sea_states)
            if abs(total - 1.0) > PROBABILITY_SUM_TOLERANCE:
                raise error("sea_states", f"the probabilities must sum to 1 (within "
                            f"{PROBABILITY_SUM_TOLERANCE:g}), got {total:.6g}")


@dataclass(frozen=True)
class Design(Part):
    """``[design]``: the code check and its factors (see the module docstring); ``fatigue``
    is read from ``[design.fatigue]``."""

    code: str = spec("dnv-st-f201", "string", choices=CODES,
                     doc="the code check: DNV's LRFD combined loading or API's von Mises")
    safety_class: str = spec(CODE_DEFAULTS["safety_class"], "string", choices=SAFETY_CLASSES,
                             doc="DNV safety class: gamma_SC 1.04, 1.14, 1.26")
    load_class: str = spec(CODE_DEFAULTS["load_class"], "string", choices=LOAD_CLASSES,
                           doc="API load class: C_f 1.0, 1.2, 1.2, 1.5, 1.35")
    gamma_f: float = spec(CODE_DEFAULTS["gamma_f"], ge=1.0, le=3.0, doc="DNV load-effect factor on the "
                                                   "functional (static) part")
    gamma_e: float = spec(CODE_DEFAULTS["gamma_e"], ge=1.0, le=3.0, doc="DNV load-effect factor on the "
                                                   "environmental (dynamic) part")
    gamma_m: float = spec(CODE_DEFAULTS["gamma_m"], ge=1.0, le=3.0, doc="DNV material resistance factor")
    alpha_u: float = spec(CODE_DEFAULTS["alpha_u"], gt=0.5, le=1.0, doc="DNV material strength factor "
                                                    "(1.0 with supplementary requirement U)")
    alpha_fab: float = spec(CODE_DEFAULTS["alpha_fab"], gt=0.5, le=1.0, doc="DNV fabrication factor of the "
                                                     "collapse check (0.93 UO, 0.85 UOE)")
    ovality: float = spec(CODE_DEFAULTS["ovality"], ge=0.0, le=0.05, doc="DNV initial out-of-roundness f0 "
                                                      "(collapse)")
    corrosion_allowance: float = spec(CODE_DEFAULTS["corrosion_allowance"], ge=0.0, le=0.1, unit="m",
                                      also="< the wall thickness",
                                      doc="DNV t_corr: t2 = wall - t_corr in the "
                                          "resistances")
    internal_pressure: float | None = spec(None, ge=0.0, le=2.0e8, unit="Pa",
                                           default_doc="[internal_flow] top_pressure, else 0",
                                           doc="design pressure of the contents at the "
                                               "hang-off (gauge)")
    design_life: float | None = spec(None, gt=0.0, le=200.0, unit="years",
                                     default_doc="not set: no fatigue verdict",
                                     doc="service life of the fatigue verdict: the fatigue "
                                         "life must reach design_fatigue_factor x "
                                         "design_life")
    bending_strain_limit: float | None = spec(None, gt=0.0, le=0.05,
                                              default_doc="SMYS / E of each line type",
                                              doc="allowable bending strain (OD/2) kappa "
                                                  "of a steel wall: the bend check's limit")
    storm_duration: float = spec(10800.0, ge=600.0, le=86400.0, unit="s",
                                 doc="the storm of a dynamic run's most probable maxima "
                                     "in an irregular sea (3 h)")
    fatigue: Fatigue | None = spec(None, "part", part=Fatigue, table=FATIGUE)

    def __post_init__(self) -> None:
        check_fields(self)
        # the code-specific keys given: not their default object (a replace passes it on)
        object.__setattr__(self, "_given", frozenset(
            k for k, v in CODE_DEFAULTS.items() if getattr(self, k) is not v))

    def __setstate__(self, state: dict) -> None:
        """Unpickled (a worker process): the keys not given get their default object back,
        so that a replace there still tells them from given ones."""
        for k in CODE_DEFAULTS:
            if k not in state.get("_given", CODE_DEFAULTS):
                state[k] = CODE_DEFAULTS[k]
        self.__dict__.update(state)

    def ignored_keys(self) -> tuple[str, ...]:
        """The keys given (in the file or the constructor) that only the other code reads
        (:data:`CODE_KEYS`): ``load_class`` under DNV, DNV's factors under API; a key left
        out is its default object (:data:`CODE_DEFAULTS`), a given one another."""
        return tuple(k for code, keys in CODE_KEYS.items() if code != self.code
                     for k in keys if k in self._given)

    def top_pressure(self, scene) -> float:
        """The contents' gauge pressure at the hang-off [Pa]: ``internal_pressure``, else
        the internal flow's ``top_pressure``, else 0."""
        if self.internal_pressure is not None:
            return self.internal_pressure
        flow = getattr(scene, "internal_flow", None)
        return flow.top_pressure if flow is not None else 0.0


def check_design(scene) -> None:
    """A scene with ``[design]`` has the wall and the material its checks need on every
    line type (a bore, SMYS; SMTS for DNV) and a water depth (the sea pressure).
    Raises :class:`~riser.errors.SceneError` naming the key."""
    design = scene.design
    if design is None:
        return
    err = scene.error
    if scene.water_depth is None:
        raise err("environment.water_depth", "required with [design] (the sea pressure "
                  "on the wall)")
    needs = ["inner_diameter", "yield_strength"]
    if design.code == "dnv-st-f201":
        needs.append("tensile_strength")
    why = {"inner_diameter": "the wall: give inner_diameter or wall_thickness [m]",
           "yield_strength": "the specified minimum yield strength SMYS [Pa]",
           "tensile_strength": "the specified minimum tensile strength SMTS [Pa] of "
                               "DNV's check"}
    used = dict.fromkeys(seg.line_type for seg in scene.segments)
    for name in used:
        lt = scene.line_types[name]
        for key in needs:
            value = getattr(lt, key)
            if value is None or value <= 0.0:
                raise err(f"line_types.{name}.{key}", f"required by [design] "
                          f"({why[key]})")
        wall = 0.5 * (lt.outer_diameter - lt.inner_diameter)
        # the wall derived from a wall_thickness (D - 2 t) carries the round-off of D:
        # an allowance equal to the given thickness leaves 1e-17 m of wall (a utilisation
        # of 1e29), so the comparison allows WALL_ROUND_OFF of D
        if design.corrosion_allowance >= wall - WALL_ROUND_OFF * lt.outer_diameter:
            raise err("design.corrosion_allowance", f"must be < the wall thickness "
                      f"{wall:.6g} m of line type {name!r} (the corroded wall t - "
                      f"t_corr carries the checks), got {design.corrosion_allowance:g}")
    check_fatigue_sea_states(scene)


def check_fatigue_sea_states(scene) -> None:
    """Each cell of the scatter diagram makes a valid sea of the scene's spectrum (a
    JONSWAP or Pierson-Moskowitz with the cell's hs and tp): refused naming
    ``design.fatigue.sea_states[i].<key>``, not the spectrum's own key."""
    fatigue, waves = scene.design.fatigue, scene.waves
    if fatigue is None or waves is None or waves.spectrum is None \
            or waves.spectrum.kind == "table":
        return
    for i, cell in enumerate(fatigue.sea_states):
        try:
            waves.spectrum.replace(hs=cell.hs, tp=cell.tp)
        except SceneError as exc:
            own = exc.key in ("hs", "tp")
            raise scene.error(f"design.fatigue.sea_states[{i}]" + (f".{exc.key}" if own
                              else ""), ("" if own else f"environment.waves.spectrum."
                              f"{exc.key}: ") + f"{exc.message} (the scene's spectrum at "
                              f"this sea state's hs {cell.hs:g} m and tp {cell.tp:g} s)"
                              ) from None


def design_warnings(scene) -> list[str]:
    """Named ``ignored_input`` warnings for the [design] keys the chosen code does not
    read (:meth:`Design.ignored_keys`) and for a ``design_life`` without
    ``[design.fatigue]``; [] without [design]."""
    design = scene.design
    if design is None:
        return []
    other = {k: code for code, keys in CODE_KEYS.items() for k in keys}
    out = [f"ignored_input: design.{k} = {getattr(design, k)!r} is a key of "
           f"{other[k]}'s check; code = {design.code!r} does not use it"
           for k in design.ignored_keys()]
    if design.design_life is not None and design.fatigue is None:
        out.append(f"ignored_input: design.design_life = {design.design_life:g} years "
                   "needs [design.fatigue] (the S-N curve): no fatigue verdict")
    return out
