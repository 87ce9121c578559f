"""``stickslip solve``: JSON and table output, NetCDF export, scaling, and one-line errors."""

from __future__ import annotations

import json

import pytest
from conftest import assert_one_error_line
import xarray as xr

from stickslip.records.process import scale_to_pga
from stickslip.records.readers import read_record
from stickslip.models.rigid.response import SCALAR_ATTRS
from stickslip.models import solve

RECORD = "SLAMMER_Cape_Mendocino_1992_PET-090.txt"


@pytest.fixture(scope="module")
def record_path(paper_records_dir):
    return paper_records_dir / RECORD


def test_json_output_matches_the_library(run_cli, record_path):
    code, out, err = run_cli("solve", record_path, "--mu", "0.1", "--json")
    assert code == 0, err
    printed = json.loads(out)
    expected = solve(read_record(record_path), mu=0.1).scalars()
    assert {name: printed[name] for name in SCALAR_ATTRS} == pytest.approx(expected, rel=1e-15)
    assert printed["n_slip_episodes"] == expected["n_slip_episodes"] > 0


def test_table_output_names_units(run_cli, record_path):
    code, out, _ = run_cli("solve", record_path, "--mu", "0.1", "--mass", "2")
    assert code == 0
    rows = {line.split()[0]: line.split()[1:] for line in out.splitlines()[1:]}
    assert set(rows) == set(SCALAR_ATTRS)
    assert rows["energy_dissipated"][1] == "J"
    assert rows["sliding_path"][1] == "m"
    expected = solve(read_record(record_path), mu=0.1, mass=2.0)
    assert float(rows["energy_dissipated"][0]) == pytest.approx(expected.energy_dissipated, rel=1e-5)


def test_target_pga_and_scale(run_cli, record_path):
    code, out, _ = run_cli("solve", record_path, "--mu", "0.15", "--target-pga", "3.0m/s2", "--json")
    assert code == 0
    expected = solve(scale_to_pga(read_record(record_path), 3.0), mu=0.15).scalars()
    assert json.loads(out)["energy_dissipated"] == pytest.approx(expected["energy_dissipated"], rel=1e-15)
    # Scaling the record by 2 and mu by 2 multiplies the energies by 4 (an exact property).
    _, base, _ = run_cli("solve", record_path, "--mu", "0.05", "--json")
    _, doubled, _ = run_cli("solve", record_path, "--mu", "0.1", "--scale", "2", "--json")
    assert json.loads(doubled)["energy_dissipated"] == pytest.approx(4 * json.loads(base)["energy_dissipated"], rel=1e-9)


def test_out_writes_a_labelled_netcdf(run_cli, record_path, tmp_path):
    target = tmp_path / "out" / "pet.nc"
    code, out, _ = run_cli("solve", record_path, "--mu", "0.1", "--json", "--out", target)
    assert code == 0
    with xr.open_dataset(target, engine="netcdf4") as dataset:
        assert dataset.attrs["record_id"] == "cape_mendocino"
        assert dataset.attrs["mu"] == 0.1
        assert dataset["energy_dissipated"].attrs["units"] == "J"
        assert float(dataset["energy_dissipated"][-1]) == pytest.approx(json.loads(out)["energy_dissipated"], rel=1e-15)
    assert [p.name for p in target.parent.iterdir()] == ["pet.nc"]


def test_newmark_method_with_time_step(run_cli, record_path):
    code, out, err = run_cli("solve", record_path, "--mu", "0.1", "--method", "newmark", "--time-step", "0.002", "--json")
    assert code == 0, err
    exact = solve(read_record(record_path), mu=0.1).energy_dissipated
    assert json.loads(out)["energy_dissipated"] == pytest.approx(exact, rel=1e-2)


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        (("--mu", "-0.1"), "friction ratio mu must be a positive finite number"),
        (("--mu", "0.1", "--mass", "0"), "block mass"),
        (("--mu", "0.1", "--time-step", "0.001"), "--time-step applies to --method newmark only"),
        (("--mu", "0.1", "--target-pga", "-3"), "target PGA"),
    ],
)
def test_bad_options_give_one_line_and_exit_2(run_cli, record_path, tmp_path, arguments, message):
    target = tmp_path / "kept.nc"
    target.write_bytes(b"an earlier result")
    code, out, err = run_cli("solve", record_path, *arguments, "--out", target)
    assert code == 2
    assert out == ""
    assert err.count("\n") == 1 and message in err
    assert target.read_bytes() == b"an earlier result"


def test_bad_record_file_is_named(run_cli, tmp_path):
    bad = tmp_path / "broken.txt"
    bad.write_text("0.1\n0.2\nnot-a-number\n0.3\n")
    code, _, err = run_cli("solve", bad, "--mu", "0.1", "--dt", "0.01", "--units", "g")
    assert code == 2
    assert err.startswith("stickslip: error: ") and str(bad) in err and err.count("\n") == 1
    missing = tmp_path / "missing.AT2"
    code, _, err = run_cli("solve", missing, "--mu", "0.1")
    assert code == 2 and f"{missing}: file not found" in err


def test_scale_and_target_pga_exclude_each_other(run_cli, record_path):
    code, out, err = run_cli("solve", record_path, "--mu", "0.1", "--scale", "2", "--target-pga", "3")
    assert code == 2 and out == "" and len(err.splitlines()) == 1
    assert "not allowed with argument" in err


def test_unwritable_out_is_an_input_error(run_cli, record_path, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    code, _, err = run_cli("solve", record_path, "--mu", "0.1", "--out", blocker / "x.nc")
    assert code == 2 and "cannot write the NetCDF file" in err
    assert [p.name for p in tmp_path.iterdir()] == ["file"]



@pytest.mark.parametrize(
    ("make_out", "phrase"),
    [
        (lambda tmp: tmp / "folder", "cannot write the NetCDF file: it is a directory"),
        (lambda tmp: tmp / "blocker" / "x.nc", "cannot write the NetCDF file: "),
    ],
)
def test_bad_out_is_refused_before_solving(run_cli, record_path, tmp_path, monkeypatch, make_out, phrase):
    from stickslip.models.rigid import RigidModel

    def no_work(*args, **kwargs):
        raise AssertionError("solved before the output path was checked")

    monkeypatch.setattr(RigidModel, "solve", no_work)
    (tmp_path / "folder").mkdir()
    (tmp_path / "blocker").write_text("kept")
    out = make_out(tmp_path)
    code, stdout, err = run_cli("solve", record_path, "--mu", "0.1", "--out", out)
    assert_one_error_line(code, stdout, err, out, phrase)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocker", "folder"]
    assert list((tmp_path / "folder").iterdir()) == []
    assert (tmp_path / "blocker").read_text() == "kept"


@pytest.mark.parametrize(
    ("arguments", "name", "phrase"),
    [
        (("--scale", "0"), "--scale 0", "a scale factor of zero leaves no ground motion"),
        (
            ("--method", "newmark", "--time-step", "1"),
            "time_step [s]",
            "must not exceed the record's time step: time_step = 1 s, record dt = 0.02 s",
        ),
    ],
)
def test_zero_scale_and_too_large_newmark_step_are_refused(run_cli, record_path, tmp_path, arguments, name, phrase):
    target = tmp_path / "kept.nc"
    target.write_bytes(b"an earlier result")
    code, out, err = run_cli("solve", record_path, "--mu", "0.1", *arguments, "--out", target)
    assert_one_error_line(code, out, err, name, phrase)
    assert target.read_bytes() == b"an earlier result"
    assert [p.name for p in tmp_path.iterdir()] == ["kept.nc"]


def test_negative_scale_flips_the_sign(run_cli, record_path):
    code, out, err = run_cli("solve", record_path, "--mu", "0.1", "--scale", "-1", "--json")
    assert code == 0, err
    flipped = json.loads(out)
    code, out, err = run_cli("solve", record_path, "--mu", "0.1", "--json")
    assert flipped["residual_displacement"] == pytest.approx(-json.loads(out)["residual_displacement"], rel=1e-9)
