"""The Snakemake workflow: per-record jobs, config that reaches the code, precise reruns, checks up front.

The end-to-end runs are the session fixtures ``test_workflow`` (the small
``.test/`` configuration, offline records) and ``paper_workflow`` (the shared
paper records); their tables are compared with stored references in
``test_references.py``.
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest
import yaml

from conftest import REPO_ROOT, SNAKEMAKE, project_config, require_shared_records, snakemake

from stickslip.plumbing.files import read_csv_rows

TEST_CONFIG = REPO_ROOT / ".test" / "config" / "config.yaml"
REPORT_RULES = {"render_paper_figures", "render_model_figures", "render_record_report", "render_collection_report",
                "render_planar_report", "render_vertical_report", "render_code_vs_exact_report",
                "render_isolation_report", "render_damper_report",
                "render_jibson2007_report", "render_estimates_report", "convert_notebook_html", "write_report_index",
                "all"}
#: The rules that read the paper's printed values (the collection study's claims set its Tables 6 and 7
#: beside ours).
COMPARISON_RULES = {"write_records_table", "compare_mu_max", "compare_scaling", "compare_harmonic",
                    "compare_shaking_table", "check_errata", "refit_paper_lines", "analyse_collection"}


def planned_jobs(result) -> dict[str, int]:
    """Rule -> number of jobs, from the job stats of a dry run."""
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    text = result.stdout + result.stderr
    if "Nothing to be done" in text:
        return {}
    table = text.split("Job stats:")[1].split("total")[0]
    return {match[0]: int(match[1]) for match in re.findall(r"^(\w+)\s+(\d+)$", table, flags=re.M) if match[0] != "job"}


@pytest.fixture(scope="module")
def finished(test_workflow) -> Path:
    """The working folder of the finished .test/ workflow."""
    return test_workflow.parent


def dry_run(workdir: Path, *args: str, configfile: Path = TEST_CONFIG, config: dict | None = None) -> dict[str, int]:
    return planned_jobs(snakemake(workdir, configfile, "--dry-run", *args, config=config))


@pytest.fixture
def touched():
    """Edit files by one line for one test (Snakemake compares contents, not only times); restore them after."""
    saved = {}

    def touch(path: Path) -> None:
        saved.setdefault(path, path.read_bytes())
        if path.suffix == ".ipynb":
            path.write_text(path.read_text(encoding="utf-8").rstrip("\n") + "\n\n", encoding="utf-8")
        else:
            path.write_bytes(saved[path] + b"\n# a one-line edit\n")

    yield touch
    for path, content in saved.items():
        path.write_bytes(content)


def test_the_default_config_plans_one_job_per_record_and_grid(tmp_path):
    config = yaml.safe_load((REPO_ROOT / "config" / "config.yaml").read_text(encoding="utf-8"))
    jobs = dry_run(tmp_path, configfile=REPO_ROOT / "config" / "config.yaml")
    records = len(config["paper_records"])
    assert jobs["acquire_record"] == records and jobs["compute_measures"] == records
    # the paper grid, the fine grid and the scaled grid for each paper record; the mass grid for its records
    assert jobs["sweep_record"] == 3 * records + len(config["mass_study"]["records"])
    assert jobs["gather_sweeps"] == 4


@pytest.mark.parametrize("profile", ["default", "slurm"])
def test_the_workflow_plans_with_each_profile(tmp_path, profile):
    jobs = dry_run(tmp_path, "--profile", str(REPO_ROOT / "workflow" / "profiles" / profile))
    assert jobs["sweep_record"] == 2 * 3 + 1 and "write_report_index" in jobs


def test_a_second_run_does_nothing(finished):
    assert dry_run(finished) == {}


def test_the_block_mass_reaches_the_sweeps_and_tables_but_not_the_records(finished):
    jobs = dry_run(finished, config={"block_mass": 50})
    assert jobs["sweep_record"] == 2 * 3 + 1
    assert {"find_mu_max", "compute_scaling", "solve_harmonic_cases", "compare_time_steps", "check_mass_scaling"} <= set(jobs)
    assert "acquire_record" not in jobs and "compute_measures" not in jobs


def test_an_edit_of_the_plots_reruns_only_the_reports(finished, touched):
    touched(REPO_ROOT / "src" / "stickslip" / "reports" / "plots.py")
    assert set(dry_run(finished)) == REPORT_RULES


def test_an_edit_of_a_notebook_reruns_only_its_reports(finished, touched):
    touched(REPO_ROOT / "src" / "stickslip" / "reports" / "notebooks" / "record_report.ipynb")
    assert set(dry_run(finished)) == {"render_record_report", "convert_notebook_html", "write_report_index", "all"}


def test_an_edit_of_the_papers_values_reruns_only_the_comparisons(finished, touched):
    touched(REPO_ROOT / "src" / "stickslip" / "reference" / "paper.yaml")
    jobs = set(dry_run(finished))
    assert COMPARISON_RULES <= jobs
    assert jobs - REPORT_RULES == COMPARISON_RULES


def test_an_edit_of_the_solver_reruns_the_sweeps_and_what_follows(finished, touched):
    touched(REPO_ROOT / "src" / "stickslip" / "models" / "rigid" / "exact.py")
    jobs = dry_run(finished)
    assert jobs["sweep_record"] == 2 * 3 + 1 and "find_mu_max" in jobs and "write_report_index" in jobs
    assert "acquire_record" not in jobs and "compute_measures" not in jobs


def test_the_offline_run_names_nothing_missing_and_reports_as_pages(test_workflow):
    index = (test_workflow.parent / "reports" / "index.html").read_text(encoding="utf-8")
    status = index.split('<div class="status">')[1].split("</div>")[0]
    assert "2 of 2 records found" in status and "missing" not in status.lower()
    assert 'href="html/paper_figures.html"' in index and 'href="html/records/cape_mendocino.html"' in index
    fits = (test_workflow / "fits.json").read_text(encoding="utf-8")
    assert "too few records: 2 available, a fit needs at least 3" in fits
    # the pages show no code, the executed notebooks beside them keep it; a record's page names its event
    reports = test_workflow.parent / "reports"
    for page in ("paper_figures", "model_figures", "collection_study", "records/cape_mendocino"):
        html = (reports / "html" / f"{page}.html").read_text(encoding="utf-8")
        assert "hl-ipython3" not in html and "PosixPath(" not in html, page  # no code, no stray cell value
        assert "import " in (reports / f"{page}.ipynb").read_text(encoding="utf-8"), page
    record_page = (reports / "html" / "records" / "cape_mendocino.html").read_text(encoding="utf-8")
    assert "<title>Record report: cape_mendocino (Cape Mendocino" in record_page


def test_without_its_data_the_verification_is_one_job_and_the_index_says_why(test_workflow):
    """No verification folder: the summary and the index say the data are not here and how to get them; no page."""
    summary = json.loads((test_workflow / "verification" / "slammer_summary.json").read_text(encoding="utf-8"))
    assert summary["status"] == "not available" and "verification_dir" in summary["reason"]
    index = (test_workflow.parent / "reports" / "index.html").read_text(encoding="utf-8")
    section = index.split('<h1 id="verification">')[1]
    assert "Not run: the verification data are not here" in section and "pySLAMMER/pySLAMMER" in section
    assert not (test_workflow.parent / "reports" / "slammer_verification.ipynb").exists()


def test_the_jibson_target_is_built_on_the_18_sample_motions_and_linked_from_the_index(test_workflow):
    """Jibson (2007), recomputed, on pyslammer's 18 motions: every row of the grid, the counts add up, a page, a link."""
    study = test_workflow / "collections" / "pyslammer"
    rows = read_csv_rows(study / "jibson2007_displacements.csv")
    config = yaml.safe_load(TEST_CONFIG.read_text(encoding="utf-8"))["jibson2007"]
    assert len(rows) == 18 * 2 * len(config["critical_accelerations_g"])
    assert {row["polarity"] for row in rows} == {"normal", "inverse"} and all(row["event"] for row in rows)
    document = json.loads((study / "jibson2007_fit.json").read_text(encoding="utf-8"))
    assert document["collection"] == {"records": 18, "records_solved": 18, "events": 17, "rows": len(rows)}
    for name, selection in document["selections"].items():
        assert selection["rows"] + sum(selection["excluded_rows"].values()) == len(rows), name
        for form, fit in selection["forms"].items():
            assert fit["status"] == "ok" and fit["rows"] == selection["rows"], (name, form)
            assert fit["bootstrap_resamples"] == config["n_boot"] and 0.0 < fit["sigma"]["value"] < 2.0
    zero_or_above = sum(float(row["critical_acceleration_ratio"]) >= 1.0 or float(row["newmark_displacement"]) == 0.0
                        for row in rows)
    excluded = document["selections"]["without_floor"]["excluded_rows"]
    assert excluded["a_c >= PGA"] + excluded["does not slide (D_n = 0)"] == zero_or_above > 0
    reports = test_workflow.parent / "reports"
    index = (reports / "index.html").read_text(encoding="utf-8")
    section = index.split('<h1 id="jibson2007">')[1]
    assert 'href="html/jibson2007.html"' in section and "(Jibson 0.510)" in section
    page = (reports / "html" / "jibson2007.html").read_text(encoding="utf-8")
    assert "hl-ipython3" not in page and "Ours beside Jibson" in page
    for name in ("jibson2007_form1", "jibson2007_form2", "jibson2007_residuals"):
        assert (reports / "figures" / "jibson2007" / f"{name}.png").stat().st_size > 8_000, name


def test_the_estimates_study_is_built_on_the_18_sample_motions_and_linked_from_the_index(test_workflow):
    """Every simplified estimate against the exact answers on pyslammer's 18 motions: the rigid D_n of the Jibson
    table reused, the coupled D at every T_s, the summary's counts from those rows; a page and an index section."""
    from stickslip.estimates.registry import AFTER_SLAMMER, METHODS

    study = test_workflow / "collections" / "pyslammer"
    settings = project_config()["estimates"]
    document = json.loads((study / "estimates_study.json").read_text(encoding="utf-8"))
    assert document["collection"]["kind"] == "pyslammer" and document["collection"]["records_solved"] == 18
    summary = read_csv_rows(study / "estimates_summary.csv")
    studied = {name: entry for name, entry in METHODS.items() if name not in AFTER_SLAMMER}  # SLAMMER's fourteen
    flexible = {name for name, entry in studied.items() if entry.kind == "flexible"}
    assert {(row["method"], float(row["site_period"])) for row in summary} == (
        {(name, 0.0) for name, entry in studied.items() if entry.kind == "rigid"} | {("bray_travasarou_2007", 0.0)}
        | {(name, period) for name in flexible for period in settings["site_periods"]})
    jibson = read_csv_rows(study / "jibson2007_displacements.csv")
    for ky in settings["ky"]:
        at = [row for row in jibson if float(row["ky"]) == ky]
        zeros = sum(float(row["newmark_displacement"]) == 0.0 for row in at) / len(at)
        row = next(row for row in summary if row["method"] == "jibson_2007_pga" and float(row["ky"]) == ky)
        assert int(row["rows"]) == len(at) == 36 and float(row["observed_zero_share"]) == pytest.approx(zeros)
        assert float(row["estimated_zero_share"]) == pytest.approx(
            sum(ky * 9.81 >= float(jib["pga"]) for jib in at) / len(at))
    coupled = [row for path in sorted((study / "estimates").glob("*.csv")) for row in read_csv_rows(path)]
    assert len(coupled) == 18 * len(settings["site_periods"]) * len(settings["ky"]) * 2
    reports = test_workflow.parent / "reports"
    section = (reports / "index.html").read_text(encoding="utf-8").split('<h1 id="estimates">')[1]
    assert 'href="html/estimates.html"' in section and "on the 18 records (17 events)" in section
    page = (reports / "html" / "estimates.html").read_text(encoding="utf-8")
    assert "hl-ipython3" not in page and "Which estimate to trust where" in page
    for name in ("estimates_bias", "estimates_scatter", "estimates_zeros", "estimates_exceedance"):
        assert (reports / "figures" / "estimates" / f"{name}.png").stat().st_size > 8_000, name


def test_the_planar_target_on_the_18_single_components_says_there_is_no_pair_and_renders_its_page(test_workflow):
    """pyslammer's sample motions are one component each: no pair, no sweep job; every table, the page and the
    index section say so, each motion listed with its reason; no pair is ever made up."""
    planar = test_workflow / "collections" / "pyslammer" / "planar"
    summary = json.loads((planar / "summary.json").read_text(encoding="utf-8"))
    assert summary["pairs_formed"] == 0 and summary["unpaired"] == {"single": 18}
    assert summary["status"].startswith("no pair: none of the 18 records")
    assert not (planar / "sweeps").exists()
    unpaired = read_csv_rows(planar / "unpaired.csv")
    assert len(unpaired) == 18 and all(row["group"] == "single" and row["reason"] for row in unpaired)
    assert read_csv_rows(planar / "pair_results.csv") == []
    reports = test_workflow.parent / "reports"
    page = (reports / "html" / "planar_study.html").read_text(encoding="utf-8")
    assert "hl-ipython3" not in page and "No pair: none of the 18 records" in page
    # every figure is written (the workflow declares it), and the page says in one sentence why none is drawn
    assert "<img" not in page and page.count("<p>Not drawn: no station pair slides in the plane.</p>") >= 5
    assert "STICKSLIP_SLAMMER_DIR" in page
    for name in ("energy_curves", "ratio_distribution", "ratio_vs_mu", "ratio_vs_pga", "mu_max_2d_vs_1d",
                 "mu_max_vs_pga_rms", "design_chart"):
        assert (reports / "figures" / "planar" / f"{name}.png").read_bytes()[:4] == b"\x89PNG", name
    section = (reports / "index.html").read_text(encoding="utf-8").split('<h1 id="planar">')[1].split("<h1")[0]
    assert 'href="html/planar_study.html"' in section and "18 records left unpaired" in section


def test_the_codes_against_the_exact_study_is_planned_per_chunk_of_pairs_and_in_the_default_target(tmp_path):
    """Without pairs (pyslammer's single components) and without the three-component records: the three-component job
    (an empty table), the analysis and the page, no pair job; on the SLAMMER library's 258 near-fault pairs, one job
    per chunk of the planar study's pairs (130 a chunk), as many as its sweep jobs."""
    jobs = dry_run(tmp_path)
    assert jobs["code_exact_three_component"] == 1 and jobs["analyse_code_vs_exact"] == 1
    assert jobs["render_code_vs_exact_report"] == 1 and "code_exact_pair_chunk" not in jobs
    slammer, workdir = require_shared_records() / "slammer", tmp_path / "slammer"
    workdir.mkdir()
    library = planned_jobs(snakemake(workdir, REPO_ROOT / "config" / "config.yaml", "--dry-run", slammer_dir=slammer))
    assert library["code_exact_pair_chunk"] == library["sweep_pair_chunk"] == 2
    assert library["analyse_code_vs_exact"] == 1


def test_the_structure_studies_are_planned_one_job_per_set_of_records_and_period(tmp_path):
    """Offline (pyslammer's 18 single components in 2 chunks, no three-component records): the isolation study's
    three-component jobs (empty cubes) and no pair job, its in-plane jobs per period and chunk of stations (empty
    cubes) and their tables, the in-plane pairs' tables (empty) and no in-plane pair job, the damper's paper and
    chunk jobs, each per period; on the SLAMMER library, a pair job per chunk of the planar study's pairs and period,
    one in the plane per share of the pairs and period, a damper job per chunk and period."""
    periods = len(project_config()["isolation_study"]["periods"])
    in_plane = project_config()["isolation_study"]["vertical"]
    damper_periods = len(project_config()["damper_study"]["periods"])
    jobs = dry_run(tmp_path)
    assert jobs["isolation_three_component"] == periods and "isolation_pair_chunk" not in jobs
    assert jobs["isolation_vertical_chunk"] == len(in_plane["periods"]) * in_plane["chunks"]
    assert jobs["tabulate_isolation_vertical"] == jobs["tabulate_isolation_plane_pairs"] == 1
    assert "isolation_plane_pair_chunk" not in jobs
    assert jobs["damper_paper_records"] == damper_periods and jobs["damper_collection_chunk"] == 2 * damper_periods
    assert jobs["render_isolation_report"] == jobs["render_damper_report"] == 1
    slammer, workdir = require_shared_records() / "slammer", tmp_path / "slammer"
    workdir.mkdir()
    library = planned_jobs(snakemake(workdir, REPO_ROOT / "config" / "config.yaml", "--dry-run", slammer_dir=slammer))
    assert library["isolation_pair_chunk"] == 2 * periods
    assert library["isolation_plane_pair_chunk"] == in_plane["chunks"] * len(in_plane["periods"])
    assert library["damper_collection_chunk"] == 3 * damper_periods


def test_the_paper_run_names_the_missing_records_on_the_index(paper_workflow):
    index = (paper_workflow.parent / "reports" / "index.html").read_text(encoding="utf-8")
    status = index.split("<h2>Notebooks")[0]
    assert "6 of 8 records found" in status and "2 missing" in status
    assert "mendoza_1985" in status and "parkfield_c02_360" in status and "How to obtain it" in status


def test_an_unknown_record_id_is_refused_before_any_job_runs(tmp_path):
    config = yaml.safe_load(TEST_CONFIG.read_text(encoding="utf-8"))
    config["report_records"] = ["cape_mendocino", "no_such_record"]
    configfile = tmp_path / "config.yaml"
    configfile.write_text(yaml.safe_dump(config), encoding="utf-8")
    result = snakemake(tmp_path, configfile, "--dry-run")
    assert result.returncode != 0
    message = result.stdout + result.stderr
    assert "report_records: unknown record id(s) 'no_such_record'" in message
    assert not (tmp_path / "results").exists()


def test_a_config_that_breaks_the_schema_is_refused(tmp_path):
    config = yaml.safe_load(TEST_CONFIG.read_text(encoding="utf-8"))
    config["block_mass"] = -5.1
    configfile = tmp_path / "config.yaml"
    configfile.write_text(yaml.safe_dump(config), encoding="utf-8")
    result = snakemake(tmp_path, configfile, "--dry-run")
    assert result.returncode != 0
    message = result.stdout + result.stderr
    assert "is less than or equal to the minimum of 0" in message and "block_mass" in message


def test_the_paper_run_counts_errata_and_missing_records_apart_from_failures(paper_workflow):
    index = (paper_workflow.parent / "reports" / "index.html").read_text(encoding="utf-8")
    total = re.search(r'<th class="text">all tables</th>((?:<th>\d+</th>)+)', index).group(1)
    within, beyond, not_comparable, erratum, cells = (int(n) for n in re.findall(r"<th>(\d+)</th>", total))
    assert within + beyond + not_comparable + erratum == cells
    assert erratum == 6  # Table 6's printed RMS cells of the six records we have (erratum E1)
    # Table 8 is the paper's Mendoza study: none of its cells can be compared, none fails
    assert re.search(r'<td class="text">table8</td><td>0</td><td>0</td><td>(\d+)</td><td>0</td><td>\1</td>', index)
    for figure in ("fig2_harmonic_regimes.png", "fig3_algorithm1_substitute.png", "fig16_friction_kobe.png",
                   "fig11_12_energy_kobe.png"):
        assert f'href="figures/{figure}"' in index
    assert "test data not published" in index and "Substitute scaling study" in index


def test_the_workflow_lints_clean_but_for_the_conda_environments():
    """`snakemake --lint`: the one finding left is the per-rule conda environment (the project's is environment.lock)."""
    result = subprocess.run([SNAKEMAKE, "--lint"], cwd=REPO_ROOT, capture_output=True, text=True, timeout=300)
    findings = [line.strip() for line in (result.stdout + result.stderr).splitlines() if line.startswith("    * ")]
    assert findings, result.stderr[-2000:]  # the conda lint is there, so the linter ran
    assert set(findings) == {"* Specify a conda environment or container for each rule.:"}
