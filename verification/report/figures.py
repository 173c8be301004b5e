"""matplotlib figures for generated reports, drawn off-screen (the Agg backend)."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def new_figure(nrows: int = 1, ncols: int = 1, size=(8.0, 4.5)):
    fig, axes = plt.subplots(nrows, ncols, figsize=size, squeeze=False)
    return fig, axes


def add_panel_below(fig, height: float):
    """A new axes under the figure's column of panels (their order kept), the figure
    taller by ``height`` [in]; the other panels keep their heights."""
    axes = list(fig.axes)
    w, h = fig.get_size_inches()
    n = len(axes)
    grid = fig.add_gridspec(n + 1, 1, height_ratios=[h / n] * n + [height])
    for i, a in enumerate(axes):
        a.set_subplotspec(grid[i])
    fig.set_size_inches(w, h + height)
    return fig.add_subplot(grid[n])


def plan_view(ax, lines) -> None:
    """The plan view of a 3D line on ``ax``: ``lines`` of (x, z, plot keywords), x [m]
    across, z [m] (out of the plane x-y) down the page, as seen from above (y up: x, -z, y
    are right-handed on the page)."""
    for x, z, style in lines:
        ax.plot(x, z, **style)
    ax.invert_yaxis()
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m] (seen from above)")
    ax.set_title("plan view (x-z)", fontsize=10)
    ax.grid(alpha=0.3)


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
