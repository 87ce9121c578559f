"""``stickslip report``: one HTML page without code; its mistakes are one line; Ctrl-C leaves nothing.

Also the page of any executed notebook (:mod:`stickslip.reports.notebook_page`) and the record
notebook's own one-line answer to a bad papermill parameter.
"""

from __future__ import annotations

import base64
import html
import json
import os
import re
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import nbformat
import numpy as np
import pytest

from conftest import REPO_ROOT, assert_one_error_line
from stickslip.reports.notebook_page import notebook_html, page_title

STICKSLIP = [sys.executable, "-m", "stickslip"]
PNG = base64.b64encode(b"\x89PNG\r\n\x1a\n" + b"\0" * 32).decode()


def _write_at2(path: Path, acceleration_g: np.ndarray, dt: float = 0.01) -> Path:
    """A PEER NGA-West2 AT2 file with event, station and component in its header."""
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD", "Quiet Valley, 1/1/2001, Far Station, 090",
             "ACCELERATION TIME SERIES IN UNITS OF G", f"NPTS= {acceleration_g.size:6d}, DT= {dt:.4f} SEC,"]
    lines += ["".join(f"{value:15.7E}" for value in acceleration_g[start:start + 5])
              for start in range(0, acceleration_g.size, 5)]
    path.write_text("\n".join(lines) + "\n", encoding="ascii")
    return path


@pytest.fixture
def weak_record(tmp_path) -> Path:
    """A record whose PGA, 0.001 g, is below every mu of the default grid: the block never slides."""
    time_ = np.arange(0.0, 5.0, 0.01)
    return _write_at2(tmp_path / "QUIET.AT2", 0.001 * np.sin(2 * np.pi * 2.5 * time_))


def test_a_page_has_no_code_no_script_from_the_web_and_the_first_heading_as_title():
    notebook = nbformat.v4.new_notebook(cells=[
        nbformat.v4.new_markdown_cell("Some words first, no heading."),
        nbformat.v4.new_code_cell("secret_code = 1", outputs=[
            nbformat.v4.new_output("display_data", {"text/markdown": "# Record report: x (Some Event, STA 090)"}),
            nbformat.v4.new_output("display_data", {"image/png": PNG}),
        ]),
        nbformat.v4.new_markdown_cell("# A later heading"),
    ])
    assert page_title(notebook) == "Record report: x (Some Event, STA 090)"
    page = notebook_html(notebook)
    assert "<title>Record report: x (Some Event, STA 090)</title>" in page
    assert "secret_code" not in page and "Some words first" in page
    assert f"data:image/png;base64,{PNG}" in page
    assert "<script src=" not in page and not re.search(r'(?:src|href)="(?:https?:)?//', page)


@pytest.mark.parametrize(("arguments", "name", "phrase"), [
    (["--mu", "0.1:0.1:0.1"], "--mu", "number 1; at least 3 are needed"),
    (["--q", "1.5"], "--q", "the near-optimal fraction must be in (0, 1]"),  # the optimum's own check
    (["--mass", "-1"], "--mass -1", "block mass [kg] must be a positive finite number"),  # the model's own check
    (["--reference-mu", "nan"], "--reference-mu", "a friction ratio must be a positive number"),
])
def test_a_bad_option_is_one_line_before_the_notebook_starts(run_cli, weak_record, tmp_path, arguments, name, phrase):
    out = tmp_path / "report.html"
    assert_one_error_line(*run_cli("report", weak_record, "--out", out, *arguments), name, phrase)
    assert not out.exists()


def test_a_file_without_a_time_step_is_one_line_naming_the_option(run_cli, tmp_path):
    record = tmp_path / "unknown.txt"
    record.write_text("0.01\n0.02\n-0.03\n0.05\n", encoding="ascii")
    out = tmp_path / "report.html"
    assert_one_error_line(*run_cli("report", record, "--out", out), record, "pass --dt in seconds")
    assert_one_error_line(*run_cli("report", record, "--out", tmp_path), tmp_path, "it is a directory")
    assert not out.exists()


@pytest.mark.slow
def test_the_report_of_a_record_that_never_slides_is_one_page_that_says_so(weak_record, tmp_path):
    out = tmp_path / "pages" / "report.html"
    result = subprocess.run([*STICKSLIP, "report", str(weak_record), "--out", str(out)], capture_output=True,
                            text=True, env={**os.environ, "MPLBACKEND": "Agg"}, timeout=300)
    assert result.returncode == 0, result.stderr[-3000:]
    assert result.stdout.strip() == str(out)
    assert result.stderr == "stickslip: rendering page 1 of 1 (QUIET.AT2)\n"  # one line per page, no progress bar
    page = out.read_text(encoding="utf-8")
    assert "<title>Record report: QUIET (Quiet Valley, Far Station 90°)</title>" in page
    assert "The block never slides at any μ of the grid" in page
    assert "its PGA 0.00981 m/s2 (0.001 g) is at most mu*g = 0.02453 m/s2 at the grid's smallest mu, 0.0025" in page
    assert "hl-ipython3" not in page and "import stickslip" not in page  # no code cells
    assert "<script src=" not in page and not re.search(r'(?:src|href)="(?:https?:)?//', page)
    # a figure with nothing to draw is one sentence, not an empty box; the others are embedded, with their text
    assert page.count("<p>Not drawn: the block never slides at any μ of the grid") == 2
    images = re.findall(r'<img alt="([^"]*)" src="data:image/png;base64,', page)
    assert images == ["QUIET: ground acceleration and Husid curve against time",
                      "QUIET: response of block and base against time at the case's friction ratio"]
    assert "Response at μ = 0.1 (the reference μ: the block slides at no μ of the grid)" in page
    assert not re.search(r">-0<|>-0\.0*<", page)  # no negative zero in any table
    assert sorted(path.name for path in out.parent.iterdir()) == ["report.html"]


def test_several_files_need_a_folder_and_every_file_is_read_before_any_page(run_cli, weak_record, tmp_path):
    page = tmp_path / "page.html"
    page.write_text("kept", encoding="utf-8")
    assert_one_error_line(*run_cli("report", weak_record, weak_record, "--out", page), page,
                          f"2 records give one page each: give a folder for them, such as --out {tmp_path / 'page'}/")
    new_page = tmp_path / "two.html"  # a page's name for two pages: refused, not made a folder
    assert_one_error_line(*run_cli("report", weak_record, weak_record, "--out", new_page), "--out",
                          f"2 records give one page each: give a folder for them, such as --out {tmp_path / 'two'}/")
    assert not new_page.exists()
    missing = tmp_path / "missing.AT2"
    assert_one_error_line(*run_cli("report", weak_record, missing, "--out", tmp_path / "pages"), missing,
                          "file not found")
    assert page.read_text(encoding="utf-8") == "kept" and not (tmp_path / "pages").exists()


def test_a_record_whose_page_would_be_the_folder_s_index_is_refused_before_any_page(run_cli, weak_record, tmp_path):
    index = _write_at2(tmp_path / "index.AT2", 0.05 * np.sin(2 * np.pi * np.arange(0.0, 5.0, 0.01)))
    out = tmp_path / "pages"
    assert_one_error_line(*run_cli("report", weak_record, index, "--out", out), f"--out {out}",
                          "a page would be named index.html, the name of the folder's index of pages")
    assert not out.exists()


@pytest.mark.slow
def test_several_files_give_one_page_each_named_by_record(weak_record, tmp_path):
    time_ = np.arange(0.0, 5.0, 0.01)
    other = _write_at2(tmp_path / "OTHER.AT2", 0.05 * np.sin(2 * np.pi * 1.5 * time_))  # slides, unlike QUIET
    out = tmp_path / "pages"
    result = subprocess.run([*STICKSLIP, "report", str(weak_record), str(other), "--out", str(out)],
                            capture_output=True, text=True, env={**os.environ, "MPLBACKEND": "Agg"}, timeout=600)
    assert result.returncode == 0, result.stderr[-3000:]
    assert result.stdout.split() == [str(out / "QUIET.html"), str(out / "OTHER.html"), str(out / "index.html")]
    for name in ("QUIET", "OTHER"):
        page = (out / f"{name}.html").read_text(encoding="utf-8")
        assert f"<title>Record report: {name} (Quiet Valley" in page
        assert not re.search(r"Fig\. ?\d", page)  # a user's page cites none of the paper's figures
    index = (out / "index.html").read_text(encoding="utf-8")
    assert index.count('href="QUIET.html"') == 2 and index.count('href="OTHER.html"') == 2  # listed, and a column
    assert "QUIET</a>: Record report: QUIET (Quiet Valley" in index
    assert "<li><b>QUIET</b>: the block never slides at any μ of the grid</li>" in index  # PGA 0.001 g
    row = re.search(r"<tr><td>μ_max on the grid</td><td>(.*?)</td><td>(.*?)</td></tr>", index)
    assert row.group(1) == "-" and float(row.group(2)) > 0


@pytest.mark.slow
def test_the_page_shows_what_stickslip_optimum_prints_on_its_refined_grid_and_the_response_at_mu_max(tmp_path):
    """The report's design answer is ``stickslip optimum``'s for the record, number for number, with the defaults:
    for a weak record, on the grid refined around its near-optimal range; the response is drawn at its μ_max."""
    from stickslip.optimum import RangeRefinement
    from stickslip.reports.design_answer import answer_rows, format_number

    time_ = np.arange(0.0, 8.0, 0.01)
    acceleration_g = 0.03 * np.sin(2 * np.pi * 1.3 * time_) * np.exp(-((time_ - 3.0) / 1.5) ** 2)
    record = _write_at2(tmp_path / "PULSE.AT2", acceleration_g + 0.002 * np.sin(2 * np.pi * 7.1 * time_))
    out = tmp_path / "report.html"
    environment = {**os.environ, "MPLBACKEND": "Agg"}
    result = subprocess.run([*STICKSLIP, "report", str(record), "--out", str(out)], capture_output=True, text=True,
                            env=environment, timeout=300)
    assert result.returncode == 0, result.stderr[-3000:]
    optimum = subprocess.run([*STICKSLIP, "optimum", str(record), "--json"], capture_output=True, text=True,
                             env=environment, timeout=120, check=True)
    document = json.loads(optimum.stdout)
    answer, (refined,) = document["records"][0], document["settings"]["grid_refinements"]
    assert answer["optimum_status"] == "ok" and answer["mu_max_at_grid_edge"] == 0.0
    page = out.read_text(encoding="utf-8")
    (answer_table,) = [table for table in re.findall(r"<table.*?</table>", page, re.S) if "μ_max on the grid" in table]
    table = {html.unescape(quantity): (value, units) for quantity, value, units
             in re.findall(r"<th>([^<]+)</th>\s*<td>([^<]+)</td>\s*<td>([^<]*)</td>", answer_table)}
    expected = answer_rows(answer, "mu", 0.95, 0.1)
    assert list(table) == [quantity for quantity, *_ in expected]
    assert answer["contiguous"] == 1.0 and "not contiguous" not in page and "on the grid's edge" not in page
    for quantity, name, value, units in expected:
        per_kg = "J/kg" if units == "J" else units  # the default 1 kg block: energies per kg, as optimum heads them
        assert table[quantity] == (value, per_kg), quantity  # as the terminal table of stickslip optimum prints it
        assert float(value) == pytest.approx(answer[name], rel=5e-4, abs=1e-12), name
    assert "<th>variable</th>" not in page and "mu_max_continuous" not in page  # the table speaks words
    described = RangeRefinement(0, refined["start"], refined["stop"], refined["step"], refined["values_added"],
                                refined["grid_values_in_range_before"],
                                refined["grid_values_in_range"]).describe("μ", 10)
    assert (f"On a grid of 400 values of μ from 0.0025 to 1 in steps of 0.0025, refined where the near-optimal range "
            f"held fewer than 10 grid values ({described}; {len(document['settings']['mu'])} values in all)") in page
    assert refined["grid_values_in_range_before"] < 10 <= answer["grid_values_in_range"]
    mu_max = format_number(answer["mu_max_continuous"], 5)
    assert f"Response at μ = {mu_max} (the record's μ_max, continuous), block mass m = 1 kg" in page


def _stderr_until(process: subprocess.Popen, marker: str, timeout: float) -> str:
    """What ``process`` wrote on stderr until ``marker`` appeared (or it ended, or ``timeout`` [s] passed)."""
    seen = ""
    deadline = time.monotonic() + timeout
    while marker not in seen and process.poll() is None and time.monotonic() < deadline:
        ready, _, _ = select.select([process.stderr], [], [], 0.1)
        if ready:
            seen += os.read(process.stderr.fileno(), 4096).decode(errors="replace")
    return seen


def _kernel_started(parent: int, timeout: float) -> bool:
    """Whether a Jupyter kernel, a child of the process ``parent``, appeared within ``timeout`` [s] (read from /proc).

    A fixed wait raced the report: on an idle machine the page was done before the signal came.
    """
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        for entry in Path("/proc").iterdir():
            try:
                stat = (entry / "stat").read_text()
                command = (entry / "cmdline").read_bytes()
            except (OSError, ValueError):
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == parent and b"ipykernel" in command:
                return True
        time.sleep(0.05)
    return False


@pytest.mark.slow
def test_ctrl_c_ends_the_report_with_130_and_nothing_written(weak_record, tmp_path):
    out = tmp_path / "report.html"
    process = subprocess.Popen([*STICKSLIP, "report", str(weak_record), "--out", str(out)], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True, start_new_session=True,
                               env={**os.environ, "MPLBACKEND": "Agg"},
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    started = _stderr_until(process, "rendering page 1 of 1", timeout=120)
    assert _kernel_started(process.pid, timeout=60), started  # papermill's kernel runs the notebook's cells
    os.killpg(process.pid, signal.SIGINT)  # as Ctrl-C sends it: to the whole foreground group
    _, stderr = process.communicate(timeout=30)
    stderr = started + stderr
    assert process.returncode == 130, stderr
    assert stderr.rstrip().endswith("stickslip: interrupted; no partial output was kept")
    assert list(tmp_path.iterdir()) == [weak_record]


@pytest.mark.slow
def test_a_bad_notebook_parameter_is_one_line_naming_the_parameter(tmp_path):
    papermill = pytest.importorskip("papermill")
    record = tmp_path / "unknown.txt"
    record.write_text("0.01\n0.02\n-0.03\n0.05\n", encoding="ascii")
    with pytest.raises(papermill.PapermillExecutionError) as raised:
        papermill.execute_notebook(str(REPO_ROOT / "notebooks" / "record_report.ipynb"), str(tmp_path / "out.ipynb"),
                                   parameters={"record": str(record)}, kernel_name="python3", progress_bar=False)
    error = raised.value
    assert error.ename == "ParameterError" and "--dt" not in error.evalue
    assert error.evalue == (f"{record}: no time step: a slammer_1col file has none and no manifest knows this file; "
                            "pass -p dt in seconds")
    assert error.traceback == [f"ParameterError: {error.evalue}"]


def test_the_help_says_what_the_report_does_by_default(capsys):
    from stickslip.cli import main

    with pytest.raises(SystemExit) as ended:
        main(["report", "--help"])
    assert ended.value.code == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "needs --mu" not in text  # a pair's report takes optimum's grid, as a record's does
    assert "--mu-case MU friction ratio of the response figures (default: the record's continuous mu_max; with " \
           "--pair, the plane's continuous mu_max); or a percentage (6%)" in text
    assert "the fewest grid values each record's near-optimal range holds" in text


def test_the_answer_table_of_a_coefficient_on_a_slope_adds_the_downslope_displacement():
    from collections import defaultdict

    from stickslip.reports.design_answer import answer_rows

    def names(coefficient):
        row = defaultdict(lambda: float("nan"), {f"{coefficient}_max_at_grid_edge": 0.0, "contiguous": 1.0})
        return [name for _, name, _, _ in answer_rows(row, coefficient, 0.9, 0.1)]

    assert [name for name in names("ky") if "downslope" in name] == [
        "downslope_displacement_at_ky_max", "downslope_displacement_at_ky_low", "downslope_displacement_at_ky_high",
        "largest_downslope_displacement"]
    assert [name for name in names("mu") if "downslope" in name] == []
    assert len(names("mu")) == len(names("ky")) - 4 == 18
