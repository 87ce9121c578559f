"""The paper's printed values, for comparison only (see ``paper.yaml``)."""

from __future__ import annotations

from functools import cache
from importlib import resources

import yaml


@cache
def paper_tables() -> dict:
    """The paper's Tables 3 to 8 as printed, keyed by table name."""
    text = resources.files(__package__).joinpath("paper.yaml").read_text(encoding="utf-8")
    return yaml.safe_load(text)
