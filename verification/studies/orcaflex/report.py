"""The files of the OrcaFlex study: ``published.csv``, ``corpus.csv``, ``round_trip.csv``,
``profiles.png`` and ``report.md``."""

from __future__ import annotations

import math
from collections import Counter
from pathlib import Path

import pandas as pd

from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, fmt, md_table

from .published import QUANTITIES

CATEGORIES = ("sections", "geometry", "environment", "vessel", "attachments", "joints",
              "seabed")


def published_frame(rows: list[dict]) -> pd.DataFrame:
    return pd.DataFrame(rows)[["model", "quantity", "unit", "orcaflex", "bvp", "vfife",
                               "bvp_rel_diff", "vfife_rel_diff", "tolerance", "pass"]]


def corpus_frame(outcomes) -> pd.DataFrame:
    return pd.DataFrame([{"fixture": o.fixture, "line": o.line, "mode": o.mode,
                          "imported": o.imported, "item": o.item, "message": o.message}
                         for o in outcomes])


#: a round trip's difference below this is float round-off (the unit factors' and the
#: frame's last bits), written as "<1e-12": its digits may differ on another machine
#: (libm's last bit), and the committed report must not
ROUND_OFF = 1e-12


def _bucket(v) -> str:
    """A difference as the report keeps it: '' (not compared), '0', '<1e-12', or 3 digits."""
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return ""
    if v == 0.0:
        return "0"
    return f"<{ROUND_OFF:g}" if v < ROUND_OFF else f"{v:.3g}"


def round_trip_frame(trips) -> pd.DataFrame:
    rows = []
    for t in trips:
        row = {"scene": t.scene, "exported": t.refused is None,
               "refused": t.refused or ""}
        for c in CATEGORIES:
            row[c] = _bucket(t.worst.get(c) if t.refused is None else None)
        row["rotary_inertia"] = _bucket(t.worst.get("rotary_inertia"))
        row["own_segments"] = " ".join(str(k) for k in t.own_segments)
        rows.append(row)
    return pd.DataFrame(rows)


def write(pub: pd.DataFrame, profiles: dict, corpus: pd.DataFrame, trips: pd.DataFrame,
          out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    pub.to_csv(out / "published.csv", index=False, float_format="%.10g")
    corpus.to_csv(out / "corpus.csv", index=False)
    trips.to_csv(out / "round_trip.csv", index=False)
    profile_figure(profiles, out / "profiles.png")
    (out / "report.md").write_text(markdown(pub, corpus, trips))


def profile_figure(profiles: dict, path: Path) -> None:
    """Each model's static shape by both methods (x, y of the imported scene)."""
    fig, axes = new_figure(1, len(profiles), size=(5.0 * len(profiles), 4.5))
    styles = {"bvp": ("C0", "-", "BVP"), "vfife": ("C1", "--", "VFIFE")}
    for ax, (name, per_method) in zip(axes[0], profiles.items()):
        for m, p in per_method.items():
            color, ls, label = styles[m]
            ax.plot(p.x, p.y, color=color, ls=ls, lw=1.4, label=label)
        ax.axhline(0.0, color="0.5", lw=0.8)
        ax.set_xlabel("x [m] (from the anchor)")
        ax.set_ylabel("y [m] above the seabed")
        ax.set_title(name)
        ax.set_aspect("equal", adjustable="datalim")
        ax.legend()
    save(fig, path)


def markdown(pub: pd.DataFrame, corpus: pd.DataFrame, trips: pd.DataFrame) -> str:
    n_models = pub["model"].nunique()
    judged = pub[pub["pass"].astype(str) != "reported"]
    ok = bool((judged["pass"].astype(str) == "True").all())
    worst = {m: judged.loc[judged[f"{m}_rel_diff"].abs().idxmax()] for m in ("bvp", "vfife")}
    rep = pub[pub["pass"].astype(str) == "reported"]
    lines = ["# OrcaFlex models in and out", "", GENERATED_NOTE, "",
             "`riser-verify import-orcaflex` turns one line of an OrcaFlex text data file into "
             "a scene, `riser-verify export-orcaflex` a scene into a text data file OrcaFlex "
             "loads ([OrcaFlex](../../docs/orcaflex.md) says what is carried, how, and what "
             "is refused). This report: public models whose OrcaFlex static results are "
             "published, imported and solved by both methods; the public corpus imported; "
             "the built-in scenes' round trip scene -> model -> scene.", "",
             "## Public models against OrcaFlex's own statics", "",
             f"{n_models} of Orcina's example models, as OrcaFlex 11.6b text data files in a "
             "public repository whose OrcFxAPI script ran OrcaFlex's statics and published "
             "the results (sources in [References](../../docs/references.md)); their lines "
             "imported with `--statics` (their Dean stream wave is not the suite's Airy "
             "wave; their Reynolds-number drag table is constant, Cd = 1.2, up to the "
             "current's flow) and solved by the BVP and the VFIFE (at the import's element "
             "length, the models' shortest segment) on the scene as imported, without "
             "seabed friction: OrcaFlex's statics lay the line 'as laid' with friction 0.5 "
             "and an elastic slip, which the suite's statics do not model. "
             f"**{'Every' if ok else 'Not every'} judged quantity within its tolerance** "
             f"({judged['model'].nunique()} models); their largest differences: BVP "
             f"{worst['bvp']['bvp_rel_diff']:+.2%} "
             f"({worst['bvp']['model']} {worst['bvp']['quantity']}), VFIFE "
             f"{worst['vfife']['vfife_rel_diff']:+.2%} ({worst['vfife']['model']} "
             f"{worst['vfife']['quantity']}).", "",
             md_table(["model", "quantity", "unit", "OrcaFlex", "BVP", "VFIFE", "BVP rel diff",
                       "VFIFE rel diff", "tolerance", "pass"],
                      [(r["model"], r["quantity"], r["unit"], fmt(r["orcaflex"], 7),
                        fmt(r["bvp"], 7), fmt(r["vfife"], 7), f"{r['bvp_rel_diff']:+.3%}",
                        f"{r['vfife_rel_diff']:+.3%}",
                        "" if r["pass"] == "reported" else f"{r['tolerance']:.1%}",
                        r["pass"] if r["pass"] == "reported" else r["pass"] is True)
                       for _, r in pub.iterrows()]), "",
             "The quantities: End A (the hang-off) and End B (the anchor) effective tension, "
             "the least effective tension and the largest bending moment along the line "
             f"(OrcaFlex's; the suite's summary keys {', '.join(k for k, _ in QUANTITIES.values())}). "
             "The top tension and the least tension agree to 0.01-0.1 %: weight, buoyancy, "
             "contents, the current's drag and the seabed's stiffness are carried exactly. "
             "The anchor's tension is where OrcaFlex's friction acts: along the grounded "
             "length OrcaFlex's tension rises from its least value to the anchor (by 0.8 % "
             "for the catenary), the suite's frictionless tension stays level, and its anchor "
             "tension is the higher by 0.3 % and 1.3 %. The peak moment (at the touchdown; "
             "the lazy wave's at the sag bend) is 0.2-0.5 % above OrcaFlex's, which its "
             "own mesh study puts still rising with refinement (9.354, 9.464, 9.502 kN m at "
             "2, 1 and the model's 0.5 m segments for the catenary).", "",
             *([f"Reported, not judged: {', '.join(sorted(set(rep['model'])))}, whose "
                "current (0.5 m/s) crosses the line's plane (the line leaves it by 5.5 m). "
                "Its top and anchor tensions agree as the others' do; its least tension "
                "and peak moment differ by about 1.5 %, in the direction of a larger effect "
                "of the current in OrcaFlex than in the suite (the suite's own: the current "
                "raises the least tension by 0.9 % and lowers the peak moment by 2.2 %; "
                "OrcaFlex's values lie 2.7 % and 3.5 % from the suite's without current). "
                "Both methods agree with each other to 0.02 %, so the difference is in the "
                "model, not the solution; its cause (the cross-flow drag, the Reynolds "
                "number OrcaFlex takes in an oblique flow, its statics' current) is not "
                "found: the import's 3D current is carried but not verified against "
                "OrcaFlex.", ""] if len(rep) else []),
             "![the models' static shapes](profiles.png)", "",
             "`published.csv` holds every digit.", ""]
    # the corpus
    files = corpus["fixture"].nunique()
    per_line = corpus[corpus["mode"] != "file"]
    n_lines = per_line.groupby("fixture")["line"].nunique().sum()
    full_ok = per_line[(per_line["mode"] == "full") & per_line["imported"]]
    stat_ok = per_line[(per_line["mode"] == "statics") & per_line["imported"]]
    refused = corpus[~corpus["imported"]]
    kinds = Counter(_item_kind(i) for i in refused["item"])
    lines += ["## The public corpus", "",
              f"{files} OrcaFlex text data files written by hand from public models "
              "(`tests/data/orcaflex/`, their sources in its `SOURCES.md`; Orcina's A01 and "
              "A05 example risers, a metocean buoy's mooring, a floating wind turbine's "
              f"moorings and export cable, variation and restart files): {n_lines} lines. "
              f"Imported as they are: {len(full_ok)} of {n_lines}; with `--statics`: "
              f"{len(stat_ok)} of {n_lines}; every other import refused with one line "
              "naming the OrcaFlex item. The refusals by kind of item: "
              + ", ".join(f"{k} {v}" for k, v in sorted(kinds.items(), key=lambda kv: -kv[1]))
              + ".", "",
              md_table(["file", "line", "import", "outcome"],
                       [(r["fixture"], r["line"], r["mode"],
                         ("imported: " + r["message"]) if r["imported"] else
                         f"refused: `{r['item']}`: {_short(r['message'])}")
                        for _, r in corpus.iterrows()]), ""]
    # the round trip
    ex = trips[trips["exported"]]
    own = ex[ex["own_segments"].astype(str).str.len() > 0]
    worst_cat = {c: _worst(ex[c]) for c in CATEGORIES}
    lines += ["## The round trip of the built-in scenes", "",
              f"Every built-in scene exported to OrcaFlex and imported back: {len(ex)} of "
              f"{len(trips)} exported, the rest refused with the scene key the OrcaFlex "
              "subset cannot express. What comes back is the same scene, translated (the "
              "anchor at x = 0) and, for a 3D scene, turned into the plane of its ends; the "
              "worst difference over the exported scenes, per category (relative; absolute "
              f"in m and deg for positions and angles; below {ROUND_OFF:g}, float round-off, "
              f"written <{ROUND_OFF:g}): "
              + ", ".join(f"{c} {v}" for c, v in worst_cat.items()) + ". "
              f"{len(own)} scenes have segments written with a line type of their own (a "
              "buoyancy section, a weight override): the displacement diameter that gives "
              "their weight, the drag diameters and Ca that give their drag and added mass; "
              "their weight, drag and added mass come back exactly, the wall's polar "
              "inertia (which the scene derives from the outer diameter) does not (up to "
              f"{_worst(ex['rotary_inertia'])}).", "",
              md_table(["scene", "outcome"] + list(CATEGORIES) + ["rotary inertia"],
                       [(r["scene"], "exported" if r["exported"] else
                         f"refused: {_short(r['refused'])}",
                         *[r[c] for c in CATEGORIES], r["rotary_inertia"])
                        for _, r in trips.iterrows()]), ""]
    return "\n".join(lines)


def _worst(col: pd.Series) -> str:
    """The largest of a column of buckets ('0' < '<1e-12' < a number)."""
    vals = [v for v in col.fillna("").astype(str) if v]
    nums = [float(v) for v in vals if not v.startswith("<") and float(v) > 0.0]
    if nums:
        return f"{max(nums):.3g}"
    return f"<{ROUND_OFF:g}" if any(v.startswith("<") for v in vals) else "0"


def _short(text: str, n: int = 140) -> str:
    text = str(text).replace("|", "/").replace("\n", " ")
    return text if len(text) <= n else text[:n - 3] + "..."


def _item_kind(item: str) -> str:
    """A refusal's item without its object's name: ``LineTypes[...].Cd`` -> LineTypes.Cd."""
    import re
    return re.sub(r"\[[^\]]*\]", "", str(item)) or "(file)"
