"""A hang-off motion along several axes (issue 35): an orbit (one period, an amplitude and
a phase lead per axis) and a time series per axis (riser/physics/dynamics.py TopMotion). The file
forms and their refusals; an orbit along one axis is that axis' motion to the bit; the
frequency domain's response to an orbit is the sum of its axes' responses (a linear line:
no drag); the VFIFE's first harmonic against the frequency domain's under an orbit."""

from __future__ import annotations

import math

import numpy as np
import pytest

import vfife
from bvp.frequency.harmonic import solve_harmonic
from riser.physics.dynamics import Dynamics, TopMotion
from riser.errors import SceneError
from riser.physics.hang_off_motion import HangOffPath
from riser.io.scene_file import parse_scene
from riser.physics.hang_off_motion import motion_amplitudes
from riser.results.response import harmonic_motion_vector
from verification.comparison import harmonics

JUMPER = """
name = "jumper-orbit"
[environment]
gravity = 9.807
water_density = 1000.0
water_depth = 100.0
[line_types.main]
outer_diameter = 0.396
mass_per_length = 165.0
axial_stiffness = 500.0e6
bending_stiffness = 120.8e3
drag_normal = DRAG
drag_tangential = 0.0
added_mass = 1.0
[[segments]]
line_type = "main"
length = 170.0
[ends]
anchor = [0.0, 45.0]
hang_off = [100.0, 95.0]
[seabed]
stiffness = 1.188e6
damping = 3.2104
"""


def jumper(drag=1.0, motion=""):
    return parse_scene(JUMPER.replace("DRAG", repr(drag)) + motion)


ORBIT = """
[dynamics]
duration = 100.0
output_interval = 0.25
[dynamics.top_motion]
amplitudes = [0.3, 0.2, 0.0]
phases_deg = [90.0, 0.0, 0.0]
period = 10.0
"""


def test_the_orbit_and_the_series_per_axis_read_from_a_file():
    tm = jumper(motion=ORBIT).dynamics.top_motion
    assert tm.is_orbit and tm.moves("x") and tm.moves("y") and not tm.moves("z")
    d = tm.displacement([0.0, 2.5])
    # x leads by 90 deg: 0.3 sin(omega t + pi/2) = 0.3 cos(omega t)
    np.testing.assert_allclose(d[:, 0], [0.3, 0.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(d[:, 1], [0.0, 0.2, 0.0], atol=1e-15)
    series = jumper(motion="""
[dynamics]
duration = 30.0
[dynamics.top_motion]
times = [0.0, 10.0, 20.0]
displacements_x = [0.0, 1.0, 0.0]
displacements_z = [0.0, 0.5, 0.0]
""").dynamics.top_motion
    np.testing.assert_allclose(series.displacement([5.0])[:, 0], [0.5, 0.0, 0.25])
    assert not series.moves("y") and series.lowest_displacement == 0.0


BAD = [
    ("amplitudes = [0.3, 0.2, 0.0]\nperiod = 10.0\naxis = \"y\"", "dynamics.top_motion.axis"),
    ("amplitudes = [0.3, 0.2]\nperiod = 10.0", "dynamics.top_motion.amplitudes"),
    ("amplitudes = [0.3, 0.2, 0.0]\namplitude = 1.0\nperiod = 10.0",
     "dynamics.top_motion.amplitude"),
    ("amplitude = 1.0\nperiod = 10.0", "dynamics.top_motion.axis"),
    # resultant peak speed 2 pi sqrt(30^2 + 30^2) / 10 = 26.7 m/s > 20 m/s
    ("amplitudes = [30.0, 30.0, 0.0]\nperiod = 10.0", "dynamics.top_motion.amplitudes"),
    ("times = [0.0, 1.0]\ndisplacements_x = [0.0, 1.0]\ndisplacements = [0.0, 1.0]",
     "dynamics.top_motion.displacements"),
    ("times = [0.0, 1.0]\ndisplacements_x = [0.0, 1.0, 2.0]",
     "dynamics.top_motion.displacements_x"),
    ("times = [0.0, 1.0]\ndisplacements_y = [0.5, 1.0]", "dynamics.top_motion.displacements_y[0]"),
    # along y below the seabed: the hang-off is 95 m up
    ("amplitudes = [0.0, 96.0, 0.0]\nperiod = 40.0", "dynamics.top_motion.amplitudes[1]"),
]


@pytest.mark.parametrize("keys,key", BAD, ids=[b[1] + str(i) for i, b in enumerate(BAD)])
def test_a_bad_motion_is_refused_naming_its_key(keys, key):
    with pytest.raises(SceneError) as exc:
        jumper(motion=f"[dynamics]\nduration = 100.0\n[dynamics.top_motion]\n{keys}\n")
    assert exc.value.key == key, str(exc.value)


def test_an_orbit_out_of_plane_makes_the_dynamics_3d():
    sc = jumper(motion=ORBIT.replace("[0.3, 0.2, 0.0]", "[0.3, 0.2, 0.1]"))
    assert not sc.is_planar and sc.statics_planar
    assert sc.out_of_plane()[0] == "dynamics.top_motion.amplitudes"


def test_an_orbit_along_one_axis_is_that_axis_motion_to_the_bit():
    t = np.linspace(0.0, 30.0, 301)
    one = jumper(motion=ORBIT.replace("amplitudes = [0.3, 0.2, 0.0]\nphases_deg = [90.0, 0.0, "
                                      "0.0]", "axis = \"y\"\namplitude = 0.2"))
    orb = jumper(motion=ORBIT.replace("[0.3, 0.2, 0.0]", "[0.0, 0.2, 0.0]"))
    np.testing.assert_array_equal(HangOffPath(one)(t), HangOffPath(orb)(t))
    a = vfife.solve(one.replace(dynamics=Dynamics(duration=12.0, output_interval=0.5,
                                                  top_motion=one.dynamics.top_motion)),
                    element_length=2.0).require()
    b = vfife.solve(orb.replace(dynamics=Dynamics(duration=12.0, output_interval=0.5,
                                                  top_motion=orb.dynamics.top_motion)),
                    element_length=2.0).require()
    np.testing.assert_array_equal(a.dynamics.timeseries["hang_off_tension"],
                                  b.dynamics.timeseries["hang_off_tension"])


def test_the_frequency_domain_superposes_an_orbits_axes():
    # without drag the linearised line is linear: the response to the orbit is the sum of
    # the responses to its axes (each with its phase), to the linear solve's round-off
    sc = jumper(drag=0.0, motion=ORBIT)
    D, period = harmonic_motion_vector(sc)
    np.testing.assert_allclose(D, [-1j * 0.3 * 1j, -1j * 0.2, 0.0], atol=1e-15)
    both = solve_harmonic(sc, period, D)
    x = solve_harmonic(sc, period, motion_amplitudes("x", 1.0) * (0.3 * 1j))
    y = solve_harmonic(sc, period, motion_amplitudes("y", 0.2))
    for key in ("tension", "moment", "dx", "dy"):
        ref = x.amplitudes[key] + y.amplitudes[key]
        scale = float(np.max(np.abs(ref)))
        assert float(np.max(np.abs(both.amplitudes[key] - ref))) <= 1e-9 * scale, key


def test_the_vfife_follows_the_frequency_domain_under_an_orbit():
    # a small orbit (0.3 m surge leading 0.2 m heave by 90 deg, T = 10 s) on the jumper:
    # the VFIFE's first harmonic of the hang-off tension over the last 4 periods against
    # the FD's (drag linearised at this orbit). Tolerances: the harmonic protocol's for
    # one axis (0.5 % of the amplitude, 1 deg), measured there 0.2 % and 0.1 deg on this
    # jumper in a wave
    sc = jumper(motion=ORBIT)
    D, period = harmonic_motion_vector(sc)
    fd = solve_harmonic(sc, period, D)
    res = vfife.solve(sc, element_length=1.0).require()
    ts = res.dynamics.timeseries
    fit = harmonics.fit(ts["time"], ts["hang_off_tension"][None, :], period,
                        sc.dynamics.duration - 4.0 * period)
    vf, ref = complex(fit.first[0]), complex(fd.amplitudes["tension"][-1])
    assert abs(vf) == pytest.approx(abs(ref), rel=5e-3)
    assert abs(math.degrees(np.angle(vf / ref))) < 1.0


def test_compare_dynamics_takes_an_orbit():
    # the harmonic protocol on an orbit, scaled so that its largest axis amplitude is
    # 0.05 m (the linear limit): every judged row within its tolerance (measured: hang-off
    # tension -0.04 %, 0.03 deg; tension along s -0.23 %, moment -0.36 %, displacement
    # -0.62 %); at 0.3 m the moment differs by 1.2 % (the nonlinearity: reported there)
    from verification.comparison.dynamic import protocol as dynamics
    sc = jumper(motion=ORBIT)
    dc = dynamics.compare_dynamics(sc, amplitudes=[0.05])
    assert dc.axis == dynamics.ORBIT
    r = dc.results[0]
    judged = [row for row in r.rows if row["pass"] is not None]
    assert len(judged) >= 5 and all(row["pass"] for row in judged), r.rows
    tm = dc.matched.dynamics.top_motion
    assert max(tm.amplitudes) == pytest.approx(0.3)      # the scene's own orbit, unscaled
