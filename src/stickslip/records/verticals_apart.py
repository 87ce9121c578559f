"""Which records enter statistics over records of horizontal shaking, and which vertical components stay apart.

A median, a percentile or a mean over many records (``stickslip optimum``
over a folder, ``stickslip displacements``) summarises horizontal shaking: a
vertical component among the files (its header or manifest says ``UP``,
``DWN``, ``V`` ..., or its file name ends so:
:func:`stickslip.records.components.vertical_component`) is still solved and
listed with its own results, but left out of the statistics and named apart
with the reason, as the collection study keeps it apart
(:mod:`stickslip.collections.members`).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np


def verticals_apart(records: Sequence[tuple[str, str, str | None]]) -> tuple[np.ndarray, list[dict]]:
    """Which of ``records`` enter the statistics, and the ones left out.

    ``records`` gives, for each record (or scaled version of one), its label,
    its file and why it is a vertical component (None for a horizontal one).
    Returns a boolean per record (True: it enters) and one dict per record
    left out: ``record`` (the label), ``source`` and ``reason``.
    """
    included = np.array([vertical is None for _, _, vertical in records], dtype=bool)
    left_out = [{"record": label, "source": source, "reason": f"a vertical component: {vertical}"}
                for label, source, vertical in records if vertical is not None]
    return included, left_out


def left_out_line(left_out: list[dict]) -> str | None:
    """One line naming the records left out of the statistics and why (None when none was)."""
    if not left_out:
        return None
    named = "; ".join(f"{item['record']} ({item['reason']})" for item in left_out)
    return (f"left out of the statistics, apart from the horizontal shaking they summarise: {len(left_out)} "
            f"record{'s' if len(left_out) != 1 else ''}: {named}")
