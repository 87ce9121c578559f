"""What our results are held against: the paper's printed values (``paper.yaml``), Jibson's (2007) coefficients
(``jibson2007.yaml``, read by :mod:`stickslip.estimates.jibson`) and pySLAMMER's acceptance rules
(:mod:`~stickslip.reference.acceptance`); for comparison only."""

from __future__ import annotations

from functools import cache
from importlib import resources

import yaml


@cache
def paper_tables() -> dict:
    """The paper's Tables 3 to 8 as printed, keyed by table name."""
    text = resources.files(__package__).joinpath("paper.yaml").read_text(encoding="utf-8")
    return yaml.safe_load(text)


def paper_record_ids() -> list[str]:
    """The manifest ids of the paper's eight records, in the order of its Table 5."""
    return list(paper_tables()["table5_records"]["rows"])
