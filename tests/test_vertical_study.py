"""The vertical ground motion on sliders and pendulums, the workflow's study: its records, variants, tables and page.

The table arithmetic on small hand-made rows; the records checked by their SHA-256 on small hand-made AT2 files;
the reversed vertical; the workflow's target on the shared three-component records (skipped without them) and
without them (the page's one sentence).
"""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest
import yaml

from conftest import PROJECT_CONFIG, require_shared_records, snakemake
from stickslip.errors import StickslipError
from stickslip.records.pair import RecordPair
from stickslip.records.readers import sha256_hex
from stickslip.records.record import Record, RecordMeta
from stickslip.records.vertical import WithVertical
from stickslip.studies.vertical import effect as vertical_effect, records as vertical_records
from stickslip.studies.vertical.effect import change_rows, liftoff_rows, summary_rows
from stickslip.studies.vertical.records import station_motion, stations, store_three_component


def case(direction, radius, vertical, record, **values) -> dict:
    """A row of the case table with the values given (the rest 0)."""
    return {"direction": direction, "radius": radius, "vertical": vertical, "record": record, "vertical_sense": "",
            "optimum_status": "ok", **{name: 0.0 for name in vertical_effect.CASE_COLUMNS}, **values}


def test_the_changes_are_ratios_and_differences_against_the_same_case_without_the_vertical():
    cases = [
        case("H1", "2", "none", "A", energy_dissipated_max=4.0, mu_max=0.05, peak_relative_displacement_at_mu_max=0.2,
             residual_displacement_at_mu_max=-0.01, peak_base_shear_at_mu_max=0.15, peak_base_shear_at_reference=0.1),
        case("H1", "2", "recorded", "A", energy_dissipated_max=5.0, mu_max=0.045,
             peak_relative_displacement_at_mu_max=0.25, residual_displacement_at_mu_max=0.02,
             peak_base_shear_at_mu_max=0.3, peak_base_shear_at_reference=0.13),
        case("H1", "2", "reversed", "A", energy_dissipated_max=3.0, mu_max=0.06, peak_relative_displacement_at_mu_max=0.1,
             residual_displacement_at_mu_max=-0.03, peak_base_shear_at_mu_max=0.15, peak_base_shear_at_reference=0.2),
        # another radius of the same station: compared with its own case without the vertical
        case("H1", "inf", "none", "A", energy_dissipated_max=2.0),
        case("H1", "inf", "recorded", "A", energy_dissipated_max=1.0),
    ]
    rows = {(row["radius"], row["vertical"]): row for row in change_rows(cases)}
    assert set(rows) == {("2", "recorded"), ("2", "reversed"), ("inf", "recorded")}
    recorded, reversed_ = rows["2", "recorded"], rows["2", "reversed"]
    assert recorded["energy_ratio"] == pytest.approx(1.25, rel=1e-15)
    assert recorded["mu_max_change"] == pytest.approx(-0.005, abs=1e-15)
    assert recorded["peak_displacement_ratio"] == pytest.approx(1.25, rel=1e-15)
    assert recorded["residual_displacement_change"] == pytest.approx(0.03, abs=1e-15)  # m
    assert recorded["base_shear_ratio"] == pytest.approx(2.0, rel=1e-15)
    assert recorded["base_shear_ratio_at_reference"] == pytest.approx(1.3, rel=1e-15)
    assert reversed_["energy_ratio"] == pytest.approx(0.75, rel=1e-15)
    assert reversed_["mu_max_change"] == pytest.approx(0.01, abs=1e-15)
    assert reversed_["residual_displacement_change"] == pytest.approx(-0.02, abs=1e-15)
    assert rows["inf", "recorded"]["energy_ratio"] == pytest.approx(0.5, rel=1e-15)
    # a ratio over a case that does not slide (0) is left empty, a difference is not
    assert math.isnan(rows["inf", "recorded"]["peak_displacement_ratio"])
    assert rows["inf", "recorded"]["residual_displacement_change"] == 0.0


def test_a_case_with_the_vertical_and_none_without_is_an_error():
    with pytest.raises(ValueError, match="no case without the vertical for H1, 2, A"):
        change_rows([case("H1", "2", "recorded", "A")])


def test_the_summary_gives_the_median_and_range_over_the_stations_per_direction_and_pooled():
    changes = [{"direction": direction, "radius": "1", "vertical": "recorded", "record": record,
                **{name: math.nan for name in vertical_effect.CHANGES}, "energy_ratio": value}
               for direction, record, value in (("H1", "A", 1.0), ("H1", "B", 1.2), ("H1", "C", 0.9),
                                                ("H2", "A", 2.0), ("H2", "B", math.nan))]
    rows = {(row["direction"], row["quantity"]): row for row in summary_rows(changes)}
    assert rows["H1", "energy_ratio"] == {"direction": "H1", "radius": "1", "vertical": "recorded",
                                               "quantity": "energy_ratio", "units": "1", "records": 3,
                                               "median": 1.0, "min": 0.9, "max": 1.2}
    assert (rows["H2", "energy_ratio"]["records"], rows["H2", "energy_ratio"]["median"]) == (1, 2.0)  # NaN left out
    pooled = rows["all", "energy_ratio"]
    assert (pooled["records"], pooled["median"], pooled["min"], pooled["max"]) == (4, 1.1, 0.9, 2.0)
    assert rows["H1", "residual_displacement_change"]["units"] == "m"
    assert rows["H1", "mu_max_change"]["records"] == 0 and math.isnan(rows["H1", "mu_max_change"]["median"])


def test_lift_off_is_read_once_per_station_and_variant_with_the_vertical():
    cases = [case(direction, radius, vertical, record, liftoff_time=0.1 if vertical == "reversed" else 0.0,
                  vertical_down_peak=1.2, vertical_pga=1.5)
             for direction in ("H1", "H2") for radius in ("inf", "1") for vertical in ("none", "recorded", "reversed")
             for record in ("A", "B")]
    rows = liftoff_rows(cases)
    assert [(row["record"], row["vertical"], row["liftoff_time"]) for row in rows] == [
        ("A", "recorded", 0.0), ("B", "recorded", 0.0), ("A", "reversed", 0.1), ("B", "reversed", 0.1)]


def station(vertical_label: str, npts=(400, 398, 401)) -> dict[str, Record]:
    """A station of three short components (the vertical labelled ``vertical_label``), of unequal lengths."""
    time = np.arange(max(npts)) * 0.01
    shapes = {"H1": np.sin(7.0 * time), "H2": np.cos(5.0 * time), "UP": np.sin(11.0 * time) + 0.3}
    return {component: Record(3.0 * shapes[component][:size], 0.01,
                              RecordMeta(record_id="S", station="Station S", event="Test Quake",
                                         component=vertical_label if component == "UP" else
                                         {"H1": "000", "H2": "090"}[component],
                                         source=f"S-{vertical_label if component == 'UP' else component}.AT2"))
            for component, size in zip(("H1", "H2", "UP"), npts)}


@pytest.mark.parametrize("label, sign", [("UP", 1.0), ("DWN", -1.0)])
def test_the_reversed_variant_reverses_the_vertical_as_recorded(label, sign):
    components = station(label)
    recorded = station_motion(components, "H1", "recorded")
    reversed_ = station_motion(components, "H1", "reversed")
    vertical = components["UP"].acceleration  # the longest component: nothing padded
    assert isinstance(recorded, WithVertical) and isinstance(reversed_, WithVertical)
    # as recorded: positive up, a DWN file turned; both padded to the longest component (401 samples)
    np.testing.assert_array_equal(recorded.vertical.acceleration, sign * vertical)
    np.testing.assert_array_equal(reversed_.vertical.acceleration, -sign * vertical)
    np.testing.assert_array_equal(reversed_.horizontal.acceleration, recorded.horizontal.acceleration)
    assert recorded.npts == 401 and recorded.horizontal.acceleration[400] == 0.0
    assert reversed_.sense == f"{recorded.sense}, then reversed"
    assert ("turned positive up" in recorded.sense) == (label == "DWN")


def test_without_the_vertical_the_motion_is_the_horizontal_component_alone_and_the_plane_is_the_pair():
    components = station("UP")
    alone = station_motion(components, "H2", "none")
    assert isinstance(alone, Record)
    np.testing.assert_array_equal(alone.acceleration[:398], components["H2"].acceleration)
    plane = station_motion(components, "plane", "recorded")
    assert isinstance(plane.horizontal, RecordPair) and plane.npts == 401


def test_a_vertical_whose_label_does_not_tell_its_sense_takes_the_configured_one():
    components = station("V1")
    with pytest.raises(StickslipError, match="do not say which way its positive axis points"):
        station_motion(components, "H1", "recorded")
    down = station_motion(components, "H1", "recorded", untold_positive="down")
    np.testing.assert_array_equal(down.vertical.acceleration[:401], -components["UP"].acceleration)
    assert down.sense == "positive down (as given), turned positive up"


def test_an_unknown_direction_or_variant_is_one_line_naming_the_setting():
    with pytest.raises(StickslipError, match=r"vertical_study.directions: 'H3' is not one of H1, H2, plane"):
        station_motion(station("UP"), "H3", "none")
    with pytest.raises(StickslipError, match=r"vertical_study.variants: 'up' is not one of none, recorded, reversed"):
        station_motion(station("UP"), "H1", "up")


def write_at2(path, station_name: str, component: str, values_g) -> bytes:
    """A PEER NGA-West2 AT2 file of ``values_g`` at dt = 0.01 s; returns its bytes."""
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD", f"Test Quake, 01/01/2000, {station_name}, {component}",
             "ACCELERATION TIME SERIES IN UNITS OF G", f"NPTS= {len(values_g)}, DT= .0100 SEC"]
    lines += ["  ".join(f"{value:.7E}" for value in values_g[i:i + 5]) for i in range(0, len(values_g), 5)]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n", encoding="ascii")
    return path.read_bytes()


def test_the_records_are_checked_by_their_sha256_and_a_station_with_a_bad_file_is_left_out(tmp_path, monkeypatch):
    time = np.arange(300) * 0.01
    manifest = []
    for name, labels in (("Good", ("000", "090", "UP")), ("Bad", ("000", "090", "DWN"))):
        for component, label, wave in zip(vertical_records.COMPONENTS, labels,
                                          (np.sin(6 * time), np.cos(4 * time), 0.2 * np.sin(9 * time))):
            path = tmp_path / "records" / name / f"{name}-{label}.AT2"
            data = write_at2(path, f"Station {name}", label, 0.3 * wave)
            manifest.append({"set": name, "component": component, "file": f"{name}/{path.name}",
                             "sha256": sha256_hex(data)})
    (tmp_path / "records" / "Bad" / "Bad-DWN.AT2").write_bytes(b"\n" + (tmp_path / "records" / "Bad" /
                                                                         "Bad-DWN.AT2").read_bytes())
    monkeypatch.setattr(vertical_records, "manifest_rows", lambda: manifest)
    store_three_component(tmp_path / "records", tmp_path / "records.nc", tmp_path / "records.csv", g=9.81)
    found, left_out = stations(tmp_path / "records.nc")
    assert list(found) == ["Good"] and set(found["Good"]) == {"H1", "H2", "UP"}
    assert found["Good"]["UP"].meta.record_id == "Good"
    assert list(left_out) == ["Bad"] and "UP: rejected" in left_out["Bad"] and "SHA-256" in left_out["Bad"]
    with open(tmp_path / "records.csv", newline="", encoding="utf-8") as handle:
        inventory = {(row["set"], row["component"]): row for row in csv.DictReader(handle)}
    assert inventory["Good", "UP"]["vertical_sense"] == "up (UP in its component)"
    assert float(inventory["Good", "H1"]["pga_g"]) == pytest.approx(0.3 * np.abs(np.sin(6 * time)).max(), rel=1e-6)
    assert inventory["Bad", "UP"]["status"] == "rejected"


def test_a_folder_without_the_records_is_one_sentence_on_how_to_get_them(tmp_path):
    with pytest.raises(StickslipError, match=r"were not available in .*: copy the fifteen PEER NGA-West2 "
                                             r"three-component sets .* set STICKSLIP_THREE_COMPONENT_DIR"):
        store_three_component(tmp_path, tmp_path / "records.nc", tmp_path / "records.csv")
    paths = [tmp_path / name for name in ("cases.csv", "changes.csv", "liftoff.csv", "summary.csv", "study.json")]
    vertical_effect.write_vertical_tables(*paths, records_dir=None)
    document = json.loads(paths[-1].read_text())
    assert document["available"] is False
    assert document["message"].startswith("The three-component records were not available (no folder configured): ")
    assert paths[0].read_text().startswith("direction,radius,vertical,record,") and len(paths[0].read_text().splitlines()) == 1


@pytest.fixture(scope="module")
def vertical_workflow(tmp_path_factory):
    """The study's page on the shared three-component records: H1, the flat slider and R = 2 m."""
    folder = require_shared_records() / "three_component"
    workdir = tmp_path_factory.mktemp("vertical_workflow")
    configfile = workdir / "config.yaml"
    config = yaml.safe_load(PROJECT_CONFIG.read_text())
    config["vertical_study"].update(radii=[math.inf, 2.0], directions=["H1"],
                                    mu=[{"start": 0.0025, "stop": 0.6, "step": 0.0025}])
    configfile.write_text(yaml.safe_dump(config))
    result = snakemake(workdir, configfile, "reports/html/vertical_study.html", three_component_dir=folder,
                       timeout=900)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    return workdir


def read_rows(path) -> list[dict]:
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


@pytest.mark.slow
def test_the_workflow_runs_the_study_on_the_shared_records(vertical_workflow):
    folder = vertical_workflow / "results" / "vertical"
    cases = read_rows(folder / "vertical_cases.csv")
    assert len(cases) == 15 * 2 * 3
    assert {row["optimum_status"] for row in cases} == {"ok"}
    liftoff = {(row["record"], row["vertical"]): float(row["liftoff_time"])
               for row in read_rows(folder / "vertical_liftoff.csv")}
    assert len(liftoff) == 30
    # g + a_v <= 0 only where the ground falls with more than 1 g: El Centro Array #6 and Gazli as recorded
    assert {key for key, time in liftoff.items() if key[1] == "recorded" and time > 0} == {
        ("ImperialValley06_ElCentroArray6", "recorded"), ("Gazli_Karakyr", "recorded")}
    # the flat slider at one mu: V/W = mu N/W while sliding, so with the vertical it is at most mu (1 + max a_v / g)
    changes = {(row["radius"], row["vertical"], row["record"]): row for row in read_rows(folder / "vertical_changes.csv")}
    for row in cases:
        if row["radius"] == "inf" and row["vertical"] == "recorded" and float(row["energy_dissipated_reference"]) > 0:
            ratio = float(changes["inf", "recorded", row["record"]]["base_shear_ratio_at_reference"])
            up = max(float(row["vertical_pga"]), 0.0)
            assert 0.0 < ratio <= 1.0 + up + 1e-9, row["record"]
    study = json.loads((folder / "vertical_study.json").read_text())
    assert study["available"] is True and study["stations"] == 15 and study["radii_m"] == ["inf", "2"]
    page = (vertical_workflow / "reports" / "html" / "vertical_study.html").read_text(encoding="utf-8")
    assert "At a glance" in page and "15 stations" in page
    assert (vertical_workflow / "logs" / "vertical" / "sweep_H1.log").read_text().count("15 stations x 240 mu") == 6


def test_without_the_records_the_page_says_in_one_sentence_how_to_get_them(tmp_path):
    result = snakemake(tmp_path, PROJECT_CONFIG, "reports/html/vertical_study.html", timeout=600)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    assert not (tmp_path / "results" / "vertical" / "vertical.nc").exists()
    page = (tmp_path / "reports" / "html" / "vertical_study.html").read_text(encoding="utf-8")
    assert "The three-component records were not available (no folder configured): copy the fifteen" in page
    assert "STICKSLIP_THREE_COMPONENT_DIR" in page and "At a glance" not in page  # the sentence, no empty sections
    assert sorted(path.name for path in (tmp_path / "reports" / "figures" / "vertical").iterdir()) == [
        "vertical_base_shear_ratio.png", "vertical_displacement_ratio.png", "vertical_energy_ratio.png",
        "vertical_liftoff.png", "vertical_mu_max.png"]


def test_the_index_section_shows_the_pooled_medians_and_ranges_per_radius_or_the_sentence(tmp_path):
    from stickslip.plumbing.files import write_csv_atomic
    from stickslip.studies.vertical.index import vertical_section_html

    changes = [{"direction": direction, "radius": "2", "vertical": variant, "record": record,
                **{name: 1.0 for name in vertical_effect.CHANGES}, "base_shear_ratio_at_reference": value}
               for direction in ("H1", "H2") for variant in ("recorded", "reversed")
               for record, value in (("A", 1.5), ("B", 1.1), ("C", 1.2))]
    write_csv_atomic(tmp_path / "vertical_summary.csv", summary_rows(changes))
    document = {"available": True, "stations": 3, "directions": ["H1", "H2"], "radii_m": ["2"], "reference_mu": 0.06}
    (tmp_path / "vertical_study.json").write_text(json.dumps(document))
    section = vertical_section_html(tmp_path / "vertical_summary.csv", tmp_path / "vertical_study.json",
                                    tmp_path / "page.html", tmp_path)
    assert "<li>R = 2 m: E_df,max with / without 1.00 (1.00 to 1.00) [1.00 (1.00 to 1.00)]; V/W at the reference μ " \
           "1.20 (1.10 to 1.50) [1.20 (1.10 to 1.50)];" in section
    assert 'href="page.html"' in section
    (tmp_path / "vertical_study.json").write_text(json.dumps({"available": False, "message": "Not here: get them."}))
    section = vertical_section_html(tmp_path / "vertical_summary.csv", tmp_path / "vertical_study.json", None, tmp_path)
    assert "<p>Not here: get them.</p>" in section and "<li>" not in section


def test_a_reference_mu_off_the_study_grid_is_refused_naming_the_key():
    from conftest import project_config
    from stickslip.plumbing.config import check_config_semantics
    from stickslip.records.manifest import load_manifest

    config, ids = project_config(), list(load_manifest())
    check_config_semantics(config, ids)  # the project's: 0.06 is on the grid
    config["vertical_study"]["reference_mu"] = 0.061
    with pytest.raises(StickslipError, match=r"vertical_study.reference_mu: 0.061 is not a value of vertical_study.mu"):
        check_config_semantics(config, ids)
    config["vertical_study"]["mu"][1]["start"] = 0.7
    with pytest.raises(StickslipError, match=r"vertical_study.mu\[1\]: expected 0 < START <= STOP"):
        check_config_semantics(config, ids)


def test_a_store_without_one_good_station_stops_the_sweep_with_the_reasons(tmp_path, monkeypatch):
    from stickslip.studies.vertical.sweep import write_direction_sweep

    path = tmp_path / "records" / "Bad" / "Bad-000.AT2"
    data = write_at2(path, "Station Bad", "000", 0.3 * np.sin(np.arange(300) * 0.06))
    monkeypatch.setattr(vertical_records, "manifest_rows", lambda: [
        {"set": "Bad", "component": component, "file": "Bad/Bad-000.AT2", "sha256": sha256_hex(data)}
        for component in vertical_records.COMPONENTS[:2]] + [
        {"set": "Bad", "component": "UP", "file": "Bad/Bad-UP.AT2", "sha256": "0" * 64}])
    store_three_component(tmp_path / "records", tmp_path / "records.nc", tmp_path / "records.csv")
    with pytest.raises(StickslipError, match=r"records.nc: no station has its three components checked ok \(Bad: UP: "
                                             r"missing \(Bad/Bad-UP.AT2 is not in .*records\)\)"):
        write_direction_sweep(tmp_path / "records.nc", tmp_path / "H1.nc", "H1", [2.0],
                              [{"start": 0.01, "stop": 0.1, "step": 0.01}], ["none", "recorded"], "up", 0.95, 0.05,
                              1e-4, 1.0, 9.81)
    assert not (tmp_path / "H1.nc").exists()


def test_the_gathered_study_keeps_every_direction_name_whole(tmp_path):
    """Directions of different lengths (``H1`` beside ``plane``) come out of the gathered cube as written."""
    import xarray as xr

    from stickslip.studies.vertical.sweep import gather_vertical_study

    paths = []
    for direction in ("H1", "plane"):
        cube = xr.Dataset({"energy_dissipated": (("record", "mu"), np.ones((1, 2)))},
                          coords={"record": ["a"], "mu": [0.01, 0.02]}).expand_dims(direction=[direction])
        paths.append(tmp_path / f"{direction}.nc")
        cube.to_netcdf(paths[-1], engine="netcdf4")
    gathered = xr.load_dataset(gather_vertical_study(paths, tmp_path / "study.nc"), engine="netcdf4")
    assert list(gathered.direction.values) == ["H1", "plane"]
