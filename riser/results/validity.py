"""Is a result inside the model it was solved with? Checks every method applies to its
own result, before solving (resolution, motion) and after (strain, water, seabed,
compression, finiteness).

These are checks of inputs and results, not physics: each method still solves its own
equations. A check before solving raises :class:`~riser.errors.SceneError` (exit 2, the
key and the allowed range); a check after solving returns *named* warnings, each a string
``"name: what and where"`` that goes into ``SolveResult.warnings`` (``summary.json`` and
the console; ``--strict`` turns them into exit 1). The names:

- ``axial_strain``: T/EA beyond the line type's ``max_strain`` (default 1 %: a linear EA
  is a small-strain model, a steel pipe yields at ~0.2 %);
- ``above_surface``: the line above the sea surface (y > water_depth): the model is fully
  submerged (no splash zone, no change of buoyancy); during the dynamics, an axis within
  its outer radius of the instantaneous surface (:func:`dynamic_warnings`);
- ``below_seabed``: the line below y = 0 where nothing holds it (no ``[seabed]``, or the
  rigid seabed of the Wang forms beyond the touchdown), or deeper in an elastic seabed
  than the line's diameter (a linear Winkler law no longer describes the soil);
- ``compression``: effective compression in a line type with ``compression = false``
  (chain, rope, slack cable);
- ``bending_strain``: a steel wall's bending strain (OD/2)/R beyond its elastic limit
  SMYS/E (:func:`riser.model.sections.bending_limit`: E from EI and the wall; SMYS the line
  type's ``yield_strength``, else X65 assumed for a wall recognised as steel);
- ``bend_radius``: a bend radius below the line type's ``minimum_bend_radius``;
- ``dynamic_compression`` (dynamics only): effective compression beyond
  :data:`COMPRESSION_NOISE` in a line type that can carry it, where and when;
- ``first_segment_length``: form (b) solved a suspended length far from the file's (not
  for the J-lay form, whose file length includes the line on the seabed).

The solvers add two names of their own: ``resolution`` (VFIFE elements long against the
bending lengths) and ``ignored_input`` (a key the method does not model); the pipeline
adds ``ends_conversion`` to a VFIFE result of a touchdown-form scene whose fixed-ends
equivalent departs from the scene's own model (``verification.pipeline``).

Conventions: SI units; y up from the seabed (y = 0), the surface at ``water_depth``; s the
unstretched arc length from the bottom end.
"""

from __future__ import annotations

import numpy as np

from ..design.part import design_warnings
from ..errors import SceneError
from .profile import Profile
from ..model.scene import Scene, TopTensionEnds
from ..model.sections import bending_limit, segment_index, segment_properties

#: the fewest elements a VFIFE line and each of its segments may have: fewer cannot carry
#: the catenary shape (a 2,800 m SCR in 900 m elements put its touchdown at x = 0) nor a
#: segment's own weight and stiffness
MIN_ELEMENTS_LINE = 10
MIN_ELEMENTS_SEGMENT = 2
#: the most elements a VFIFE line may have: the explicit step shrinks with the element
#: length (axially ~ l, in bending ~ l^2), so a finer mesh runs for hours or exhausts the
#: memory (1e-9 m elements on a 900 m chain: 9e11 elements) instead of answering; the
#: built-in scenes use 1,000-4,000 and the cost study's finest 5,800
MAX_ELEMENTS_LINE = 100_000
#: the fewest elements per slug length ([internal_flow.slug]): the nodes sample the density
#: wave (a 0.5 m slug on 4 m elements aliased into a wave 8 times longer, quietly) and its
#: gradient force is a central difference (8 per wavelength: 10 % low; Liu's shortest
#: slug, 40 m on 4 m elements, has 10)
MIN_ELEMENTS_SLUG = 8
#: effective compression below this fraction of the largest tension is numerical noise
COMPRESSION_NOISE = 1e-3
#: form (b): a solved first-segment length this far (fraction) from the file's is warned
FIRST_SEGMENT_CHANGE = 0.1


def check_resolution(scene: Scene, element_length: float, *, source: str | None = None,
                     key: str = "vfife.element_length") -> None:
    """Refuse (SceneError) an element length [m] too coarse for the line and its
    segments (at least :data:`MIN_ELEMENTS_LINE` elements on the line and
    :data:`MIN_ELEMENTS_SEGMENT` on every segment and :data:`MIN_ELEMENTS_SLUG` per slug
    of an internal slug flow) or too fine to run (at most :data:`MAX_ELEMENTS_LINE` on the
    line)."""
    src = source or scene.source
    total = scene.total_length
    if element_length < total / MAX_ELEMENTS_LINE:
        raise SceneError(src, key, f"must be >= {total / MAX_ELEMENTS_LINE:.4g} m (at most "
                         f"{MAX_ELEMENTS_LINE:,} elements on the {total:g} m line: the "
                         f"explicit time step shrinks with the element length), got "
                         f"{element_length:g}")
    if element_length > total / MIN_ELEMENTS_LINE:
        raise SceneError(src, key, f"must be <= {total / MIN_ELEMENTS_LINE:.4g} m (at least "
                         f"{MIN_ELEMENTS_LINE} elements on the {total:g} m line, to carry its "
                         f"shape), got {element_length:g}")
    i = int(np.argmin([seg.length for seg in scene.segments]))
    shortest = scene.segments[i].length
    if element_length > shortest / MIN_ELEMENTS_SEGMENT:
        raise SceneError(src, key, f"must be <= {shortest / MIN_ELEMENTS_SEGMENT:.4g} m (at "
                         f"least {MIN_ELEMENTS_SEGMENT} elements on segments[{i}], "
                         f"{shortest:g} m long), got {element_length:g}")
    flow = scene.internal_flow
    if flow is not None and flow.has_slug and element_length > (
            flow.slug_length / MIN_ELEMENTS_SLUG):
        raise SceneError(src, key, f"must be <= {flow.slug_length / MIN_ELEMENTS_SLUG:.4g} m "
                         f"(at least {MIN_ELEMENTS_SLUG} elements per slug, "
                         f"internal_flow.slug.slug_length = {flow.slug_length:g} m), got "
                         f"{element_length:g}")


def check_end_loads(scene: Scene) -> None:
    """Before solving (raises SceneError): a tensioner pulls harder than the line and its
    attachments weigh (submerged; otherwise the bottom is in compression and a slender
    riser buckles), and no buoy lifts a hanging line with a free end (the line and the
    attachments below every point weigh more than zero there, or it floats up)."""
    e = scene.ends
    t = getattr(e, "tensioner", None)
    free = getattr(e, "free_anchor", False)
    if t is None and not free:
        return
    props = segment_properties(scene)
    g, rho = scene.gravity, scene.water_density
    points = sorted(((a.s, a.net_weight(g, rho), i) for i, a in enumerate(scene.attachments)))
    weight = sum(p.weight * p.length for p in props) + sum(w for _, w, _ in points)
    if t is not None and t.top_tension <= weight:
        raise SceneError(scene.source, "ends.tensioner.top_tension", f"must exceed the "
                         f"submerged weight of the line and its attachments {weight:.6g} N "
                         f"(the bottom would be in compression), got {t.top_tension:g}")
    if free:
        starts = np.array([p.s_start for p in props])
        w = np.array([p.weight for p in props])

        def line_below(s):           # the line's submerged weight from the free end to s
            return float(sum(wk * min(max(s - s0, 0.0), p.length)
                             for wk, s0, p in zip(w, starts, props)))
        hung = 0.0
        for s, wp, i in points:
            hung += wp
            if line_below(s) + hung <= 0.0:
                raise SceneError(scene.source, f"attachments[{i}].volume", "lifts the "
                                 "hanging line: the line and the attachments below it weigh "
                                 f"{line_below(s) + hung:.6g} N in water (a free end would "
                                 "float up: no equilibrium)")
        if weight <= 0.0:
            raise SceneError(scene.source, "ends.anchor_joint.kind", f"'free': the line "
                             f"and its attachments weigh {weight:.6g} N in water (it would "
                             "float up: no equilibrium)")


def nonfinite(profile: Profile) -> str | None:
    """The reason a profile cannot be a result (NaN/inf in it), else None."""
    for name in ("s", "x", "y", "z", "tension", "moment"):
        v = getattr(profile, name)
        if v is not None and not np.all(np.isfinite(v)):
            return f"non-finite {name} in the result (NaN/inf): the solution is not valid"
    return None


def _segment_index(scene: Scene, s: np.ndarray, lengths=None) -> np.ndarray:
    """Index of the segment holding each arc length s [m] (``lengths``: the segment
    lengths as solved, default the scene's)."""
    return segment_index(scene, s, lengths)


def _where(s: float) -> str:
    return f"at s = {s:.1f} m"


def line_warnings(scene: Scene, s: np.ndarray, y_min: np.ndarray, y_max: np.ndarray,
                  t_min: np.ndarray, t_max: np.ndarray, lengths=None,
                  when: str = "", surface: bool = False,
                  still_water: bool = True) -> list[str]:
    """Named warnings for a line whose stations at arc lengths ``s`` [m] reach heights
    ``y_min``..``y_max`` [m] and effective tensions ``t_min``..``t_max`` [N] (one state:
    equal pairs; a dynamic run: the extremes over time). ``when``: e.g. ' during the
    dynamics'. ``surface``: the run modelled the sea surface (the VFIFE dynamics), so
    leaving the water is a statement, not a model violation. ``still_water`` False: no
    above_surface check against the still water level (a dynamic run's envelope checks
    the instantaneous surface, :func:`dynamic_warnings`)."""
    out = []
    seg = _segment_index(scene, s, lengths)
    lts = [scene.line_types[g.line_type] for g in scene.segments]
    scale = max(float(np.max(np.abs(t_max))), float(np.max(np.abs(t_min))), 1.0)
    if scene.axial_model == "extensible":
        ea = np.array([lts[i].axial_stiffness for i in seg])
        lim = np.array([lts[i].max_strain for i in seg])
        strain = np.maximum(np.abs(t_max), np.abs(t_min)) / ea
        j = int(np.argmax(strain / lim))
        if strain[j] > lim[j]:
            out.append(f"axial_strain: T/EA = {100 * strain[j]:.3g} % {_where(s[j])}{when}, "
                       f"beyond the {100 * lim[j]:g} % of line type "
                       f"{lts[seg[j]].name!r} (max_strain; a linear EA is a small-strain "
                       "model): check the line length, the ends and axial_stiffness")
    if scene.water_depth is not None and still_water:
        j = int(np.argmax(y_max))
        if y_max[j] > scene.water_depth * (1.0 + 1e-9):
            wet = np.sum(y_max > scene.water_depth * (1.0 + 1e-9))
            what = (f"{wet} node(s) leave the water (modelled: in air a node carries its "
                    "weight in air, with no buoyancy, drag or added mass)" if surface else
                    "the model is fully submerged")
            out.append(f"above_surface: the line reaches y = {y_max[j]:.6g} m {_where(s[j])}"
                       f"{when}, above the sea surface (water_depth {scene.water_depth:g} m); "
                       + what)
    j = int(np.argmin(y_min))
    depth = -float(y_min[j])
    tol = 1e-6 * max(scene.total_length, 1.0)
    if scene.seabed_model == "elastic":
        D = lts[seg[j]].outer_diameter
        if depth > D:
            out.append(f"below_seabed: {depth:.3g} m into the elastic seabed {_where(s[j])}"
                       f"{when}, more than the line's diameter {D:g} m: a linear Winkler "
                       "seabed does not describe that; check [seabed] stiffness")
    elif depth > tol:
        why = ("the scene has no [seabed]" if scene.seabed_model is None else
               "the rigid seabed of this end form holds only the touchdown")
        out.append(f"below_seabed: the line passes {depth:.3g} m below the seabed y = 0 "
                   f"{_where(s[j])}{when}; {why}")
    weak = np.array([not lts[i].compression for i in seg])
    if np.any(weak):
        tw = np.where(weak, t_min, np.inf)
        j = int(np.argmin(tw))
        if tw[j] < -COMPRESSION_NOISE * scale:
            out.append(f"compression: effective tension {tw[j] / 1e3:.4g} kN {_where(s[j])}"
                       f"{when} in line type {lts[seg[j]].name!r}, which cannot carry "
                       "compression (compression = false)")
    return out


def profile_warnings(scene: Scene, profile: Profile, lengths=None) -> list[str]:
    """Named warnings for a static profile (see :func:`line_warnings`,
    :func:`bending_warnings` on its curvature), and the
    ``ignored_input`` of [design] keys the chosen code does not read."""
    return line_warnings(scene, profile.s, profile.y, profile.y, profile.tension,
                         profile.tension, lengths) + bending_warnings(
        scene, profile.s, profile.curvature, lengths) + design_warnings(scene)


def _at_time(times, j: int) -> str:
    """' at t = 12.5 s' from per-station times [s] (None: a static state, no time)."""
    if times is None or not np.isfinite(times[j]):
        return ""
    return f" at t = {float(times[j]):.4g} s"


def bending_warnings(scene: Scene, s: np.ndarray, curvature: np.ndarray, lengths=None,
                     when: str = "", times=None) -> list[str]:
    """Named warnings for a line bent at stations ``s`` [m] to curvatures ``curvature``
    [1/m] (a static profile's, or a dynamic run's largest over time, reached at
    ``times`` [s]) beyond its line types' :func:`riser.model.sections.bending_limit`:

    - ``bending_strain``: the wall's bending strain (OD/2) kappa beyond the elastic limit
      SMYS / E of a steel line type (the worst station relative to its limit);
    - ``bend_radius``: the bend radius 1/kappa below a line type's
      ``minimum_bend_radius``.
    """
    out = []
    k = np.abs(np.asarray(curvature, float))
    if k.size == 0 or not np.all(np.isfinite(k)):
        return out
    seg = _segment_index(scene, s, lengths)
    lts = [scene.line_types[g.line_type] for g in scene.segments]
    limits = [bending_limit(lt) for lt in lts]
    D = np.array([lts[i].outer_diameter for i in seg])
    elastic = np.array([np.inf if limits[i].strain is None else limits[i].strain
                        for i in seg])
    strain = 0.5 * D * k
    ratio = strain / elastic
    j = int(np.argmax(ratio))
    if ratio[j] > 1.0:
        lim = limits[seg[j]]
        out.append(f"bending_strain: (OD/2)/R = {100 * strain[j]:.3g} % (bend radius "
                   f"{1.0 / k[j]:.4g} m) {_where(s[j])}{_at_time(times, j)}{when}, beyond the "
                   f"elastic limit SMYS/E = {100 * elastic[j]:.3g} % (bend radius "
                   f"{lim.strain_radius(D[j]):.4g} m) of line type {lts[seg[j]].name!r} "
                   f"({lim.basis}): check the end angles (direction_deg is in degrees), "
                   "the ends and the loads")
    mbr = np.array([0.0 if limits[i].radius is None else limits[i].radius for i in seg])
    ratio = mbr * k
    j = int(np.argmax(ratio))
    if ratio[j] > 1.0:
        out.append(f"bend_radius: {1.0 / k[j]:.4g} m {_where(s[j])}{_at_time(times, j)}"
                   f"{when}, below the minimum_bend_radius {mbr[j]:g} m of line type "
                   f"{lts[seg[j]].name!r}")
    return out


def dynamic_warnings(scene: Scene, envelope: dict) -> list[str]:
    """Named warnings over a dynamic run's envelope (columns along s, the extremes over
    the statistics window; see :mod:`riser.results.result`): those of :func:`line_warnings` on
    the heights and tensions, :func:`bending_warnings` on ``curvature_max`` (when:
    ``curvature_max_time``), and

    - ``dynamic_compression``: effective compression in a line type that can carry it
      (``compression`` warns for those that cannot) beyond :data:`COMPRESSION_NOISE` of
      the largest tension: the least ``tension_min`` [N], where and when
      (``tension_min_time``): a slender line buckles, and a line that goes slack snaps;
    - ``above_surface``: with the ``submergence_min`` column (the least depth [m] of the
      line's axis below the instantaneous sea surface), a station whose axis comes within
      its outer radius of the surface (its wall breaks the surface: leaves the water),
      where and when (``submergence_min_time``), the hang-off named; without it, the
      height above the still water level of :func:`line_warnings`.

    The times are those of the run's own sampling (the envelope interval)."""
    when = " during the dynamics"
    e = envelope
    s = np.asarray(e["s"], float)
    t_min, t_max = np.asarray(e["tension_min"], float), np.asarray(e["tension_max"], float)
    sub = e.get("submergence_min")
    out = line_warnings(scene, s, e["y_min"], e["y_max"], t_min, t_max, when=when,
                        surface=True, still_water=sub is None)
    seg = _segment_index(scene, s)
    lts = [scene.line_types[g.line_type] for g in scene.segments]
    scale = max(float(np.max(np.abs(t_max))), float(np.max(np.abs(t_min))), 1.0)
    strong = np.array([lts[i].compression for i in seg])
    tw = np.where(strong, t_min, np.inf)
    j = int(np.argmin(tw))
    if tw[j] < -COMPRESSION_NOISE * scale:
        out.append(f"dynamic_compression: effective tension {tw[j] / 1e3:.4g} kN "
                   f"{_where(s[j])}{_at_time(e.get('tension_min_time'), j)}{when} "
                   f"(line type {lts[seg[j]].name!r}; the hang-off's least "
                   f"{t_min[-1] / 1e3:.4g} kN): a slender line buckles, a slack one "
                   "snaps; check the motion, the waves and the top tension")
    if sub is not None and scene.water_depth is not None:
        sub = np.asarray(sub, float)
        radius = 0.5 * np.array([lts[i].outer_diameter for i in seg])
        out_of_water = sub < radius
        if np.any(out_of_water):
            j = int(np.argmin(sub - radius))
            def depth(i: int) -> str:
                return (f"{sub[i] + 0.0:.3g} m below" if sub[i] >= 0.0 else
                        f"{-sub[i]:.3g} m above")
            top = (f"; the hang-off's axis {depth(-1)} it"
                   f"{_at_time(e.get('submergence_min_time'), len(s) - 1)}"
                   if j != len(s) - 1 else " (the hang-off)")
            out.append(f"above_surface: the line's axis comes {depth(j)} the instantaneous "
                       f"sea surface {_where(s[j])}"
                       f"{_at_time(e.get('submergence_min_time'), j)}{when}{top}, within "
                       f"its outer radius {radius[j]:.4g} m: {int(np.sum(out_of_water))} "
                       "station(s) leave the water (modelled: in air a node carries its "
                       "weight in air, with no buoyancy, drag or added mass)")
    if "curvature_max" in e:
        out.extend(bending_warnings(scene, s, e["curvature_max"], when=when,
                                    times=e.get("curvature_max_time")))
    return out


def first_segment_warnings(scene: Scene, solved: float) -> tuple[str, list[str]]:
    """Form (b): a sentence saying the first segment's suspended length was solved
    [m], and a named warning when it is far from the file's. The J-lay form
    ('top_tension'): the file's length is the pipe available, the suspended part plus what
    lies on the seabed; the sentence says both (a solver finds no equilibrium when the
    suspended part is longer), no warning."""
    given = scene.segments[0].length
    diff = solved - given
    if isinstance(scene.ends, TopTensionEnds):
        if solved > given:
            return (f"the solved suspended length of segments[0], {solved:.3f} m, exceeds its "
                    f"length in the file, {given:g} m, the pipe available (the suspended part "
                    "plus what lies on the seabed): lengthen segments[0] or lower "
                    "top_tension"), []
        return (f"segments[0] suspended length solved: {solved:.3f} m; {-diff:.3f} m of the "
                f"file's {given:g} m lies on the seabed"), []
    note = (f"segments[0] suspended length solved: {solved:.3f} m (the file gives "
            f"{given:g} m; {diff:+.3f} m, {100 * diff / given:+.2f} %)")
    warn = []
    if abs(diff) > FIRST_SEGMENT_CHANGE * given:
        warn.append(f"first_segment_length: {note}, more than {100 * FIRST_SEGMENT_CHANGE:g} "
                    "% off: check the hang-off angle (hang_off_angle_from_horizontal_deg or "
                    "_from_vertical_deg) and height")
    return note, warn
