"""Links between the pages the workflow writes: relative, so that ``reports/`` can be moved or served as is."""

from __future__ import annotations

import os
from pathlib import Path


def relative_href(path: str | Path, base: str | Path) -> str:
    """``path`` relative to the folder ``base``, with forward slashes, for an ``href`` or ``src``."""
    return Path(os.path.relpath(path, base)).as_posix()
