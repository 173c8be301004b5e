"""Fatigue by two methods on one sea state (slow: about 70 s): scr-steel-fatigue's middle
sea state (Hs 3 m, Tp 10 s), the VFIFE's rainflow against the frequency domain's record
of the same realisation and its spectral estimates (verification/studies/design)."""

from __future__ import annotations

import numpy as np
import pytest

from verification.catalog import resolve
from verification.studies.design.fatigue import TOUCHDOWN_ZONE, run_sea_state

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def state():
    sc = resolve("scr-steel-fatigue")
    return run_sea_state(sc, sc.design.fatigue.sea_states[1], 2.0)


def zone_max(st, key):
    z = (st.s >= st.tdp_s + TOUCHDOWN_ZONE[0]) & (st.s <= st.tdp_s + TOUCHDOWN_ZONE[1])
    return float(np.max(st.rates[key][z]))


def test_the_spectral_estimator_matches_the_rainflow_of_the_same_linear_record(state):
    # Dirlik against the rainflow count of the FD's own record of the same realisation:
    # the estimator alone. A record of one repeat period (333 s, ~40 cycles) samples the
    # range distribution once: with the damage's m = 5 weighting its scatter is ~10-20 %
    # (measured: 1.04 at the touchdown, 1.21 at the hang-off over the scatter diagram);
    # 35 % is the bound. The narrow band is conservative against Dirlik.
    for where in ("touchdown", "hang_off"):
        get = (lambda k: zone_max(state, k)) if where == "touchdown" else \
            (lambda k: float(state.rates[k][-1]))
        ratio = get("dirlik_fd") / get("rainflow_fd")
        assert 1 / 1.35 < ratio < 1.35, (where, ratio)
        assert get("narrow_band_fd") >= get("dirlik_fd")


def test_the_methods_agree_at_the_hang_off(state):
    # at the hang-off the response is linear: the FD's record against the VFIFE's (the
    # same realisation and counting: the response model alone) within 25 % (measured 0.97
    # in this sea state; the tension's standard deviation agrees to 1.2 %, the damage
    # weights it by its 3rd to 5th power)
    ratio = float(state.rates["rainflow_fd"][-1] / state.rates["rainflow_vfife"][-1])
    assert 0.75 < ratio < 1.25, ratio


def test_the_linear_model_overestimates_the_touchdown(state):
    # the known limit of the linear model, measured and kept as a regression of both
    # methods: the FD holds the touchdown where the static state has it and gathers the
    # bending there (x19.7 in this sea state); the time domain's touchdown travels
    # (35 m here). A change that brought them within a factor 3 would be a change of
    # physics in one of them, to be explained.
    ratio = zone_max(state, "rainflow_fd") / zone_max(state, "rainflow_vfife")
    assert ratio > 3.0, ratio
    info = state.comparison.vfife_result.info
    assert info["dynamic_max_touchdown_s"] - info["dynamic_min_touchdown_s"] > 10.0
