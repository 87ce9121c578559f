"""Each variant is a registry entry: a toy record format (one reader, one entry), a toy solver scheme (one
module, one line) and a toy report page (one declaration) flow through the library, the command line and the
workflow; each registry's rules come from its entries."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import textwrap
import types

import numpy as np
import pytest
from conftest import REPO_ROOT, SNAKEMAKE

from stickslip.collections import load_collection
from stickslip.errors import RecordError, StickslipError
from stickslip.records.formats import FORMATS, Parsed, RecordFormat, known_formats
from stickslip.records.readers import detect_format, read_record
from stickslip.records.record import Record, RecordMeta
from stickslip.reports.index_page import write_index
from stickslip.models import solve
from stickslip.models import rigid
from stickslip.models.rigid import RIGID, exact_scheme
from stickslip.models.rigid.scheme import RigidScheme
from stickslip.models import sweep

G = 9.81


def _read_semicolons(decoded, source):
    """Time [s] and acceleration [g] separated by a semicolon, one pair per line."""
    rows = np.array([[float(field) for field in line.split(";")] for line in decoded.lines if line.strip()])
    return Parsed(rows[:, 1], float(rows[1, 0] - rows[0, 0]), "g")


@pytest.fixture
def semicolons(monkeypatch):
    entry = RecordFormat("semicolon", "time;acceleration per line", lambda head: ";" in head.data_line,
                         _read_semicolons, columns=2, units="g")
    monkeypatch.setitem(FORMATS, "semicolon", entry)
    return entry


@pytest.fixture
def semicolon_file(tmp_path):
    path = tmp_path / "wave.ssv"
    time = np.arange(0.0, 4.0, 0.01)
    path.write_text("\n".join(f"{t:.2f};{0.2 * np.sin(2 * np.pi * t):.6f}" for t in time) + "\n", encoding="ascii")
    return path


def test_a_new_format_is_one_reader_and_one_entry(semicolons, semicolon_file, run_cli):
    assert detect_format(semicolon_file.read_text(), str(semicolon_file)) == "semicolon"
    record = read_record(semicolon_file)
    assert record.meta.format == "semicolon" and record.dt == 0.01 and record.npts == 400
    assert np.max(np.abs(record.acceleration)) == pytest.approx(0.2 * 9.81, rel=1e-5)
    assert "semicolon" in known_formats()
    code, out, err = run_cli("measures", semicolon_file, "--format", "semicolon", "--json")
    assert code == 0, err
    assert '"record": "wave"' in out


def _read_semicolon_values(decoded, source):
    """Accelerations [g] separated by semicolons, no time: the file states no time step."""
    return Parsed(np.array([float(field) for field in decoded.text.replace("\n", ";").split(";") if field.strip()]),
                  None, "g")


def test_a_format_without_a_time_step_of_its_own_takes_the_folder_s_dt(monkeypatch, tmp_path):
    """The collection asks the format's entry whether its files state dt, whatever the format's name."""
    monkeypatch.setitem(FORMATS, "semicolon_values", RecordFormat(
        "semicolon_values", "accelerations separated by semicolons", lambda head: ";" in head.data_line,
        _read_semicolon_values, units="g", states_dt=False))
    (tmp_path / "mine").mkdir()
    values = 0.2 * np.sin(np.linspace(0.0, 8.0, 200))
    (tmp_path / "mine" / "wave.txt").write_text(";".join(f"{value:.6f}" for value in values) + "\n", encoding="ascii")
    collection = load_collection("folder", tmp_path / "mine", dt=0.02)
    assert collection.table.at["wave", "format"] == "semicolon_values" and collection.table.at["wave", "dt"] == 0.02
    record = collection.read("wave")
    assert record.dt == 0.02 and record.npts == 200
    np.testing.assert_allclose(record.acceleration, np.round(values, 6) * G, rtol=1e-12)


def test_without_its_entry_the_file_is_unknown(semicolon_file):
    with pytest.raises(RecordError, match="unknown format: .*known formats: netcdf, peer_at2, slammer_1col, time_acc_csv, "
                                          "two_column$"):
        read_record(semicolon_file)


def test_each_built_in_format_declares_its_columns_and_implied_units():
    assert {name: (entry.columns, entry.units) for name, entry in FORMATS.items()} == {
        "peer_at2": (1, None), "time_acc_csv": (2, "g"), "two_column": (2, None), "slammer_1col": (1, "g"),
        "netcdf": (1, "m/s2")}


def _toy_history(acceleration, dt, resistance, *, label: str = "toy"):
    """The exact scheme's history under another name, with an option of its own."""
    return exact_scheme.sliding_history(acceleration, dt, resistance)


@pytest.fixture
def toy(monkeypatch):
    """A flat-only scheme ``toy`` without a batched kernel: one module, one more entry of the rigid model's schemes."""
    module = types.ModuleType("toy_scheme")
    module.sliding_history = _toy_history
    monkeypatch.setitem(sys.modules, "toy_scheme", module)
    scheme = RigidScheme("toy", "a toy for the registry's test", "toy_scheme:sliding_history", flat_only=True)
    monkeypatch.setattr(rigid, "SCHEMES", (*rigid.SCHEMES, scheme))
    monkeypatch.setattr(rigid.RigidModel, "schemes", rigid.SCHEMES)
    return scheme


@pytest.fixture
def record():
    time = np.arange(0.0, 8.0, 0.01)
    return Record(3.0 * np.sin(2 * np.pi * 1.3 * time) * np.exp(-0.3 * time), 0.01, RecordMeta(record_id="wave"))


def test_a_new_scheme_is_one_module_and_one_line(toy, record):
    assert RIGID.scheme("toy") is toy and toy.options == {"label": "toy"}
    assert [scheme.name for scheme in RIGID.schemes if "label" in scheme.options] == ["toy"]
    ours, reference = solve(record, mu=0.1, method="toy"), solve(record, mu=0.1)
    assert ours.method == "toy" and ours.solver_options == {"label": "toy"}
    assert ours.energy_dissipated == reference.energy_dissipated > 0
    mu = [0.05, 0.1, 0.2]
    cube, batched = sweep([record], mu=mu, method="toy", progress=False), sweep([record], mu=mu, progress=False)
    np.testing.assert_allclose(cube.energy_dissipated.values, batched.energy_dissipated.values, rtol=1e-12)
    assert cube.attrs["solver"] == "toy"


def test_the_entry_s_rules_are_checked_once_for_every_caller(toy, record):
    message = r"toy \(a toy for the registry's test\) solves flat friction only, not .*; use method exact or slammer"
    with pytest.raises(StickslipError, match=message):
        solve(record, ky=0.1, method="toy")
    with pytest.raises(StickslipError, match=message):
        sweep([record], ky=[0.1, 0.2], method="toy", progress=False)
    with pytest.raises(StickslipError, match="solver 'toy' does not accept option\\(s\\) time_step; it accepts: label"):
        solve(record, mu=0.1, method="toy", time_step=0.001)
    with pytest.raises(StickslipError, match="the rigid model is solved by method exact, newmark, slammer, toy, not "
                                             "'toys'"):
        solve(record, mu=0.1, method="toys")


def test_the_command_line_offers_the_new_scheme(toy, run_cli, tmp_path):
    path = tmp_path / "wave.txt"
    time = np.arange(0.0, 8.0, 0.01)
    path.write_text("\n".join(f"{t:.2f} {0.3 * np.sin(2 * np.pi * 1.3 * t):.6f}" for t in time) + "\n",
                    encoding="ascii")
    code, out, err = run_cli("solve", path, "--mu", "0.1", "--units", "g", "--method", "toy", "--json")
    assert code == 0, err
    assert '"method": "toy"' in out and '"label": "toy"' in out
    code, out, err = run_cli("solve", path, "--mu", "0.1", "--units", "g", "--method", "toy", "--time-step", "0.001")
    assert code == 2 and err.strip() == ("stickslip: error: --time-step applies to --method newmark only (toy follows "
                                         "the record's samples)")


def test_inverse_polarity_options_reach_solve_and_sweep_alike(record):
    inverse = solve(record, ky=0.05, method="slammer", inverse=True)
    assert inverse.solver_options == {"skip_zero_samples": False}
    cube = sweep([record], ky=[0.05, 0.1], method="slammer", inverse=True, progress=False)
    assert cube.downslope_displacement.values[0, 0] == pytest.approx(inverse.downslope_displacement, rel=1e-12)


TOY_RULES = '''
report_page(
    "toy_page",
    rank=1000,
    rule_name="render_toy_page",
    title="A toy page",
    notebook="notebooks/toy.ipynb",
    inputs={"tables": "results/tables/table5_records.csv"},
    parameters={"results_dir": "results", "colour": "teal",
                "table_name": lambda wildcards, input, output: Path(input.tables).name},
    figures_dir="toy",
    figures={"toy_figure.png": "A toy figure: nothing against nothing"},
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


def _dry_run_with_a_toy_page(tmp_path) -> str:
    """The jobs (shell commands printed) of a dry run of the copy with a toy page, up to the index."""
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
    return run.stdout


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
    (tmp_path / "reports" / "figures" / "toy").mkdir(parents=True)
    figure = tmp_path / "reports" / "figures" / "toy" / "toy_figure.png"
    figure.write_bytes(b"\x89PNG")
    index = write_index([], tmp_path / "reports" / "index.html", {}, results_dir=tmp_path / "results",
                        reports_dir=tmp_path / "reports",
                        sections=[("toy_section:section_html", {"summary_path": str(summary)})],
                        figure_alts={figure.as_posix(): "A toy figure: nothing against nothing"})
    text = index.read_text(encoding="utf-8")
    assert '<h1 id="toy">Toy section</h1><p>42 found, relative to reports</p>' in text
    assert 'alt="A toy figure: nothing against nothing"' in text
    assert text.rstrip().endswith("</body></html>")


def test_a_toy_entry_of_each_kind_flows_through(semicolons, toy, semicolon_file, run_cli, tmp_path):
    """A toy format read by a toy scheme from the command line; a toy page declared in a copy of the workflow."""
    code, out, err = run_cli("solve", semicolon_file, "--mu", "0.1", "--method", "toy", "--json")
    assert code == 0, err
    result = json.loads(out)
    assert result["format"] == "semicolon" and result["method"] == "toy" and result["label"] == "toy"
    reference = solve(read_record(semicolon_file), mu=0.1, mass=result["mass"])
    assert reference.energy_dissipated > 0
    assert result["energy_dissipated"] == pytest.approx(reference.energy_dissipated, rel=1e-12)

    out = _dry_run_with_a_toy_page(tmp_path)
    assert "rule render_toy_page:" in out
    assert "reports/toy_page.ipynb" in out and "reports/figures/toy/toy_figure.png" in out
    # the one papermill command, with the declared parameters (a function of the inputs evaluated) and alt texts
    command = next(line for line in out.splitlines() if "papermill" in line and "toy.ipynb" in line)
    assert '"colour": "teal"' in command and '"table_name": "table5_records.csv"' in command
    assert '"figures_dir": "reports/figures/toy"' in command
    assert '"figure_alts": {"toy_figure.png": "A toy figure: nothing against nothing"}' in command
    # the page becomes a page and an input of the index, which gets the figure's alternative text
    index_job = out[out.index("rule write_report_index:"):]
    assert "reports/html/toy_page.html" in index_job.split("output:")[0]
