"""What accuracy costs in time: convergence and cost study of both methods on one scene.

``riser-verify cost SCENE [--out DIR]`` (default ``reports/cost/SCENE/``) writes
``runs.csv``, ``values.csv``, ``dynamics.csv``, ``dynamics_ancf.csv``, ``report.md`` and
five plots. Modules:
``settings`` (the runs swept), ``runner`` (solving and timing them, :func:`study`),
``errors`` (quantity errors against a reference), ``fits`` (Richardson limit, order fits),
``touchdown`` (the lengths of the asymptotic range, the lift-off), ``analysis`` (what the
runs say), ``assessment`` (the wording of the order assessment), ``records`` (the run and
study records and their tables), ``report`` (Markdown, plots, CSV), and the dynamic
sweep: ``dynamics`` (its runs and records), ``dynamics_analysis`` (reference, errors,
orders, step factor, recommendation) and ``dynamics_report`` (its report section, plot
and ``dynamics.csv``); the ANCF's beside it: ``dynamics_ancf`` (its runs and records),
``dynamics_ancf_analysis`` (each method's reference, the common one, the picks at 0.5 %
and their CPU-time ratio) and ``dynamics_ancf_report`` (the section "The ANCF beside the
VFIFE", its plot and ``dynamics_ancf.csv``).

Protocol
--------
- One model for both methods. A fixed-ends scene is solved as it is; a Wang-form scene
  (touchdown tension, or hang-off angle) is first solved by the BVP in its own form
  (inextensible on a rigid seabed, the paper's model) only to place the hang-off, then
  converted to fixed ends with 300 m of line on an elastic seabed ahead of the touchdown
  (:func:`verification.pipeline.vfife_equivalent`). Both methods then solve that
  same continuum model: extensible line on the scene's elastic (Winkler) seabed.
- Settings swept. VFIFE: element length (20 ... 0.5 m), time-step safety factor, static
  tolerance, relaxation scheme (coarse-mesh sequencing, rotational-inertia scale), and the
  cost of one second of dynamics per element length. BVP: ``solve_bvp`` tolerance
  (1e-2 ... 1e-8), initial mesh size, node cap. Every setting not swept keeps its default.
- Dynamics (:mod:`~verification.studies.cost.dynamics`): 40 s of a 1.5 m heave at 10 s from the
  static state of each element length, the same window for every run; cost and accuracy
  (hang-off tension amplitude, peak moment) against element length and time-step factor,
  against the finest length at the smallest factor (or a clean Richardson limit).
- The ANCF beside the VFIFE (:mod:`~verification.studies.cost.dynamics_ancf`, issue 46):
  the same heave, window and quantities by the ANCF against its element length and steps
  per period; both methods' errors against one common reference per quantity (the finer
  of their own references), each method's cheapest run within 0.5 % in the peak moment
  (and in both quantities) by CPU time per simulated second, and the ratio of the two.
- Fast and full sweep. ``riser-verify cost SCENE`` and ``reproduce all`` run the fast
  sweep (:data:`~verification.studies.cost.settings.FAST_SWEEP`: BVP tolerances, VFIFE element
  lengths, coarse mesh 5 m, dynamics; ~1/6 of the time); ``--full`` adds the rest
  (:data:`~verification.studies.cost.settings.FULL_ADDS`), which the order fit, the VFIFE limit
  and the relaxation errors need: without it the report says so and shows none of them.
- Timing: one global warm-up (Numba compilation, or its on-disk cache load, reported as
  ``compile_time_s``), then the median of ``repeats`` runs (the solvers' own
  ``wall_time_s``). A run that does not converge, or takes longer than
  :data:`~verification.studies.cost.runner.REPEAT_BELOW_S`, is timed once.
- Errors (runs.csv ``err_*``): against the reference, the BVP of the same scene at the
  finest tolerance, as fractions: tensions and moment relative to the reference value;
  touchdown position, crest and sag heights and the curve distance relative to the water
  depth (else the hang-off height). Same model and same arc length, so a VFIFE error is
  its discretisation and relaxation error only.
- Self-convergence (``self_*``): VFIFE runs against VFIFE's own limit, Richardson-
  extrapolated from the three finest element lengths of the order sweep (the curve
  distance against the finest curve); BVP runs against the reference. The VFIFE limit
  against the BVP reference is a consistency check of the two methods.
- Observed VFIFE order: slope of log(error vs the reference) against log(element length)
  over the order sweep (``element_length_tight``: static and creep tolerances tight enough
  that the relaxation error is far below the discretisation error). A length enters the
  fit if it is not longer than the asymptotic length (the shorter of the bending boundary
  layer sqrt(EI/T) at the touchdown and the seabed's foundation length (4 EI/k)^(1/4)),
  its error is at most 1e-2, and at least 10x both the relaxation error of the sweep
  (measured at the middle length against a run with both tolerances 10x tighter,
  ``element_length_tight_check``) and the reference's own uncertainty. The report gives
  the local orders of successive lengths too, and says per quantity why an order differs
  from 2.
"""

from __future__ import annotations

from ..study import Study
from .analysis import recommendations
from .records import CostStudy, Run
from .report import index_row, write
from .runner import run_unit, study
from .settings import COST_SCENES, Setting, default_settings

__all__ = ["COST_SCENES", "STUDY", "CostStudy", "Run", "Setting", "default_settings",
           "recommendations", "study", "write"]

#: the study of the registry (:mod:`verification.studies`): one unit per scene; wall
#: times [s] of ``reproduce all`` on 2 processes of this 2-core machine, fast sweep and
#: (``--full``) full sweep: measured before the dynamic sweep, plus its time measured in
#: single-scene runs (fast 17-27 s, full 45-125 s; a shared machine), plus the ANCF's
#: sweep beside it measured in single-scene runs of the fast sweep (``riser-verify cost
#: SCENE``: Yu A2 sheared 30 s, Yu A3 33 s, Wang 60 s; whole studies 100, 94, 147 s on a
#: shared machine); its full sweep estimated at twice that (not measured)
STUDY = Study("cost", COST_SCENES, run_unit, index_row,
              seconds={"yu2021-a2-sheared": 93, "yu2021-a3": 94, "wang2014-baseline": 113},
              full_seconds={"yu2021-a2-sheared": 423, "wang2014-baseline": 511,
                            "yu2021-a3": 370},
              stable=False)       # its numbers are timings: the whole study is one
