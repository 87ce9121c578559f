"""Tests of stickslip.measures: analytic signals, identities, and the paper's Table 5 records."""

from __future__ import annotations

import json

import numpy as np
import pytest

from stickslip.errors import RecordError, StickslipError
from stickslip.measures import (
    MEASURE_UNITS,
    arias_intensity,
    husid_curve,
    husid_time,
    intensity_measures,
    rms_acceleration,
    significant_duration,
    significant_interval,
)
from stickslip.records.process import resample
from stickslip.records.readers import read_record
from stickslip.records.record import Record, RecordMeta
from stickslip.reference import paper_tables

G = 9.81


def make_record(acceleration, dt, source="synthetic.txt") -> Record:
    return Record(np.asarray(acceleration, dtype=float), dt, RecordMeta(record_id="synthetic", source=source))


# --- a sine over whole cycles -----------------------------------------------------

SINE_AMPLITUDE = 3.0  # m/s²
SINE_FREQUENCY = 2.0  # Hz
SINE_CYCLES = 10  # 20 half cycles: H = 0.05 and 0.95 fall on half-cycle boundaries


@pytest.fixture
def sine_record() -> Record:
    samples_per_cycle = 40
    dt = 1.0 / (SINE_FREQUENCY * samples_per_cycle)
    time = np.arange(SINE_CYCLES * samples_per_cycle + 1) * dt
    return make_record(SINE_AMPLITUDE * np.sin(2 * np.pi * SINE_FREQUENCY * time), dt)


def test_sine_arias_intensity_is_the_closed_form(sine_record):
    duration = SINE_CYCLES / SINE_FREQUENCY
    expected = np.pi / (2 * G) * SINE_AMPLITUDE**2 * duration / 2
    assert arias_intensity(sine_record.acceleration, sine_record.dt, G) == pytest.approx(expected, rel=1e-12)


def test_sine_significant_window_is_whole_half_cycles_with_rms_amplitude_over_root_two(sine_record):
    half_period = 0.5 / SINE_FREQUENCY
    measures = intensity_measures(sine_record)
    assert measures.t5 == pytest.approx(1 * half_period, abs=1e-12)
    assert measures.t95 == pytest.approx(19 * half_period, abs=1e-12)
    assert measures.significant_duration == pytest.approx(18 * half_period, abs=1e-12)
    assert measures.rms_acceleration == pytest.approx(SINE_AMPLITUDE / np.sqrt(2), rel=1e-12)


# --- a step: constant acceleration after t_s ---------------------------------------


STEP_DT, STEP_INDEX, STEP_END_INDEX = 0.01, 200, 1000  # the step at t_s = 2 s, the record ends at 10 s


def step_acceleration(level: float) -> np.ndarray:
    acceleration = np.zeros(STEP_END_INDEX + 1)
    acceleration[STEP_INDEX:] = level
    return acceleration


@pytest.mark.parametrize("fraction", [0.05, 0.3, 0.95])
def test_step_husid_is_linear_with_closed_form_crossings(fraction):
    dt, step_time, end_time = STEP_DT, STEP_INDEX * STEP_DT, STEP_END_INDEX * STEP_DT
    husid = husid_curve(step_acceleration(1.5), dt)
    # Trapezoid rule: the step sample adds half a step of a², then a² is constant,
    # so H rises linearly from t_s − dt/2 over a length L = t_end − t_s + dt/2.
    length = end_time - step_time + dt / 2
    assert np.all(husid[:STEP_INDEX] == 0.0)
    np.testing.assert_allclose(np.diff(husid[STEP_INDEX:]), dt / length, rtol=1e-12)
    expected = step_time - dt / 2 + fraction * length
    assert husid_time(husid, dt, fraction) == pytest.approx(expected, abs=1e-12)
    first_sample_at_or_after = np.ceil(expected / dt) * dt  # expected / dt is never an integer here
    assert husid_time(husid, dt, fraction, whole_sample=True) == pytest.approx(first_sample_at_or_after, abs=1e-12)


def test_step_significant_duration_closed_form():
    dt, step_time, end_time = STEP_DT, STEP_INDEX * STEP_DT, STEP_END_INDEX * STEP_DT
    acceleration = step_acceleration(-4.0)
    expected = 0.9 * (end_time - step_time + dt / 2)
    assert significant_duration(acceleration, dt) == pytest.approx(expected, abs=1e-12)
    t5, t95 = significant_interval(acceleration, dt)
    assert t5 == pytest.approx(step_time - dt / 2 + 0.05 * (end_time - step_time + dt / 2), abs=1e-12)
    assert t95 - t5 == pytest.approx(expected, abs=1e-12)


# --- identities ---------------------------------------------------------------------


@pytest.fixture
def random_record() -> Record:
    rng = np.random.default_rng(7)
    envelope = np.exp(-(((np.arange(3000) * 0.01) - 12.0) ** 2) / 20.0)
    return make_record(rng.normal(0.0, 3.0, 3000) * envelope, 0.01)


def test_rms_identity_holds_to_round_off(random_record):
    measures = intensity_measures(random_record)
    left = measures.rms_acceleration**2 * measures.significant_duration
    right = (2 * G / np.pi) * 0.9 * measures.arias_intensity
    assert left == pytest.approx(right, rel=1e-12)


def test_rms_over_the_whole_record_is_the_arias_average(random_record):
    record = random_record
    whole = rms_acceleration(record.acceleration, record.dt, 0.0, record.duration)
    expected = np.sqrt(2 * G / np.pi * arias_intensity(record.acceleration, record.dt, G) / record.duration)
    assert whole == pytest.approx(expected, rel=1e-12)


def test_whole_sample_times_are_samples_bracketing_the_interpolated_ones(random_record):
    measures = intensity_measures(random_record)
    dt = random_record.dt
    husid = measures.husid
    for fraction, interpolated in ((0.05, measures.t5), (0.95, measures.t95)):
        sample_time = husid_time(husid, dt, fraction, whole_sample=True)
        index = round(sample_time / dt)
        assert husid[index] >= fraction > husid[index - 1]
        assert sample_time - dt < interpolated <= sample_time
    assert abs(measures.significant_duration_samples - measures.significant_duration) < dt


def test_constant_acceleration_pgv_and_pgd_are_exact():
    level, dt = 0.8, 0.02
    record = make_record(np.full(501, level), dt)
    measures = intensity_measures(record)
    assert measures.pgv == pytest.approx(level * record.duration, rel=1e-12)
    assert measures.pgd == pytest.approx(level * record.duration**2 / 2, rel=1e-12)
    assert measures.pga == level


def test_arias_intensity_scales_with_gravity(random_record):
    record = random_record
    ratio = arias_intensity(record.acceleration, record.dt, 9.81) / arias_intensity(record.acceleration, record.dt, 9.80665)
    assert ratio == pytest.approx(9.80665 / 9.81, rel=1e-14)


def test_resampling_keeps_pga_and_original_samples_but_moves_arias_slightly(random_record):
    fine = resample(random_record, random_record.dt / 7)
    coarse_measures, fine_measures = intensity_measures(random_record), intensity_measures(fine)
    assert fine_measures.pga == pytest.approx(coarse_measures.pga, rel=1e-12)
    np.testing.assert_allclose(fine.acceleration[::7], random_record.acceleration, atol=1e-12)
    # The trapezoid rule on a² is not exact for a linear a: the fine grid integrates
    # (a_i² + a_i·a_{i+1} + a_{i+1}²)/3 instead of (a_i² + a_{i+1}²)/2 per step, which
    # is smaller (never larger) by (a_{i+1} − a_i)²/6.
    exact_square_integral = np.sum(
        random_record.dt * (random_record.acceleration[:-1] ** 2 + random_record.acceleration[:-1] * random_record.acceleration[1:] + random_record.acceleration[1:] ** 2) / 3
    )
    exact_arias = np.pi / (2 * G) * exact_square_integral
    assert fine_measures.arias_intensity < coarse_measures.arias_intensity
    assert abs(fine_measures.arias_intensity - exact_arias) < abs(coarse_measures.arias_intensity - exact_arias)


def test_as_dict_has_the_scalar_measures_only(random_record):
    values = intensity_measures(random_record).as_dict()
    assert set(values) == {
        "pga", "pgv", "pgd", "arias_intensity", "t5", "t95", "significant_duration",
        "significant_duration_samples", "rms_acceleration", "mean_period", "npts", "dt", "duration",
    }
    assert values["npts"] == 3000 and values["duration"] == pytest.approx(29.99)


# --- bad input --------------------------------------------------------------------


def test_silent_record_is_an_error_naming_the_file():
    with pytest.raises(RecordError, match=r"^quiet\.at2: every acceleration is zero"):
        intensity_measures(make_record(np.zeros(50), 0.01, source="quiet.at2"))


def test_single_sample_record_is_an_error():
    with pytest.raises(RecordError, match="at least 2"):
        intensity_measures(make_record([1.0], 0.01))


def test_bad_gravity_is_an_error(random_record):
    with pytest.raises(StickslipError, match="gravity g must be a positive finite number"):
        intensity_measures(random_record, g=0.0)


# --- the paper's records (Table 5) --------------------------------------------------

#: The file used for each available paper record, and its time step [s] when the file has none.
PAPER_FILES = {
    "cape_mendocino": ("SLAMMER_Cape_Mendocino_1992_PET-090.txt", 0.02),
    "chichi_chy080n": ("CHY080-N.AT2", None),  # dt from the AT2 header
    "coyote_g06_230": ("SLAMMER_Coyote_Lake_1979_G06-230.txt", 0.005),
    "coyote_g06_320": ("SLAMMER_Coyote_Lake_1979_G06-320.txt", 0.005),
    "kobe_kjm090": ("SLAMMER_Kobe_1995_KJM-090.txt", 0.02),
    "northridge_nwh090": ("SLAMMER_Northridge_1994_NWH-090.txt", 0.02),
}


def load_paper_record(directory, record_id) -> Record:
    file_name, dt = PAPER_FILES[record_id]
    return read_record(directory / file_name, dt=dt)


@pytest.fixture(scope="module")
def paper_measures(request):
    directory = request.getfixturevalue("paper_records_dir")
    return {record_id: intensity_measures(load_paper_record(directory, record_id)) for record_id in PAPER_FILES}


@pytest.mark.parametrize("record_id", sorted(PAPER_FILES))
def test_paper_records_match_table5(paper_measures, record_id):
    paper = paper_tables()["table5_records"]["rows"][record_id]
    measures = paper_measures[record_id]
    assert measures.arias_intensity == pytest.approx(paper["arias_intensity"], rel=0.01)
    assert measures.significant_duration == pytest.approx(paper["significant_duration"], abs=0.15)
    assert measures.dt == paper["dt"]


def test_whole_sample_convention_gives_the_papers_kobe_duration(paper_measures):
    paper = paper_tables()["table5_records"]["rows"]["kobe_kjm090"]
    assert paper_measures["kobe_kjm090"].significant_duration_samples == pytest.approx(paper["significant_duration"], abs=1e-9)


# --- the command line: stickslip measures ------------------------------------------

JSON_KEYS = {"pga", "pgv", "pgd", "arias_intensity", "t5", "t95", "significant_duration", "rms_acceleration", "mean_period", "npts", "dt", "duration"}


@pytest.fixture
def two_column_file(tmp_path):
    """A hand-made time [s] / acceleration [cm/s²] file: one sine cycle of 200 cm/s² at 1 Hz."""
    time = np.arange(101) * 0.01
    path = tmp_path / "sine_cm.txt"
    np.savetxt(path, np.column_stack([time, 200.0 * np.sin(2 * np.pi * time)]), fmt="%.10f")
    return path


def test_cli_json_prints_exactly_the_si_measures(run_cli, two_column_file):
    code, out, err = run_cli("measures", two_column_file, "--units", "cm/s2", "--json")
    assert code == 0 and err == ""
    values = json.loads(out)
    assert values.pop("units") == {"g": "m s-2", **{key: MEASURE_UNITS[key] for key in JSON_KEYS}}
    assert values.pop("record") == "sine_cm" and values.pop("source") == str(two_column_file)
    assert values.pop("g") == 9.81 and values.pop("vertical") is None
    assert values.pop("read") == {"units": "cm/s2"}  # how the file was read, as given
    assert set(values) == set(JSON_KEYS)
    expected = intensity_measures(read_record(two_column_file, units="cm/s2")).as_dict()
    assert values == {key: pytest.approx(expected[key], rel=1e-12) for key in JSON_KEYS}
    assert values["pga"] == pytest.approx(2.0, rel=1e-6)  # 200 cm/s² in m/s²
    assert values["npts"] == 101 and values["dt"] == pytest.approx(0.01)


def test_cli_table_lists_every_measure_with_units(run_cli, two_column_file):
    code, out, _ = run_cli("measures", two_column_file, "--units", "cm/s2")
    assert code == 0
    assert "Arias intensity" in out and "m/s2" in out  # the source file's units, in the header
    arias_line = next(line for line in out.splitlines() if line.startswith("Arias intensity"))
    value, units = arias_line.removeprefix("Arias intensity").split(maxsplit=1)
    assert float(value) == pytest.approx(np.pi / (2 * G) * 2.0**2 * 1.0 / 2, rel=1e-5)
    assert units == "m/s"  # as people write it; the JSON keeps the UDUNITS spelling
    assert next(line for line in out.splitlines() if line.startswith("number of samples")).split()[-2:] == ["101", "-"]


def test_cli_missing_file_is_one_line_on_stderr(run_cli, tmp_path):
    missing = tmp_path / "nowhere.AT2"
    code, out, err = run_cli("measures", missing, "--json")
    assert code == 2 and out == ""
    assert err.count("\n") == 1
    assert err.startswith("stickslip: error: ") and str(missing) in err and "file not found" in err


def test_cli_silent_record_is_one_line_on_stderr(run_cli, tmp_path):
    silent = tmp_path / "silent.txt"
    silent.write_text("0.0 0.0\n0.01 0.0\n0.02 0.0\n", encoding="utf-8")
    code, out, err = run_cli("measures", silent, "--units", "g")
    assert code == 2 and out == ""
    assert err == f"stickslip: error: {silent}: every acceleration is zero: the file holds no ground motion\n"


def test_cli_on_a_shared_slammer_file_takes_dt_from_the_manifest(run_cli, paper_records_dir):
    code, out, _ = run_cli("measures", paper_records_dir / "SLAMMER_Kobe_1995_KJM-090.txt", "--json")
    assert code == 0
    values = json.loads(out)
    assert values["dt"] == 0.02 and values["npts"] == 2232
    assert values["arias_intensity"] == pytest.approx(paper_tables()["table5_records"]["rows"]["kobe_kjm090"]["arias_intensity"], rel=0.01)


def test_cli_negative_dt_is_one_line_on_stderr(run_cli, tmp_path):
    one_column = tmp_path / "one_column.txt"
    one_column.write_text("0.1\n-0.2\n0.3\n", encoding="utf-8")
    code, out, err = run_cli("measures", one_column, "--dt", "-0.01")
    assert code == 2 and out == ""
    assert err == f"stickslip: error: {one_column}: time step must be positive, got dt = -0.01 s\n"
