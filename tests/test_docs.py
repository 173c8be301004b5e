"""The documentation a user finds their way in: README.md, CHANGELOG.md and docs/*.md.

- every relative link resolves: the file exists inside the repository, and a
  ``file.md#anchor`` (or ``#anchor``) names a heading of that file by its GitHub slug;
- README.md stays a front door (under 250 lines);
- no file of the repository (code, docs, scenes; not the generated reports/) cites a path
  outside it: the papers are cited through docs/references.md;
- the command-line page has a section for every command and names every option;
- the scene and sweep examples in the pages load as the code reads them;
- docs/scene-files.md keeps the two marker lines of its generated key tables.

Each checker is also run on a file that breaks it, so that the test can fail.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGES = sorted([ROOT / "README.md", ROOT / "CHANGELOG.md", *(ROOT / "docs").glob("*.md")])
README_MAX_LINES = 250

#: citations of files outside the repository (written in pieces, so that this file does
#: not cite them itself)
OUTSIDE = (re.compile(re.escape("REFERENCE" + ".md")), re.compile(re.escape("../" + "shared")),
           re.compile(re.escape("shared/" + "papers")), re.compile(r"\bpapers/\d{3}_"))
#: folders never scanned for citations: generated reports, version control, caches,
#: build products and run outputs
SKIP_DIRS = {".git", "reports", "__pycache__", ".pytest_cache", ".benchmarks", "build",
             "dist", "out", ".venv", "venv", "node_modules"}
MARKERS = ("<!-- BEGIN generated: scene keys -->", "<!-- END generated: scene keys -->")

_FENCE = re.compile(r"^\s*(```|~~~)")
_LINK = re.compile(r"!?\[((?:[^\[\]]|\[[^\]]*\])*)\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
_CODE_SPAN = re.compile(r"(`+)(?:(?!\1).)+?\1")
_HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
_HTML_ANCHOR = re.compile(r"<a\s+(?:name|id)=\"([^\"]+)\"")


def prose_lines(text: str):
    """(line number, line) of the Markdown outside fenced and indented code blocks."""
    fenced = False
    for no, line in enumerate(text.splitlines(), 1):
        if _FENCE.match(line):
            fenced = not fenced
            continue
        if fenced or line.startswith(("    ", "\t")):
            continue
        yield no, line


def github_slug(heading: str) -> str:
    """The anchor GitHub gives a heading: the rendered text (links and code marks
    dropped), lower case, punctuation removed but hyphens and underscores, spaces as
    hyphens."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)   # a link: its text
    text = re.sub(r"<[^>]+>", "", text).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path: Path) -> set[str]:
    """The anchors of a Markdown file: its headings' slugs (a repeated slug gets -1, -2,
    ... as on GitHub) and explicit ``<a id="...">``."""
    out: set[str] = set()
    seen: dict[str, int] = {}
    for _, line in prose_lines(path.read_text(encoding="utf-8")):
        out.update(_HTML_ANCHOR.findall(line))
        m = _HEADING.match(line)
        if not m:
            continue
        slug = github_slug(m.group(2))
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        out.add(slug if n == 0 else f"{slug}-{n}")
    return out


def links(path: Path):
    """(line number, target) of every Markdown link and image in the prose of ``path``."""
    for no, line in prose_lines(path.read_text(encoding="utf-8")):
        for m in _LINK.finditer(_CODE_SPAN.sub("", line)):
            yield no, m.group(2)


def broken_links(path: Path, root: Path = ROOT) -> list[str]:
    """One line per relative link of ``path`` that does not resolve inside ``root``."""
    problems = []
    for no, target in links(path):
        if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):      # http:, https:, mailto:
            continue
        file_part, _, anchor = target.partition("#")
        dest = (path.parent / file_part).resolve() if file_part else path.resolve()
        where = f"{path.relative_to(root)}:{no}: {target}"
        if not dest.is_relative_to(root.resolve()):
            problems.append(f"{where}: outside the repository")
        elif not dest.exists():
            problems.append(f"{where}: no such file")
        elif anchor and dest.suffix == ".md" and anchor not in anchors(dest):
            problems.append(f"{where}: no heading with the anchor #{anchor}")
    return problems


def outside_citations(root: Path = ROOT) -> list[str]:
    """One line per citation of a path outside the repository in a text file under
    ``root`` (the folders of SKIP_DIRS and *.egg-info skipped)."""
    found = []
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root)
        if any(p in SKIP_DIRS or p.endswith(".egg-info") for p in rel.parts[:-1]):
            continue
        if not path.is_file() or path.stat().st_size > 2_000_000:
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except (UnicodeDecodeError, OSError):
            continue                                  # binary: an image, an archive
        for no, line in enumerate(text.splitlines(), 1):
            if any(p.search(line) for p in OUTSIDE):
                found.append(f"{rel}:{no}: {line.strip()[:120]}")
    return found


# ----------------------------------------------------------------------------- links
def test_the_pages_exist():
    names = {p.name for p in PAGES}
    assert {"README.md", "CHANGELOG.md", "command-line.md", "scene-files.md", "theory.md",
            "results.md", "comparison.md", "moordyn.md", "sweeps.md", "reading-a-report.md",
            "references.md"} <= names


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_relative_link_resolves(page):
    assert broken_links(page) == []


def test_every_docs_page_is_linked_from_the_readme():
    linked = {(ROOT / t.partition("#")[0]).resolve() for _, t in links(ROOT / "README.md")}
    missing = [p.name for p in (ROOT / "docs").glob("*.md") if p.resolve() not in linked]
    assert missing == []


def test_the_link_checker_can_fail(tmp_path):
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "other.md").write_text("# Other page\n\n## The `agreement.csv` file\n")
    page = tmp_path / "page.md"
    page.write_text(
        "# A page\n\n## Section one\n\n"
        "[good](docs/other.md) [good anchor](docs/other.md#the-agreementcsv-file) "
        "[own](#section-one) [web](https://example.org/x.md#nowhere)\n"
        "[missing file](docs/none.md)\n"
        "[missing anchor](docs/other.md#no-such-heading)\n"
        "[own missing](#section-two)\n"
        "[outside](../elsewhere.md)\n"
        "`[in code](docs/none.md)`\n\n"
        "```\n[in a fence](docs/none.md)\n# not a heading\n```\n")
    problems = broken_links(page, root=tmp_path)
    assert [p.split(": ", 1)[0] for p in problems] == [
        "page.md:6", "page.md:7", "page.md:8", "page.md:9"], problems
    assert "no such file" in problems[0] and "#no-such-heading" in problems[1]
    assert "#section-two" in problems[2] and "outside the repository" in problems[3]
    assert "not-a-heading" not in anchors(page)


def test_github_slugs():
    assert github_slug("Wang et al. 2014") == "wang-et-al-2014"
    assert github_slug("The `agreement.csv` file") == "the-agreementcsv-file"
    assert github_slug("Theory: conventions and units") == "theory-conventions-and-units"
    assert github_slug("One model, two methods") == "one-model-two-methods"
    assert github_slug("Is the result inside the model?") == "is-the-result-inside-the-model"


# ---------------------------------------------------------------------- front door
def test_readme_is_a_front_door():
    lines = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    assert len(lines) < README_MAX_LINES
    text = "\n".join(lines)
    # the two commands that work on a fresh machine, as CI runs them
    assert 'pip install -e ".[orcaflex]" && riser-verify reproduce all' in text
    assert 'pip install -e ".[test,moordyn,cluster,orcaflex]" && python -m pytest' in text
    assert "python -m pytest -m slow" in text


# ------------------------------------------------------------------------- citations
def test_no_file_cites_a_path_outside_the_repository():
    assert outside_citations() == []


def test_the_citation_check_can_fail(tmp_path):
    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg" / "mod.py").write_text(
        '"""Inputs from the ' + "REFERENCE" + '.md section 2."""\nx = 1\n')
    (tmp_path / "scene.toml").write_text('source = "see ' + "../" + 'shared/digest"\n')
    (tmp_path / "notes.md").write_text("the text of " + "shared/" + "papers" + "/000_x.txt\n")
    (tmp_path / "reports").mkdir()                  # generated: not scanned
    (tmp_path / "reports" / "report.md").write_text("REFERENCE" + ".md section 1\n")
    (tmp_path / "fine.md").write_text("docs/references.md, Wang et al. 2014\n")
    found = outside_citations(tmp_path)
    assert [f.split(":", 1)[0] for f in found] == ["notes.md", "pkg/mod.py", "scene.toml"]


# ---------------------------------------------------------------------- command line
def _section(text: str, heading: str) -> str:
    m = re.search(rf"^## {re.escape(heading)}\n(.*?)(?=^## |\Z)", text, re.S | re.M)
    return m.group(1) if m else ""


def test_every_command_and_option_is_documented():
    from verification.cli import build_parser
    page = (ROOT / "docs" / "command-line.md").read_text(encoding="utf-8")
    sub = next(a for a in build_parser()._actions if a.dest == "command")
    missing = []
    for name, parser in sub.choices.items():
        section = _section(page, name)
        if not section:
            missing.append(f"## {name}")
            continue
        for action in parser._actions:
            longs = [o for o in action.option_strings if o.startswith("--")]
            if not longs or longs[0] in ("--help", "--quiet"):
                continue
            if longs[0] not in section:
                missing.append(f"{name} {longs[0]}")
    assert "--quiet" in page
    assert missing == []


# -------------------------------------------------------------------------- examples
def _toml_blocks(path: Path) -> list[str]:
    return re.findall(r"^```toml\n(.*?)^```", path.read_text(encoding="utf-8"), re.S | re.M)


def test_the_scene_examples_load():
    from riser.io.scene_file import parse_scene
    loaded = 0
    for page in PAGES:
        for block in _toml_blocks(page):
            if re.match(r"\s*name\s*=", block):          # a whole scene, not a fragment
                parse_scene(block, f"{page.name} example")
                loaded += 1
    assert loaded >= 3          # the README's minimal scene, and the two of scene-files.md


def test_the_sweep_example_loads(tmp_path):
    from verification.sweeps.file import load_sweep
    blocks = [b for b in _toml_blocks(ROOT / "docs" / "sweeps.md") if b.startswith("base")]
    assert len(blocks) == 1
    (tmp_path / "example.toml").write_text(blocks[0])
    assert len(load_sweep(tmp_path / "example.toml").cases) == 24   # 3 x 4 x 2, as the page says


def test_scene_files_keeps_the_generated_block_markers():
    lines = (ROOT / "docs" / "scene-files.md").read_text(encoding="utf-8").splitlines()
    assert [lines.count(m) for m in MARKERS] == [1, 1]
    assert lines.index(MARKERS[0]) < lines.index(MARKERS[1])
