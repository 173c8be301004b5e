"""The settings swept by the cost study: which runs it makes, and what each is predicted
to cost (for the remaining-time estimate)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from riser.model.scene import Scene

from .dynamics import FAST_DYNAMICS, FULL_DYNAMICS
from .dynamics_ancf import FAST_ANCF, FULL_ANCF

#: scenes of the study (``riser-verify reproduce all``)
COST_SCENES = ("wang2014-baseline", "yu2021-a3", "yu2021-a2-sheared")

ELEMENT_LENGTHS = (20.0, 10.0, 5.0, 2.0, 1.0, 0.5)
#: element lengths of the order sweep (``element_length_tight``), finer ones from
#: ELEMENT_LENGTHS added only while fewer than three are in the asymptotic range. The
#: built-in scenes' range ends at 4.2-4.4 m, hence 4, 3 and 1.5 m: five lengths in the fit
#: without going below 1 m, where the tight creep test gets dear (converted Wang baseline,
#: creep 1e-9: 68 s at 1 m; at 0.5 m a creep test of 1e-8 did not finish in 18 min).
ORDER_LENGTHS = (20.0, 10.0, 5.0, 4.0, 3.0, 2.0, 1.5, 1.0)
#: the finest is the reference; 1e-9 adds ~40 s on the Yu scenes and changes no quantity
#: by more than 1e-10 (yu2021-a3: 1e-8 -> 1e-9 moves the peak moment by 1.5e-11)
BVP_TOLERANCES = (1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8)
#: tolerances of the order sweep (element_length_tight rows): static force tolerance
#: [element weights] and creep tolerance [fraction of the line length]. The creep test
#: bounds the displacement still to come; the default 1e-5 (29 mm on the 2,900 m
#: converted Wang line) is far above the discretisation error of the heights below 5 m, and
#: even 1e-7 (0.3 mm) left relaxation errors near 1e-7 of the depth in the heights and
#: 1e-5 in the touchdown tension at 0.5-1 m on the soft (1e5 N/m2) seabed; 1e-8 and 1e-9
#: agree to 1e-8 in every quantity at 2 m (Wang baseline).
TIGHT_TOLERANCE = 1e-5
TIGHT_CREEP = 1e-9
#: the relaxation noise of the order sweep is measured at the middle element length by a
#: run with both tolerances 10x tighter (``element_length_tight_check``)
CHECK_FACTOR = 10.0


#: relaxation settings of the fast (default) sweep: coarse-mesh sequencing from 5 m, the
#: cheapest way to the 2 m accuracy and a pick of the recommendation tables of every
#: built-in scene; the other relaxation values are in the full sweep only
FAST_RELAXATION = {"coarse_element_length": (5.0,)}
#: what ``--full`` adds to the fast sweep, in words (the report says it): ~85 % of the
#: full study's time (built-in scenes before the dynamic sweep: fast 26-46 s, full
#: 244-303 s in ``reproduce``), most of it the order sweep at the tight creep tolerance;
#: the dynamic sweep adds 17-27 s to the fast and 45-125 s to the full study
FULL_ADDS = ("the BVP initial-mesh and node-cap rows, the other VFIFE relaxation settings "
             "(time-step safety, static tolerance, coarse meshes of 2 and 20 m, "
             "rotational-inertia scale), the order sweep at tight tolerances "
             "(`element_length_tight`) with its relaxation check "
             "(`element_length_tight_check`), " + FULL_DYNAMICS + ", and " + FULL_ANCF)
#: what the fast sweep runs, in words (the report says it)
FAST_SWEEP = ("the BVP tolerance sweep, the VFIFE element-length sweep at the default "
              "tolerances, mesh sequencing from a 5 m coarse mesh at 2 m, one second "
              "of dynamics per element length, " + FAST_DYNAMICS + ", and " + FAST_ANCF)


@dataclass
class Setting:
    """One run of the study: ``solve_kwargs`` go to the solver's ``solve``,
    ``vfife_changes`` replace settings of the scene's ``[vfife]``."""

    method: str                      # 'bvp' | 'vfife' | 'vfife-dyn'
    setting: str
    value: float
    solve_kwargs: dict = field(default_factory=dict)
    vfife_changes: dict = field(default_factory=dict)


def default_settings(scene: Scene, quick: bool = False, element_lengths=None,
                     asymptotic: float = math.inf, full: bool = False) -> list[Setting]:
    """The runs of the study. By default the fast sweep (:data:`FAST_SWEEP`): the BVP
    tolerance sweep (its finest is the reference), the VFIFE element-length sweep at the
    default tolerances with :data:`FAST_RELAXATION` and one second of dynamics per element
    length. ``full`` (``--full``) adds the dear rows (:data:`FULL_ADDS`): the BVP initial
    mesh and node cap, every VFIFE relaxation setting, and the order sweep at tight
    tolerances (``element_length_tight``) with its relaxation check. ``quick``: a coarse
    subset for tests and development. ``asymptotic`` [m] (see
    :func:`verification.studies.cost.touchdown.asymptotic_length`): the order sweep runs
    :data:`ORDER_LENGTHS` (``element_lengths`` when given), and finer ones of
    ELEMENT_LENGTHS only while fewer than three of its lengths are within the asymptotic
    range."""
    out: list[Setting] = []
    hs = tuple(element_lengths) if element_lengths else (
        (20.0, 10.0, 5.0) if quick else ELEMENT_LENGTHS)
    tols = (1e-3, 1e-6, 1e-8) if quick else BVP_TOLERANCES
    for t in tols:
        out.append(Setting("bvp", "tolerance", t, {"tolerance": t}))
    if full and not quick:
        for n in (50, 100, 400, 1600):
            out.append(Setting("bvp", "initial_nodes", n, {"tolerance": 1e-6, "initial_nodes": n}))
        for n in (300, 600, 1200, 30000):
            out.append(Setting("bvp", "max_nodes", n, {"tolerance": 1e-6, "max_nodes": n}))
    for h in hs:
        out.append(Setting("vfife", "element_length", h, {"element_length": h}))
    hmid = 2.0 if not quick else hs[-1]
    if not quick:
        relax = _relaxation_settings(scene, hmid)
        out += relax if full else [s for s in relax
                                   if s.value in FAST_RELAXATION.get(s.setting, ())]
        if full:
            out += _order_settings(hs, hmid, element_lengths, asymptotic)
        for h in hs:
            out.append(Setting("vfife-dyn", "dynamics_1s_element_length", h,
                               {"element_length": h}))
    return out


def _relaxation_settings(scene: Scene, hmid: float) -> list[Setting]:
    """The VFIFE relaxation settings at element length ``hmid``, each value but the
    scene's own."""
    vf = scene.vfife
    out = []
    for f in (0.2, 0.4, 0.8, 0.95):
        if f != vf.time_step_safety:
            out.append(Setting("vfife", "time_step_safety", f, {"element_length": hmid},
                               {"time_step_safety": f}))
    for tol in (1e-2, 1e-3, 1e-4, 1e-5):
        if tol != vf.static_tolerance:
            out.append(Setting("vfife", "static_tolerance", tol,
                               {"element_length": hmid, "tolerance": tol},
                               {"max_steps": 2_000_000}))
    for hc in (hmid, 5.0, 20.0):
        if hc != vf.coarse_element_length:
            out.append(Setting("vfife", "coarse_element_length", hc,
                               {"element_length": hmid}, {"coarse_element_length": hc}))
    for r in (1.0, 16.0):
        if r != vf.rotational_inertia_scale:
            out.append(Setting("vfife", "rotational_inertia_scale", r,
                               {"element_length": hmid}, {"rotational_inertia_scale": r}))
    return out


def _order_settings(hs: tuple, hmid: float, element_lengths, asymptotic: float) -> list:
    """The order sweep at tight tolerances (``element_length_tight``) and its relaxation
    check at ``hmid`` (``element_length_tight_check``)."""
    out = []
    tight = {"max_steps": 50_000_000, "creep_tolerance": TIGHT_CREEP}
    tight_hs = list(element_lengths) if element_lengths else list(ORDER_LENGTHS)
    for h in sorted((h for h in hs if h < min(tight_hs)), reverse=True):
        if sum(1 for g in tight_hs if g <= asymptotic) >= 3:
            break
        tight_hs.append(h)
    for h in tight_hs:
        out.append(Setting("vfife", "element_length_tight", h,
                           {"element_length": h, "tolerance": TIGHT_TOLERANCE}, tight))
    out.append(Setting("vfife", "element_length_tight_check", hmid,
                       {"element_length": hmid, "tolerance": TIGHT_TOLERANCE / CHECK_FACTOR},
                       {**tight, "creep_tolerance": TIGHT_CREEP / CHECK_FACTOR}))
    return out


def predicted_cost(s: Setting) -> float:
    """Rough predicted cost of a setting [~s on the Yu scenes] (remaining-time estimate)."""
    if s.method == "bvp":
        t = s.solve_kwargs.get("tolerance", 1e-6)
        return 2.0 * 2.0 ** max(0.0, -math.log10(t) - 6.0)
    h = s.solve_kwargs.get("element_length", 2.0)
    if s.method == "vfife-dyn":
        return 0.1 * max(0.3, (2.0 / h) ** 2)
    # the tight creep test costs ~20x the default at 2 m, the 10x tighter check ~40x
    factor = {"element_length_tight": 20.0, "element_length_tight_check": 40.0}.get(
        s.setting, 1.0) * (1.0 if s.setting.startswith("element_length") else 3.0)
    return factor * max(0.3, 2.0 / h)
