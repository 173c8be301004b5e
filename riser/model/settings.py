"""Solver settings of a scene: typed, frozen, validated, each default written once.

``[bvp]`` becomes :class:`BVPSettings`, ``[analytic]`` :class:`AnalyticSettings` and
``[vfife]`` (with its ``[vfife.expert]`` sub-table) :class:`VFIFESettings`. Every field is
declared with :func:`riser.spec.spec` (its range, unit and meaning); the same spec checks
the scene file and any programmatic change (``scene.vfife.replace(static_damping=...)``),
so a bad value gets the same one-line :class:`~riser.errors.SceneError` naming the key
(``vfife.expert.static_damping``) wherever it comes from.

Expert knobs (``[vfife.expert]``) tune the dynamic relaxation; they change how fast the
static solve converges, never the equilibrium it converges to (see vfife/statics/equilibrium.py).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .line import MAX_SEGMENT_LENGTH
from ..spec import Part, spec

EXPERT = "expert"


class _Settings(Part):
    """A frozen settings dataclass: a scene table of its own name (``KEY_PREFIX``)."""

    UNKNOWN = "unknown setting"

    def override(self, **values: Any):
        """A validated copy with the settings given a value (``None``: keep this one's),
        e.g. the overrides a caller passes to a solver."""
        return self.replace(**{k: v for k, v in values.items() if v is not None})


@dataclass(frozen=True)
class BVPSettings(_Settings):
    """``[bvp]``: settings of ``scipy.integrate.solve_bvp`` (bvp/solver.py)."""

    KEY_PREFIX = "bvp"
    tolerance: float = spec(1.0e-6, ge=1.0e-12, le=1.0e-1,
                             doc="solve_bvp tolerance on the relative collocation residual")
    max_nodes: int = spec(30000, "integer", ge=100, le=1_000_000,
                           doc="largest mesh solve_bvp may refine to")
    initial_nodes: int = spec(400, "integer", ge=20, le=100_000,
                               doc="nodes of the starting mesh on the line (shared by "
                                   "length, at least 8 a segment, clustered at its ends)")
    memory_budget: float = spec(2.0, gt=0.0, le=1.0e4, unit="GB",
                                 doc="largest memory solve_bvp may take, estimated at "
                                     "max_nodes before solving: a larger problem is "
                                     "refused")


@dataclass(frozen=True)
class AnalyticSettings(_Settings):
    """``[analytic]``: which model the analytic method evaluates (analytic/composite.py)."""

    KEY_PREFIX = "analytic"
    model: str = spec("composite", "string", choices=("composite", "piecewise", "catenary"),
                       doc="composite asymptotic solution, Kang's piecewise model, or the "
                           "catenary alone")
    curvature_threshold: float | None = spec(
        None, gt=0.0, le=10.0, unit="1/m",
        doc="piecewise model: catenary curvature [1/m] below which the catenary takes over "
            "from the beam (default: half the catenary's touchdown curvature w/H)")


@dataclass(frozen=True)
class VFIFESettings(_Settings):
    """``[vfife]`` and ``[vfife.expert]``: settings of the VFIFE solver (vfife/)."""

    KEY_PREFIX = "vfife"
    element_length: float = spec(1.0, gt=0.0, le=1000.0, unit="m",
                                  doc="target element length [m]")
    time_step_safety: float = spec(0.8, gt=0.0, le=1.0,
                                    doc="time step as a fraction of the critical step")
    static_tolerance: float = spec(1.0e-3, gt=0.0, le=1.0,
                                    doc="converged when the largest nodal out-of-balance force "
                                        "is below this fraction of one element's weight")
    max_steps: int = spec(5_000_000, "integer", ge=1, le=10**9,
                           doc="step budget of the static relaxation")
    coarse_element_length: float = spec(10.0, gt=0.0, le=1000.0, unit="m",
                                         doc="first mesh of the mesh sequence [m]")
    rotational_inertia_scale: float = spec(4.0, ge=1.0, le=1.0e6,
                                            doc="statics: factor on the rotational inertia")
    seabed_length: float = spec(300.0, ge=0.0, le=MAX_SEGMENT_LENGTH, unit="m",
                                 doc="line laid on the seabed ahead of the touchdown when a "
                                     "Wang-form scene is converted to fixed ends [m]")
    rotational_inertia_scale_dynamics: float = spec(
        4.0, gt=0.0, le=1.0e6, doc="dynamics: factor on the physical rotational inertia (1 = "
        "physical; 4 makes the step axial-limited, see vfife/dynamics/run.py)")
    time_step: float | None = spec(None, gt=0.0, le=10.0, unit="s",
                                    doc="dynamics: fixed time step [s] instead of safety x "
                                        "critical step")
    static_time_step: float | None = spec(None, gt=0.0, le=10.0, unit="s",
                                           doc="statics: fixed relaxation step [s] (above the "
                                               "critical step the relaxation diverges and "
                                               "says so)")
    clamped_ends: tuple = spec((), "strings", choices=("bottom", "top"),
                                doc="ends whose rotation is clamped (default: pinned)")
    # expert knobs of the dynamic relaxation ([vfife.expert]); see vfife/statics/equilibrium.py
    static_damping: float = spec(3.0, table=EXPERT, gt=0.0, le=1.0e4,
                                  doc="relaxation damping, multiple of critical of mode 1")
    static_damping_fine: float = spec(30.0, table=EXPERT, gt=0.0, le=1.0e4,
                                       doc="... its starting value on the finer meshes")
    static_damping_current: float = spec(10.0, table=EXPERT, gt=0.0, le=1.0e4,
                                          doc="... on the finer meshes with a current")
    creep_tolerance: float = spec(1.0e-5, table=EXPERT, ge=0.0, le=1.0,
                                   doc="remaining-displacement tolerance, fraction of the "
                                       "line length (0 turns the creep test off)")
    tension_tolerance: float = spec(1.0e-5, table=EXPERT, ge=0.0, le=1.0,
                                     doc="change still to come of every element tension, "
                                         "fraction of the largest (0 turns the test off)")
    moment_tolerance: float = spec(5.0e-4, table=EXPERT, ge=0.0, le=1.0,
                                    doc="change still to come of every element end moment, "
                                        "fraction of the largest (0 turns the test off)")
    static_axial_damping: float = spec(0.1, table=EXPERT, ge=0.0, le=100.0,
                                        doc="axial dashpot, fraction of critical at the "
                                            "highest axial frequency (0: off)")
    static_fictitious_inertia: bool = spec(True, "boolean", table=EXPERT,
                                            doc="fictitious masses where bending, rotation or "
                                                "the seabed would limit the step")
    static_contact_damping: float = spec(1.0, table=EXPERT, ge=0.0, le=100.0,
                                          doc="seabed contact damping in statics, fraction "
                                              "of critical (at least; the scene's if higher)")
    static_weight_continuation_steps: int = spec(10, "integer", table=EXPERT, ge=0, le=1000,
                                                  doc="weight ramp steps when the catenary "
                                                      "start is unusable (0: off)")
    static_newton: bool = spec(True, "boolean", table=EXPERT,
                               doc="solve the finer meshes of a statics by Newton's "
                                   "method (relaxed where seabed friction is engaged; "
                                   "false: relax every mesh of the sequence)")


@dataclass(frozen=True)
class ANCFSettings(_Settings):
    """``[ancf]``: settings of the ANCF solver (ancf/): its mesh, the Newton statics' test
    and the implicit time integration."""

    KEY_PREFIX = "ancf"
    element_length: float = spec(2.0, gt=0.0, le=1000.0, unit="m",
                                  doc="target element length [m] (cubic elements: several "
                                      "times the VFIFE's for the same accuracy)")
    gauss_points: int = spec(5, "integer", ge=3, le=12,
                              doc="Gauss points per element (elastic forces, loads, mass)")
    static_tolerance: float = spec(1.0e-6, gt=0.0, le=1.0e-2,
                                    doc="Newton statics: converged when the largest nodal "
                                        "out-of-balance force is below this fraction of the "
                                        "load scale (see ancf/statics/newton.py)")
    max_iterations: int = spec(200, "integer", ge=1, le=10_000,
                                doc="Newton iterations per load step (statics) before the "
                                    "step is halved")
    integrator: str = spec("generalised-alpha", "string",
                           choices=("generalised-alpha", "newmark"),
                           doc="dynamics: generalised-alpha (Chung-Hulbert) or Newmark's "
                               "average acceleration (Liu et al.)")
    rho_inf: float = spec(0.8, ge=0.0, le=1.0,
                          doc="dynamics: generalised-alpha's spectral radius at infinite "
                              "frequency (1: no numerical damping)")
    time_step: float | None = spec(None, gt=0.0, le=10.0, unit="s",
                                    doc="dynamics: time step [s] (default: the excitation's "
                                        "shortest period / steps_per_period)")
    steps_per_period: int = spec(100, "integer", ge=8, le=100_000,
                                  doc="dynamics: steps per period of the excitation when "
                                      "time_step is not given")
