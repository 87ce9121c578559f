"""Links between the pages the workflow writes: relative, so that ``reports/`` can be moved or served as is."""

from __future__ import annotations

import html
import os
from collections.abc import Mapping, Sequence
from pathlib import Path


def relative_href(path: str | Path, base: str | Path) -> str:
    """``path`` relative to the folder ``base``, with forward slashes, for an ``href`` or ``src``."""
    return Path(os.path.relpath(path, base)).as_posix()


def thumbnails_html(figures: Sequence[str | Path], base: str | Path, alts: Mapping[str, str] | None = None) -> str:
    """Each PNG of ``figures`` as a linked thumbnail, with its alternative text from ``alts`` (else its file stem).

    ``alts`` are keyed by the figure's path as the workflow writes it (``reports/figures/...``, the
    declarations of ``report_page``); ``base`` is the page's folder.
    """
    parts = []
    for figure in map(Path, figures):
        href = relative_href(figure, base)
        alt = (alts or {}).get(figure.as_posix(), figure.stem)
        parts.append(f'<a href="{href}"><img src="{href}" alt="{html.escape(alt)}" title="{html.escape(figure.name)}"></a>')
    return "\n".join(parts)
