"""The plot of a solve's design checks (``riser-verify solve`` of a scene with
``[design]``): ``utilisation.png``, the code's utilisation and the von Mises stress along
the line, static and, for a dynamic run, the envelope's largest over the window."""

from __future__ import annotations

from pathlib import Path

from .figures import new_figure, save

#: the figure written beside profile.csv
FILES = ("utilisation.png",)


def write_plot(profile, envelope: dict | None, out: Path, title: str) -> None:
    """utilisation.png of a static ``profile`` with design columns and, when given, a
    dynamic run's ``envelope`` (its ``utilisation_max`` and ``von_mises_max``)."""
    fig, ax = new_figure(2, 1, size=(9.0, 6.5))
    ax[0, 0].plot(profile.s, profile.utilisation, label="static")
    ax[1, 0].plot(profile.s, profile.von_mises / 1e6, label="static")
    if envelope is not None and "utilisation_max" in envelope:
        ax[0, 0].plot(envelope["s"], envelope["utilisation_max"], "--",
                      label="dynamic, largest over the window")
        ax[1, 0].plot(envelope["s"], envelope["von_mises_max"] / 1e6, "--",
                      label="dynamic, largest over the window")
    ax[0, 0].axhline(1.0, color="r", lw=0.8)
    ax[0, 0].set_ylabel(f"utilisation ({profile.design_code}) [-]")
    ax[1, 0].set_ylabel("von Mises stress [MPa]")
    for a in ax[:, 0]:
        a.grid(alpha=0.3)
        a.set_xlabel("arc length s from the bottom end [m]")
        a.legend(fontsize=8)
    fig.suptitle(f"{title}: design checks")
    save(fig, out / "utilisation.png")
