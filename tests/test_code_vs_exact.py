"""The codes' equivalent-linear displacement from a record's own spectrum, beside the pendulum's exact peak displacement.

The code's D is the fixed point D = SD₅(T_eff)/B(β_eff) on the record's spectrum (checked against the oscillator
run at T_eff itself), found by the codes' iteration or, where that cycles, bracketed; the study's case table sets
it beside a direct solve of the pendulum; the bias table's statistics are checked by hand.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import stickslip
from stickslip.codes.damping import aashto_damping_coefficient, asce_damping_coefficient, eurocode_damping_correction
from stickslip.errors import StickslipError
from stickslip.plumbing.config import check_config_semantics
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record, RecordMeta
from stickslip.response_spectrum import relative_displacement
from stickslip.spectra import pair_spectra
from stickslip.studies.code_vs_exact.displacement import DEFAULT_PERIODS, CODES, RecordSpectrum, bracketed_fixed_point, \
    code_displacement, motion_displacement_spectra
from stickslip.studies.code_vs_exact.cases import CASE_COLUMNS, station_cases
from stickslip.studies.code_vs_exact.analysis import bias_rows

G = 9.81
#: Each code's damping reduction B(β), written out from the codes' own functions.
REDUCTION = {"asce7_22": asce_damping_coefficient, "aashto": aashto_damping_coefficient,
             "en1998_2": lambda beta: 1.0 / eurocode_damping_correction(beta)}


def component(acceleration: np.ndarray, name: str, dt: float = 0.01) -> Record:
    return Record(acceleration, dt, RecordMeta(record_id=f"SYN-{name}", event="synthetic", station="SYN",
                                               component=name))


def synthetic_pair(seconds: float = 12.0, dt: float = 0.01) -> RecordPair:
    """Two components of a decaying pulse-and-coda motion, 0.45 g and 0.3 g peaks, different periods."""
    t = np.arange(0.0, seconds, dt)
    envelope = (t / 2.0) * np.exp(1.0 - t / 2.0)
    first = 0.45 * G * envelope * (np.sin(2 * np.pi * 0.7 * t) + 0.3 * np.sin(2 * np.pi * 3.1 * t)) / 1.3
    second = 0.30 * G * envelope * (np.cos(2 * np.pi * 1.1 * t) + 0.4 * np.sin(2 * np.pi * 4.3 * t)) / 1.4
    return RecordPair(component(first, "000", dt), component(second, "090", dt))


@pytest.fixture(scope="module")
def pair() -> RecordPair:
    return synthetic_pair()


@pytest.mark.parametrize("code", list(CODES))
def test_the_code_displacement_is_the_fixed_point_on_the_records_own_spectrum(pair, code):
    """D = SD₅(T_eff)/B(β_eff) with T_eff and β_eff at D: on the interpolated spectrum to round-off, and on the
    oscillator run at T_eff itself to the interpolation's error (well under 1 %)."""
    spectra = motion_displacement_spectra(pair.first)
    for radius, mu in ((1.0, 0.03), (2.0, 0.06), (4.0, 0.12)):
        design = code_displacement(code, DEFAULT_PERIODS, spectra["psa"], radius, mu, G)
        assert design.note == "" and design.method in ("iteration", "bracketed")
        period = 2 * math.pi / math.sqrt(G * (1 / radius + mu / design.displacement))
        damping = 2 / math.pi * mu / (mu + design.displacement / radius)
        assert design.period == pytest.approx(period, rel=1e-12)
        assert design.damping == pytest.approx(damping, rel=1e-12)
        assert design.reduction == pytest.approx(REDUCTION[code](damping), rel=1e-12)
        interpolated = np.exp(np.interp(math.log(period), np.log(DEFAULT_PERIODS), np.log(spectra["psa"])))
        assert design.displacement == pytest.approx(interpolated / REDUCTION[code](damping), rel=1e-9)
        direct = np.max(np.abs(relative_displacement(pair.first.acceleration, pair.dt, period, 0.05)))
        assert design.displacement == pytest.approx(direct / REDUCTION[code](damping), rel=0.01)


def test_where_the_iteration_cycles_the_fixed_point_is_bracketed():
    """A spectrum falling as T⁻⁶ makes the map D ← f(D) steeper than −1 at its fixed point: the plain iteration
    cycles, and the bracketed root satisfies f(D) = D."""
    periods = np.geomspace(0.01, 6.0, 200)
    displacements = 0.05 * (periods / 1.5) ** -6.0
    displacements = np.minimum(displacements, 0.5)
    design = code_displacement("asce7_22", periods, displacements, 2.0, 0.05, G)
    assert design.method == "bracketed" and design.fixed_points >= 1
    sd = np.exp(np.interp(math.log(design.period), np.log(periods), np.log(displacements)))
    assert design.displacement == pytest.approx(sd / asce_damping_coefficient(design.damping), rel=1e-9)
    spectrum = RecordSpectrum(periods, displacements, G, asce_damping_coefficient)
    procedure = CODES["asce7_22"][0](spectrum)
    assert bracketed_fixed_point(procedure, 2.0, 0.05, G)[0] == pytest.approx(design.displacement, rel=1e-12)


def test_a_period_off_the_spectrums_grid_is_refused_not_extrapolated():
    spectrum = RecordSpectrum(np.array([0.5, 1.0, 2.0]), np.array([0.01, 0.02, 0.03]), G, asce_damping_coefficient)
    with pytest.raises(StickslipError, match=r"T_eff = 3 s is outside its periods 0.5-2 s"):
        spectrum([3.0])


def test_the_pair_spectrum_is_the_projects_rotd100_and_each_components_own(pair):
    ours = motion_displacement_spectra(pair, DEFAULT_PERIODS[::10])
    reference = pair_spectra(*pair.horizontal(), pair.dt, DEFAULT_PERIODS[::10])
    assert ours["rotd100"] == pytest.approx(reference.displacements["rotd100"], rel=1e-12)
    assert ours["second"] == pytest.approx(motion_displacement_spectra(pair.second, DEFAULT_PERIODS[::10])["psa"],
                                           rel=1e-12)


def test_the_case_table_sets_the_exact_peak_of_a_direct_solve_beside_the_codes(pair):
    radii, mu = [1.0, 3.0], [0.04, 0.1]
    station = {"library": "slammer", "station": "synthetic/SYN", "rupture_distance": 5.0, "pair": pair,
               "motions": {("first", "none"): pair.first, ("second", "none"): pair.second, ("plane", "none"): pair}}
    rows = station_cases([station], radii, mu, G, DEFAULT_PERIODS)
    assert len(rows) == 3 * len(radii) * len(mu) * len(CODES) and set(rows[0]) == set(CASE_COLUMNS)
    spectra = motion_displacement_spectra(pair)
    for direction, motion, spectrum in (("first", pair.first, spectra["first"]), ("plane", pair, spectra["rotd100"])):
        for radius in radii:
            for friction in mu:
                solved = stickslip.solve(motion, model="pendulum", radius=radius, mu=friction, g=G)
                chosen = [row for row in rows if row["direction"] == direction and row["radius"] == radius
                          and row["mu"] == friction]
                assert {row["code"] for row in chosen} == set(CODES)
                for row in chosen:
                    assert row["d_exact"] == pytest.approx(solved.scalars()["peak_relative_displacement"], rel=1e-9)
                    assert row["d_code"] == pytest.approx(
                        code_displacement(row["code"], DEFAULT_PERIODS, spectrum, radius, friction, G).displacement,
                        rel=1e-12)
                    assert row["ln_ratio"] == pytest.approx(math.log(row["d_exact"] / row["d_code"]), rel=1e-12)
                    assert row["d_code_over_r"] == pytest.approx(row["d_code"] / radius, rel=1e-12)
    assert {row["component"] for row in rows} == {"000", "090", "plane"}


def _row(code, ln_ratio, *, d_code=0.1, vertical="none", library="slammer", direction="first", distance="5.0",
         radius="2.0", mu="0.06"):
    exact = "0.0" if ln_ratio is None else repr((d_code or 0.1) * math.exp(ln_ratio))
    return {"library": library, "station": "s", "direction": direction, "vertical": vertical, "code": code,
            "rupture_distance": distance, "pulse": "unknown", "radius": radius, "mu": mu, "d_exact": exact,
            "d_code": "" if d_code is None else repr(d_code), "d_code_over_r": "" if d_code is None else repr(d_code / 2),
            "ln_ratio": "" if ln_ratio is None or d_code is None else repr(ln_ratio)}


def test_the_bias_table_gives_the_mean_sigma_and_unconservative_share_by_hand():
    logs = [0.3, -0.1, 0.05, 0.25]
    rows = [_row("aashto", value) for value in logs]
    rows += [_row("aashto", None), _row("aashto", 0.5, d_code=None)]  # no slip; no code D
    rows += [_row("aashto", 0.4, distance="35.0"), _row("aashto", 0.9, vertical="recorded", library="three_component")]
    rows += [_row("aashto", 0.1, library="three_component", distance="")]
    table = bias_rows(rows, 20.0, [0.025, 0.05, 0.1], 1.2)
    near = next(row for row in table if row["grouping"] == "distance" and row["group"] == "near-fault")
    assert near["n"] == 4 and near["bias"] == pytest.approx(np.mean(logs), rel=1e-12)
    assert near["sigma"] == pytest.approx(np.std(logs, ddof=1), rel=1e-12)
    assert near["rms"] == pytest.approx(math.sqrt(np.mean(np.square(logs))), rel=1e-12)
    # D_exact > 1.2 D_code: ln ratio above ln 1.2 = 0.182 (0.3 and 0.25), among the five with a code D
    assert near["unconservative_share"] == pytest.approx(2 / 5) and near["no_slip"] == 1
    assert near["no_code_displacement"] == 1
    pooled = next(row for row in table if row["grouping"] == "all")
    assert pooled["n"] == 6  # the vertical case is left out of every grouping but "vertical"
    groups = {(row["grouping"], row["group"]): row["n"] for row in table}
    assert groups[("distance", "far-field")] == 1 and groups[("distance", "unknown")] == 1
    assert groups[("vertical", "recorded")] == 1 and groups[("vertical", "none")] == 1
    assert groups[("d_code_over_r", "0.05-0.1")] == 6


def test_a_spectrum_grid_short_of_the_largest_free_swing_is_refused():
    config = {"gravity": G, "code_vs_exact": {"radii": [1.0, 4.0], "mu": [0.03, 0.06], "d_over_r_edges": [0.1],
                                              "spectrum_periods": {"shortest": 0.01, "longest": 3.0, "count": 50}}}
    with pytest.raises(StickslipError, match=r"code_vs_exact.spectrum_periods: 0.01-3 s must hold the free swing's "
                                             r"period 2 pi sqrt\(R/g\) = 4.012 s of the largest radius"):
        check_config_semantics(config, [])


def test_the_index_section_gives_each_codes_bias_and_share_or_says_what_is_missing(tmp_path):
    from stickslip.plumbing.files import write_csv_atomic
    from stickslip.studies.code_vs_exact.index import code_exact_section_html
    from stickslip.studies.code_vs_exact.analysis import BIAS_COLUMNS

    rows = [_row(code, value) for code in CODES for value in (0.3, -0.1, -0.4)]
    write_csv_atomic(tmp_path / "bias.csv", bias_rows(rows, 20.0, [0.1], 1.2), list(BIAS_COLUMNS))
    document = {"available": True, "pairs": 1, "three_component_stations": 0, "radii_m": [2.0], "mu": [0.06],
                "unconservative_factor": 1.2, "closest_code": "aashto", "far_field_status": "no far-field record",
                "pulse_status": "not known", "three_component_status": "not here: get them"}
    (tmp_path / "code_vs_exact.json").write_text(json.dumps(document), encoding="utf-8")
    section = code_exact_section_html(tmp_path / "bias.csv", tmp_path / "code_vs_exact.json", None, tmp_path)
    assert "ASCE 7-22 (B_M): bias of ln(D_exact/D_code) -0.07, σ 0.35 over 3 cases; D_exact &gt; 1.2·D_code in 33 %" \
        in section
    assert "Closest (smallest root mean square of the log ratio): AASHTO (B_L)." in section
    assert "no far-field record Pulse-like records: not known. not here: get them" in section
    document.update(available=False)
    (tmp_path / "code_vs_exact.json").write_text(json.dumps(document), encoding="utf-8")
    section = code_exact_section_html(tmp_path / "bias.csv", tmp_path / "code_vs_exact.json", None, tmp_path)
    assert "No case" in section and "not here: get them" in section and "bias of" not in section


def test_without_records_the_tables_are_empty_and_the_summary_says_what_is_missing(tmp_path):
    from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
    from stickslip.studies.code_vs_exact.cases import write_three_component_cases
    from stickslip.studies.code_vs_exact.analysis import write_code_vs_exact_analysis

    periods = {"shortest": 0.1, "longest": 6.0, "count": 60}
    cases = write_three_component_cases(tmp_path / "three_component.csv", [1.0], [0.06], periods, G, "up")
    assert cases.read_text(encoding="utf-8").strip() == ",".join(CASE_COLUMNS)
    write_csv_atomic(tmp_path / "pairs.csv", [], ["pair", "chunk", "status"])
    write_code_vs_exact_analysis([cases], tmp_path / "pairs.csv", tmp_path / "cases.csv", tmp_path / "bias.csv",
                                 tmp_path / "summary.json", 20.0, [0.1], 1.2, [1.0], [0.06],
                                 "The three-component records were not available (no folder configured): get them.")
    summary = json.loads((tmp_path / "summary.json").read_text(encoding="utf-8"))
    assert summary["available"] is False and summary["pairs"] == 0 and summary["closest_code"] is None
    assert summary["three_component_status"].startswith("The three-component records were not available")
    assert read_csv_rows(tmp_path / "bias.csv") == []
