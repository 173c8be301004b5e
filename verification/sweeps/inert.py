"""Sweep keys that cannot change what a sweep solves, refused before anything runs.

A sweep case is the static equilibrium of its scene, solved by the sweep's methods
(:func:`verification.sweeps.case.run_case`: ``solve_scene`` of each method, no dynamics,
no fatigue). A key read only by what a case never runs leaves every case the same; a
sweep varying it would run identical cases and report them as a load-case envelope.
Such a key is refused (one :class:`~riser.errors.SceneError` naming it, exit 2) whether
varied or set under ``[set]``:

- ``environment.waves`` and ``vessel``: the waves load the line and move the vessel (and
  through its RAOs the hang-off) in a dynamic run only; the static hang-off is
  ``ends.hang_off`` (riser/physics/waves.py, riser/physics/vessel.py);
- ``design.fatigue``: the fatigue of a dynamic run (``riser-verify fatigue``);
- ``vfife.time_step``, ``vfife.rotational_inertia_scale_dynamics``: the VFIFE's dynamic
  integration only (riser/model/settings.py; statics has ``static_time_step``);
- a method's settings table (``[bvp]``, ``[vfife]``, ``[analytic]``) when the sweep does
  not run that method, except ``[bvp]`` when the VFIFE converts a touchdown-form case to
  fixed ends from the BVP's solution (:func:`verification.pipeline.vfife_equivalent`).

``[dynamics]`` and ``name`` are refused by the sweep file's reader itself
(:data:`verification.sweeps.file.FIXED_ROOTS`). Keys that change what is solved only
slightly (``[vfife.expert]``: the relaxation's path, not its equilibrium) stay allowed: a
sweep over them is how their effect is measured.
"""

from __future__ import annotations

from riser.model.ends import FixedEnds

#: key-path prefix -> why a static sweep case never reads it
STATIC_INERT = {
    "environment.waves": "waves load the line and move the vessel in a dynamic run only",
    "vessel": "the vessel moves the hang-off through its RAOs in a dynamic run only (the "
              "static hang-off is ends.hang_off)",
    "design.fatigue": "fatigue is computed from a dynamic run (riser-verify fatigue)",
    "vfife.time_step": "it is the dynamic run's time step (statics: vfife.static_time_step)",
    "vfife.rotational_inertia_scale_dynamics": "it scales the rotational inertia of a "
                                               "dynamic run only",
}
#: the settings table of each method
SETTINGS = {"bvp": "bvp", "vfife": "vfife", "analytic": "analytic"}


def _under(key: str, prefix: str) -> bool:
    """``key`` is ``prefix`` or a key below it (``vessel.raos[0].surge`` under ``vessel``)."""
    return key == prefix or key.startswith((prefix + ".", prefix + "["))


def why_inert(key: str, methods, converts: bool) -> str | None:
    """Why ``key`` (a dotted key path) cannot change what a sweep solving statics with
    ``methods`` solves, or None when it can. ``converts``: some case has touchdown-form
    ends and the sweep runs the VFIFE (whose conversion solves the BVP)."""
    for prefix, why in STATIC_INERT.items():
        if _under(key, prefix):
            return why
    for method, table in SETTINGS.items():
        if _under(key, table) and method not in methods:
            if method == "bvp" and converts:
                continue
            return (f"it is a setting of the {method} method, which this sweep does not run "
                    f"(methods: {', '.join(methods)})")
    return None


def message(key: str, why: str) -> str:
    """The refusal's text (after the key)."""
    return (f"{key!r} cannot change what a sweep solves: a sweep solves each case's static "
            f"equilibrium and {why}, so every case would be the same; remove it")


def converts(base_scene, keys, methods) -> bool:
    """Whether the VFIFE of this sweep may convert a case to fixed ends (it then solves
    the BVP of that case's own model, whose settings count): the base scene has a
    touchdown form, or the sweep varies or sets its ends."""
    return "vfife" in methods and (not isinstance(base_scene.ends, FixedEnds)
                                   or any(_under(k, "ends") for k in keys))
