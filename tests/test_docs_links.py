"""Every relative link and image of the README and docs/ points at a file of the repository.

Sections move between the README and docs/; a link left behind would send a
reader nowhere.  Web links and in-page anchors are not checked.
"""

from __future__ import annotations

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
