"""Waves on the sea surface (scene table ``[environment.waves]``): regular Airy wave
trains and irregular seas from a spectrum, as the wave *components* every method sums.

This module holds the inputs and their reduction to components (amplitude, circular
frequency, wave number by the finite-depth dispersion relation, phase, heading); each
method computes its own kinematics from them (:mod:`vfife.dynamics.waves`, :mod:`bvp.frequency.wave_loads`),
as the principle of independent code asks. :func:`elevation` is the one closed form kept
here, for outputs (the wave elevation in a time series) and the inputs' own checks.

Conventions (SI units). Heights y up from the seabed, the mean surface at y = h (the
scene's ``water_depth``); a heading beta [deg] is the direction the wave travels: 0 = +x
(towards the hang-off, in plane), 90 = +z (out of plane), as the current's heading. A
component j of amplitude a_j [m] (half its height), circular frequency omega_j [rad/s],
wave number k_j [1/m] (omega^2 = g k tanh(k h), solved by Newton) and phase epsilon_j
[rad] has the elevation

    eta_j(x, z, t) = a_j cos(omega_j t - k_j ((x - x0) cos beta_j + (z - z0) sin beta_j)
                     - epsilon_j)

at the horizontal point (x, z) [m]; (x0, z0) is the waves' origin (``origin``, default the
hang-off's static position, where a vessel's RAOs are referred). epsilon is the *phase
lag* of the component at the origin: epsilon = 0 puts a crest there at t = 0 (OrcaFlex's
and MoorDyn's convention: MoorDyn-C's test of the Lowe and Langley jumper writes
cos(k x - omega t + phi), the same lag phi). The sea is the sum of its components.

Irregular seas: a spectrum S(omega) [m2 s/rad] (JONSWAP, Pierson-Moskowitz, or a table)
cut into ``components`` equal steps d omega between ``omega_min`` and ``omega_max``
(defaults 0.5 and 3.5 times the peak frequency: ~0.2 % of a JONSWAP's variance is left
out), each a component at the step's centre with the amplitude sqrt(2 S(omega) d omega)
and a phase drawn uniformly in [0, 2 pi) by NumPy's PCG64 from ``seed``: the realisation
is the same on every machine for the same seed. The range is shifted by less than half a
step so that every frequency is a whole multiple of d omega: the sea repeats exactly after
2 pi / d omega, and a record of that length has exactly the variance sum a^2 / 2 (a
response record of that length measures the response's variance without the sampling
error of a random record).

Short-crested seas (``spreading``): the spectrum's energy spread over directions theta
about the mean heading theta_m (``heading_deg``), S(omega, theta) = S(omega) D(theta -
theta_m), D a probability density independent of omega:

- 'none' (the default): long-crested, every component at theta_m;
- 'cos2s': D(phi) = C_s cos^(2s)(phi / 2) on (-180, 180] deg, C_s = Gamma(s + 1) /
  (2 sqrt(pi) Gamma(s + 1/2)); E[cos phi] = s / (s + 1), E[cos 2 phi] = s (s - 1) / ((s
  + 1) (s + 2));
- 'cosn': D(phi) = C_n cos^n(phi) for |phi| <= 90 deg (0 beyond: nothing travels against
  the mean heading), C_n = Gamma(n / 2 + 1) / (sqrt(pi) Gamma((n + 1) / 2)); E[cos^2 phi]
  = (n + 1) / (n + 2), E[cos 2 phi] = n / (n + 2) (Wallis' recursion);

s or n the ``spreading_exponent``. Both cumulative distributions are closed forms, the
regularised incomplete beta function I (scipy.special.betainc; its inverse betaincinv):
F(phi) = 1/2 + sign(phi) I_x(1/2, b) / 2 with x = sin^2(phi / 2), b = s + 1/2 (cos2s) or
x = sin^2(phi), b = (n + 1) / 2 (cosn) (the substitution x = sin^2 turns the integral of
cos^(2b - 1) into the incomplete beta integral). The component j of the sea (one per
frequency) travels at theta_m + F^{-1}(q_j): the quantiles q_j = (m_j + u_j) / N are
stratified, one in each of the N equal slices m = 0 ... N - 1 of probability, u_j uniform
in [0, 1) drawn by the same generator after the phases (so the phases are those of the
long-crested sea of the same seed, and 'none' draws nothing more: its sea is the same to
the bit); the slice m_j of component j is the rank of frac(j g + u_0) (g = (sqrt 5 - 1) /
2, the golden ratio's fraction, u_0 drawn by the generator), a randomly shifted Kronecker
sequence: neighbouring frequencies take directions far apart, every band of frequencies
sees the whole spread, and a linear response's variance sum_j a_j^2 |H(omega_j,
theta_j)|^2 / 2 converges to the double integral like 1/N (a random order of the slices,
a Latin hypercube, converges like 1/sqrt(N): measured in tests/test_short_crested.py and
docs/short-crested-seas.md).

Kinematics above the mean level (``stretching``): 'wheeler' maps the wetted column [0, h
+ eta] onto [0, h] (the velocity at the crest is the linear theory's at the mean level);
'vertical' holds the linear theory's value at the mean level from y = h up to the surface.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.special import betainc, betaincinv, gammaln

from ..spec import Part, check_fields, part_error, spec

#: the steepest regular wave accepted: H / L <= 0.142 tanh(k h) (Miche's breaking limit)
MICHE = 0.142
#: JONSWAP/Pierson-Moskowitz seas steeper than Tp / sqrt(Hs) < this [s/sqrt(m)] are
#: refused: a significant steepness 2 pi Hs / (g Tp^2) above 1/15, the limit of seas that
#: do not break (DNV-RP-C205's steepness criterion)
MIN_TP_OVER_ROOT_HS = math.sqrt(2.0 * math.pi * 15.0 / 9.81)
#: default frequency range of a spectrum, in multiples of its peak frequency
OMEGA_RANGE = (0.5, 3.5)
SPECTRA = ("jonswap", "pierson-moskowitz", "table")
STRETCHING = ("wheeler", "vertical")
#: directional spreading functions of a spectrum (see the module docstring)
SPREADING = ("none", "cos2s", "cosn")
#: the golden ratio's fraction (sqrt 5 - 1) / 2: the step of the Kronecker sequence that
#: orders the spreading's strata over the components
GOLDEN = 0.5 * (math.sqrt(5.0) - 1.0)


@dataclass(frozen=True)
class WaveTrain(Part):
    """One regular Airy wave train: height H [m] (crest to trough), period T [s], heading
    [deg] (direction of travel: 0 = +x, 90 = +z), phase lag [deg] at the waves' origin."""

    height: float = spec(gt=0.0, le=40.0, unit="m",
                         also="steepness H / L <= 0.142 tanh(k h) (breaking)",
                         doc="wave height, crest to trough")
    period: float = spec(ge=1.0, le=40.0, unit="s", doc="wave period")
    heading_deg: float = spec(0.0, ge=-360.0, le=360.0, unit="deg",
                              doc="direction of travel: 0 = +x (in plane), 90 = +z")
    phase_deg: float = spec(0.0, ge=-360.0, le=360.0, unit="deg",
                            doc="phase lag at the waves' origin (0: a crest there at t = 0)")


@dataclass(frozen=True)
class WaveSpectrum(Part):
    """An irregular sea from a spectrum (see the module docstring)."""

    kind: str = spec(kind="string", choices=SPECTRA,
                     doc="JONSWAP, Pierson-Moskowitz, or a table of omega and density")
    hs: float | None = spec(None, gt=0.0, le=30.0, unit="m",
                            also="Tp / sqrt(Hs) >= 3.1 s/m^0.5 (steepness <= 1/15)",
                            default_doc="required (jonswap, pierson-moskowitz)",
                            doc="significant wave height")
    tp: float | None = spec(None, ge=2.0, le=40.0, unit="s",
                            default_doc="required (jonswap, pierson-moskowitz)",
                            doc="peak period")
    gamma: float | None = spec(None, ge=1.0, le=10.0,
                               default_doc="DNV: 5 for Tp/sqrt(Hs) <= 3.6, 1 for >= 5, "
                                           "exp(5.75 - 1.15 Tp/sqrt(Hs)) between",
                               doc="JONSWAP peak enhancement factor")
    omega: tuple[float, ...] | None = spec(None, "numbers", min_length=2, gt=0.0, le=20.0,
                                           unit="rad/s", also="strictly increasing",
                                           default_doc="required (table)",
                                           doc="circular frequencies of a spectrum table")
    density: tuple[float, ...] | None = spec(None, "numbers", ge=0.0, le=1.0e4,
                                             unit="m2 s/rad", also="as many as omega; "
                                             "not all zero", default_doc="required (table)",
                                             doc="spectral density S(omega) of the table")
    heading_deg: float = spec(0.0, ge=-360.0, le=360.0, unit="deg",
                              doc="direction of travel (a spread sea: the mean direction)")
    spreading: str = spec("none", "string", choices=SPREADING,
                          doc="directional spreading about heading_deg: none (long-crested), "
                              "cos2s: D ~ cos^(2s)((theta - heading) / 2), cosn: D ~ "
                              "cos^n(theta - heading) within +-90 deg")
    spreading_exponent: float | None = spec(None, ge=1.0, le=100.0,
                                            also="only with spreading cos2s or cosn",
                                            default_doc="required (cos2s, cosn)",
                                            doc="the spreading's exponent: s of cos2s, n of "
                                                "cosn (larger: narrower)")
    components: int = spec(200, "integer", ge=4, le=5000,
                           doc="number of components (equal frequency steps)")
    omega_min: float | None = spec(None, gt=0.0, le=20.0, unit="rad/s",
                                   default_doc="0.5 x peak (table: its first omega)",
                                   doc="lowest frequency of the discretisation")
    omega_max: float | None = spec(None, gt=0.0, le=40.0, unit="rad/s",
                                   also="> omega_min",
                                   default_doc="3.5 x peak (table: its last omega)",
                                   doc="highest frequency of the discretisation")
    seed: int = spec(1, "integer", ge=0, le=2 ** 63 - 1,
                     doc="seed of the random phases and a spread sea's directions "
                         "(PCG64): the same sea every run")

    def __post_init__(self) -> None:
        check_fields(self)
        error = part_error(self)
        if self.kind == "table":
            for name in ("omega", "density"):
                if getattr(self, name) is None:
                    raise error(name, "required with kind = 'table'")
            for name in ("hs", "tp", "gamma"):
                if getattr(self, name) is not None:
                    raise error(name, "not with kind = 'table' (the table is the spectrum)")
            w, d = self.omega, self.density
            if len(d) != len(w):
                raise error("density", f"must have as many entries as omega ({len(w)}), "
                            f"got {len(d)}")
            for i in range(1, len(w)):
                if not w[i] > w[i - 1]:
                    raise error(f"omega[{i}]", f"must be > omega[{i - 1}] = {w[i - 1]:g} "
                                f"rad/s (strictly increasing), got {w[i]:g}")
            if not any(v > 0.0 for v in d):
                raise error("density", "the spectrum has no energy (every density is 0)")
        else:
            for name in ("hs", "tp"):
                if getattr(self, name) is None:
                    raise error(name, f"required with kind = {self.kind!r}")
            for name in ("omega", "density"):
                if getattr(self, name) is not None:
                    raise error(name, "only with kind = 'table'")
            if self.kind == "pierson-moskowitz" and self.gamma is not None:
                raise error("gamma", "only with kind = 'jonswap' (Pierson-Moskowitz is "
                            "gamma = 1)")
            ratio = self.tp / math.sqrt(self.hs)
            if ratio < MIN_TP_OVER_ROOT_HS:
                raise error("tp", f"Tp / sqrt(Hs) = {ratio:.3g} s/m^0.5 (Hs {self.hs:g} m, "
                            f"Tp {self.tp:g} s) must be >= {MIN_TP_OVER_ROOT_HS:.3g}: a "
                            "steeper sea breaks (significant steepness > 1/15); check hs "
                            "[m] and tp [s]")
        if self.spreading == "none" and self.spreading_exponent is not None:
            raise error("spreading_exponent", "only with spreading = 'cos2s' or 'cosn' (a "
                        "long-crested sea has no spreading)")
        if self.spreading != "none" and self.spreading_exponent is None:
            raise error("spreading_exponent", f"required with spreading = "
                        f"{self.spreading!r} (s of cos^(2s)(phi / 2), n of cos^n(phi))")
        lo, hi = self.omega_range
        if not hi > lo:
            raise error("omega_max", f"must be > omega_min = {lo:g} rad/s, got {hi:g}")
        if not np.any(self.density_at(self.component_omegas()[0]) > 0.0):
            raise error("omega_min", f"the range {lo:g}-{hi:g} rad/s holds no energy of the "
                        "spectrum")

    @property
    def peak_omega(self) -> float:
        """The peak's circular frequency [rad/s] (a table: its largest density)."""
        if self.kind == "table":
            return float(self.omega[int(np.argmax(self.density))])
        return 2.0 * math.pi / self.tp

    @property
    def gamma_used(self) -> float:
        """The peak enhancement factor applied: 1 for Pierson-Moskowitz, the given gamma,
        or DNV-RP-C205's default by Tp / sqrt(Hs)."""
        if self.kind != "jonswap":
            return 1.0
        if self.gamma is not None:
            return float(self.gamma)
        r = self.tp / math.sqrt(self.hs)
        return 5.0 if r <= 3.6 else (1.0 if r >= 5.0 else math.exp(5.75 - 1.15 * r))

    @property
    def omega_range(self) -> tuple[float, float]:
        """(omega_min, omega_max) [rad/s] of the discretisation."""
        if self.kind == "table":
            lo0, hi0 = self.omega[0], self.omega[-1]
        else:
            lo0, hi0 = (f * self.peak_omega for f in OMEGA_RANGE)
        lo = self.omega_min if self.omega_min is not None else lo0
        hi = self.omega_max if self.omega_max is not None else hi0
        return float(lo), float(hi)

    def density_at(self, omega) -> np.ndarray:
        """S(omega) [m2 s/rad] at circular frequencies omega [rad/s] (a table: linear
        between its points, zero outside). JONSWAP as DNV-RP-C205 3.5.5: S = (1 - 0.287
        ln gamma) S_PM gamma^exp(-(omega - wp)^2 / (2 sigma^2 wp^2)), sigma 0.07 below
        the peak and 0.09 above; S_PM = 5/16 Hs^2 wp^4 omega^-5 exp(-5/4 (omega/wp)^-4)."""
        w = np.asarray(omega, float)
        if self.kind == "table":
            return np.interp(w, self.omega, self.density, left=0.0, right=0.0)
        wp = self.peak_omega
        with np.errstate(over="ignore", divide="ignore"):
            pm = np.where(w > 0.0, 5.0 / 16.0 * self.hs ** 2 * wp ** 4 * w ** -5.0
                          * np.exp(-1.25 * (w / wp) ** -4.0), 0.0)
        g = self.gamma_used
        if g == 1.0:
            return pm
        sigma = np.where(w <= wp, 0.07, 0.09)
        peak = g ** np.exp(-0.5 * ((w - wp) / (sigma * wp)) ** 2)
        return (1.0 - 0.287 * math.log(g)) * pm * peak

    def component_omegas(self) -> tuple[np.ndarray, float]:
        """(omega_j (n,) [rad/s], d omega [rad/s]): the centres of ``components`` equal
        steps over the range, the range shifted by less than half a step so that every
        omega_j is a whole multiple of d omega (the record then repeats exactly after 2 pi
        / d omega, and over that time the components are orthogonal: its variance is
        exactly sum a_j^2 / 2)."""
        lo, hi = self.omega_range
        dw = (hi - lo) / self.components
        first = max(1, int(round(lo / dw + 0.5)))
        return dw * (first + np.arange(self.components)), dw

    @property
    def spread(self) -> bool:
        """True for a short-crested sea (``spreading`` other than 'none')."""
        return self.spreading != "none"

    def spreading_density(self, phi) -> np.ndarray:
        """The spreading function D(phi) [1/rad] at angles phi [rad] from the mean heading
        (a probability density: its integral over a turn is 1; see the module docstring).
        A long-crested sea has no density: ValueError."""
        phi = np.remainder(np.asarray(phi, float) + math.pi, 2.0 * math.pi) - math.pi
        e = self._exponent()
        if self.spreading == "cos2s":
            c = math.exp(gammaln(e + 1.0) - gammaln(e + 0.5)) / (2.0 * math.sqrt(math.pi))
            return c * np.cos(0.5 * phi) ** (2.0 * e)
        c = math.exp(gammaln(0.5 * e + 1.0) - gammaln(0.5 * (e + 1.0))) / math.sqrt(math.pi)
        return np.where(np.abs(phi) <= 0.5 * math.pi,
                        c * np.abs(np.cos(phi)) ** e, 0.0)

    def spreading_cdf(self, phi) -> np.ndarray:
        """The cumulative distribution F(phi) of the spreading at angles phi [rad] from
        the mean heading, phi in [-pi, pi] (cosn: 0 below -pi/2, 1 above pi/2), in closed
        form by the regularised incomplete beta function (the module docstring)."""
        phi = np.asarray(phi, float)
        e = self._exponent()
        if self.spreading == "cos2s":
            x, b = np.sin(0.5 * phi) ** 2, e + 0.5
        else:
            phi = np.clip(phi, -0.5 * math.pi, 0.5 * math.pi)
            x, b = np.sin(phi) ** 2, 0.5 * (e + 1.0)
        return 0.5 + 0.5 * np.sign(phi) * betainc(0.5, b, x)

    def spreading_angle(self, q) -> np.ndarray:
        """The inverse of :meth:`spreading_cdf`: the angle phi [rad] from the mean heading
        of the quantiles q in [0, 1] (closed form: scipy.special.betaincinv)."""
        q = np.asarray(q, float)
        e = self._exponent()
        b = e + 0.5 if self.spreading == "cos2s" else 0.5 * (e + 1.0)
        x = betaincinv(0.5, b, np.clip(np.abs(2.0 * q - 1.0), 0.0, 1.0))
        half = np.arcsin(np.sqrt(x))
        return np.sign(q - 0.5) * (2.0 * half if self.spreading == "cos2s" else half)

    def spreading_moments(self) -> tuple[float, float]:
        """(E[cos phi], E[cos 2 phi]) of the spreading (closed forms; the module
        docstring): the variance of a horizontal kinematic quantity along a direction at
        an angle alpha to the mean heading goes with E[cos^2(phi - alpha)] = (1 + cos(2
        alpha) E[cos 2 phi]) / 2 (D is even)."""
        if not self.spread:
            return 1.0, 1.0
        e = self._exponent()
        if self.spreading == "cos2s":
            return e / (e + 1.0), e * (e - 1.0) / ((e + 1.0) * (e + 2.0))
        c1 = math.exp(2.0 * gammaln(0.5 * e + 1.0) - gammaln(0.5 * (e + 1.0))
                      - gammaln(0.5 * (e + 3.0)))
        return c1, e / (e + 2.0)

    def _exponent(self) -> float:
        if not self.spread:
            raise ValueError("a long-crested sea (spreading = 'none') has no spreading "
                             "function")
        return float(self.spreading_exponent)

    def component_headings(self, rng: np.random.Generator) -> np.ndarray:
        """The directions [rad] of the ``components`` components of a spread sea, drawn by
        ``rng`` (the generator of the phases, after them): stratified quantiles in the
        order of a randomly shifted Kronecker sequence (the module docstring)."""
        n = self.components
        u0 = rng.uniform(0.0, 1.0)
        u = rng.uniform(0.0, 1.0, n)
        order = np.argsort(np.remainder(np.arange(n) * GOLDEN + u0, 1.0), kind="stable")
        strata = np.empty(n)
        strata[order] = np.arange(n)
        q = (strata + u) / n
        return math.radians(self.heading_deg) + self.spreading_angle(q)

    def moment(self, order: int = 0, points: int = 20001) -> float:
        """The spectral moment m_n = int omega^n S(omega) d omega [m2 (rad/s)^n] of the
        continuous spectrum (trapezoidal over 0.05-10 x peak; a table over its points)."""
        if self.kind == "table":
            w = np.linspace(self.omega[0], self.omega[-1], points)
        else:
            w = np.linspace(0.05, 10.0, points) * self.peak_omega
        return float(np.trapezoid(w ** order * self.density_at(w), w))


@dataclass(frozen=True)
class WaveComponents:
    """The sea as a sum of Airy components (see the module docstring): amplitude [m],
    omega [rad/s], k [1/m], phase [rad] (lag at the origin), heading [rad], each (n,);
    origin (x0, z0) [m]; depth h [m]; stretching ('wheeler' or 'vertical')."""

    amplitude: np.ndarray
    omega: np.ndarray
    k: np.ndarray
    phase: np.ndarray
    heading: np.ndarray
    origin: tuple[float, float]
    depth: float
    stretching: str
    ramp_time: float = 0.0
    labels: tuple[str, ...] = field(default=())

    @property
    def size(self) -> int:
        return int(self.amplitude.size)

    @property
    def shortest_period(self) -> float:
        return float(2.0 * math.pi / np.max(self.omega))

    def ramp(self, t) -> np.ndarray:
        """The half-cosine ramp factor at times t [s] (1 after ``ramp_time``)."""
        t = np.asarray(t, float)
        if self.ramp_time <= 0.0:
            return np.ones_like(t)
        r = np.minimum(t, self.ramp_time) / self.ramp_time
        return 0.5 * (1.0 - np.cos(math.pi * r))


@dataclass(frozen=True)
class Waves(Part):
    """The waves of a scene: regular trains and/or one irregular sea (see the module
    docstring). ``trains`` and ``spectrum`` are read from ``[[environment.waves.trains]]``
    and ``[environment.waves.spectrum]``."""

    trains: tuple[WaveTrain, ...] = field(default=())
    spectrum: WaveSpectrum | None = spec(None, "part", part=WaveSpectrum)
    stretching: str = spec("wheeler", "string", choices=STRETCHING,
                           doc="kinematics above the mean level: Wheeler, or held vertical")
    origin: tuple[float, ...] | None = spec(None, "numbers", length=2, ge=-1.0e5, le=1.0e5,
                                            unit="m", default_doc="the hang-off's (x, z)",
                                            doc="(x, z) where the phases are referred")
    line_loads: bool = spec(True, "boolean",
                            doc="wave loads on the line (false: the waves move the vessel "
                                "only)")
    ramp_time: float | None = spec(None, ge=0.0, le=1.0e4, unit="s",
                                   also="<= dynamics.duration",
                                   default_doc="two longest periods (a sea: two peak "
                                               "periods)",
                                   doc="half-cosine ramp of the wave loads and motions")

    def __post_init__(self) -> None:
        check_fields(self)
        error = part_error(self)
        if isinstance(self.trains, list):
            object.__setattr__(self, "trains", tuple(self.trains))
        for i, tr in enumerate(self.trains):
            if not isinstance(tr, WaveTrain):
                raise error(f"trains[{i}]", f"must be a WaveTrain, got {type(tr).__name__}")
        if not self.trains and self.spectrum is None:
            raise error("trains", "give at least one [[environment.waves.trains]] or an "
                        "[environment.waves.spectrum] (waves without a wave)")

    @property
    def ramp(self) -> float:
        """The ramp duration applied [s]."""
        if self.ramp_time is not None:
            return float(self.ramp_time)
        periods = [tr.period for tr in self.trains]
        if self.spectrum is not None:
            periods.append(2.0 * math.pi / self.spectrum.peak_omega)
        return 2.0 * max(periods)

    @property
    def headings(self) -> tuple[float, ...]:
        """Every heading [deg] of the trains and the sea (a spread sea: its mean heading;
        its components' own are :meth:`components`')."""
        out = [tr.heading_deg for tr in self.trains]
        if self.spectrum is not None:
            out.append(self.spectrum.heading_deg)
        return tuple(out)

    @property
    def is_planar(self) -> bool:
        """True when every wave travels along x (headings 0 or 180 deg; a spread sea's
        components travel at many headings: never planar)."""
        if self.spectrum is not None and self.spectrum.spread:
            return False
        return all(abs(math.sin(math.radians(h))) < 1e-12 for h in self.headings)

    def components(self, depth: float, gravity: float,
                   origin: tuple[float, float]) -> WaveComponents:
        """The components of the trains, then of the sea, in water ``depth`` [m] under
        ``gravity`` [m/s2]; ``origin`` (x0, z0) [m] when :attr:`origin` is not given."""
        amp, omg, ph, hd, labels = [], [], [], [], []
        for i, tr in enumerate(self.trains):
            amp.append(0.5 * tr.height)
            omg.append(2.0 * math.pi / tr.period)
            ph.append(math.radians(tr.phase_deg))
            hd.append(math.radians(tr.heading_deg))
            labels.append(f"trains[{i}]")
        sp = self.spectrum
        if sp is not None:
            w, dw = sp.component_omegas()
            a = np.sqrt(2.0 * sp.density_at(w) * dw)
            rng = np.random.Generator(np.random.PCG64(sp.seed))
            phases = rng.uniform(0.0, 2.0 * math.pi, sp.components)
            keep = a > 0.0
            amp.extend(a[keep])
            omg.extend(w[keep])
            ph.extend(phases[keep])
            if sp.spread:
                hd.extend(sp.component_headings(rng)[keep])
            else:
                hd.extend([math.radians(sp.heading_deg)] * int(np.sum(keep)))
            labels.extend(["spectrum"] * int(np.sum(keep)))
        omg = np.asarray(omg, float)
        k = wave_numbers(omg, depth, gravity)
        o = tuple(float(v) for v in (self.origin if self.origin is not None else origin))
        return WaveComponents(np.asarray(amp, float), omg, k, np.asarray(ph, float),
                              np.asarray(hd, float), o, float(depth), self.stretching,
                              self.ramp, tuple(labels))


def wave_numbers(omega, depth: float, gravity: float) -> np.ndarray:
    """Wave numbers k [1/m] of omega^2 = g k tanh(k h) (finite-depth dispersion), by
    Newton from the deep-water k = omega^2 / g, to round-off."""
    w = np.asarray(omega, float)
    k = w * w / gravity
    k = np.maximum(k, w / math.sqrt(gravity * depth))        # shallow-water start
    for _ in range(100):
        th = np.tanh(k * depth)
        f = gravity * k * th - w * w
        df = gravity * th + gravity * k * depth * (1.0 - th * th)
        step = f / df
        k = k - step
        if np.all(np.abs(step) <= 1e-15 * k):
            break
    return k


def elevation(comp: WaveComponents, x, z, t) -> np.ndarray:
    """The surface elevation eta [m] above the mean level at horizontal points (x, z) [m]
    (arrays broadcasting together) at time t [s], ramp included."""
    x = np.asarray(x, float)[..., None]
    z = np.asarray(z, float)[..., None]
    t = np.asarray(t, float)[..., None]
    dx, dz = x - comp.origin[0], z - comp.origin[1]
    arg = (comp.omega * t - comp.k * (dx * np.cos(comp.heading) + dz * np.sin(comp.heading))
           - comp.phase)
    return comp.ramp(t[..., 0]) * np.sum(comp.amplitude * np.cos(arg), axis=-1)


def steepness_error(train: WaveTrain, depth: float, gravity: float) -> str | None:
    """Why a regular train is steeper than it can be (Miche's breaking limit), or None."""
    k = float(wave_numbers([2.0 * math.pi / train.period], depth, gravity)[0])
    limit = MICHE * math.tanh(k * depth)
    ratio = train.height * k / (2.0 * math.pi)
    if ratio > limit:
        return (f"H / L = {ratio:.3g} (height {train.height:g} m, wavelength "
                f"{2.0 * math.pi / k:.4g} m in {depth:g} m of water) must be <= "
                f"0.142 tanh(k h) = {limit:.3g}: the wave breaks (Miche's limit)")
    return None
