"""Report pages: each page declares exactly the figures its notebook shows, and the pages' ranks, not the order
in which the rule files are included, place their sections on the index.

The declarations are read from the workflow itself (a copy of it parsed by
Snakemake, with one toy page declared last at a small rank and one declared
after the pages' rules were made); the figures a notebook shows are read from
its source: each ``show(figure, name)`` of its ``FigureFolder(...).show``.
"""

from __future__ import annotations

import ast
import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from conftest import REPO_ROOT, SNAKEMAKE

from stickslip.reports import pair_report, record_report

#: What a wildcard of a declared figure name ({record}) stands for when it is held against a notebook's names.
WILDCARD_VALUE = "WILDCARD"


def _text_pattern(node: ast.expr) -> str | None:
    """The regular expression of a string ``node``: a constant as it is, each field of an f-string any text."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return re.escape(node.value)
    if isinstance(node, ast.JoinedStr):
        return "".join(re.escape(part.value) if isinstance(part, ast.Constant) else ".+" for part in node.values)
    return None


def _loop_values(tree: ast.Module) -> dict[str, list[ast.expr] | None]:
    """For each name a ``for`` loop binds, the values it takes from a literal list of tuples or strings (None: from
    anything else, such as the declared names themselves, ``figure_alts.items()``)."""
    values: dict[str, list[ast.expr] | None] = {}
    for loop in (node for node in ast.walk(tree) if isinstance(node, ast.For)):
        targets = loop.target.elts if isinstance(loop.target, ast.Tuple) else [loop.target]
        literal = isinstance(loop.iter, (ast.List, ast.Tuple))
        for position, target in enumerate(targets):
            if not isinstance(target, ast.Name):
                continue
            if not literal:
                values[target.id] = None
            elif isinstance(loop.target, ast.Tuple):
                values[target.id] = [item.elts[position] for item in loop.iter.elts]
            else:
                values[target.id] = list(loop.iter.elts)
    return values


def shown_figures(notebook: Path) -> list[re.Pattern]:
    """The file names of the figures ``notebook`` shows, as patterns (see the module's docstring).

    ``show`` is the name bound to ``FigureFolder(folder, prefix=...).show``;
    the name of ``show(figure, name)`` is a string, an f-string (its fields
    match any text) or a loop's variable over a literal list (each value); a
    loop over anything else shows the declared figures themselves (a notebook
    whose data are not here draws each as "not drawn") and adds none.
    ``.png`` is added unless the name ends so, after the folder's prefix.
    """
    cells = json.loads(notebook.read_text(encoding="utf-8"))["cells"]
    tree = ast.parse("\n".join("".join(cell["source"]) for cell in cells if cell["cell_type"] == "code"))
    folders = [node for node in ast.walk(tree) if isinstance(node, ast.Assign) and isinstance(node.value, ast.Attribute)
               and node.value.attr == "show" and isinstance(node.value.value, ast.Call)
               and getattr(node.value.value.func, "id", "") == "FigureFolder"]
    assert len(folders) == 1, f"{notebook.name}: expected one show = FigureFolder(...).show, found {len(folders)}"
    (show,), folder = folders[0].targets, folders[0].value.value
    prefix = next((_text_pattern(keyword.value) for keyword in folder.keywords if keyword.arg == "prefix"), "")
    loops = _loop_values(tree)
    patterns = []
    for call in ast.walk(tree):
        if not (isinstance(call, ast.Call) and getattr(call.func, "id", None) == show.id):
            continue
        name = call.args[1]
        if isinstance(name, ast.Name):
            assert name.id in loops, f"{notebook.name}, line {call.lineno}: {name.id} is bound by no loop"
        names = loops[name.id] if isinstance(name, ast.Name) else [name]
        for each in names or ():  # None: the declared names themselves
            text = _text_pattern(each)
            assert text is not None, f"{notebook.name}, line {call.lineno}: a figure name that is no string"
            patterns.append(re.compile(prefix + text + ("" if text.endswith(re.escape(".png")) else re.escape(".png"))))
    return patterns


def figure_differences(declared: list[str], shown: list[re.Pattern]) -> tuple[list[str], list[str]]:
    """The declared file names no shown pattern matches, and the shown patterns that match no declared name."""
    return ([name for name in declared if not any(pattern.fullmatch(name) for pattern in shown)],
            [pattern.pattern for pattern in shown if not any(pattern.fullmatch(name) for name in declared)])


def _declared_names(page: dict) -> list[str]:
    """The file names of a page's declared figures, its wildcards standing for :data:`WILDCARD_VALUE`."""
    wildcards = {wildcard: WILDCARD_VALUE for wildcard in page["each"]}
    return [Path(path).name.format(**wildcards) for path in page["figures"]]


TOY_PAGE = '''
report_page("toy_page", rank=5, rule_name="render_toy_page", title="A toy page", notebook="notebooks/toy.ipynb",
            inputs={}, parameters={}, figures_dir="toy", figures={"toy_figure.png": "A toy figure"},
            category="Toy pages", caption="collection_study.rst",
            index_section=("toy_section:section_html", {}))
'''

#: Run at the end of the copied Snakefile: a page declared after reports.smk, and what the workflow declared.
DUMP = '''
import json as _json
try:
    report_page("late_page", rank=1001, rule_name="render_late_page", title="Late", notebook="notebooks/toy.ipynb",
                inputs={}, parameters={}, figures_dir="late", figures={}, category="Late", caption="late.rst")
    _late = None
except WorkflowError as _error:
    _late = str(_error)
Path(__DUMP_PATH__).write_text(_json.dumps({
    "declared": list(REPORT_PAGES),
    "pages": {name: {"rank": page["rank"], "notebook": page["notebook"], "figures": page["figures"],
                     "each": list(page["each"]), "rule": page["rule"], "rendered": page["rendered"],
                     "section": page["index_section"] and page["index_section"][0]}
              for name, page in REPORT_PAGES.items()},
    "sections": [section[0] for section in workflow.get_rule("write_report_index").params.sections],
    "rendering_rules": [rule.name for rule in workflow.rules if rule.name.startswith("render_")],
    "late": _late,
}))
'''


@pytest.fixture(scope="module")
def declared(tmp_path_factory) -> dict:
    """The report pages the workflow declares, read from a copy of it parsed by Snakemake (``--list``)."""
    tmp_path = tmp_path_factory.mktemp("report_pages")
    project = tmp_path / "project"
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc")
    for folder in ("workflow", "config", "notebooks", "src", ".test"):
        shutil.copytree(REPO_ROOT / folder, project / folder, symlinks=True, ignore=ignore)
    (project / "workflow" / "rules" / "toy.smk").write_text(TOY_PAGE, encoding="utf-8")
    (project / "notebooks" / "toy.ipynb").write_text(json.dumps({"cells": [], "metadata": {}, "nbformat": 4,
                                                                "nbformat_minor": 5}), encoding="utf-8")
    reports = 'include: "workflow/rules/reports.smk"\n'
    snakefile = (REPO_ROOT / "Snakefile").read_text(encoding="utf-8")
    assert snakefile.count(reports) == 1
    dump = tmp_path / "pages.json"
    (project / "Snakefile").write_text(
        snakefile.replace(reports, 'include: "workflow/rules/toy.smk"\n' + reports)
        + DUMP.replace("__DUMP_PATH__", repr(str(dump))), encoding="utf-8")
    workdir = tmp_path / "work"
    workdir.mkdir()
    run = subprocess.run(
        [SNAKEMAKE, "--snakefile", str(project / "Snakefile"), "--directory", str(workdir),
         "--configfile", str(project / ".test" / "config" / "config.yaml"), "--list"],
        capture_output=True, text=True, timeout=600,
        env={key: value for key, value in os.environ.items() if not key.startswith("STICKSLIP_")},
    )
    assert run.returncode == 0, run.stderr[-3000:]
    result = json.loads(dump.read_text(encoding="utf-8"))
    result["project"] = str(project)
    return result


def test_each_page_declares_the_figures_its_notebook_shows(declared):
    pages = {name: page for name, page in declared["pages"].items() if name != "toy_page"}
    assert {"paper_figures", "model_figures", "records/{record}", "collection_study", "planar_study",
            "slammer_verification", "jibson2007", "estimates"} <= set(pages)
    project = Path(declared["project"])
    for name, page in pages.items():
        notebook = REPO_ROOT / Path(page["notebook"]).relative_to(project)
        declared_names, shown = _declared_names(page), shown_figures(notebook)
        assert len(declared_names) >= 3 and shown, name
        assert figure_differences(declared_names, shown) == ([], []), f"{name}: declared, shown by {notebook.name}"


@pytest.mark.parametrize("notebook, figure_alts", [("record_report", record_report.figure_alts),
                                                   ("pair_report", pair_report.figure_alts)])
def test_the_command_line_reports_declare_the_figures_their_notebooks_show(notebook, figure_alts):
    declared_names = list(figure_alts(WILDCARD_VALUE))
    assert len(declared_names) >= 4
    shown = shown_figures(REPO_ROOT / "notebooks" / f"{notebook}.ipynb")
    assert figure_differences(declared_names, shown) == ([], [])


def test_the_index_and_the_rules_follow_the_ranks_not_the_includes(declared):
    pages = declared["pages"]
    ranks = [page["rank"] for page in pages.values()]
    assert len(set(ranks)) == len(ranks)
    # the toy page's section is declared last (its rule file is included just before reports.smk), and it ranks first
    in_declared_order = [pages[name]["section"] for name in declared["declared"] if pages[name]["section"]]
    assert in_declared_order[-1] == "toy_section:section_html" and pages["toy_page"]["rank"] == min(ranks)
    assert declared["sections"] == ["toy_section:section_html", *in_declared_order[:-1]]
    by_rank = sorted(pages.values(), key=lambda page: page["rank"])
    assert declared["rendering_rules"] == [page["rule"] for page in by_rank if page["rendered"]]
    # the ranks keep the sections in the order they had
    assert declared["sections"][1:] == ["stickslip.studies.collections.index:collection_section_html",
                                        "stickslip.studies.planar.index:planar_section_html",
                                        "stickslip.studies.verification.index:verification_section_html",
                                        "stickslip.studies.jibson2007.index:jibson_section_html",
                                        "stickslip.studies.estimates.index:estimates_section_html",
                                        "stickslip.studies.vertical.index:vertical_section_html",
                                        "stickslip.studies.code_vs_exact.index:code_exact_section_html",
                                        "stickslip.studies.isolation.index:isolation_section_html",
                                        "stickslip.studies.damper.index:damper_section_html"]


def test_a_page_declared_after_the_rules_were_made_is_refused(declared):
    assert declared["late"] == ("report_page 'late_page' is declared after workflow/rules/reports.smk made the "
                                "pages' rules: include its rule file before reports.smk")
    assert "late_page" not in declared["pages"]


def _notebook(tmp_path: Path, source: str) -> Path:
    path = tmp_path / "page.ipynb"
    cells = [{"cell_type": "markdown", "source": ["show(x, 'in_markdown')"]},
             {"cell_type": "code", "source": source.splitlines(keepends=True)}]
    path.write_text(json.dumps({"cells": cells}), encoding="utf-8")
    return path


def test_the_shown_names_are_read_from_strings_f_strings_and_literal_loops(tmp_path):
    notebook = _notebook(tmp_path, '''
show = FigureFolder(figures, prefix=f"{name}_", alts=figure_alts).show
show(plot(), "energy")
for k in range(3):
    show(plot(k), f"fig{18 + k}_timestep.png")
for x, label in [("pga", "peak.png"), ("rms", "rms")]:
    show(plot(x), label)
for name, text in figure_alts.items():
    show(not_drawn(text), name)
''')
    shown = shown_figures(notebook)
    assert [pattern.pattern for pattern in shown] == [r".+_energy\.png", r".+_fig.+_timestep\.png",
                                                      r".+_peak\.png", r".+_rms\.png"]
    declared = ["R1_energy.png", "R1_fig18_timestep.png", "R1_fig19_timestep.png", "R1_peak.png", "R1_stroke.png"]
    assert figure_differences(declared, shown) == (["R1_stroke.png"], [r".+_rms\.png"])
