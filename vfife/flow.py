"""Internal flow in the VFIFE model: steady flow and a steady slug (scene [internal_flow]).

Formulation (pipe conveying fluid: Paidoussis, *Fluid-Structure Interactions* vol. 1,
ch. 3, 1998; Patel & Seyed, Eng. Struct. 11, 1989, for the slug; Fylling 1988 for the
effective tension). Contents of mass per length mu(s, t) move along the pipe at the
constant relative speed U; mass conservation d mu/dt + U d mu/ds = 0 makes any density
pattern travel with the flow, so the slug mu = mu_0 (1 + eta cos(k s - omega t + psi))
has omega = k U. A contents particle at r(s, t) has the velocity r_t + U tau and the
acceleration r_tt + 2 U tau_t + U^2 tau_s (tau = r_s the unit tangent), so the momentum
balance of pipe plus contents per unit length reads

    (m + mu) r_tt = d/ds (T_e0 tau) + shear + loads - mu (2 U tau_t + U^2 tau_s),

T_e0 the usual effective tension. Writing mu U^2 tau_s = d/ds (mu U^2 tau) - U^2 mu_s tau
and T_e = T_e0 - mu U^2 (the effective tension with rho U^2 taken as an extra internal
pressure, Fylling) gives the form this model integrates:

    (m + mu) r_tt = d/ds (T_e tau) + shear + loads + U^2 (d mu/ds) tau - 2 mu U tau_t.

The element force of the VFIFE (EA times the strain) is T_e, so

- a steady uniform flow adds no static force: shape and T_e are those without flow, and
  only the wall tension rises, by mu U^2 (riser/physics/internal_flow.py reports it);
- the centrifugal force of a slug is the axial gradient term, the rest of it being carried
  by the curvature of T_e tau;
- the Coriolis force -2 mu U tau_t acts on a moving line, with tau_t = d r_t / ds taken
  as the central difference of the neighbours' velocities (skew-symmetric: no work for a
  uniform mu), in dynamics only (it vanishes at rest), extrapolated from the lagged
  velocities to the step's time (Adams-Bashforth 2, see :func:`vfife.kernels.flow_pass`);
- the nodes' mass and weight (in water and in air) follow mu(s_i, t) every step.

Statics runs no flow kernel: a steady flow has no static force, and a slug is frozen at
t = 0 by its weight only (the equilibrium of the line with that density pattern). Its
gradient force enters with the dynamics: along the pipe, U^2 k eta mu_0 per metre (U^2 k
/ g = 5 % of the weight ripple eta mu_0 g for Liu's riser), it ripples the effective
tension by +-eta mu_0 U^2 (100 N against 1.4 MN there), and that ripple's transverse
effect, the centrifugal ripple eta mu_0 U^2 kappa, is U^2 kappa / g = 0.2 % of the
weight ripple. As a follower force in the fictitious dynamics of the relaxation it kept
a hanging pipe at 5 m/s from converging (a steady 1e-3 x element weight residual).
Dynamics: the flow pass runs every step from t = 0 whenever the scene has
[internal_flow] (effect ``internal_flow``; ``slug_flow`` with a slug). Stability: the
explicit Coriolis term grows a mode by about theta^4 / 4 per step, theta = 2 mu U dt /
((m + mu + m_a) l) (1e-16 for Liu's riser at 4 m elements; 3e-8 for the taut pipe of the
tests at 20 m/s), far below the drag's damping; the critical step uses the lightest
nodal mass of the slug.
"""

from __future__ import annotations

import math

import numpy as np

from riser.physics.internal_flow import contents_mass_per_length
from riser.model.sections import segment_properties


def flow_arrays(scene, mesh, mass: np.ndarray, wload: np.ndarray):
    """(fpar, fnodes) of :func:`vfife.kernels.flow_pass` for ``scene`` on ``mesh``, with
    the nodal masses ``mass`` [kg] and weights ``wload`` [N] holding the mean contents."""
    flow = scene.internal_flow
    mu0 = contents_mass_per_length(scene)
    eta = flow.density_amplitude if flow.slug_length is not None else 0.0
    phase = flow.wavenumber * mesh.s + math.radians(flow.phase_deg)
    fpar = np.array([flow.speed, mu0, eta, flow.omega, scene.gravity])
    trib = mesh.trib
    fnodes = np.vstack([np.cos(phase), np.sin(phase), mass - mu0 * trib, wload,
                        np.full(mesh.n, mu0)])
    return fpar, fnodes


def lightest_mass_factor(scene) -> float:
    """Smallest (m + mu) / (m + mu_0) over the slug (1 without one): the factor on the
    nodal masses the critical step is taken with (m the lightest pipe mass per length)."""
    flow = scene.internal_flow
    if flow is None or not flow.has_slug:
        return 1.0
    mu0 = contents_mass_per_length(scene)
    m = min(p.mass for p in segment_properties(scene))
    return (m - flow.density_amplitude * mu0) / m
