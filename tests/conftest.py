"""Fixtures shared by the test modules.

Solutions here are computed once per session and shared: the tests only read them
(summary(), profile arrays, info); none modifies one in place. A test that needs a variant
builds its own scene with ``Scene.replace`` (scenes are frozen dataclasses).
"""

from __future__ import annotations

import pytest

import bvp
from verification import cli
from verification.catalog import resolve


@pytest.fixture(scope="session")
def wang_scene():
    """The built-in Wang, Duan & Tian (2014) baseline: the touchdown-tension form, solved
    by the BVP in the paper's model (inextensible line, rigid seabed)."""
    return resolve("wang2014-baseline")


@pytest.fixture(scope="session")
def wang_bvp(wang_scene):
    """The BVP solution of ``wang_scene`` at the default settings (~0.7 s), used by
    test_bvp.py (Table 2 and the checks on the baseline) and test_model_limits.py (the
    reference of the EA -> inf and k -> inf limits); read-only."""
    res = bvp.solve(wang_scene)
    assert res.converged, res.message
    return res


@pytest.fixture
def run_cli(capsys):
    """``run_cli(argv)`` runs ``riser-verify ARGV`` in this process and returns (exit code,
    stdout, stderr)."""
    def run(argv):
        code = cli.main(argv)
        cap = capsys.readouterr()
        return code, cap.out, cap.err
    return run
