"""The damper study's steps on three of the paper's records: a flat friction damper on a one-story building, the μ
of most E_df against the μ of least drift.

The paper job's step on stored records (one of them missing), a collection chunk's step on a record store (one row
not read), the gathering and the tables; μ_Edf is the grid's argmax of E_df and μ_drift its argmin of the drift; a
damper that never slides is the building with its mass attached; the optima and the statistics by hand.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from conftest import read_shared_paper_record
from stickslip.collections.store import StoredRecord, write_record_store
from stickslip.errors import StickslipError
from stickslip.plumbing.files import read_csv_rows
from stickslip.records.netcdf import write_missing_record, write_record
from stickslip.response_spectrum import relative_displacement
from stickslip.solvers.structure.linear_response import linear_history
from stickslip.studies.damper.index import damper_section_html
from stickslip.solvers.structure.friction_linked import friction_linked_sweep, search_points
from stickslip.studies.damper.response import STRUCTURE_MASS, bare_peaks, building, damper_system
from stickslip.studies.damper.sweep import (gather_damper_study, optima, study_settings, write_collection_chunk_cube,
                                            write_paper_cube)
from stickslip.studies.damper.tables import summary_rows, write_damper_tables
from stickslip.sweeps import read_cube

G = 9.81
#: One mass ratio, two periods, friction levels that hold the optima and end where the damper never slides (μg five
#: times the bare floor's peak acceleration).
SETTINGS = {"mass_ratios": [0.05], "periods": [0.5, 1.0], "levels": [0.02, 0.05, 0.1, 0.2, 0.4, 5.0],
            "damping_ratio": 0.02}
PAPER_FILES = {"coyote_g06_230": "SLAMMER_Coyote_Lake_1979_G06-230.txt",
               "coyote_g06_320": "SLAMMER_Coyote_Lake_1979_G06-320.txt"}
COLLECTION_FILE = "SLAMMER_Cape_Mendocino_1992_PET-090.txt"


@pytest.fixture(scope="module")
def damper_study(paper_records_dir, tmp_path_factory):
    """The paper job on two stored records and one missing, a chunk of one record (and one not read), gathered."""
    folder = tmp_path_factory.mktemp("damper")
    records = {name: read_shared_paper_record(paper_records_dir, file) for name, file in PAPER_FILES.items()}
    for name, record in records.items():
        write_record(record, folder / f"{name}.nc")
    write_missing_record("mendoza_1985", "not in the records folder", folder / "mendoza_1985.nc")
    paper = [folder / f"{name}.nc" for name in (*PAPER_FILES, "mendoza_1985")]
    for period in SETTINGS["periods"]:
        write_paper_cube(paper, folder / f"paper_{period}.nc", SETTINGS, period, G)
    cape = read_shared_paper_record(paper_records_dir, COLLECTION_FILE)
    write_record_store([StoredRecord("PET-090", cape, "ok"), StoredRecord("XYZ-000", None, "rejected", "bad file")],
                       folder / "store.nc")
    for period in SETTINGS["periods"]:
        write_collection_chunk_cube(folder / "store.nc", folder / f"chunk_{period}.nc", "slammer", SETTINGS, period, G)
    cubes = [folder / f"{name}_{period}.nc" for name in ("paper", "chunk") for period in SETTINGS["periods"]]
    gather_damper_study(cubes, folder / "damper.nc", len(SETTINGS["periods"]))
    paths = [folder / name for name in ("cases.csv", "summary.csv", "curves.csv", "study.json")]
    write_damper_tables(*paths, folder / "damper.nc", SETTINGS, "slammer")
    return {"records": {**records, "PET-090": cape}, "cube": read_cube(folder / "damper.nc"),
            "cases": read_csv_rows(paths[0]), "summary": read_csv_rows(paths[1]), "curves": read_csv_rows(paths[2]),
            "document": json.loads(paths[3].read_text()), "folder": folder}


def test_mu_energy_is_the_grid_argmax_of_edf_and_mu_drift_the_argmin_of_the_drift(damper_study):
    cube = damper_study["cube"]
    mu = np.broadcast_to(cube.mu.values[:, None, :, :], cube.energy_dissipated.shape)
    energy, drift = cube.energy_dissipated.values, cube.peak_drift.values
    assert np.all(energy[..., 0] > 0.0) and np.all(energy[..., -1] == 0.0)
    at = lambda index: np.take_along_axis(mu, index[..., None], axis=-1)[..., 0]  # noqa: E731
    assert np.array_equal(cube.mu_energy.values, at(np.argmax(energy, axis=-1)))
    assert np.array_equal(cube.mu_drift.values, at(np.argmin(drift, axis=-1)))
    assert np.allclose(cube.mu_ratio, cube.mu_energy / cube.mu_drift, rtol=1e-15)
    reduction = 1.0 - drift / cube.bare_peak_drift.values[:, None, :, None]
    assert np.allclose(cube.drift_reduction, reduction, rtol=1e-15)
    given_up = cube.drift_reduction_at_mu_drift - cube.drift_reduction_at_mu_energy
    assert np.allclose(cube.reduction_given_up, given_up, rtol=0, atol=1e-15)
    assert np.all(cube.reduction_given_up.values >= 0.0)
    # each record's grid is the levels times its bare floor's peak acceleration in g
    levels = np.asarray(SETTINGS["levels"])
    assert np.allclose(cube.mu, levels * cube.bare_peak_floor_acceleration.values[..., None] / G, rtol=1e-15)


def test_a_record_scaled_to_its_friction_levels_is_the_record_at_its_own_mu(damper_study):
    """The records are solved scaled to a bare peak floor acceleration of g at μ = η; scaled back, the drift and
    E_df are those of the record itself at μ = η·PFA/g (to 1e-9)."""
    record = damper_study["records"]["coyote_g06_320"]
    cube = damper_study["cube"].sel(record="coyote_g06_320", period=1.0, mass_ratio=0.05)
    mu = cube.mu.values[:-1]
    direct = friction_linked_sweep(damper_system(1.0, 0.05, 0.02, G), [record.acceleration], [record.dt], mu,
                                   [[1.0, 0.0, 0.0, 0.0, 0.0, 0.0]])
    assert np.allclose(cube.energy_dissipated.values[:-1], direct.energy_dissipated[0], rtol=1e-9, atol=0)
    assert np.allclose(cube.peak_drift.values[:-1], direct.peaks[0, :, 0], rtol=1e-9, atol=0)


def resampled_history(system, mass_matrix, record):
    """The linear structure of ``mass_matrix`` with ``system``'s building under ``record``, at the samples and the
    scheme's search points between them: the first-order hold on the record resampled there."""
    points = search_points(np.stack(system.phase_matrices()), record.dt)
    fine = np.interp(np.arange((record.npts - 1) * points + 1) / points, np.arange(record.npts), record.acceleration)
    size = mass_matrix.shape[0]
    return linear_history(mass_matrix, system.damping_matrix[:size, :size], system.stiffness_matrix[:size, :size],
                          np.ones(size), fine, record.dt / points)


def test_a_damper_that_never_slides_is_the_building_with_its_mass_attached(damper_study):
    """At the level 5 the damper holds: no energy dissipated, and the drift is that of the building of mass
    m_s + m_d."""
    cube = damper_study["cube"].sel(level=5.0, mass_ratio=0.05)
    assert np.all(cube.energy_dissipated.values == 0.0)
    for index, name in enumerate(cube.record.values):
        record = damper_study["records"][str(name)]
        for p, period in enumerate(cube.period.values):
            system = damper_system(float(period), 0.05, 0.02, G)
            attached = resampled_history(system, np.array([[STRUCTURE_MASS * 1.05]]), record)
            expected = np.abs(attached.displacement[:, 0]).max()
            assert cube.peak_drift.values[index, p] == pytest.approx(expected, rel=1e-9), (name, period)


def test_the_bare_building_is_the_single_oscillator_at_the_same_instants_as_with_the_damper(damper_study):
    """A damper at μ = 0 exerts no force: the bare building's peak drift is the oscillator's, taken at the samples and
    the scheme's search points (the first-order hold on the record resampled there, to 1e-9)."""
    record = damper_study["records"]["coyote_g06_230"]
    history = resampled_history(damper_system(1.0, 1.0, 0.02, G), np.array([[STRUCTURE_MASS]]), record)
    bare = bare_peaks([record], 1.0, 0.02, G)
    assert bare.drift[0] == pytest.approx(np.abs(history.displacement).max(), rel=1e-9)
    assert bare.floor_acceleration[0] == pytest.approx(np.abs(history.absolute_acceleration).max(), rel=1e-9)
    at_samples = np.abs(relative_displacement(record.acceleration, record.dt, 1.0, 0.02)).max()
    assert at_samples <= bare.drift[0] <= at_samples * (1 + 1e-3)
    assert building(1.0, 0.02).total_mass == STRUCTURE_MASS


def test_the_records_are_the_paper_and_the_collection_and_what_is_missing_is_named(damper_study):
    cube = damper_study["cube"]
    assert list(cube.record.values) == ["coyote_g06_230", "coyote_g06_320", "PET-090"]
    assert list(cube.library.values) == ["paper", "paper", "slammer"]
    left_out = cube.attrs["left_out"]
    assert "mendoza_1985" in left_out and "not in the records folder" in left_out
    assert "XYZ-000: rejected: bad file" in left_out
    assert cube.energy_dissipated.attrs["units"] == "J" and cube.peak_drift.attrs["units"] == "m"
    assert cube.mu_ratio.attrs["units"] == "1" and cube.period.attrs["units"] == "s"
    document = damper_study["document"]
    assert document["records"] == {"paper": 2, "slammer": 1} and document["pooled"] == "all"
    assert document["left_out"] == left_out


def test_the_summary_is_the_median_and_the_84th_percentile_over_the_records(damper_study):
    cases = damper_study["cases"]
    assert len(cases) == 3 * 1 * 2
    for row in damper_study["summary"]:
        values = np.array([float(case[row["quantity"]]) for case in cases
                           if (case["mass_ratio"], case["period"]) == (row["mass_ratio"], row["period"])
                           and row["library"] in ("all", case["library"])])
        assert int(row["records"]) == values.size
        assert float(row["median"]) == pytest.approx(np.median(values), rel=1e-12)
        assert float(row["p84"]) == pytest.approx(np.percentile(values, 84), rel=1e-12)
    curves = [row for row in damper_study["curves"] if row["library"] == "all"]
    assert sorted({float(row["level"]) for row in curves}) == SETTINGS["levels"]
    assert len(curves) == 1 * 2 * 6 and all(int(row["records"]) == 3 for row in curves)
    assert all(float(row["p16"]) <= float(row["median"]) <= float(row["p84"]) for row in curves)


def test_the_optima_by_hand():
    mu = np.array([0.01, 0.02, 0.05, 0.1])
    energy = np.array([[1.0, 3.0, 2.0, 0.5], [0.0, 0.0, 0.0, 0.0], [0.1, 0.2, 0.3, 0.4]])
    drift = np.array([[0.10, 0.08, 0.06, 0.09], [0.05, 0.05, 0.05, 0.05], [0.2, 0.1, 0.15, 0.16]])
    found = optima(energy, drift, np.array([0.12, 0.05, 0.2]), mu)
    assert found["mu_energy"][0] == 0.02 and found["mu_drift"][0] == 0.05
    assert found["mu_ratio"][0] == pytest.approx(0.4, rel=1e-15)
    assert found["drift_reduction_at_mu_energy"][0] == pytest.approx(1 - 0.08 / 0.12, rel=1e-15)
    assert found["drift_reduction_at_mu_drift"][0] == pytest.approx(0.5, rel=1e-15)
    assert found["reduction_given_up"][0] == pytest.approx(0.5 - (1 - 0.08 / 0.12), rel=1e-14)
    assert found["mu_energy_at_grid_edge"][0] == 0.0 and found["mu_drift_at_grid_edge"][0] == 0.0
    # a damper that never slides on the grid has no mu_energy
    assert math.isnan(found["mu_energy"][1]) and math.isnan(found["mu_ratio"][1])
    assert math.isnan(found["reduction_given_up"][1]) and math.isnan(found["mu_energy_at_grid_edge"][1])
    # optima at the grid's ends are flagged as bounds
    assert found["mu_energy"][2] == 0.1 and found["mu_energy_at_grid_edge"][2] == 1.0
    assert found["mu_drift"][2] == 0.02 and found["mu_drift_at_grid_edge"][2] == 0.0


def test_the_summary_leaves_out_cases_without_a_value():
    rows = [{"library": "paper", "record": name, "mass_ratio": "0.05", "period": "1", "mu_ratio": value,
             "mu_energy": value, "mu_drift": 0.1, "drift_reduction_at_mu_energy": 0.1,
             "drift_reduction_at_mu_drift": 0.2, "reduction_given_up": 0.1}
            for name, value in (("A", 1.0), ("B", math.nan), ("C", 3.0))]
    summary = {row["quantity"]: row for row in summary_rows(rows)}
    assert summary["mu_ratio"]["records"] == 2 and summary["mu_ratio"]["median"] == 2.0
    assert summary["mu_drift"]["records"] == 3


def test_the_index_section_gives_the_ratio_and_the_reduction_given_up(damper_study):
    html = damper_section_html(damper_study["folder"] / "study.json", "reports/html/damper_study.html", "reports")
    assert "on 2 paper, 1 slammer records" in html and "m_d/m_s = 0.05, T = 0.5 s: μ_Edf/μ_drift" in html
    assert 'href="html/damper_study.html"' in html


def test_a_grid_out_of_order_is_one_line_naming_its_key():
    with pytest.raises(StickslipError, match=r"^damper_study.mass_ratios: values must be strictly increasing"):
        study_settings({**SETTINGS, "mass_ratios": [0.1, 0.02]})
