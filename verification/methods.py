"""The methods of the suite, by name: the one table every command, study and comparison
reaches a method through (:data:`METHODS`, :func:`method`).

A method is a package beside ``riser/`` (``bvp/``, ``vfife/``, ``analytic/``) that imports
only ``riser`` (the shared inputs and results) and offers some of these entry points, each
a plain function of the package, wrapped below by a function that imports it when first
called (loading a solver costs ~1.5 s: ``riser-verify scenes`` or a refusal of bad input
loads none):

- ``solve(scene, **overrides) -> riser.results.result.SolveResult``: statics, and the time domain
  when the scene has ``[dynamics]`` and the method has ``time_domain`` (its solve then takes
  ``observers=``, told of every sample of its recorder);
- ``modes(scene, count, *, static=None, progress=None) -> riser.results.modes.ModalResult``;
- the frequency domain about the static state (the BVP): ``harmonic`` (one period, a
  top motion or a wave), ``transfer`` (a sweep of periods along one axis of motion), ``sea``
  (an irregular sea's spectral response) and their ``require_*`` refusals.

The design checks (``riser.design``) are post-processing of a result, run here once after
the solve (:func:`after_design`): the static profile's columns, and a time domain's samples
through an observer of its recorder. No method imports them.

Adding a method (ARCHITECTURE.md, "Adding a method"): its folder, its wrappers and one
:class:`Method` line here, its column in the comparisons. ``tests/test_layers.py`` holds
that a module of ``verification/`` calls a method's entry points only through this table
(an import of ``bvp``, ``vfife``, ``analytic`` or their modal and frequency-domain modules
anywhere else fails it); a method's other modules (its mesh, its bench, its time step) are
its internals, which the studies and benches about that method may read.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Callable


@dataclass(frozen=True)
class Method:
    """A method of the suite.

    name : ``SolveResult.method``, ``--method NAME``, the method's column in a comparison.
    summary : one line on what it is.
    solve : ``solve(scene, **overrides)``, a :class:`riser.results.result.SolveResult` with
        the design checks of a scene with [design] (the method's own solve wrapped by
        :func:`after_design`).
    overrides : the settings a caller may override per solve (``tolerance``: the BVP's
        solve_bvp tolerance; ``element_length`` [m]: the VFIFE's).
    fixed_ends_only : it solves fixed-ends scenes only; a scene in a touchdown form is
        converted first (``verification.pipeline.vfife_equivalent``).
    progress : its ``solve`` (and ``modes``) take ``progress=`` (riser.callbacks).
    time_domain : its ``solve`` integrates a scene's ``[dynamics]`` in time.
    modes : ``modes(scene, count, *, static=None, progress=None)`` or None.
    harmonic, transfer, sea, require_harmonic, require_wave : the frequency domain about
        the static state (None: the method has none).
    """

    name: str
    summary: str
    solve: Callable
    overrides: tuple[str, ...] = ()
    fixed_ends_only: bool = False
    progress: bool = False
    time_domain: bool = False
    modes: Callable | None = None
    harmonic: Callable | None = None
    transfer: Callable | None = None
    sea: Callable | None = None
    require_harmonic: Callable | None = None
    require_wave: Callable | None = None


def after_design(solve: Callable, observes: bool = False) -> Callable:
    """``solve`` followed by the design checks of its result, once: a static profile's
    columns (:func:`riser.design.checks.with_design`) and, with ``observes`` (a time
    domain whose solve takes ``observers=``), the dynamic run's samples through
    :class:`riser.design.dynamic.DynamicDesign` watching its recorder; then the bend check
    of a scene that states a bending limit, with or without [design]
    (:func:`riser.design.bending.with_bending`: the profile's and the envelope's
    curvatures). A scene without [design] and without a limit runs ``solve`` alone."""
    @functools.wraps(solve)
    def solve_then_check(scene, **overrides):
        from riser.design.bending import with_bending
        if scene.design is None:
            return with_bending(scene, solve(scene, **overrides))
        from riser.design.checks import with_design
        if observes and scene.dynamics is not None:
            overrides = {**overrides,
                         "observers": (*overrides.get("observers", ()),
                                       *design_observers(scene))}
        return with_bending(scene, with_design(scene, solve(scene, **overrides)))
    return solve_then_check


def design_observers(scene) -> tuple:
    """The observers a time-domain run of ``scene`` hands its recorder for the design
    checks: a fresh :class:`riser.design.dynamic.DynamicDesign` with [design], else none
    (also for a run continued from a checkpoint outside the registry's solve)."""
    if scene.design is None:
        return ()
    from riser.design.dynamic import DynamicDesign
    return (DynamicDesign(scene),)


# --------------------------------------------------------------------------------- the BVP
def _bvp_solve(scene, **overrides):
    import bvp
    return bvp.solve(scene, **overrides)


def _bvp_modes(scene, count=10, **kwargs):
    from bvp.modal.modes import solve_modes
    return solve_modes(scene, count, **kwargs)


def _bvp_harmonic(scene, period=None, motion=None, **kwargs):
    from bvp.frequency.harmonic import solve_harmonic
    return solve_harmonic(scene, period, motion, **kwargs)


def _bvp_transfer(scene, periods, axis, **kwargs):
    from bvp.frequency.harmonic import transfer_sweep
    return transfer_sweep(scene, periods, axis, **kwargs)


def _bvp_sea(scene, **kwargs):
    from bvp.frequency.sea_response import solve_sea
    return solve_sea(scene, **kwargs)


def _bvp_require_harmonic(scene, motion):
    from bvp.frequency.harmonic import require_harmonic
    return require_harmonic(scene, motion)


def _bvp_require_wave(scene):
    from bvp.frequency.harmonic import require_wave
    return require_wave(scene)


# ------------------------------------------------------------------------------- the VFIFE
def _vfife_solve(scene, **overrides):
    import vfife
    return vfife.solve(scene, **overrides)


def _vfife_modes(scene, count=10, **kwargs):
    from vfife.modal.modes import solve_modes
    return solve_modes(scene, count, **kwargs)


# -------------------------------------------------------------------------------- the ANCF
def _ancf_solve(scene, **overrides):
    import ancf
    return ancf.solve(scene, **overrides)


def _ancf_modes(scene, count=10, **kwargs):
    from ancf.modal import solve_modes
    return solve_modes(scene, count, **kwargs)


# ---------------------------------------------------------------------------- the analytic
def _analytic_solve(scene, **overrides):
    import analytic
    return analytic.solve(scene, **overrides)


#: the methods, by name (iterating gives the names, in the comparisons' column order)
METHODS: dict[str, Method] = {m.name: m for m in (
    Method("bvp", "large-deformation beam equations, scipy solve_bvp", after_design(_bvp_solve),
           overrides=("tolerance",), modes=_bvp_modes, harmonic=_bvp_harmonic,
           transfer=_bvp_transfer, sea=_bvp_sea, require_harmonic=_bvp_require_harmonic,
           require_wave=_bvp_require_wave),
    Method("vfife", "vector form intrinsic finite elements, dynamic relaxation and dynamics",
           after_design(_vfife_solve, observes=True), overrides=("element_length",),
           fixed_ends_only=True, progress=True, time_domain=True, modes=_vfife_modes),
    Method("analytic", "extensible catenary with matched boundary layers, closed form",
           after_design(_analytic_solve)),
    Method("ancf", "absolute nodal coordinate formulation (Liu et al. 2021), Newton statics "
           "and implicit dynamics", after_design(_ancf_solve, observes=True),
           overrides=("element_length", "tolerance"), fixed_ends_only=True, progress=True,
           time_domain=True, modes=_ancf_modes),
)}


def method(name: str) -> Method:
    """The method called ``name``; ``ValueError`` naming the methods otherwise."""
    try:
        return METHODS[name]
    except KeyError:
        raise ValueError(f"method must be one of {tuple(METHODS)}, got {name!r}") from None
