"""matplotlib figures for generated reports, drawn off-screen (the Agg backend)."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def new_figure(nrows: int = 1, ncols: int = 1, size=(8.0, 4.5)):
    fig, axes = plt.subplots(nrows, ncols, figsize=size, squeeze=False)
    return fig, axes


def save(fig, path: str | Path) -> None:
    """Write ``fig`` and close it. On a log axis spanning less than about a decade
    matplotlib labels the minor ticks too (2x10^-1, 3x10^-1, ...), and the labels run into
    each other: minor tick labels are dropped on every log axis (the major ones, at least
    two, stay; a span without two decades gets plain labels at the data's ends)."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter
    for ax in fig.axes:
        for axis, scale in ((ax.xaxis, ax.get_xscale()), (ax.yaxis, ax.get_yscale())):
            if scale != "log":
                continue
            axis.set_minor_formatter(NullFormatter())
            lo, hi = sorted(ax.get_xlim() if axis is ax.xaxis else ax.get_ylim())
            if lo > 0 and hi / lo < 100.0:     # under two decades: label 1-2-5 steps
                axis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
                axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
