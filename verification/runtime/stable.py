"""Reports that stay put: the files ``reproduce`` commits are the same on any machine.

After a unit has written its files (into its staging folder, :mod:`.outdir`), and before
they replace the committed ones, :func:`stabilise` rewrites its CSV and JSON files:

- **timings out**: a measured wall time depends on the machine and on what else runs, so
  it has no place in a committed file. The CSV columns and JSON keys named in
  :data:`TIMING_NAMES` (seconds of wall time, Numba's compile or cache-load time) are
  taken out and returned, to be written to ``reports/timings.json``, which is not
  committed (``.gitignore``; :func:`verification.studies.reproduce.write_timings`);
- **round-off out**: every other float is written to :data:`SIGNIFICANT` (6) significant
  digits, and a value below :data:`NOISE` (1e-12) of the largest magnitude of its CSV
  column, or of the numbers of its JSON object, is written as 0: the noise of a zero (an
  anchor moment of 2e-12 N m in a record whose tension is 8e5 N), which differs entirely
  from one CPU to another. A double's round-off is 1e-16 of the largest term of a sum;
  1e-12 leaves 4 orders for the amplification of the solvers' arithmetic, and is 7 orders
  below the tightest tolerance. Why 6 significant digits (docs/reading-a-report.md,
  "Digits"): the tightest tolerance the reports judge against is 1e-5 of a value (the
  VFIFE's tension tolerance; the protocol's are 1e-3 and more), so 6 digits keep every
  verdict's number to a tenth of its tolerance and better; the round-off of another CPU
  (BLAS, fused multiply-adds) moves a solve's results by ~1e-8 relative (measured: 1e-8 in
  the issue's 451 rewritten files, 3e-9 between Numba's cold and warm code), 100 times
  below the 6th digit's half-unit, so a number moves only in the rare case that it lies
  within 1e-8 of a rounding boundary (~1 in 100 numbers of the 6th digit's last unit: then
  that one digit moves).

Text (Markdown) and figures are the studies' own: they print their numbers at the digits
their tolerances justify (:mod:`verification.report.markdown`).
"""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

#: significant digits of a float in a committed CSV or JSON file (module docstring)
SIGNIFICANT = 6
#: significant digits of the files of a dynamic response (time or frequency domain):
#: 4. A response amplitude is ~1e-3 of the static force it rides on, so the static
#: state's round-off (1e-8) reaches it as ~1e-5, and an explicit integration over 1e5
#: steps adds to it (another CPU moved a dynamic agreement by 4e-5); the dynamic
#: tolerances are 0.5-1 %: 4 digits (1e-4) are 50 times finer than them and 10 times
#: coarser than that round-off
DYNAMIC_FILES = frozenset({
    "response.csv", "transfer.csv", "transfer_along_s.csv", "stations.csv", "spectra.csv",
    "sea_along_s.csv", "timeseries.csv", "envelope.csv", "tension.csv", "dynamics.csv",
    "fatigue_along_s.csv", "sea_states.csv", "dynamics_ancf.csv"})
DYNAMIC_SIGNIFICANT = 4
#: the columns of those files that are places, times or inputs (6 digits: an arc length
#: of 1999.5 m is not a response); also every column whose name ends in ``_s``
COORDINATES = frozenset({"s", "t", "omega", "hs", "tp", "probability", "amplitude_m",
                         "element_length", "time_step", "time_step_factor"})
#: a value below this fraction of the largest magnitude of its CSV column (of the numbers
#: of its JSON object) is written as 0
NOISE = 1e-12
#: CSV columns and JSON keys holding a measured time [s] (wall, CPU or compile time, and
#: a dynamic run's wall or CPU seconds per simulated second): moved to the report's
#: ``timings.json``. Names only: ``_s`` alone also ends arc lengths (``tdp_s``)
#: and periods (``period_s``), which stay.
TIMING_NAMES = frozenset({
    "wall_time_s", "wall_s", "compile_s", "compile_time_s", "cache_load_s", "newton_s",
    "fd_s", "vfife_s", "bvp_s", "bvp_seconds", "fd_wall_s", "vfife_wall_s", "ancf_s",
    "ancf_wall_s",
    "static_wall_s", "total_wall_s", "dynamic_wall_s", "cpu_s", "wall_s_per_simulated_s",
    "cpu_s_per_simulated_s"})

#: absolute quanta of differences (file name -> {column: quantum}): a difference of two
#: methods is rounded to a multiple of the quantum, not to 6 digits of itself (a
#: difference of 1e-8 is round-off, and its 6 digits would move on any other CPU).
#: Static agreements (``rel_diff``): 1e-6, a thousandth of the protocol's tightest
#: tolerance (1e-3) and 100 times the round-off of the values (1e-8); ``abs_diff``: 1e-6 of
#: the row's larger value (:data:`ROW_SCALE`). Dynamic agreements: 5e-4 (0.05 %), a tenth
#: of the tightest dynamic tolerance (0.5 % of the hang-off tension amplitude) and 12
#: times the 4e-5 another CPU moved scr-steel's surge (-0.088 % -> -0.084 %: the
#: amplitude is 1e-3 of the static tension, so the static state's round-off of 1e-8
#: reaches it as 1e-5, and the explicit integration adds to it): such a shift still moves
#: a number that lies within it of a rounding boundary (~8 % of them); the phase [deg] at
#: 0.05 deg (tolerance 1 deg)
_DYNAMIC = {k: 5e-4 for k in (
    "hang_off_tension_amplitude", "tension_amplitude", "moment_amplitude",
    "displacement_amplitude", "min_tension", "higher_harmonics", "moment_out_amplitude")}
_DYNAMIC["hang_off_tension_phase_deg"] = 5e-2
_DYNAMIC.update({f"ancf_{k}": v for k, v in list(_DYNAMIC.items())})
QUANTA = {
    "agreement.csv": {"rel_diff": 1e-6, "analytic_rel_diff": 1e-6, "moordyn_rel_diff": 1e-6,
                      "ancf_rel_diff": 1e-6},
    "dynamic_agreement.csv": {"rel_diff": 5e-4},
    "dynamic_agreement_ancf.csv": {"rel_diff": 5e-4},
    "sea_agreement.csv": {"rel_diff": 5e-4},
    "cases.csv": _DYNAMIC, "convergence.csv": _DYNAMIC,
}
#: columns rounded to 1e-6 of the largest of the row's columns named beside them
ROW_SCALE = {"abs_diff": ("bvp", "vfife", "fd")}


def round_float(value: float, digits: int = SIGNIFICANT) -> float:
    """``value`` rounded to ``digits`` significant digits (non-finite values as given)."""
    if not math.isfinite(value) or value == 0.0:
        return value
    return float(f"{value:.{digits}g}")


def _number(text: str) -> float | None:
    """The float a CSV cell holds, None for text, blanks, integers and booleans (an
    integer is exact: step and node counts stay as written)."""
    t = text.strip()
    if not t or not any(c in t for c in ".eEn") or t.lower() in ("true", "false"):
        return None
    try:
        return float(t)
    except ValueError:
        return None


def _float(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def _cell(value: float, scale: float, digits: int = SIGNIFICANT) -> str:
    if not math.isfinite(value):
        return "" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if abs(value) < NOISE * scale:
        return "0"
    return f"{round_float(value, digits):.{digits}g}"


def stable_csv(text: str, name: str = "") -> tuple[str, dict]:
    """(the CSV ``text`` with its timing columns out and its floats rounded, {column:
    [values]} of the timing columns taken out); ``name``: the file's name, for the
    relative differences it rounds to an absolute quantum (:data:`QUANTA`)."""
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return text, {}
    header, body = rows[0], rows[1:]
    timed = [j for j, name in enumerate(header) if name in TIMING_NAMES]
    timings = {header[j]: [_number(r[j]) if j < len(r) else None for r in body]
               for j in timed}
    keep = [j for j in range(len(header)) if j not in timed]
    quanta = QUANTA.get(name, {})
    digits = {j: DYNAMIC_SIGNIFICANT if name in DYNAMIC_FILES and header[j] not in COORDINATES
              and not header[j].endswith("_s") else SIGNIFICANT for j in keep}
    scale = {}
    for j in keep:
        vals = [abs(v) for r in body if j < len(r)
                for v in [_number(r[j])] if v is not None and math.isfinite(v)]
        scale[j] = max(vals, default=0.0)
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow([header[j] for j in keep])
    for r in body:
        cells = []
        for j in keep:
            c = r[j] if j < len(r) else ""
            v = _number(c)
            q = quanta.get(header[j])
            if header[j] in ROW_SCALE and v is not None:
                row = [_float(r[k]) for k, h in enumerate(header)
                       if h in ROW_SCALE[header[j]] and k < len(r)]
                big = max((abs(x) for x in row if x is not None and math.isfinite(x)),
                          default=0.0)          # a power of ten: digits, not odd multiples
                q = 10.0 ** math.floor(math.log10(1e-6 * big)) if big > 0 else None
            if v is not None and q is not None and math.isfinite(v):
                v = round(v / q) * q              # a multiple of the quantum, then 6 digits
            cells.append(c if v is None else _cell(v, scale[j], digits[j]))
        w.writerow(cells)
    return out.getvalue(), timings


def _stable_json(value, timings: dict, path: str):
    if isinstance(value, dict):
        scale = max((abs(v) for k, v in value.items() if k not in TIMING_NAMES
                     and isinstance(v, float) and math.isfinite(v)), default=0.0)
        out = {}
        for k, v in value.items():
            here = f"{path}.{k}" if path else str(k)
            if k in TIMING_NAMES and (v is None or isinstance(v, (int, float))):
                timings[here] = v
            elif isinstance(v, float) and math.isfinite(v) and abs(v) < NOISE * scale:
                out[k] = 0.0
            else:
                out[k] = _stable_json(v, timings, here)
        return out
    if isinstance(value, list):
        return [_stable_json(v, timings, f"{path}[{i}]") for i, v in enumerate(value)]
    if isinstance(value, float):
        return round_float(value)
    return value


def stable_json(text: str) -> tuple[str, dict]:
    """(the JSON ``text`` with its timing keys out and its floats rounded, {key path:
    seconds} of the timings taken out)."""
    timings: dict = {}
    data = _stable_json(json.loads(text), timings, "")
    return json.dumps(data, indent=2) + "\n", timings


def stabilise(folder: Path) -> dict:
    """Rewrite every CSV and JSON file under ``folder`` (:func:`stable_csv`,
    :func:`stable_json`); returns {file relative to ``folder``:
    its timings} for the files that held any."""
    found = {}
    for p in sorted(folder.rglob("*")):
        if not p.is_file() or p.suffix not in (".csv", ".json"):
            continue
        text, timings = (stable_csv(p.read_text(), p.name) if p.suffix == ".csv"
                         else stable_json(p.read_text()))
        p.write_text(text)
        if timings:
            found[p.relative_to(folder).as_posix()] = timings
    return found
