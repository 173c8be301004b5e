"""A dynamic run continued from a checkpoint is the run that never stopped (issue 36).

The dynamic comparison doubles the settling of a window that drifts by continuing the
run from a checkpoint (verification/comparison/dynamic/vfife_side.py) where it used to start
again at t = 0: the continued run's states, envelope and window statistics must be those
of the run started again, bit for bit (the same arithmetic on the same state)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import vfife
from verification.catalog import resolve
from verification.comparison.dynamic.vfife_side import continued
from verification.comparison.dynamic.protocol import dynamic_scene
from vfife.dynamics.run import run_dynamics

JUMPER = Path(__file__).resolve().parents[1] / "examples" / "scenes" / "flexible-jumper.toml"
PERIOD, RAMP = 6.9, 3


def scene_for(settle: int):
    return dynamic_scene(resolve(str(JUMPER)), "y", 0.1, PERIOD, settle, RAMP)


def test_a_run_continued_from_its_checkpoint_is_the_run_started_again():
    h = 1.6                                   # coarse: a cheap run, the same arithmetic
    first = vfife.solve(scene_for(6), element_length=h,
                        checkpoint_at=(RAMP + 12) * PERIOD).require()
    ck = first.dynamics.checkpoint
    assert ck is not None and abs(ck.t - (RAMP + 12) * PERIOD) < 1e-9
    later = scene_for(12)
    _, dinfo = run_dynamics(later, first.solver_state, first.solver_state.planar,
                            resume=ck)
    again = vfife.solve(later, element_length=h).require()
    states = continued(first.dynamics.states, dinfo["states"], ck.t)
    ref = again.dynamics.states
    assert states.keys() == ref.keys()
    for key in ref:
        assert np.array_equal(states[key], ref[key]), key
    for key, value in again.dynamics.envelope.items():
        assert np.array_equal(dinfo["envelope"][key], value), key
    stats = {k: v for k, v in again.info.items() if k.startswith("dynamic_")
             and k in dinfo["statistics"]}
    assert len(stats) > 5
    assert {k: dinfo["statistics"][k] for k in stats} == stats
    assert dinfo["steps"] == again.info["dynamic_steps"]
