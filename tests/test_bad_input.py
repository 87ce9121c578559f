"""Bad record files through the command line: exit 2, one line naming the file and the problem, nothing written."""

from __future__ import annotations

import json

import pytest
from conftest import assert_one_error_line

from conftest import FIXTURES

BAD = FIXTURES / "bad"

#: Bad file -> a phrase its error message must contain.
CORPUS = {
    "truncated.AT2": "header says NPTS=13 but 10 values were read (truncated file)",
    "npts_mismatch.AT2": "header says NPTS=8 but 10 values were read (extra values)",
    "text_in_numbers.AT2": "line 6: non-numeric value 'abc'",
    "unknown_units.AT2": "unknown units 'FURLONGS'",
    "nan_value.csv": "line 5: value 'nan' is not a finite number",
    "non_uniform_time.csv": "non-uniform time step: 0.03 s between t=0.02 s and t=0.05 s",
    "repeated_time.csv": "time step must be positive: t=0.02 s follows t=0.02 s",
    "empty.txt": "empty file",
    "binary.dat": "binary file (contains NUL bytes)",
    "unknown_format.txt": "unknown format",
    "one_column_no_dt.txt": "no time step: a slammer_1col file has none and no manifest knows this file; pass --dt in seconds",
    "two_column_no_units.txt": "units unknown for a two_column file",
}


def test_corpus_is_complete():
    assert sorted(path.name for path in BAD.iterdir()) == sorted(CORPUS)



@pytest.mark.parametrize("name", sorted(CORPUS))
def test_records_validate_rejects(run_cli, name):
    path = BAD / name
    code, out, err = run_cli("records", "validate", path)
    assert_one_error_line(code, out, err, path, CORPUS[name])
    assert out == ""


@pytest.mark.parametrize("name", sorted(CORPUS))
def test_measures_json_rejects(run_cli, name):
    path = BAD / name
    code, out, err = run_cli("measures", path, "--json")
    assert_one_error_line(code, out, err, path, CORPUS[name])
    assert out == ""


@pytest.mark.parametrize(
    ("args", "phrase"),
    [
        (("--format", "mseed"), "unknown format 'mseed'; known formats: netcdf, peer_at2, slammer_1col, time_acc_csv, two_column"),
        (("--units", "furlongs"), "unknown units 'furlongs'"),
    ],
)
def test_records_validate_rejects_bad_options(run_cli, args, phrase):
    path = FIXTURES / "two_column.txt"
    code, out, err = run_cli("records", "validate", path, *args)
    assert_one_error_line(code, out, err, path, phrase)


def test_records_validate_missing_file(run_cli, tmp_path):
    path = tmp_path / "absent.AT2"
    code, out, err = run_cli("records", "validate", path)
    assert_one_error_line(code, out, err, path, "file not found")


@pytest.mark.parametrize("name", ["truncated.AT2", "binary.dat", "nan_value.csv"])
def test_records_fetch_writes_nothing_for_a_bad_local_file(run_cli, tmp_path, name):
    """A bad file in the records folder under a known name: exit 2, the out-dir keeps what it had."""
    records = tmp_path / "records"
    records.mkdir()
    local = records / "SLAMMER_Kobe_1995_KJM-090.txt"
    local.write_bytes((BAD / name).read_bytes())
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    earlier = out_dir / "kobe_kjm090.nc"
    earlier.write_bytes(b"written earlier")
    code, out, err = run_cli("records", "fetch", "kobe_kjm090", "--records-dir", records, "--out-dir", out_dir, "--no-download")
    assert_one_error_line(code, out, err, local, "is not a known version of record kobe_kjm090")
    assert sorted(p.name for p in out_dir.iterdir()) == ["kobe_kjm090.nc"]
    assert earlier.read_bytes() == b"written earlier"


def test_records_fetch_missing_record(run_cli, tmp_path):
    out_dir = tmp_path / "out"
    code, out, err = run_cli(
        "records", "fetch", "parkfield_c02_360", "--records-dir", tmp_path, "--out-dir", out_dir, "--no-download"
    )
    assert code == 2 and len(err.splitlines()) == 1
    assert "record parkfield_c02_360 not found" in err and "parkfield_c02_360.AT2" in err
    assert not out_dir.exists()


@pytest.mark.parametrize(
    ("file_name", "args", "phrase"),
    [
        ("pySLAMMER_Cape_Mendocino_1992_PET-090.csv", ("--units", "cm/s2"), "the file says units g but units 'cm/s2' were given"),
        ("SLAMMER_Kobe_1995_KJM-090.txt", ("--dt", "0.01"), "the manifest says dt = 0.02 s for this version of record kobe_kjm090 but dt = 0.01 s was given"),
        ("SLAMMER_Kobe_1995_KJM-090.txt", ("--units", "m/s2"), "the manifest says units g for this version of record kobe_kjm090 but units 'm/s2' were given"),
    ],
)
def test_measures_refuses_options_that_contradict_the_file_or_manifest(run_cli, paper_records_dir, file_name, args, phrase):
    path = paper_records_dir / file_name
    code, out, err = run_cli("measures", path, *args, "--json")
    assert_one_error_line(code, out, err, path, phrase)
    assert out == ""


@pytest.mark.parametrize(
    ("file_name", "args"),
    [
        ("pySLAMMER_Cape_Mendocino_1992_PET-090.csv", ("--units", "g")),
        ("SLAMMER_Kobe_1995_KJM-090.txt", ("--dt", "0.02", "--units", "g")),
    ],
)
def test_measures_accepts_options_that_agree_with_the_file_or_manifest(run_cli, paper_records_dir, file_name, args):
    code, out, err = run_cli("measures", paper_records_dir / file_name, *args, "--json")
    assert code == 0, err


def test_records_fetch_refuses_an_out_dir_that_is_a_file(run_cli, tmp_path, paper_records_dir):
    blocker = tmp_path / "blocker"
    blocker.write_text("kept")
    code, out, err = run_cli(
        "records", "fetch", "kobe_kjm090", "--records-dir", paper_records_dir, "--out-dir", blocker, "--no-download"
    )
    assert_one_error_line(code, out, err, blocker, "cannot write the records: it is a file, not a folder")
    assert out == ""
    assert blocker.read_text() == "kept" and sorted(p.name for p in tmp_path.iterdir()) == ["blocker"]


def test_records_fetch_refuses_an_out_dir_under_a_file(run_cli, tmp_path, paper_records_dir):
    blocker = tmp_path / "blocker"
    blocker.write_text("kept")
    out_dir = blocker / "records"
    code, out, err = run_cli(
        "records", "fetch", "kobe_kjm090", "--records-dir", paper_records_dir, "--out-dir", out_dir, "--no-download"
    )
    assert_one_error_line(code, out, err, out_dir, f"{blocker} is a file, not a folder")
    assert blocker.read_text() == "kept"


def test_in_python_the_missing_time_step_names_the_argument_of_read_record():
    from stickslip.errors import RecordError
    from stickslip.records.readers import read_record

    path = BAD / "one_column_no_dt.txt"
    with pytest.raises(RecordError, match=r"pass dt= in seconds$") as raised:
        read_record(path)
    assert "--dt" not in str(raised.value)


def test_a_folder_among_the_files_is_skipped_with_a_note(run_cli, tmp_path):
    (tmp_path / "subfolder").mkdir()
    record = FIXTURES / "two_column.txt"
    code, out, err = run_cli("measures", record, tmp_path / "subfolder", "--units", "cm/s2", "--json")
    assert code == 0
    assert err.splitlines() == [f"stickslip: note: {tmp_path / 'subfolder'} is a directory, skipped "
                                f"(give the files in it, e.g. {tmp_path / 'subfolder'}/*)"]
    assert json.loads(out)["record"] == "two_column"
    assert_one_error_line(*run_cli("measures", tmp_path / "subfolder"), tmp_path / "subfolder",
                          "a directory, no record file")


@pytest.mark.parametrize("command", [["report", "--out", "page.html"], ["measures"], ["records", "validate"]])
def test_an_unknown_argument_points_to_the_command_s_own_help(run_cli, command):
    prog = " ".join(["stickslip", *command[:2 if command[0] == "records" else 1]])
    assert_one_error_line(*run_cli(*command, FIXTURES / "two_column.txt", "--bogus"), "--bogus",
                          f"{prog}: unrecognized arguments: --bogus (see '{prog} --help')")
