"""Reports a newcomer reads right (issue 30): the index's digits, the reasons beside the
VFIFE - BVP differences, the cases a method gave no values for, plots whose tick labels
do not run into each other. Checked on the committed reports and on small figures."""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from verification.report.figures import new_figure, save  # noqa: E402
from verification.studies.compare import index_row as compare_row  # noqa: E402
from verification.studies.wang2014.table2 import index_row as wang_row  # noqa: E402

REPORTS = Path(__file__).resolve().parent.parent / "reports"


def test_the_index_keeps_two_significant_digits_of_a_small_difference():
    # the index printed "+0.00 % of depth" for 8e-6 of the depth (read as none at all):
    # every percentage of a compare row now has a nonzero digit where the value has one,
    # and a difference below the CSV's step (1e-6, issue 44's stable digits) says so
    _, text, verdict = compare_row(REPORTS / "compare" / "wang2014-baseline")
    for q in ("configuration", "tension", "moment"):
        m = re.search(rf"{q} ([+-][0-9.e+-]+) %", text)
        if m is None:
            assert re.search(rf"{q} below 0.0001 %", text), text
        else:
            assert float(m.group(1)) != 0.0, text
    assert " +0 %" not in text and " -0 %" not in text
    assert "nearest its tolerance" in text and verdict == "pass"


def test_the_wang_index_gives_the_reason_beside_the_difference_it_does_not_judge():
    # it said "VFIFE vs BVP worst 6.9 % ... pass" without the reason its report gives
    _, text, _ = wang_row(REPORTS / "wang2014")
    assert "within their tolerances" in text
    assert "F_max" in text and "not judged" in text and "buoyancy joint" in text


def test_the_yu_report_says_which_method_gave_no_values_and_why():
    # a mid-run line "yu2021: bvp failed on buoyancy/A4 x0.9: ... refused" looked like an
    # error in a run that ends with exit 0; the report now lists the case with its reason
    text = (REPORTS / "yu2021" / "report.md").read_text()
    assert "no BVP values" in text and "buoyancy/A4 x0.9" in text


def _overlaps(labels) -> bool:
    boxes = [t.get_window_extent() for t in labels if t.get_text() and t.get_visible()]
    return any(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1:])


def test_log_axes_of_a_short_span_have_tick_labels_that_do_not_overlap(tmp_path):
    # a log axis spanning less than a decade: matplotlib labels the minor ticks as well
    # (2x10^-1, 3x10^-1, ...), which ran into each other on the cost plots. After save the
    # minor labels are empty and the major labels (1-2-5 steps) are apart
    fig, axes = new_figure(1, 1, (3, 2))
    ax = axes[0, 0]
    ax.loglog([0.11, 0.62], [2.1e-3, 7e-3], "o-")
    save(fig, tmp_path / "f.png")
    fig.canvas.draw()
    for axis in (ax.xaxis, ax.yaxis):
        assert not any(t.get_text() for t in axis.get_minorticklabels())
        majors = [t for t in axis.get_majorticklabels() if t.get_text()]
        assert len(majors) >= 1
        assert not _overlaps(majors)
