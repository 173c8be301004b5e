"""Solver settings of a scene: typed, frozen, validated, each default written once.

``[bvp]`` becomes :class:`BVPSettings`, ``[analytic]`` :class:`AnalyticSettings` and
``[vfife]`` (with its ``[vfife.expert]`` sub-table) :class:`VFIFESettings`. Every field carries its range and unit in its metadata;
the same spec validates the scene file and any programmatic change
(``scene.vfife.replace(static_damping=...)``), so a bad value gets the same one-line
:class:`~riser.errors.SceneError` naming the key wherever it comes from.

Expert knobs (``[vfife.expert]``) tune the dynamic relaxation; they change how fast the
static solve converges, never the equilibrium it converges to (see vfife/statics.py).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any

from .errors import SceneError
from .io.toml_table import Table

#: the longest segment a scene may hold [m] (riser.scene.LIMITS["length"])
MAX_SEGMENT_LENGTH = 5.0e4


def _knob(default: Any, kind: str = "number", *, expert: bool = False, doc: str = "",
          **bounds: Any):
    """A settings field: ``kind`` 'number' | 'integer' | 'boolean' | 'string' | 'strings';
    ``bounds`` are the Table getter's (gt, ge, le, unit, choices)."""
    return field(default=default,
                 metadata={"kind": kind, "expert": expert, "doc": doc, "bounds": bounds})


class _Settings:
    """Shared reading and validation of a frozen settings dataclass."""

    TABLE = ""            # the scene table, e.g. 'vfife'

    def __post_init__(self) -> None:
        _validate(self, "<settings>")

    def replace(self, **changes: Any):
        """A validated copy with some settings changed."""
        unknown = sorted(set(changes) - {f.name for f in dataclasses.fields(self)})
        if unknown:
            raise SceneError("<settings>", f"{self.TABLE}.{unknown[0]}", "unknown setting "
                             f"(known: {', '.join(f.name for f in dataclasses.fields(self))})")
        return dataclasses.replace(self, **changes)

    def override(self, **values: Any):
        """A validated copy with the settings given a value (``None``: keep this one's),
        e.g. the overrides a caller passes to a solver."""
        return self.replace(**{k: v for k, v in values.items() if v is not None})

    @classmethod
    def read(cls, t: Table | None):
        """The settings of a scene table (``None``: all defaults); raises SceneError."""
        if t is None:
            return cls()
        expert_t = t.table("expert") if any(f.metadata["expert"]
                                            for f in dataclasses.fields(cls)) else None
        values = {}
        for f in dataclasses.fields(cls):
            src = expert_t if f.metadata["expert"] else t
            if src is None:
                continue
            v = _get(src, f)
            if v is not None:
                values[f.name] = v
        if expert_t is not None:
            expert_t.finish()
        t.finish()
        return cls(**values)


def _get(t: Table, f: dataclasses.Field) -> Any:
    kind, bounds = f.metadata["kind"], f.metadata["bounds"]
    default = f.default if f.default is not None else None
    if kind == "number":
        return t.number(f.name, default, **bounds)
    if kind == "integer":
        return t.integer(f.name, default, **bounds)
    if kind == "boolean":
        return t.boolean(f.name, default)
    if kind == "string":
        return t.string(f.name, default, **bounds)
    return t.strings(f.name, default, **bounds)


def _validate(obj, source: str) -> None:
    """Check every field of ``obj`` against its spec (the scene file's rules)."""
    data = {}
    for f in dataclasses.fields(obj):
        v = getattr(obj, f.name)
        if v is None:
            continue
        data[f.name] = list(v) if isinstance(v, tuple) else v
    table = Table(data, obj.TABLE, source)
    for f in dataclasses.fields(obj):
        if f.name in data:
            v = _get(table, f)
            if f.metadata["kind"] == "integer" or isinstance(v, tuple):
                object.__setattr__(obj, f.name, v)


@dataclass(frozen=True)
class BVPSettings(_Settings):
    """``[bvp]``: settings of ``scipy.integrate.solve_bvp`` (bvp/solver.py)."""

    TABLE = "bvp"
    tolerance: float = _knob(1.0e-6, ge=1.0e-12, le=1.0e-1,
                             doc="solve_bvp tolerance on the relative collocation residual")
    max_nodes: int = _knob(30000, "integer", ge=100, le=1_000_000,
                           doc="largest mesh solve_bvp may refine to")
    initial_nodes: int = _knob(400, "integer", ge=20, le=100_000,
                               doc="nodes of the starting mesh (clustered at the ends)")


@dataclass(frozen=True)
class AnalyticSettings(_Settings):
    """``[analytic]``: which model the analytic method evaluates (analytic/composite.py)."""

    TABLE = "analytic"
    model: str = _knob("composite", "string", choices=("composite", "piecewise", "catenary"),
                       doc="composite asymptotic solution, Kang's piecewise model, or the "
                           "catenary alone")
    curvature_threshold: float | None = _knob(
        None, gt=0.0, le=10.0, unit="1/m",
        doc="piecewise model: catenary curvature [1/m] below which the catenary takes over "
            "from the beam (default: half the catenary's touchdown curvature w/H)")


@dataclass(frozen=True)
class VFIFESettings(_Settings):
    """``[vfife]`` and ``[vfife.expert]``: settings of the VFIFE solver (vfife/)."""

    TABLE = "vfife"
    element_length: float = _knob(1.0, gt=0.0, le=1000.0, unit="m",
                                  doc="target element length [m]")
    time_step_safety: float = _knob(0.8, gt=0.0, le=1.0,
                                    doc="time step as a fraction of the critical step")
    static_tolerance: float = _knob(1.0e-3, gt=0.0, le=1.0,
                                    doc="converged when the largest nodal out-of-balance force "
                                        "is below this fraction of one element's weight")
    max_steps: int = _knob(5_000_000, "integer", ge=1, le=10**9,
                           doc="step budget of the static relaxation")
    coarse_element_length: float = _knob(10.0, gt=0.0, le=1000.0, unit="m",
                                         doc="first mesh of the mesh sequence [m]")
    rotational_inertia_scale: float = _knob(4.0, ge=1.0, le=1.0e6,
                                            doc="statics: factor on the rotational inertia")
    seabed_length: float = _knob(300.0, ge=0.0, le=MAX_SEGMENT_LENGTH, unit="m",
                                 doc="line laid on the seabed ahead of the touchdown when a "
                                     "Wang-form scene is converted to fixed ends [m]")
    rotational_inertia_scale_dynamics: float = _knob(
        4.0, gt=0.0, le=1.0e6, doc="dynamics: factor on the physical rotational inertia (1 = "
        "physical; 4 makes the step axial-limited, see vfife/dynamics.py)")
    time_step: float | None = _knob(None, gt=0.0, le=10.0, unit="s",
                                    doc="dynamics: fixed time step [s] instead of safety x "
                                        "critical step")
    static_time_step: float | None = _knob(None, gt=0.0, le=10.0, unit="s",
                                           doc="statics: fixed relaxation step [s] (above the "
                                               "critical step the relaxation diverges and "
                                               "says so)")
    clamped_ends: tuple = _knob((), "strings", choices=("bottom", "top"),
                                doc="ends whose rotation is clamped (default: pinned)")
    # expert knobs of the dynamic relaxation ([vfife.expert]); see vfife/statics.py
    static_damping: float = _knob(3.0, expert=True, gt=0.0, le=1.0e4,
                                  doc="relaxation damping, multiple of critical of mode 1")
    static_damping_fine: float = _knob(30.0, expert=True, gt=0.0, le=1.0e4,
                                       doc="... its starting value on the finer meshes")
    static_damping_current: float = _knob(10.0, expert=True, gt=0.0, le=1.0e4,
                                          doc="... on the finer meshes with a current")
    creep_tolerance: float = _knob(1.0e-5, expert=True, ge=0.0, le=1.0,
                                   doc="remaining-displacement tolerance, fraction of the "
                                       "line length (0 turns the creep test off)")
    static_axial_damping: float = _knob(0.1, expert=True, ge=0.0, le=100.0,
                                        doc="axial dashpot, fraction of critical at the "
                                            "highest axial frequency (0: off)")
    static_fictitious_inertia: bool = _knob(True, "boolean", expert=True,
                                            doc="fictitious masses where bending, rotation or "
                                                "the seabed would limit the step")
    static_contact_damping: float = _knob(1.0, expert=True, ge=0.0, le=100.0,
                                          doc="seabed contact damping in statics, fraction "
                                              "of critical (at least; the scene's if higher)")
    static_weight_continuation_steps: int = _knob(10, "integer", expert=True, ge=0, le=1000,
                                                  doc="weight ramp steps when the catenary "
                                                      "start is unusable (0: off)")
