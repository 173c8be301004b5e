"""The VFIFE's natural modes about a 3D static state (vfife/modal/modes.py, the coupled
path; vfife/modal/tangent.py about a 3D state), each against an independent source:

- the coupled eigenproblem forced on a planar state gives the two planar families'
  frequencies merged (the same model solved two ways);
- a line whose ends lie in a vertical plane turned about y (the hang-off out of the
  anchor's x-y plane, no current) is the planar line turned: its coupled modes are the
  planar twin's families merged, and a mode out of the turned plane has the out-of-plane
  share cos^2 of the turn (rotation invariance; the state is 3D in the global axes, the
  directors have z components, the rotations are about :func:`normal_axes`);
- the tangent about a 3D state in a cross-flow is symmetric (an energy's Hessian) and is
  the derivative of the kernel's own nodal forces and moments (central differences of
  :func:`vfife.statics.newton.out_of_balance`, the time integration's force assembly);
- a coupled mode's frequency is the one the time-domain model vibrates at when released
  in it (:func:`free_vibration`, the drag held as a dead load in a current);
- slow: scr-steel-current-90 against the BVP's 3D modes (another discretisation of the
  same continuum), and its free vibration.

The small scenes are :func:`builders.catenary`'s 150 m line (0.1 m pipe, 100 N/m
submerged, k = 1e5 N/m2 seabed) at 2 m elements.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import builders
import vfife
from riser.results.modes import COUPLED, PLANES, mac, out_of_plane_share, shape_at
from verification.catalog import resolve
from vfife.modal.modes import free_vibration, held_drag, solve_modes
from vfife.modal.tangent import NDOF, dynamic_model, linearise, normal_axes, rotate
from vfife.statics.newton import out_of_balance

#: the turned scene's hang-off offset out of the x-y plane [m] (hang-off 100 m along x)
Z_OFFSET = 20.0
#: a current across the catenary's plane [m/s]: the line moves ~18 m sideways (of 150 m)
CROSS_FLOW = {"heights": [0.0], "speeds": [0.5], "heading_deg": 90.0}


def catenary_line(hang_off, *, name, current=None, tolerance=1e-4):
    """The catenary's line to ``hang_off`` ((x, y) or (x, y, z) [m]), 2 m elements, the
    statics relaxed to ``tolerance`` element weights."""
    return builders.scene(builders.line(
        150.0, (0.0, 0.0), hang_off, name=name, line_type=builders.small_pipe(),
        submerged_weight=100.0, seabed={"stiffness": 1.0e5},
        environment={"current": current} if current else None,
        vfife={"element_length": 2.0, "static_tolerance": tolerance}))


@pytest.fixture(scope="module")
def turned():
    """(scene, static) of the catenary whose hang-off is Z_OFFSET out of the x-y plane, and
    (scene, static) of its planar twin (the same span in the x-y plane). ~1 s."""
    span = math.hypot(100.0, Z_OFFSET)
    sc3 = catenary_line((100.0, 60.0, Z_OFFSET), name="turned")
    sc2 = catenary_line((span, 60.0), name="twin")
    st3, st2 = vfife.solve(sc3), vfife.solve(sc2)
    assert st3.converged and st2.converged, (st3.message, st2.message)
    return sc3, st3, sc2, st2


@pytest.fixture(scope="module")
def cross_flow():
    """(scene, static) of the catenary in a 0.5 m/s current across its plane. ~1.2 s."""
    sc = catenary_line((100.0, 60.0), name="cross-flow", current=CROSS_FLOW)
    st = vfife.solve(sc)
    assert st.converged, st.message
    return sc, st


def merged(res, k):
    """The ``k`` lowest planar modes of ``res`` (both families), by frequency."""
    return sorted(res.modes, key=lambda m: m.frequency_hz)[:k]


# ------------------------------------------------------------------ the coupled path itself
def test_coupled_path_on_a_planar_state_merges_the_families():
    """scr-steel at 5 m elements (planar): the coupled eigenproblem on all its free DOFs
    against the two families solved apart, merged by frequency. Its families interleave
    (out, out, in, out, in, out, out, in, out, in), modes 5 and 6 only 0.5 % apart."""
    sc = resolve("scr-steel")
    sc = sc.replace(vfife=sc.vfife.replace(element_length=5.0))
    st = vfife.solve(sc)
    count = 5
    planar = solve_modes(sc, 2 * count, static=st)
    coupled = solve_modes(sc, count, static=st, coupled=True)
    assert planar.converged and coupled.converged, (planar.message, coupled.message)
    assert coupled.info["static_state"] == "planar"
    assert coupled.message.startswith(f"{2 * count} coupled modes about the planar static")
    ref = merged(planar, 2 * count)
    assert {r.plane for r in ref} == set(PLANES)
    f_ref = np.array([m.frequency_hz for m in ref])
    f = np.array([m.frequency_hz for m in coupled.modes])
    # the same K and M (the second rotation's axis reversed: e_z x d against d x e_z),
    # split into blocks or not; ARPACK's shift-invert converges the eigenvalues to
    # round-off (measured 2.4e-11): 1e-9
    assert np.max(np.abs(f / f_ref - 1.0)) < 1e-9
    # no two of these within 0.2 % (measured 0.5 %), so each eigenvector is one family's:
    # its out-of-plane share 0 or 1 to round-off (a block-diagonal K and M mix the blocks'
    # vectors only by round-off over the eigenvalue gap; measured 1e-18), its shape the
    # family mode's
    assert np.min(np.diff(f_ref) / f_ref[1:]) > 2e-3
    for m, r, share in zip(coupled.modes, ref, coupled.info["out_of_plane_share"]):
        assert share == pytest.approx(1.0 if r.plane == "out_of_plane" else 0.0, abs=1e-9)
        assert mac(m.shape, r.shape) > 1.0 - 1e-9


def test_turned_plane_is_the_planar_line_turned(turned):
    """The line to a hang-off out of the x-y plane hangs in the vertical plane through its
    ends, turned by alpha = atan(Z_OFFSET / 100) about y: the weight, the vertical seabed
    spring and the added mass normal to the axis do not change under that turn, so its
    coupled modes are the planar twin's families merged; a mode normal to the turned plane
    moves along (-sin alpha, 0, cos alpha) (share cos^2 alpha), an in-plane one (x, y) of the
    twin moves (x cos alpha, y, x sin alpha) (share sin^2 alpha sum x^2 / sum(x^2 + y^2))."""
    sc3, st3, sc2, st2 = turned
    count = 4
    res = solve_modes(sc3, count, static=st3)
    twin = solve_modes(sc2, 2 * count, static=st2)
    assert res.converged and twin.converged, (res.message, twin.message)
    # the contract of the coupled family
    assert res.info["static_state"] == "3d"
    assert res.info["out_of_plane_z_m"] == pytest.approx(Z_OFFSET, rel=1e-12)
    assert res.message.startswith(f"{2 * count} coupled modes about the 3D static state")
    assert [m.plane for m in res.modes] == [COUPLED] * (2 * count)
    assert [m.number for m in res.modes] == list(range(1, 2 * count + 1))
    for m in res.modes:
        assert m.shape.shape == (len(m.s), 3) and np.all(m.shape[[0, -1]] == 0.0)
        assert m.shape.ravel()[np.argmax(np.abs(m.shape))] == 1.0
    # the coupling of the in-plane and out-of-plane DOFs is large (the state is 3D in the
    # global axes: the check is not one of two decoupled problems)
    assert res.info["coupling"] > 0.5
    ref = merged(twin, 2 * count)
    f_ref = np.array([m.frequency_hz for m in ref])
    f = np.array([m.frequency_hz for m in res.modes])
    assert np.min(np.diff(f_ref) / f_ref[1:]) > 1e-2          # no two within 1 %
    # both statics end with Newton to round-off (vfife/statics/newton.py, POLISH), so the
    # two states are the same discrete equilibrium turned; the tangents agree to the
    # central differences' round-off (~1e-10 of K), measured 8e-12 on the frequencies: 1e-9
    assert np.max(np.abs(f / f_ref - 1.0)) < 1e-9
    c2 = 1.0 / (1.0 + (Z_OFFSET / 100.0) ** 2)            # cos^2 alpha
    for share, r in zip(res.info["out_of_plane_share"], ref):
        if r.plane == "out_of_plane":
            expected = c2
        else:
            x2, y2 = (np.trapezoid(r.shape[:, j] ** 2, r.s) for j in (0, 1))
            expected = (1.0 - c2) * x2 / (x2 + y2)
        # the eigenvectors to round-off over the gaps (> 1 %): measured 1e-13; 1e-8
        assert share == pytest.approx(expected, abs=1e-8)
    assert res.info["out_of_plane_share"] == [out_of_plane_share(m) for m in res.modes]


# ------------------------------------------------------------------ the tangent about a 3D state
def _turned_directors(D0, basis, r3, r4):
    """Directors D0 (3, n) turned by the rotation vector r3 basis[:, 0] + r4 basis[:, 1]."""
    phi = r3 * basis[:, 0].T + r4 * basis[:, 1].T
    angle = np.linalg.norm(phi, axis=0)
    return rotate(D0, phi / np.where(angle > 0.0, angle, 1.0), angle)


def test_tangent_about_a_3d_state_is_the_kernels_force_derivative(cross_flow):
    """K about the state in a cross-flow against central differences of the kernel's own
    out-of-balance forces and moments (one explicit step of the 3D kernels, the force
    assembly of the time integration), the static drag held as the dead load of the
    modes' model (:func:`held_drag`), along a random direction of all the free DOFs."""
    sc, st = cross_flow
    model = dynamic_model(sc, st.solver_state, 1.0)
    tan = linearise(model, normal_axes(model.D))
    # an energy's Hessian: symmetric to the central differences' round-off (measured
    # 1.4e-11 of the diagonal); the coupling of the in-plane and out-of-plane DOFs is of
    # the order of the diagonal: the state is far from planar (18 m sideways)
    assert tan.asymmetry < 1e-8
    assert tan.coupling > 0.5
    with_drag = out_of_balance(model)[0]
    model.use_drag = False
    drag = with_drag - out_of_balance(model)[0]      # the kernel's drag at the static state
    model.P, model.use_dead = held_drag(model), True
    # the held dead load is the kernel's static drag up to the statics' out-of-balance
    # force, < 1e-4 element weights (the tolerance: 1e-4 x 100 N/m x 2 m = 0.02 N) against
    # a drag of up to 25 N a node (measured 9e-4 N)
    assert np.max(np.abs(drag)) > 10.0
    assert np.max(np.abs(model.P - drag)) < 1e-4 * 100.0 * 2.0
    n = model.mesh.n
    free = tan.free_dofs()
    X0, D0 = model.X.copy(), model.D.copy()

    def g(dq):
        """The generalised out-of-balance forces at the state + dq (all DOFs)."""
        for k in range(3):
            model.X[k] = X0[k] + dq[k::NDOF]
        model.D[:] = _turned_directors(D0, tan.basis, dq[3::NDOF], dq[4::NDOF])
        F, M = out_of_balance(model)
        model.X[:], model.D[:] = X0, D0
        out = np.zeros(NDOF * n)
        out[0::NDOF], out[1::NDOF], out[2::NDOF] = F
        out[3::NDOF] = np.einsum("in,ni->n", M, tan.basis[:, 0])
        out[4::NDOF] = np.einsum("in,ni->n", M, tan.basis[:, 1])
        return out

    v = np.zeros(NDOF * n)
    v[free] = np.random.default_rng(7).uniform(-1.0, 1.0, free.size)
    v[3::NDOF] *= 0.1                     # rotations ~ translations / 10 m
    v[4::NDOF] *= 0.1
    h = 1e-5                              # m: no node crosses the seabed (1 mm penetration)
    fd = (g(h * v) - g(-h * v)) / 2.0
    kv = -(tan.K @ (h * v))
    # central differences: O(h^2) curvature ~1e-10 and the round-off of the forces
    # (~1e-13 N against K h v ~1e-2 N) ~1e-11; measured 4e-10 of the largest. A missing
    # seabed spring (1e5 N/m2 x 2 m x 1e-5 m = 2 N) or a wrong rotation basis would be
    # of order 1: 1e-7
    assert np.max(np.abs(fd[free] - kv[free])) < 1e-7 * np.max(np.abs(kv[free]))


# ------------------------------------------------------------------ free vibration
def test_free_vibration_of_coupled_modes_in_a_current(cross_flow):
    """The time-domain model (3D kernels, the static drag held as a dead load, no damping)
    released in coupled modes 1 and 2 about the state in a cross-flow vibrates at their
    eigenfrequencies. These modes are strongly coupled (out-of-plane shares 0.66, 0.80)."""
    sc, st = cross_flow
    res = solve_modes(sc, 1, static=st)
    assert res.converged and res.info["static_state"] == "3d", res.message
    shares = res.info["out_of_plane_share"]
    assert all(0.2 < s < 0.9 for s in shares)       # neither family's: coupled (measured)
    for number in (1, 2):
        fv = free_vibration(sc, COUPLED, number, static=st, periods=6)
        # as the planar check (tests/test_vfife_modes.py): time integration (omega dt)^2
        # / 24 < 1e-7, zero crossings over 5 periods sampled 40 times a period ~1e-6, the
        # seabed's contact switching at 1.5 mm amplitude ~1e-6 (measured -1.1e-6 and
        # +1.1e-7; released without the held drag: -32 %, with the added mass isotropic
        # in the eigenproblem: +2.7 %): 2e-5
        assert abs(fv["rel_diff"]) < 2e-5, (number, fv)
        # x4 rotational inertia (the dynamics') against solve_modes' x1: -3/2 (k r_g)^2
        f = res.modes[number - 1].frequency_hz
        assert fv["modal_frequency_hz"] == pytest.approx(f, rel=1e-5)
    # the planar families' check still refuses a current (it releases without the drag)
    with pytest.raises(ValueError, match="current"):
        free_vibration(sc, "in_plane", 1, static=st)


def test_free_vibration_of_a_coupled_mode_without_current(turned):
    """The same about the turned line (no current, nothing held): the 3D kernels released
    in coupled mode 1, out of the turned plane."""
    sc3, st3, _, _ = turned
    fv = free_vibration(sc3, COUPLED, 1, static=st3, periods=6)
    # as above (measured +2.3e-6): 2e-5
    assert abs(fv["rel_diff"]) < 2e-5, fv


# ------------------------------------------------------------------ a riser (slow)
@pytest.mark.slow
def test_scr_steel_current_90_against_the_bvp():
    """scr-steel-current-90 (1 m elements): the VFIFE's coupled modes against the BVP's
    (the 3D rod's coupled family, bvp/modal), another discretisation of the same
    continuum and linearisation (~16 s)."""
    import bvp.modal.modes
    sc = resolve("scr-steel-current-90")
    v = solve_modes(sc, 3)
    b = bvp.modal.modes.solve_modes(sc, 3)
    assert v.converged and b.converged, (v.message, b.message)
    assert v.info["static_state"] == "3d" and len(v.modes) == len(b.modes) == 6
    assert v.info["asymmetry"] < 1e-8 and v.info["negative_eigenvalues"] == 0
    shares = v.info["out_of_plane_share"]
    for mv, mb, share in zip(v.modes, b.modes, shares):
        # scr-steel (planar) at 1 m: the in-plane modes -1.9e-4 (the VFIFE's touchdown
        # resolved to an element, O(h)), out of plane -1e-6; here -4.0e-4 and -3.2e-4 for
        # the two in-plane-like modes, within -2e-5 for the others. 1e-3: 2.5x the largest,
        # a fifth of the modal comparison's 0.5 % target
        assert mv.frequency_hz / mb.frequency_hz - 1.0 == pytest.approx(0.0, abs=1e-3)
        # the same shape (measured MAC >= 0.99992; modes 5 and 6 are 0.8 % apart and mix
        # a little differently in each method)
        sb = shape_at(mb, mv.s)
        assert mac(sb, mv.shape) > 0.999
        # the share (integrated along s, each on its own mesh): measured within 4e-7 of the
        # BVP's on the same points but for modes 5 and 6 (3.6e-3)
        assert share == pytest.approx(out_of_plane_share(mb), abs=1e-2)
    # physics: the current moves the line 14 m sideways (of 2000 m); scr-steel's lowest
    # out-of-plane frequencies (0.0157, 0.0302 Hz) lie well below its lowest in-plane one
    # (0.0377 Hz), so modes 1 and 2 stay out of plane and mode 3 in plane (measured
    # shares 0.9987, 0.9991, 0.0002)
    assert shares[0] > 0.9 and shares[1] > 0.9 and shares[2] < 0.1
    assert all(0.0 <= s <= 1.0 for s in shares)


@pytest.mark.slow
def test_free_vibration_scr_steel_current_90():
    """scr-steel-current-90 at 5 m elements released in coupled modes 1 (out of plane) and
    3 (in plane, with the seabed contact), its drag held (~10 s)."""
    sc = resolve("scr-steel-current-90")
    sc = sc.replace(vfife=sc.vfife.replace(element_length=5.0))
    static = vfife.solve(sc)
    assert static.converged, static.message
    for number in (1, 3):
        fv = free_vibration(sc, COUPLED, number, static=static, periods=4)
        # as the small line's (measured -6.9e-7 and -2.4e-7): 1e-5
        assert abs(fv["rel_diff"]) < 1e-5, (number, fv)
