"""The ANCF's implicit time integration: one step of the generalised-alpha method
(Chung & Hulbert 1993) or of Newmark's average acceleration (Liu et al.'s), solved by
Newton's method with the consistent Jacobian.

Equation of motion (per unit of the generalised coordinates q, (N,)):

    M(q) (a + c v) + F_int(q, v) - F_ext(q, v, t) = 0,

M the consistent mass with the added mass across the axis (:mod:`ancf.mass`), c the
scene's mass-proportional damping [1/s], F_int the elastic forces and the line types'
internal axial damping BA d(eps)/dt (:func:`ancf.element.damping_pass`), F_ext the weight, seabed, drag (on the velocity
relative to the water) and the ends' forces (:meth:`ancf.model.Model.residual`).
Generalised-alpha: the inertia at a_{n+1-am} = (1 - am) a_{n+1} + am a_n and the rest at
q, v, t_{n+1-af}, with am = (2 rho - 1)/(rho + 1), af = rho/(rho + 1), gamma = 1/2 - am
+ af, beta = (1 - am + af)^2 / 4 (second order, unconditionally stable, the spectral
radius rho_inf at infinite frequency: 1 no numerical damping, 0 the most); Newmark's
average acceleration is am = af = 0, beta = 1/4, gamma = 1/2. The Newmark relations
q_{n+1} = q_n + h v_n + h^2 ((1/2 - beta) a_n + beta a_{n+1}), v_{n+1} = v_n + h ((1 -
gamma) a_n + gamma a_{n+1}) make q_{n+1} the unknown; its Jacobian is
(1 - am) / (beta h^2) M + (1 - af) (K + gamma / (beta h) (C + c M)), K and C the
linearisations of the forces in q and v (the tangent of the elastic forces, the axial
damping's Jacobians and those of the seabed's and drag's loads). Prescribed unknowns (the hang-off's path, the anchor) are set
at t_{n+1} and their velocity and acceleration follow the same relations.

Convergence of a step: the largest out-of-balance nodal force below ``tolerance`` x the
load scale (as the statics', with the same round-off floor); a step that does not
converge in ``max_iterations`` is halved (at most :data:`MAX_HALVINGS` times).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..mass import mass_pass
from ..model import Model, newton_correction, residual_ratio, round_off_floor

#: the most times a step is halved before the run stops
MAX_HALVINGS = 6


@dataclass(frozen=True)
class Scheme:
    """The integrator's constants (see the module docstring)."""

    name: str
    am: float
    af: float
    beta: float
    gamma: float

    @classmethod
    def of(cls, integrator: str, rho_inf: float) -> "Scheme":
        if integrator == "newmark":
            return cls("newmark", 0.0, 0.0, 0.25, 0.5)
        am = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0)
        af = rho_inf / (rho_inf + 1.0)
        return cls("generalised-alpha", am, af, 0.25 * (1.0 - am + af) ** 2, 0.5 - am + af)


@dataclass
class Kinematic:
    """The state at a time: q, v, a (N,)."""

    q: np.ndarray
    v: np.ndarray
    a: np.ndarray

    def copy(self) -> "Kinematic":
        return Kinematic(self.q.copy(), self.v.copy(), self.a.copy())


class Integrator:
    """Steps ``model`` in time. ``prescribed(t)`` returns (indices, values) of the
    prescribed positions at t [s]; ``set_time(t, q)`` tells the model the time of a
    step's forces and the state at the step's start (the tensioner's reference, the
    waves' kinematics)."""

    def __init__(self, model: Model, scheme: Scheme, damping: float, tolerance: float,
                 max_iterations: int, prescribed, set_time=None):
        self.model = model
        self.scheme = scheme
        self.damping = damping
        self.tolerance = tolerance
        self.max_iterations = max_iterations
        self.prescribed = prescribed
        self.set_time = set_time or (lambda t, q: None)
        m = model.mesh
        self.m, self.ma = m.mass, m.added
        self.point_mass = model.point_mass
        self.iterations = 0
        self.halvings = 0
        self.balance = None
        self.previous = None

    def inertia(self, q: np.ndarray, acc: np.ndarray, per_element: np.ndarray | None = None):
        """M(q) acc (N,) (and each element's share into ``per_element``)."""
        model = self.model
        f = np.zeros(model.N)
        Fe = per_element if per_element is not None else model._none
        mass_pass(q, acc, model.d, model.mesh.l0, self.m, self.ma, model.xg, model.wg, 0.0,
                  np.zeros((1, 1)), model.kl, f, Fe, model.use_surface, model.ysurf,
                  model.band)
        if model.flow is not None:       # the slug's own inertia (ancf/flow.py)
            model.flow.inertia(acc, f, np.zeros((1, 1)), model.kl, 0.0, Fe)
        return f + self.point_mass * acc

    def kinetic_energy(self, st: Kinematic) -> float:
        return 0.5 * float(st.v @ self.inertia(st.q, st.v))

    def step(self, st: Kinematic, t: float, h: float) -> tuple[Kinematic, bool, int]:
        """The state at t + h from ``st`` at t (halving the step inside when Newton fails);
        (state, converged, iterations)."""
        new, ok, it = self._step(st, t, h)
        if ok:
            return new, True, it
        total = it
        for level in range(1, MAX_HALVINGS + 1):
            k = 2 ** level
            cur, ok = st, True
            for j in range(k):
                cur, ok, it = self._step(cur, t + j * h / k, h / k)
                total += it
                if not ok:
                    break
            if ok:
                self.halvings += 1
                return cur, True, total
        return st, False, total

    def _step(self, st: Kinematic, t: float, h: float) -> tuple[Kinematic, bool, int]:
        sc, model = self.scheme, self.model
        am, af, beta, gamma = sc.am, sc.af, sc.beta, sc.gamma
        kl = model.kl
        t1 = t + h
        # predictor: the acceleration kept
        a1 = st.a.copy()
        q1 = st.q + h * st.v + h * h * ((0.5 - beta) * st.a + beta * a1)
        idx, vals = self.prescribed(t1)
        q1[idx] = vals
        tol = max(self.tolerance, 16.0 * round_off_floor(model, q1))
        tf = t + (1.0 - af) * h
        self.set_time(tf, st.q)
        it = 0
        ratio = math.inf
        while True:
            a1 = (q1 - st.q - h * st.v - h * h * (0.5 - beta) * st.a) / (beta * h * h)
            v1 = st.v + h * ((1.0 - gamma) * st.a + gamma * a1)
            qf = (1.0 - af) * q1 + af * st.q
            vf = (1.0 - af) * v1 + af * st.v
            am_acc = (1.0 - am) * a1 + am * st.a
            acc = am_acc + self.damping * vf
            coef = (1.0 - am) / (beta * h * h) + (1.0 - af) * gamma / (beta * h) * self.damping
            # after a correction, the residual alone first (the step usually converges
            # there: no tangent assembled for the test); the tangent when it is needed
            tangent = it == 0
            while True:
                R, K, _ = model.residual(qf, tangent, vf, 1.0, gamma / (beta * h))
                if tangent:
                    K *= (1.0 - af)
                # the inertia's force and its part of the Jacobian in one pass
                mass_pass(qf, acc, model.d, model.mesh.l0, self.m, self.ma, model.xg,
                          model.wg, coef if tangent else 0.0,
                          K if tangent else np.zeros((1, 1)), kl, R, model._none,
                          model.use_surface, model.ysurf, model.band)
                R += self.point_mass * acc
                if model.flow is not None:       # the slug's inertia (ancf/flow.py)
                    model.flow.inertia(acc, R, K if tangent else np.zeros((1, 1)), kl,
                                       coef if tangent else 0.0, model._none)
                ratio = residual_ratio(model, R)
                if not math.isfinite(ratio):
                    return st, False, it
                if (ratio < tol and it > 0) or tangent:
                    break
                tangent = True
            if ratio < tol and it > 0:
                break
            if it >= self.max_iterations:
                return st, False, it
            it += 1
            if np.any(self.point_mass):
                K[2 * kl] += coef * self.point_mass
            dq = newton_correction(model, K, R)
            if dq is None:
                return st, False, it
            q1 = q1 + dq
        self.iterations += it
        # the balance the step solved, at the alpha levels, and the one before: the
        # section forces' states (ancf/dynamics/run.py reads the forces at t_{n+1} off them)
        self.previous = self.balance
        self.balance = (qf, vf, acc, tf, t1)
        return Kinematic(q1, v1, a1), True, it
