"""Internal flow of the contents: steady flow and steady slug flow (scene table
``[internal_flow]``), and the wall tension it implies.

Contract (SI): ``[internal_flow] speed`` U [m/s], the steady speed of the contents along
the line relative to the pipe, positive from the bottom end to the hang-off;
``top_pressure`` [Pa], the contents' gauge pressure at the hang-off (default 0; only the
reported wall tension uses it). Optional ``[internal_flow.slug]`` (Patel & Seyed 1989, as
used by Liu et al. 2021): the contents density is the travelling wave

    rho_f(s, t) = rho_0 (1 + eta cos(k s - omega t + psi)),  k = 2 pi / L_s,  omega = k U,

with ``density_amplitude`` eta (0 <= eta < 1), ``slug_length`` L_s [m] and ``phase_deg``
psi [deg]; rho_0 is the line types' ``contents_density`` and the slug travels with the
contents (v = omega / k = U, what mass conservation requires of a pattern carried by a
flow of constant speed). The contents mass per length mu_0 = rho_0 pi d^2 / 4 must be the
same along the whole line (one fluid through one bore: a change of bore would change the
speed).

Wall tension. With the effective tension T_e that the methods solve for (the tension in
the shape equations, Fylling's: the flow's momentum flux rho U^2 counts as an extra
internal pressure), the pipe wall carries

    T_w = T_e + mu U^2 + p_i A_i - p_o A_o,

with p_o = rho_w g (h - y) the hydrostatic sea pressure (h = water depth), p_i = p_top +
rho_0 g (y_top - y) the contents' pressure (mean density, hydrostatic from the hang-off)
and A_i, A_o the bore and outer areas. A steady uniform flow leaves T_e and the shape
unchanged and raises T_w by mu U^2 exactly. The axial strain is taken as T_e / EA, the
suite's convention for pressure effects (the end-cap and Poisson coupling of a restrained
pipe, Sparks' effect, is not modelled: for Liu's riser mu U^2 = 402 N against a top
tension of 1.4 MN).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..design.wall import pressures, wall_at
from ..design.wall import wall_tension as of_wall
from ..errors import SceneError
from ..spec import Part, spec

#: largest |speed| accepted [m/s] (production flow is a few m/s; 50 catches unit slips)
MAX_FLOW_SPEED = 50.0
#: the slug's keys sit in the sub-table [internal_flow.slug]
SLUG = "slug"
IN_SLUG = "required in [internal_flow.slug]"


@dataclass(frozen=True)
class InternalFlow(Part):
    """Steady internal flow, optionally with a steady slug (see the module docstring).

    speed [m/s]; top_pressure [Pa, gauge]; density_amplitude eta [-] (0: uniform
    contents); slug_length [m] (None without a slug); phase_deg [deg]. The slug's keys sit
    in the file's ``[internal_flow.slug]``, which needs density_amplitude and slug_length.
    """

    speed: float = spec(ge=-MAX_FLOW_SPEED, le=MAX_FLOW_SPEED, unit="m/s",
                        doc="speed of the contents relative to the pipe, positive from "
                            "the bottom end to the hang-off")
    top_pressure: float = spec(0.0, ge=-1.01325e5, le=1.0e9, unit="Pa",
                               doc="gauge pressure of the contents at the hang-off (the "
                                   "reported wall tension only)")
    density_amplitude: float = spec(0.0, ge=0.0, lt=1.0, table=SLUG, default_doc=IN_SLUG,
                                    doc="eta of rho_f = rho_0 (1 + eta cos(k s - omega t "
                                        "+ psi)); 0: uniform contents")
    slug_length: float | None = spec(None, gt=0.0, le=1.0e5, unit="m", table=SLUG,
                                     default_doc=IN_SLUG, doc="slug length L_s = 2 pi / k")
    phase_deg: float = spec(0.0, ge=-360.0, le=360.0, unit="deg", table=SLUG,
                            doc="phase psi of the slug at s = 0, t = 0")

    @property
    def has_slug(self) -> bool:
        """True when the contents density varies (a slug with eta > 0)."""
        return self.slug_length is not None and self.density_amplitude > 0.0

    @property
    def wavenumber(self) -> float:
        """k = 2 pi / L_s [1/m] (0 without a slug)."""
        return 2.0 * math.pi / self.slug_length if self.slug_length else 0.0

    @property
    def omega(self) -> float:
        """Slug circular frequency omega = k U [rad/s] as seen at a fixed point."""
        return self.wavenumber * self.speed

    @property
    def slug_period(self) -> float | None:
        """L_s / |U| [s], the time between slugs at a fixed point (None without a slug or
        flow)."""
        if self.slug_length is None or self.speed == 0.0:
            return None
        return self.slug_length / abs(self.speed)

    def density_factor(self, s, t: float):
        """rho_f / rho_0 = 1 + eta cos(k s - omega t + psi) at arc lengths s [m], time t [s]."""
        s = np.asarray(s, float)
        if self.slug_length is None:
            return np.ones_like(s)
        return 1.0 + self.density_amplitude * np.cos(
            self.wavenumber * s - self.omega * t + math.radians(self.phase_deg))


def contents_mass_per_length(scene) -> float:
    """mu_0 = rho_0 pi d^2 / 4 [kg/m] of the line (the same on every segment)."""
    lt = scene.line_types[scene.segments[0].line_type]
    return lt.contents_density * math.pi / 4.0 * (lt.inner_diameter or 0.0) ** 2


def check_internal_flow(scene) -> None:
    """Every segment's line type has a bore and contents, all with the same contents mass
    per length; a water depth is given (the external pressure of the wall tension).
    Raises :class:`SceneError` naming the key."""
    src = scene.source
    if scene.water_depth is None:
        raise SceneError(src, "environment.water_depth", "required with [internal_flow] "
                         "(the sea pressure in the reported wall tension)")
    mus = {}
    for seg in scene.segments:
        lt = scene.line_types[seg.line_type]
        if lt.inner_diameter is None or lt.inner_diameter <= 0.0:
            raise SceneError(src, f"line_types.{lt.name}.inner_diameter", "required by "
                             "[internal_flow] (the bore the contents flow through): give "
                             "inner_diameter or wall_thickness [m]")
        if not lt.contents_density > 0.0:
            raise SceneError(src, f"line_types.{lt.name}.contents_density", "must be > 0 "
                             "with [internal_flow] (the mean density of the flowing contents), "
                             f"got {lt.contents_density:g}")
        mus[lt.name] = lt.contents_density * math.pi / 4.0 * lt.inner_diameter ** 2
    lo, hi = min(mus.values()), max(mus.values())
    if hi - lo > 1e-9 * hi:
        name = max(mus, key=mus.get)
        raise SceneError(src, f"line_types.{name}.contents_density", "with [internal_flow] "
                         "every line type must hold the same contents mass per length "
                         f"(rho pi d^2 / 4; one fluid through one bore), got {lo:.6g} to "
                         f"{hi:.6g} kg/m")


def wall_tension(scene, s, y, tension) -> np.ndarray:
    """Wall tension T_w [N] at stations s [m] of heights y [m] with effective tension
    ``tension`` [N] (see the module docstring; y[-1] is the hang-off): the wall's
    pressures and tension of :mod:`riser.design.wall` with the flow's ``top_pressure``."""
    y = np.asarray(y, float)
    wall = wall_at(scene, s)
    p_i, p_e = pressures(scene, wall, y, float(y[-1]), scene.internal_flow.top_pressure)
    return of_wall(scene, wall, tension, p_i, p_e)
