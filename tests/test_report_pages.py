"""Report pages are data: one ``report_page`` declaration gives a rendering rule, a link and a section on the index."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import textwrap

from conftest import REPO_ROOT, SNAKEMAKE

from stickslip.reports.index_page import write_index

TOY_RULES = '''
report_page(
    "toy_page",
    rule_name="render_toy_page",
    title="A toy page",
    notebook="notebooks/toy.ipynb",
    inputs={"tables": "results/tables/table5_records.csv"},
    parameters={"results_dir": "results", "colour": "teal",
                "table_name": lambda wildcards, input, output: Path(input.tables).name},
    figures_dir="toy",
    figures=["toy_figure.png"],
    category="Toy pages",
    caption="collection_study.rst",
    index_section=("toy_section:section_html", {"summary_path": "results/toy_summary.json"}),
    index_inputs=["results/tables/table5_records.csv"],
)
'''


def _workflow_with_a_toy_page(tmp_path):
    """A copy of the project's workflow with one more page declared, in its own rule file."""
    project = tmp_path / "project"
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc")
    for folder in ("workflow", "config", "notebooks", "src", ".test"):
        shutil.copytree(REPO_ROOT / folder, project / folder, symlinks=True, ignore=ignore)
    (project / "workflow" / "rules" / "toy.smk").write_text(TOY_RULES, encoding="utf-8")
    snakefile = (REPO_ROOT / "Snakefile").read_text(encoding="utf-8")
    reports = 'include: "workflow/rules/reports.smk"\n'
    assert reports in snakefile
    (project / "Snakefile").write_text(
        snakefile.replace(reports, 'include: "workflow/rules/toy.smk"\n' + reports), encoding="utf-8")
    notebook = {"cells": [{"cell_type": "code", "execution_count": None, "id": "parameters", "outputs": [],
                           "metadata": {"tags": ["parameters"]}, "source": ["colour = 'red'\n", "table_name = ''"]}],
                "metadata": {}, "nbformat": 4, "nbformat_minor": 5}
    (project / "notebooks" / "toy.ipynb").write_text(json.dumps(notebook), encoding="utf-8")
    return project


def test_a_declared_page_gets_its_rule_its_parameters_and_the_index_link(tmp_path):
    project = _workflow_with_a_toy_page(tmp_path)
    workdir = tmp_path / "work"
    workdir.mkdir()
    run = subprocess.run(
        [SNAKEMAKE, "--snakefile", str(project / "Snakefile"), "--directory", str(workdir), "--cores", "1",
         "--configfile", str(project / ".test" / "config" / "config.yaml"), "--dry-run", "--printshellcmds",
         "--forceall", "reports/index.html"],
        capture_output=True, text=True, timeout=300,
        env={key: value for key, value in os.environ.items() if not key.startswith("STICKSLIP_")},
    )
    assert run.returncode == 0, run.stderr[-3000:]
    out = run.stdout
    assert "rule render_toy_page:" in out
    assert "reports/toy_page.ipynb" in out and "reports/figures/toy/toy_figure.png" in out
    # the one papermill command, with the declared parameters (a function of the inputs evaluated)
    command = next(line for line in out.splitlines() if "papermill" in line and "toy.ipynb" in line)
    assert '"colour": "teal"' in command and '"table_name": "table5_records.csv"' in command
    assert '"figures_dir": "reports/figures/toy"' in command
    # the page becomes a page and an input of the index
    assert "reports/html/toy_page.html" in out
    index_job = out[out.index("rule write_report_index:"):]
    assert "reports/html/toy_page.html" in index_job.split("output:")[0]


def test_the_index_shows_a_declared_section(tmp_path, monkeypatch):
    module = tmp_path / "modules" / "toy_section.py"
    module.parent.mkdir()
    module.write_text(textwrap.dedent('''
        import json
        from pathlib import Path

        def section_html(summary_path, base):
            summary = json.loads(Path(summary_path).read_text())
            return f'<h1 id="toy">Toy section</h1><p>{summary["answer"]} found, relative to {Path(base).name}</p>'
    '''), encoding="utf-8")
    monkeypatch.syspath_prepend(str(module.parent))
    summary = tmp_path / "toy_summary.json"
    summary.write_text(json.dumps({"answer": 42}), encoding="utf-8")
    (tmp_path / "reports").mkdir()
    index = write_index([], tmp_path / "reports" / "index.html", {}, results_dir=tmp_path / "results",
                        reports_dir=tmp_path / "reports",
                        sections=[("toy_section:section_html", {"summary_path": str(summary)})])
    text = index.read_text(encoding="utf-8")
    assert '<h1 id="toy">Toy section</h1><p>42 found, relative to reports</p>' in text
    assert text.rstrip().endswith("</body></html>")
