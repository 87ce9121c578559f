"""What every report notebook uses to show its figures and tables, defined once.

A notebook makes its :class:`FigureFolder` from its ``figures_dir`` and
``figure_alts`` parameters (``show = FigureFolder(figures_dir,
alts=figure_alts).show``: the workflow's ``report_page`` declares each
figure's alternative text and passes them) and calls :func:`table` for rows
read from the workflow's CSV files; both display in the notebook and so in
its HTML page (:mod:`stickslip.reports.notebook_page`), a figure with its
alternative text.
"""

from __future__ import annotations

import html
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from IPython.display import HTML, Image, display

from stickslip.reports.plots import NotDrawn, save_figure


@dataclass(frozen=True)
class FigureFolder:
    """Where a notebook's figures go, ``{folder}/{prefix}{name}.png``, and their alternative texts by file name."""

    folder: str | Path
    prefix: str = ""
    alts: Mapping[str, str] = field(default_factory=dict)

    def show(self, figure, name: str) -> None:
        """Save ``figure`` as the PNG ``{folder}/{prefix}{name}`` (``.png`` added unless given) and display it with
        its alternative text, ``alts`` of the file name (a figure without one is shown without).

        A figure that could not be drawn (:class:`~stickslip.reports.plots.NotDrawn`) is saved all the same (the
        workflow declares the file) and shown as its one sentence, not as an empty box.  It returns nothing, so
        that a notebook cell ending with it shows the figure and no file path.
        """
        path = save_figure(figure, Path(self.folder) / f"{self.prefix}{name}{'' if name.endswith('.png') else '.png'}")
        if isinstance(figure, NotDrawn):
            display(HTML(f"<p>{html.escape(figure.sentence)}</p>"))
            return
        alt = self.alts.get(path.name, "")
        display(Image(filename=str(path), metadata={"alt": alt} if alt else None))


def html_table(rows: Sequence[Mapping], columns: Sequence, digits: int | None = 3, fold_beyond: int = 40,
               what: str = "rows") -> str:
    """An HTML table of ``rows`` (dicts), one column per entry of ``columns``: a key, or a (key, heading) pair.

    A number is written to ``digits`` significant digits (a whole number as
    such; ``digits=None`` writes every cell as its text, numbers aligned as
    numbers), ``-`` or NaN (no value) as ``-``, ``True``/``False``
    as yes/**no**, text escaped; more than ``fold_beyond`` rows are folded
    behind a "``n`` ``what`` (click to show)" line.
    """
    columns = [(column, column) if isinstance(column, str) else column for column in columns]

    def cell(value) -> str:
        if value == "-":  # no value, in a column of numbers
            return "<td>-</td>"
        if isinstance(value, bool) or value in ("True", "False"):
            return f"<td>{'yes' if str(value) == 'True' else '<b>no</b>'}</td>"
        try:
            number = float(value)
        except (TypeError, ValueError, OverflowError):
            return f'<td style="text-align:left">{html.escape(str(value))}</td>'
        if math.isnan(number):  # no value
            return "<td>-</td>"
        if digits is None:  # a number written as given, aligned as numbers are
            return f"<td>{html.escape(str(value))}</td>"
        return f"<td>{int(number) if number.is_integer() else f'{number:.{digits}g}'}</td>"

    head = "".join(f"<th>{html.escape(heading)}</th>" for _, heading in columns)
    body = "".join("<tr>" + "".join(cell(row.get(key, "")) for key, _ in columns) + "</tr>" for row in rows)
    page = f"<table><tr>{head}</tr>{body}</table>"
    if len(rows) > fold_beyond:
        page = f"<details><summary>{len(rows)} {what} (click to show)</summary>{page}</details>"
    return page


def table(rows: Sequence[Mapping], columns: Sequence, digits: int | None = 3, **options) -> None:
    """Display :func:`html_table` of ``rows`` (``digits`` and ``options`` as there)."""
    display(HTML(html_table(rows, columns, digits, **options)))
