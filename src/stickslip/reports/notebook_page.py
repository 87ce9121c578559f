"""An executed notebook as one self-contained HTML page, without its code.

The reports are for reading: :func:`notebook_html` converts an executed
notebook with nbconvert's HTML exporter (JupyterLab's look) and leaves out
every code cell's input and prompts, so the page shows the text, tables and
figures only; the executed notebook keeps the code for whoever wants it.
Figures are the PNGs embedded in the outputs, and the page loads nothing
from the web (``templates/offline.html.j2`` drops require.js, MathJax and
Mermaid, which the reports do not use), so the one file opens anywhere,
offline.  Its title is the first level-1 heading the page shows.
"""

from __future__ import annotations

import re
from pathlib import Path

import nbformat

from stickslip.plumbing.files import write_text_atomic

#: nbconvert templates of the package (``offline.html.j2``).
TEMPLATES = Path(__file__).parent / "templates"

_HEADING = re.compile(r"^# +(.+?)\s*$", re.MULTILINE)


def page_title(notebook: nbformat.NotebookNode) -> str | None:
    """The first level-1 Markdown heading the page shows: of a Markdown cell, or of a code cell's Markdown output."""
    for cell in notebook.cells:
        texts = [cell.source] if cell.cell_type == "markdown" else [
            output.get("data", {}).get("text/markdown", "") for output in cell.get("outputs", [])]
        for text in texts:
            found = _HEADING.search("".join(text))
            if found:
                return found.group(1)
    return None


def notebook_html(notebook: nbformat.NotebookNode) -> str:
    """The HTML page of an executed ``notebook``: no code, figures embedded, no script from the web."""
    from nbconvert import HTMLExporter

    exporter = HTMLExporter(template_name="lab", extra_template_paths=[str(TEMPLATES)],
                            template_file="offline.html.j2", exclude_input=True, exclude_input_prompt=True,
                            exclude_output_prompt=True)
    notebook = nbformat.from_dict(notebook)
    title = page_title(notebook)
    if title:
        notebook.metadata["title"] = title
    body, _ = exporter.from_notebook_node(notebook)
    return body


def write_notebook_page(notebook_path: str | Path, html_path: str | Path) -> Path:
    """The executed notebook ``notebook_path`` as the page ``html_path`` (:func:`notebook_html`), written atomically."""
    write_text_atomic(html_path, notebook_html(nbformat.read(notebook_path, as_version=4)))
    return Path(html_path)
