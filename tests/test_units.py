"""One table of units (UDUNITS spelling), one CF version, readers that accept equivalent spellings, and the CF checker."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from stickslip.errors import RecordError
from stickslip.records.netcdf import read_record_netcdf, write_missing_record, write_record
from stickslip.records.record import Record, RecordMeta
from stickslip.models import sweep
from stickslip.sweeps import write_cube
from stickslip.studies.units import write_units_table
from stickslip.units import CF_CONVENTIONS, EQUIVALENT_SPELLINGS, UNITS, normalise_units

REFERENCES = Path(__file__).parent / "references"
#: Columns of text that may look like numbers (a component "090").
TEXT_COLUMNS = {"component"}
CF_TABLES = Path(__file__).parent / "fixtures" / "cf"


def _record(record_id: str = "sine") -> Record:
    acceleration = 3.0 * np.sin(np.arange(400) * 0.05)  # [m/s²]
    return Record(acceleration, 0.01, RecordMeta(record_id=record_id, event="test", station="s", component="c"))


def test_every_unit_is_valid_udunits_and_every_equivalent_spelling_means_the_same():
    cfunits = pytest.importorskip("cfunits")
    for name, units in UNITS.items():
        assert cfunits.Units(units).isvalid, f"{name}: {units!r} is not a UDUNITS unit"
    for spelling, units in EQUIVALENT_SPELLINGS.items():
        parsed = cfunits.Units(spelling.replace("j", "J"))
        if parsed.isvalid:  # UDUNITS cannot parse "m/s²" or "-"; the others it reads must agree with the map
            assert parsed.equals(cfunits.Units(units)), f"{spelling!r} is not {units!r}"


@pytest.mark.parametrize("spelling", ["m s-2", "m/s2", "m/s²", "M/S^2", "m s^-2", " m  s-2 "])
def test_normalise_units_accepts_spellings_of_m_per_s2(spelling):
    assert normalise_units(spelling) == "m s-2"


def test_normalise_units_leaves_unknown_units_unknown():
    assert normalise_units("cm/s2") is None
    assert normalise_units("furlongs per fortnight") is None


def _with_acceleration_units(path: Path, units: str) -> Path:
    dataset = xr.load_dataset(path)
    dataset["acceleration"].attrs["units"] = units
    dataset.to_netcdf(path, mode="w")
    return path


@pytest.mark.parametrize("spelling", ["m/s²", "m/s2", "m s^-2"])
def test_read_record_netcdf_accepts_equivalent_spellings(tmp_path, spelling):
    path = _with_acceleration_units(write_record(_record(), tmp_path / "sine.nc"), spelling)
    np.testing.assert_array_equal(read_record_netcdf(path).acceleration, _record().acceleration)


def test_read_record_netcdf_rejects_other_units_naming_the_file(tmp_path):
    path = _with_acceleration_units(write_record(_record(), tmp_path / "sine.nc"), "cm/s2")
    with pytest.raises(RecordError, match=r"sine\.nc.*'cm/s2'.*m s-2"):
        read_record_netcdf(path)


def test_every_numeric_column_of_the_workflow_tables_has_units():
    """Each numeric column of the stored reference tables is in the units table (results/tables/units.csv)."""
    tables = sorted(REFERENCES.glob("*/*.csv"))
    assert tables
    for table in tables:
        if table.name == "units.csv":
            continue
        with open(table, newline="", encoding="utf-8") as handle:
            rows = list(csv.DictReader(handle))
        if {"units", "x_units"} & set(rows[0]):
            continue  # each row names the units of its values (errata, Tables 3-4, the paper's fits)
        for column in rows[0]:
            values = [row[column] for row in rows if row[column] not in ("", None)]
            numeric = column not in TEXT_COLUMNS and values and all(_is_number(value) for value in values)
            assert not numeric or column in UNITS, f"{table.parent.name}/{table.name}: column {column!r} has no units"


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return text.lower() not in ("true", "false", "nan")


def test_units_table_lists_the_units(tmp_path):
    path = write_units_table(tmp_path / "units.csv")
    with open(path, newline="", encoding="utf-8") as handle:
        rows = {row["column"]: row["units"] for row in csv.DictReader(handle)}
    assert rows == UNITS


def test_measures_json_carries_its_units(run_cli, tmp_path):
    path = tmp_path / "pulse.txt"
    path.write_text("\n".join(f"{a:.6f}" for a in _record().acceleration) + "\n")
    code, out, err = run_cli("measures", path, "--format", "slammer_1col", "--dt", "0.01", "--units", "m/s2", "--json")
    assert code == 0, err
    document = json.loads(out)
    assert document["units"]["pga"] == "m s-2" and document["units"]["arias_intensity"] == "m s-1"
    assert document["record"] == "pulse" and document["source"] == str(path) and document["vertical"] is None  # text
    assert document["read"] == {"format": "slammer_1col", "dt": 0.01, "units": "m/s2"}  # the options it was read with
    assert set(document["units"]) == set(document) - {"units", "record", "source", "vertical", "read"}


def _cf_check(path: Path) -> dict:
    """The CF checker's counts for ``path``, against the standard tables stored in tests/fixtures/cf (offline)."""
    cfchecks = pytest.importorskip("cfchecker.cfchecks")
    checker = cfchecks.CFChecker(
        cfStandardNamesXML=str(CF_TABLES / "standard-name-table.xml"),
        cfAreaTypesXML=str(CF_TABLES / "area-type-table.xml"),
        cfRegionNamesXML=str(CF_TABLES / "standardized-region-list.xml"),
        silent=True,
    )
    checker.checker(str(path))
    return checker.get_counts()


def _cf_files(tmp_path: Path) -> dict[str, Path]:
    """One file of each kind stickslip writes as NetCDF."""
    from stickslip.models import with_optimum
    from stickslip.models import solve

    record = _record()
    response_path = tmp_path / "response.nc"
    solve(record, mu=0.1).to_xarray().to_netcdf(response_path)
    return {
        "record": write_record(record, tmp_path / "record.nc"),
        "missing record": write_missing_record("gone", "not found", tmp_path / "gone.nc"),
        "cube": write_cube(with_optimum(sweep([record], mu=[0.05, 0.1]), [record]), tmp_path / "cube.nc"),
        "target_pga cube": write_cube(with_optimum(sweep([record], mu=[0.05, 0.1], target_pga=[2.0, 4.0]), [record]),
                                      tmp_path / "scaled.nc"),
        "response": response_path,
    }


def test_netcdf_files_pass_the_cf_checker(tmp_path):
    for kind, path in _cf_files(tmp_path).items():
        with xr.open_dataset(path) as dataset:
            assert dataset.attrs["Conventions"] == CF_CONVENTIONS, kind
        counts = _cf_check(path)
        assert counts["FATAL"] == 0 and counts["ERROR"] == 0, f"{kind}: {counts}"
        # the one warning CF allows us: a text coordinate named as its dimension (xarray's record index)
        assert counts["WARN"] <= (1 if "cube" in kind else 0), f"{kind}: {counts}"
