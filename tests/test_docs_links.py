"""Every relative link and image of the README and docs/ points at a file of the repository, and every
module, function and source file they name exists.

Sections move between the README and docs/, and code moves between modules; a
link or a name left behind would send a reader nowhere.  Web links and in-page
anchors are not checked.
"""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[1]
PAGES = [REPO_ROOT / "README.md", *sorted((REPO_ROOT / "docs").glob("*.md")), REPO_ROOT / "config" / "README.md",
         REPO_ROOT / "benchmarks" / "README.md"]
#: ``[text](target)`` and ``![alt](target)``, target without spaces.
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def relative_targets(page: Path) -> list[str]:
    """The link targets of ``page`` that are files of the repository (no scheme, not an in-page anchor)."""
    targets = (match.group(1).split("#", 1)[0] for match in LINK.finditer(page.read_text(encoding="utf-8")))
    return [target for target in targets if target and not re.match(r"[a-z]+:", target)]


@pytest.mark.parametrize("page", PAGES, ids=lambda page: str(page.relative_to(REPO_ROOT)))
def test_every_relative_link_resolves(page):
    missing = [target for target in relative_targets(page) if not (page.parent / target).exists()]
    assert missing == [], f"{page.relative_to(REPO_ROOT)} links to files that do not exist: {missing}"


def test_the_readme_links_the_pages_it_moved_to_docs():
    targets = set(relative_targets(REPO_ROOT / "README.md"))
    assert {"docs/workflow.md", "docs/reproduction.md", "docs/images/record_report.png"} <= targets
    manual = {"command_line", "slopes", "estimates", "isolators", "spectra", "isolation_design", "findings", "speed",
              "design"}
    assert {f"docs/{name}.md" for name in manual} <= targets


def test_the_readme_links_every_page_of_docs():
    targets = set(relative_targets(REPO_ROOT / "README.md"))
    assert sorted(f"docs/{page.name}" for page in (REPO_ROOT / "docs").glob("*.md")
                  if f"docs/{page.name}" not in targets) == []


def test_the_readme_keeps_to_what_a_newcomer_needs_first():
    """The README is at most 300 lines: what it is, the two commands, a short tour; the manual is in docs/."""
    lines = (REPO_ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    assert len(lines) <= 300
    assert {"## The two commands", "## A short tour", "## Where the rest is"} <= set(lines)


#: A name of the package in a code span: ``stickslip.models.swept.Design.still_reason``.
DOTTED_NAME = re.compile(r"`(stickslip(?:\.\w+)+)")
#: A source file of the repository in a code span: ``src/stickslip/models/rigid/scheme.py`` (or
#: ``stickslip/models/rigid/scheme.py``), ``tests/test_sweep.py``; not an output (``benchmarks/results.json``).
REPOSITORY_PATH = re.compile(r"`((?:src|stickslip|tests|workflow|notebooks|scripts|benchmarks|config|docs)/[\w./-]+"
                             r"\.(?:py|smk|ipynb|md|yaml|sh))`")


def resolves(dotted: str) -> bool:
    """Whether ``dotted`` names a module of the package, or something defined in one (a class, its member)."""
    parts = dotted.split(".")
    for split in range(len(parts), 0, -1):
        try:
            found = importlib.import_module(".".join(parts[:split]))
        except ImportError:
            continue
        for part in parts[split:]:
            if not hasattr(found, part):
                return False
            found = getattr(found, part)
        return True
    return False


@pytest.mark.parametrize("page", PAGES, ids=lambda page: str(page.relative_to(REPO_ROOT)))
def test_every_module_function_and_file_the_docs_name_exists(page):
    text = page.read_text(encoding="utf-8")
    unknown = sorted({name.rstrip(".") for name in DOTTED_NAME.findall(text) if not resolves(name.rstrip("."))})
    missing = sorted({path for path in REPOSITORY_PATH.findall(text)
                      if not (REPO_ROOT / path).exists() and not (REPO_ROOT / "src" / path).exists()})
    assert (unknown, missing) == ([], []), f"{page.relative_to(REPO_ROOT)} names what does not exist"


def test_resolves_tells_a_gone_name_from_a_present_one():
    assert resolves("stickslip.models.swept.Design.still_reason") and resolves("stickslip.models.rigid.scheme")
    assert not resolves("stickslip.grids.never_slides_reason") and not resolves("stickslip.solution")


def readme_block(start: str) -> str:
    """The README's lines from the one that starts with ``start`` to the next that starts with no space."""
    lines = (REPO_ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    first = next(index for index, line in enumerate(lines) if line.startswith(start))
    rest = lines[first + 1:]
    end = next((index for index, line in enumerate(rest) if line and not line.startswith(" ")), len(rest))
    return "\n".join(lines[first:first + 1 + end])


def test_the_readme_s_layout_names_every_notebook():
    notebooks = readme_block("notebooks/")
    assert [path.stem for path in sorted((REPO_ROOT / "notebooks").glob("*.ipynb"))
            if not re.search(rf"\b{path.stem}\b", notebooks)] == []
