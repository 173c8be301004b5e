"""The settings the VFIFE's static relaxation reads (``[vfife]``, ``[vfife.expert]``), in
one frozen record, and the ``static_scheme`` sentence of summary.json (vfife/statics/equilibrium.py)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class RelaxationKnobs:
    """The ``[vfife]`` and ``[vfife.expert]`` settings the relaxation reads, with the
    scene's seabed stiffness and the creep tolerance in metres (their defaults and ranges:
    :class:`riser.model.settings.VFIFESettings`)."""

    safety: float                 # time step / critical step
    rot_scale: float              # factor on the rotational inertia
    max_steps: int                # step budget of the whole relaxation
    coarse_element_length: float  # [m], first mesh of the sequence
    axial_damping: float          # axial dashpot, fraction of critical (0: off)
    damping: float                # x critical of mode 1: coarse mesh and long-mode creep
    damping_fine: float           # ... on the finer meshes
    damping_current: float        # ... on the finer meshes with a current
    creep_tol_m: float            # [m] displacement still to come (0: test off)
    tension_tol: float            # tension still to come, of the largest (0: test off)
    moment_tol: float             # moment still to come, of the largest (0: test off)
    fictitious: bool              # fictitious masses where bending/rotation/seabed limit
    contact_damping: float        # seabed contact damping, fraction of critical (at least)
    continuation_steps: int       # weight ramp steps for an unusable catenary start
    fixed_time_step: float | None  # [s] expert: fixed relaxation step
    seabed_stiffness: float       # [N/m2], 0 without a seabed
    newton: bool = True           # Newton on the final mesh after the first (planar)

    @classmethod
    def of(cls, scene) -> "RelaxationKnobs":
        vf = scene.vfife
        return cls(vf.time_step_safety, vf.rotational_inertia_scale, vf.max_steps,
                   vf.coarse_element_length, vf.static_axial_damping, vf.static_damping,
                   vf.static_damping_fine, vf.static_damping_current,
                   vf.creep_tolerance * float(sum(sg.length for sg in scene.segments)),
                   vf.tension_tolerance, vf.moment_tolerance,
                   vf.static_fictitious_inertia, vf.static_contact_damping,
                   vf.static_weight_continuation_steps, vf.static_time_step,
                   scene.seabed.stiffness if scene.seabed is not None else 0.0,
                   vf.static_newton)


def scheme_text(knobs: RelaxationKnobs, stages: list[float], next_damping: float) -> str:
    """The ``static_scheme`` sentence of summary.json."""
    damp = (f"{knobs.damping:g} x on the first mesh, {next_damping:g} x on the next ones "
            f"(then {knobs.damping:g} x while long modes creep)" if len(stages) > 1
            else f"{knobs.damping:g} x")
    damp += " critical of mode 1"
    return ("catenary start, dynamic relaxation, mesh sequencing "
            f"{' -> '.join(f'{s:g}' for s in stages)} m, viscous mass-proportional damping "
            f"{damp}, axial dashpot {knobs.axial_damping:g} x critical at the "
            f"highest axial frequency (stiffness-proportional), rotational inertia "
            f"x{knobs.rot_scale:g}"
            + (", fictitious nodal masses and rotational inertias where the bending, "
               "rotation or seabed spring would limit the step below the axial one "
               "(contact damping 1 x critical)" if knobs.fictitious else "")
            + ", length-consistent starting shapes; fictitious inertia "
            "and damping only, the equilibrium and the out-of-balance force "
            "(fictitious damping not counted) are unchanged")
