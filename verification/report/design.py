"""The plot of a solve's design checks (``riser-verify solve`` of a scene with
``[design]`` or a bending limit): ``utilisation.png``, the code's utilisation and the
bend utilisation (:mod:`riser.design.bending`) against 1, and the von Mises stress along
the line, static and, for a dynamic run, the envelope's largest over the window."""

from __future__ import annotations

from pathlib import Path

from .figures import new_figure, save

#: the figure written beside profile.csv
FILES = ("utilisation.png",)
WINDOW = "dynamic, largest over the window"


def write_plot(profile, envelope: dict | None, out: Path, title: str) -> None:
    """utilisation.png of a static ``profile`` with design columns (``utilisation``,
    ``von_mises``) or a ``bend_utilisation`` column, or both, and, when given, a dynamic
    run's ``envelope`` (its ``utilisation_max``, ``von_mises_max`` and
    ``bend_utilisation_max``). Without the code check, one panel: the bend utilisation."""
    env = envelope if envelope is not None else {}
    code = profile.utilisation is not None
    bend = profile.bend_utilisation is not None
    fig, ax = new_figure(2 if code else 1, 1, size=(9.0, 6.5 if code else 4.0))
    top = ax[0, 0]
    if code:
        top.plot(profile.s, profile.utilisation, label="static")
        ax[1, 0].plot(profile.s, profile.von_mises / 1e6, label="static")
        if "utilisation_max" in env:
            top.plot(env["s"], env["utilisation_max"], "--", label=WINDOW)
            ax[1, 0].plot(env["s"], env["von_mises_max"] / 1e6, "--", label=WINDOW)
        ax[1, 0].set_ylabel("von Mises stress [MPa]")
    if bend:
        top.plot(profile.s, profile.bend_utilisation, ":" if code else "-",
                 label="bend, static" if code else "static")
        if "bend_utilisation_max" in env:
            top.plot(env["s"], env["bend_utilisation_max"], "-." if code else "--",
                     label=f"bend, {WINDOW}" if code else WINDOW)
    top.axhline(1.0, color="r", lw=0.8)
    top.set_ylabel(" and ".join(
        ([f"utilisation ({profile.design_code})"] if code else []) +
        (["bend utilisation"] if bend else [])) + " [-]")
    for a in ax[:, 0]:
        a.grid(alpha=0.3)
        a.set_xlabel("arc length s from the bottom end [m]")
        a.legend(fontsize=8)
    fig.suptitle(f"{title}: design checks" if code else f"{title}: bending limits")
    save(fig, out / "utilisation.png")
