"""Internal flow and steady slug flow (scene [internal_flow], vfife/flow.py): the exact
checks of issue 15 against closed forms and conservation laws, and the bad-input contract.

Closed forms used:
- Fylling (1988): a steady uniform flow acts as an extra internal pressure rho U^2: the
  effective tension and the static shape do not change, the wall tension rises by mu U^2.
- A taut pipe conveying fluid between fixed ends (Paidoussis 1998, ch. 3, with EI -> 0):
  M w_tt + 2 mu U w_st - T w_ss = 0 (T the effective tension). With w = exp(i(omega t +
  k s)) the two roots k = omega (mu U +- S) / T, S = sqrt(mu^2 U^2 + M T), and w = 0 at both
  ends give omega_n = n pi T / (L S), and the mode sin(delta s) cos(omega t + k_bar s) with
  k_bar = omega mu U / T: a point further downstream leads in phase by k_bar per metre.
"""

from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

import bvp
import vfife
from riser.physics.internal_flow import contents_mass_per_length
from riser.io.scene_file import scene_from_dict
from verification.catalog import builtin_paths
from vfife.dynamics.run import run_dynamics


def liu(flow: dict | None, dynamics: dict | None = None, h: float = 4.0):
    """Liu et al.'s SCR (verification/scenes/flow/liu2021-scr.toml) with another
    [internal_flow] (None: none) and [dynamics] (None: statics), elements of h [m]."""
    data = tomllib.loads(builtin_paths()["liu2021-scr"].read_text())
    data.pop("internal_flow")
    data.pop("dynamics")
    if flow is not None:
        data["internal_flow"] = flow
    if dynamics is not None:
        data["dynamics"] = dynamics
    data["vfife"] = {"element_length": h}
    return scene_from_dict(data, "liu.toml")


# ------------------------------------------------------------------ 1. steady flow
@pytest.fixture(scope="module")
def steady_statics():
    flow = liu({"speed": 2.5})
    none = liu(None)
    still = liu({"speed": 0.0})
    return {name: {"vfife": vfife.solve(sc), "bvp": bvp.solve(sc)}
            for name, sc in (("flow", flow), ("none", none), ("still", still))}


def test_steady_flow_leaves_shape_and_effective_tension_unchanged(steady_statics):
    # protects: Fylling's invariance. Both methods solve the same equations with and
    # without flow (the flow's mu U^2 is in the effective tension's definition), so shape
    # and effective tension must agree to the solvers' own repeatability: the BVP is
    # deterministic (bit-identical), the VFIFE relaxation path sees no flow force in
    # statics (identical too); 1e-9 leaves room for a reordered sum only
    for m in ("vfife", "bvp"):
        a, b = steady_statics["flow"][m].profile, steady_statics["none"][m].profile
        assert steady_statics["flow"][m].converged
        span = float(np.ptp(b.y))
        assert np.max(np.abs(a.y - b.y)) <= 1e-9 * span
        assert np.max(np.abs(a.x - b.x)) <= 1e-9 * span
        assert np.max(np.abs(a.tension - b.tension)) <= 1e-9 * np.max(b.tension)
        assert "internal_flow" in steady_statics["flow"][m].effects


def test_steady_flow_raises_the_wall_tension_by_mu_u2(steady_statics):
    # protects: the reported wall tension. Flow at 2.5 m/s against the same contents at
    # rest: T_w differs by exactly mu U^2 = 64.34 kg/m x 6.25 = 402.1 N everywhere (the
    # pressure terms are the same); and at rest T_w - T_e is the pressure term p_i A_i -
    # p_o A_o, evaluated here by hand at the hang-off (10 m below the surface, p_i = 0)
    mu = 632.135 * math.pi / 4 * 0.36 ** 2
    for m in ("vfife", "bvp"):
        a, b = steady_statics["flow"][m].profile, steady_statics["still"][m].profile
        np.testing.assert_allclose(a.wall_tension - b.wall_tension, mu * 2.5 ** 2,
                                   rtol=1e-9)
        top = -1025.0 * 9.81 * 10.0 * math.pi / 4 * 0.4 ** 2
        assert b.wall_tension[-1] - b.tension[-1] == pytest.approx(top, rel=1e-9)
        sm = steady_statics["flow"][m].summary()
        assert sm["hang_off_wall_tension"] == pytest.approx(a.wall_tension[-1])


def test_both_methods_agree_on_the_static_state_with_flow(steady_statics):
    # protects: the cross-check with steady flow. On 4 m elements the VFIFE's touchdown
    # moment peak is 0.12 % off the BVP's (its discretisation error at this mesh, see
    # reports/compare); tensions agree to 1e-4
    v, b = (steady_statics["flow"][m].summary() for m in ("vfife", "bvp"))
    assert v["hang_off_tension"] == pytest.approx(b["hang_off_tension"], rel=1e-4)
    assert v["hang_off_wall_tension"] == pytest.approx(b["hang_off_wall_tension"], rel=1e-4)
    assert v["max_moment"] == pytest.approx(b["max_moment"], rel=5e-3)
    assert v["tdp_s"] == pytest.approx(b["tdp_s"], abs=2.0)      # half an element


def test_steady_flow_keeps_a_line_at_rest_in_dynamics():
    # protects: no flow force on a line at rest (Coriolis ~ velocity, the centrifugal force
    # in the effective tension): over 20 s of dynamics without motion the hang-off tension
    # stays within 1e-6 of the run without flow (the static residual, 1e-3 element
    # weights, drives both the same)
    dyn = {"duration": 20.0, "output_interval": 1.0}
    runs = [vfife.solve(liu(f, dyn, h=10.0)) for f in ({"speed": 2.5}, None)]
    ya = np.asarray(runs[0].dynamics.timeseries["hang_off_tension"])
    yb = np.asarray(runs[1].dynamics.timeseries["hang_off_tension"])
    assert np.max(np.abs(ya - yb)) < 1e-6 * np.max(yb)
    assert "internal_flow" in runs[0].effects


# ------------------------------------------------------------------ 2. eta = 0
def test_slug_with_zero_amplitude_is_the_steady_flow():
    # protects: the slug path reduces to the steady flow (same kernel, eta = 0): identical
    # time series, to round-off
    dyn = {"duration": 30.0, "output_interval": 0.5,
           "top_motion": {"axis": "x", "amplitude": 0.5, "period": 9.0}}
    a = vfife.solve(liu({"speed": 2.5, "slug": {"density_amplitude": 0.0,
                                                "slug_length": 80.0}}, dyn, h=10.0))
    b = vfife.solve(liu({"speed": 2.5}, dyn, h=10.0))
    for k in ("hang_off_tension", "max_moment", "kinetic_energy"):
        np.testing.assert_allclose(a.dynamics.timeseries[k], b.dynamics.timeseries[k],
                                   rtol=1e-12, atol=1e-9)


# ------------------------------------------------------------------ 3. Coriolis
def taut_pipe(speed: float, duration: float = 150.0):
    """A weightless horizontal pipe of 100 m (1 m elements) stretched to T = 1e4 N, no
    hydrodynamics, conveying water (mu = 49.09 kg/m, pipe 50 kg/m) at ``speed``."""
    ea = 1.0e8
    return scene_from_dict({
        "name": "taut-pipe", "environment": {"water_depth": 1000.0},
        "line_types": {"pipe": {"outer_diameter": 0.3, "inner_diameter": 0.25,
                                "mass_per_length": 50.0, "axial_stiffness": ea,
                                "bending_stiffness": 1.0, "drag_normal": 0.0,
                                "added_mass": 0.0, "contents_density": 1000.0}},
        "segments": [{"line_type": "pipe", "length": 100.0, "submerged_weight": 0.0}],
        "ends": {"anchor": [0.0, 50.0], "hang_off": [100.0 * (1.0 + 1.0e4 / ea), 50.0]},
        "internal_flow": {"speed": speed},
        "dynamics": {"duration": duration, "output_interval": 0.1, "save_states": True},
        "vfife": {"element_length": 1.0},
    }, "taut.toml")


def pluck(scene, amplitude: float = 0.005):
    """Free vibration from mode 1 of the pipe without flow (w = a sin(pi s / L), in plane),
    at rest; returns (t, s, w (k, n)) of the in-plane deflection."""
    static = vfife.solve(scene.replace(dynamics=None)).solver_state
    s = static.mesh.s
    static.X[1] += amplitude * np.sin(math.pi * s / s[-1])
    _, info = run_dynamics(scene, static, planar=True)
    st = info["states"]
    return np.asarray(st["t"]), s, np.asarray(st["x"])[:, :, 1] - 50.0


def fundamental(t, w, s):
    """(omega [rad/s], phase lead [rad] of s = 75 m over s = 25 m) of the modal
    coordinate's fundamental: upward zero crossings over whole periods, then the phase of
    each station's signal at that frequency (least squares over those periods)."""
    q = w @ np.sin(math.pi * s / s[-1])
    up = np.flatnonzero((q[:-1] < 0) & (q[1:] >= 0))
    tc = t[up] - q[up] * (t[up + 1] - t[up]) / (q[up + 1] - q[up])
    om = 2 * math.pi * (len(tc) - 1) / (tc[-1] - tc[0])
    sel = (t >= tc[0]) & (t <= tc[-1])
    phases = []
    for x in (25.0, 75.0):
        j = int(np.argmin(np.abs(s - x)))
        a = np.column_stack([np.cos(om * t[sel]), np.sin(om * t[sel])])
        c, d = np.linalg.lstsq(a, w[sel, j], rcond=None)[0]
        phases.append(math.atan2(-d, c))          # w ~ cos(om t + phase)
    return om, phases[1] - phases[0]


def test_coriolis_frequency_and_phase_of_a_taut_pipe_conveying_fluid():
    # protects: the Coriolis force, its size and sign. Closed form (module docstring):
    # omega_1 = pi T / (L S), 29 % below the no-flow pi/L sqrt(T/M) at U = 20 m/s; the
    # downstream quarter point leads the upstream one by k_bar L/2 = 1.10 rad (a wrong sign
    # would make it lag). Measured: 2.6e-5 and 3e-5 off. Tolerances 1e-3: the lumped
    # mass's discretisation error is (pi h/L)^2/24 = 4e-5, the other modes (excited because
    # the flowing mode is complex) move the zero crossings a little, and the pluck of 5 mm
    # stretches the pipe by 1 N of tension (5e-5 on omega; 5 cm gave +0.2 %)
    scene = taut_pipe(20.0)
    mu = contents_mass_per_length(scene)
    M, T, L, U = 50.0 + mu, 1.0e4, 100.0, 20.0
    S = math.sqrt(mu ** 2 * U ** 2 + M * T)
    omega = math.pi * T / (L * S)
    t, s, w = pluck(scene)
    om, lead = fundamental(t, w, s)
    assert om == pytest.approx(omega, rel=1e-3)
    assert lead == pytest.approx(omega * mu * U / T * 50.0, rel=1e-3)
    # and without flow the string's pi/L sqrt(T/M), in phase
    t0, s0, w0 = pluck(taut_pipe(0.0))
    om0, lead0 = fundamental(t0, w0, s0)
    assert om0 == pytest.approx(math.pi / L * math.sqrt(T / M), rel=1e-3)
    assert abs(lead0) < 1e-3


# ------------------------------------------------------------------ 4. slug: momentum, speed
SLUG_U, SLUG_L = 5.0, 50.0          # m/s, m: six slugs on the line, one every 10 s


def hanging_pipe(duration: float = 0.0, h: float = 2.0):
    """A free-hanging catenary (300 m between (0, 50) and (200, 250), no seabed) in still
    water with drag, carrying a slug (eta 0.25, 40 m, 5 m/s)."""
    data = {
        "name": "hanging-slug", "environment": {"water_depth": 300.0},
        "line_types": {"pipe": {"outer_diameter": 0.2, "inner_diameter": 0.16,
                                "mass_per_length": 40.0, "axial_stiffness": 1.0e9,
                                "bending_stiffness": 1.0e5, "contents_density": 800.0}},
        "segments": [{"line_type": "pipe", "length": 300.0}],
        "ends": {"anchor": [0.0, 50.0], "hang_off": [200.0, 250.0]},
        "internal_flow": {"speed": SLUG_U, "slug": {"density_amplitude": 0.25,
                                                    "slug_length": SLUG_L}},
        "vfife": {"element_length": h},
    }
    if duration:
        data["dynamics"] = {"duration": duration, "output_interval": 0.1,
                            "save_states": True}
    return scene_from_dict(data, "hanging.toml")


@pytest.fixture(scope="module")
def slug_run():
    """Step the hanging pipe's dynamic model from its static state (no top motion) for 13
    slug periods in chunks of 10 steps, a whole number of chunks per period; keep, over
    the 13th period, the end elements' forces on the free nodes ((k, 2): the first
    element's on node 1 is -F[:, 0], the last element's on node n-2 is F[:, -1]) and the
    nodal masses (pipe + contents) at every chunk."""
    from vfife.model import Model
    from vfife.timestep import choose_step, critical_steps
    scene = hanging_pipe()
    static = vfife.solve(scene).solver_state
    model = Model(scene, static.mesh, rot_scale=4.0, added_mass=True, planar=True,
                  drag=True, surface=True, flow="dynamic")
    model.X[:] = static.X
    model.D[:] = static.D
    tmax = float(np.max(static.nodal_results()["element_tension"]))
    dt, _ = choose_step(critical_steps(static.mesh, rot_scale=4.0, tension=1.5 * tmax,
                                       added_mass=True, mass_factor=0.8), 0.8)
    period = SLUG_L / SLUG_U
    chunk = 10
    per = int(round(period / (chunk * dt)))
    dt = period / (per * chunk)                      # a whole number of chunks per period
    ends, mass = [], []
    for k in range(13 * per):
        model.run(chunk, dt, 0.0)
        if k >= 12 * per:                              # the 13th period
            ends.append(model.F[:, -1] - model.F[:, 0])
            mass.append(model.mass.copy())
    return {"model": model, "ends": np.array(ends), "mass": np.array(mass),
            "sample_dt": chunk * dt, "s": static.mesh.s}


def test_momentum_balance_over_one_slug_period(slug_run):
    # protects: the flow forces are internal to pipe + contents. Over one slug period of
    # the periodic state the line's momentum returns to its value, so the impulse of the
    # end elements' forces on the free nodes balances the weight of pipe and *mean*
    # contents (each node's contents average mu_0 over a period) and nothing else: a flow
    # force with a net resultant (a centrifugal force counted twice, in T_e and as mu U^2
    # kappa, would add mu U^2 (tau_top - tau_bottom) = 0.6 kN vertically here) breaks it.
    # Tolerance 1e-4 of the weight (7 N of 70 kN): the transient left after 12 periods of
    # drag damping and second-order (eta^2) mean forces; measured 7e-6 (vertical) and 6e-7
    # (horizontal), with the end forces swinging by +-145 N over the period
    mean = slug_run["ends"].mean(axis=0)
    weight = float(np.sum(slug_run["model"].fnodes[3][1:-1]))   # interior, mean contents
    assert abs(mean[0]) < 1e-4 * weight
    assert mean[1] == pytest.approx(weight, rel=1e-4)


def test_slug_travels_at_the_flow_speed(slug_run):
    # protects: the slug's kinematics in the kernel (omega = k U, travelling towards the
    # hang-off for U > 0): the contents mass the kernel gives two nodes 20 m apart repeats
    # with the delay 20 m / U = 4 s, read from their time series by circular
    # cross-correlation over one period, refined by a parabola through the peak. The
    # structural response is no clean reading: the slug train drives the line's own
    # sway at the slug frequency, and the moment's delay between stations 20 m apart varies
    # by +-15 % along this line (tried). Tolerance 1e-3: the sampling (0.0056 s of 4 s)
    s = slug_run["s"]
    j1, j2 = (int(np.argmin(np.abs(s - x))) for x in (140.0, 160.0))
    a, b = (slug_run["mass"][:, j] - slug_run["mass"][:, j].mean() for j in (j1, j2))
    n = len(a)
    corr = np.array([np.dot(a, np.roll(b, -k)) for k in range(n)])
    j = int(np.argmax(corr))
    c0, c1, c2 = corr[j - 1], corr[j], corr[(j + 1) % n]
    lag = (j + 0.5 * (c0 - c2) / (c0 - 2 * c1 + c2)) * slug_run["sample_dt"]
    assert (s[j2] - s[j1]) / lag == pytest.approx(SLUG_U, rel=1e-3)


# ------------------------------------------------------------------ 5. bad input
LIU_TEXT = builtin_paths()["liu2021-scr"].read_text()


@pytest.mark.parametrize("old,new,words", [
    ("density_amplitude = 0.25", "density_amplitude = 1.0",
     "internal_flow.slug.density_amplitude: must be < 1, got 1"),
    ("slug_length = 80.0", "slug_length = -80.0",
     "internal_flow.slug.slug_length: must be > 0 m, got -80"),
    ("inner_diameter = 0.36\nmass_per_length = 189.1\nyoungs_modulus = 2.07e11",
     "mass_per_length = 189.1\naxial_stiffness = 4.94e9\nbending_stiffness = 8.95e7",
     "line_types.pipe.inner_diameter: required by [internal_flow]"),
    ("contents_density = 632.135", "contents_density = 0.0",
     "line_types.pipe.contents_density: must be > 0 with [internal_flow]"),
    ("speed = 2.5", "speed = 2500.0", "internal_flow.speed: must be <= 50 m/s"),
    ("phase_deg = 0.0", "phase = 0.0", "internal_flow.slug.phase: unknown key"),
    ("slug_length = 80.0", "slug_length = 0.5",      # aliased on 4 m elements otherwise
     "vfife.element_length: must be <= 0.0625 m (at least 8 elements per slug"),
])
def test_bad_flow_input_one_line_exit_2(run_cli, tmp_path, old, new, words):
    # protects: the bad-input contract (one line naming the key, exit 2, before
    # any solver runs)
    assert old in LIU_TEXT
    text = LIU_TEXT.replace(old, new)
    if "axial_stiffness" in new:      # a section by its properties: no bore, no contents
        text = text.replace("contents_density = 632.135\n", "")
    path = tmp_path / "flow.toml"
    path.write_text(text)
    code, out, err = run_cli(["solve", str(path), "--method", "vfife",
                              "--out", str(tmp_path / "o")])
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and words in lines[0], err
    assert not (tmp_path / "o").exists() or not any((tmp_path / "o").iterdir())


def test_bvp_refuses_a_slug_and_modes_refuse_flow(run_cli, tmp_path):
    # protects: no silent wrong answer: the BVP has no slug (a travelling load) and the
    # modal analysis no Coriolis (its modes would be complex): both refuse, exit 2
    code, out, err = run_cli(["solve", "liu2021-scr", "--method", "bvp",
                              "--out", str(tmp_path / "b")])
    assert code == 2 and "internal_flow.slug" in err and "--method vfife" in err
    steady = tmp_path / "steady.toml"
    steady.write_text(LIU_TEXT[:LIU_TEXT.index("[internal_flow.slug]")])
    code, out, err = run_cli(["modes", str(steady), "--out", str(tmp_path / "m")])
    assert code == 2 and "internal_flow.speed: modes do not model" in err, err
