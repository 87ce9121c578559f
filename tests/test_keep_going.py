"""``--keep-going``: with several files, every readable one is computed and the others listed at the end, exit 2.

Without it the first file that cannot be read stops the call, as before.  A
file left out of a pair (``--pair``) leaves its pair out, and the other file
of the pair is listed too.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr
from conftest import assert_one_error_line

UNKNOWN_FORMAT = ("unknown format: not a PEER AT2 file, nor one or two numeric columns, nor a stored record (NetCDF); "
                  "known formats: netcdf, peer_at2, slammer_1col, time_acc_csv, two_column")


def write_record(path, pga: float, seed: int):
    """A random motion with the peak ``pga`` [g], as a time,acc CSV (values in g)."""
    values = np.random.default_rng(seed).normal(size=1500) * np.hanning(1500)
    np.savetxt(path, np.column_stack([np.arange(1500) * 0.01, pga * values / np.max(np.abs(values))]),
               delimiter=",", header="time,acc", comments="", fmt=["%.2f", "%.9g"])
    return path


@pytest.fixture
def files(tmp_path):
    broken = tmp_path / "broken.csv"
    broken.write_text("garbage\n")
    return [write_record(tmp_path / "first.csv", 0.3, 1), broken, write_record(tmp_path / "second.csv", 0.4, 2)]


def unread_lines(files, count: int = 1) -> list[str]:
    return [f"stickslip: error: {files[1]}: {UNKNOWN_FORMAT}",
            f"stickslip: error: {count} file{'s' if count > 1 else ''} could not be read (listed above); --keep-going "
            "computed the others"]


def test_measures_computes_every_readable_file_and_lists_the_others(run_cli, files):
    code, out, err = run_cli("measures", *files, "--json", "--keep-going")
    assert code == 2 and [json.loads(line)["record"] for line in out.splitlines()] == ["first", "second"]
    assert err.splitlines() == unread_lines(files)
    assert_one_error_line(*run_cli("measures", *files, "--json"), str(files[1]), "unknown format")  # as before


@pytest.mark.parametrize("command", [("solve", "--mu", "0.1", "--json"), ("optimum", "--mu", "0.05:0.2:0.05", "--json"),
                                     ("displacements", "--ky", "0.1,0.2", "--json")])
def test_solve_optimum_and_displacements_keep_going(run_cli, files, command):
    code, out, err = run_cli(*command, *files, "--keep-going")
    assert code == 2 and err.splitlines()[-2:] == unread_lines(files), err
    assert "first" in out and "second" in out and "broken" not in out


def test_sweep_writes_the_cube_of_the_readable_files(run_cli, files, tmp_path):
    code, out, err = run_cli("sweep", *files, "--mu", "0.1,0.2", "--out", tmp_path / "cube.nc", "--keep-going")
    assert code == 2 and err.splitlines()[-2:] == unread_lines(files), err
    with xr.open_dataset(tmp_path / "cube.nc") as cube:
        assert list(cube["record"].values) == ["first", "second"]


def test_a_pair_with_an_unreadable_file_is_left_out_whole(run_cli, files, tmp_path):
    partner = write_record(tmp_path / "first_y.csv", 0.2, 3)
    second_y = write_record(tmp_path / "second_y.csv", 0.25, 4)
    code, out, err = run_cli("solve", partner, files[1], files[2], second_y, "--pair", "--mu", "0.1", "--json",
                             "--keep-going")
    assert code == 2 and [json.loads(line)["pair"] for line in out.splitlines()] == ["second + second_y"]
    assert err.splitlines() == [f"stickslip: error: {files[1]}: {UNKNOWN_FORMAT}",
                                f"stickslip: error: {partner}: not computed: the other file of its pair could not be "
                                "read", *unread_lines(files, 2)[1:]]


def test_none_readable_is_an_error_after_the_list(run_cli, tmp_path):
    broken = [tmp_path / "a.csv", tmp_path / "b.csv"]
    for path in broken:
        path.write_text("garbage\n")
    code, out, err = run_cli("solve", *broken, "--mu", "0.1", "--keep-going")
    assert (code, out) == (2, "")
    assert err.splitlines() == [f"stickslip: error: {path}: {UNKNOWN_FORMAT}" for path in broken] + [
        "stickslip: error: --keep-going: none of the 2 files could be read"]
