"""``reports/README.md``: one line per report directory, read back from its CSV files by
the study that wrote it (:data:`verification.studies.STUDIES`). A study whose numbers are
this machine's timings (``stable=False``: the cost study) is not committed: the index names
the command that writes it instead of its folders, so that the committed index is the same
whether or not this checkout has run it."""

from __future__ import annotations

import os
from pathlib import Path

from verification.report.markdown import GENERATED_NOTE, md_table

from . import STUDIES, study


def write_index(reports: Path = Path("reports")) -> Path:
    rows = []
    for d in sorted(p for p in reports.rglob("*") if p.is_dir()):
        rel = d.relative_to(reports)
        if rel.parts[0] not in STUDIES or not study(rel.parts[0]).stable:
            continue
        row = study(rel.parts[0]).index_row(d)
        if row is not None:
            rows.append((f"[{rel}]({rel}/report.md)", *row))
    timed = [name for name in STUDIES if not study(name).stable]
    text = "\n".join([
        "# Verification reports", "", GENERATED_NOTE, "",
        "Regenerate everything with `riser-verify reproduce all`. Each line: the study, its "
        "cases, the worst agreement and the verdict against the stated tolerances.", "",
        md_table(["study", "cases", "worst agreement", "verdict"], rows), "",
        *[f"Not committed (its numbers are this machine's timings): `reports/{name}/`, "
          f"written by `riser-verify reproduce {name}` (and by `reproduce all`)." for name in timed],
        "",
    ])
    path = reports / "README.md"
    tmp = reports / f".README.md.partial-{os.getpid()}"
    tmp.write_text(text)
    os.replace(tmp, path)                 # an interrupted write leaves the old index
    return path
