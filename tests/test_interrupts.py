"""Ctrl-C and SIGTERM end a command within 2 s with exit 130 or 143, leaving no temporary file;
the ``.part`` files of a killed writer are ignored by readers and removed by the next write."""

from __future__ import annotations

import os
import random
import signal
import socket
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

from stickslip.errors import RecordError
from stickslip.plumbing.files import atomic_path, write_text_atomic
from stickslip.records.readers import read_record

#: The command line, run by this Python.
STICKSLIP = [sys.executable, "-m", "stickslip"]

#: Exit code of each signal, as a shell reports it.
EXIT_CODES = {signal.SIGINT: 130, signal.SIGTERM: 143}

#: A writer that never finishes: it rewrites a 24 MB NetCDF file through xarray inside atomic_path.
ENDLESS_WRITE = textwrap.dedent(
    """
    import sys
    import numpy as np
    import xarray as xr
    from stickslip.plumbing.files import atomic_path, exit_on_interrupted_writes

    exit_on_interrupted_writes(True)
    data = xr.Dataset({"x": (("a", "b"), np.random.default_rng(1).normal(size=(3000, 1000)))})
    with atomic_path(sys.argv[1]) as tmp:
        print("writing", flush=True)
        while True:
            data.to_netcdf(tmp, engine="netcdf4", encoding={"x": {"zlib": True, "complevel": 1}})
    """
)


def _wait_for_exit(process: subprocess.Popen, sent_at: float) -> float:
    try:
        process.wait(timeout=10)
    except subprocess.TimeoutExpired:
        process.kill()
        pytest.fail("the process did not end within 10 s of the signal")
    return time.monotonic() - sent_at


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM, signal.SIGINT, signal.SIGTERM])
def test_a_signal_inside_a_netcdf_write_ends_it_at_once_without_leftovers(tmp_path, signum):
    target = tmp_path / "cube.nc"
    process = subprocess.Popen(
        [sys.executable, "-c", ENDLESS_WRITE, str(target)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    assert process.stdout.readline() == "writing\n"
    time.sleep(random.Random(signum * 7 + len(str(tmp_path))).uniform(0.1, 1.0))
    process.send_signal(signum)
    sent_at = time.monotonic()
    elapsed = _wait_for_exit(process, sent_at)
    assert process.returncode == EXIT_CODES[signum], process.stderr.read()
    assert elapsed < 2.0
    assert sorted(path.name for path in tmp_path.iterdir()) == []


def _one_column_files(folder: Path, count: int) -> list[Path]:
    rng = np.random.default_rng(3)
    paths = []
    for index in range(count):
        path = folder / f"record{index}.txt"
        np.savetxt(path, rng.normal(scale=0.1, size=20_000), fmt="%.6f")
        paths.append(path)
    return paths


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_while_reading_records_ends_the_command(tmp_path, signum):
    paths = _one_column_files(tmp_path, 20)
    command = [*STICKSLIP, "records", "validate", "--dt", "0.01", *map(str, paths * 500)]
    environment = {**os.environ, "PYTHONUNBUFFERED": "1"}
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=environment)
    assert process.stdout.readline().startswith(str(paths[0]))  # reading has begun
    time.sleep(0.3)
    process.send_signal(signum)
    elapsed = _wait_for_exit(process, time.monotonic())
    assert process.returncode == EXIT_CODES[signum]
    assert elapsed < 2.0
    assert "no partial output was kept" in process.stderr.read()


def test_the_library_delivers_ctrl_c_after_the_write_and_keeps_nothing(tmp_path):
    target = tmp_path / "out.txt"
    with pytest.raises(KeyboardInterrupt):
        with atomic_path(target) as tmp:
            tmp.write_text("half")
            signal.raise_signal(signal.SIGINT)
            tmp.write_text("whole")  # the write goes on to its end
    assert list(tmp_path.iterdir()) == []


def test_parts_of_a_killed_writer_are_ignored_by_readers_and_removed_by_the_next_write(tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    pid = int(dead.stdout)  # a process that has ended
    host = socket.gethostname().split(".")[0]
    stale = tmp_path / f".table.csv.{host}-{pid}.abc123.part"
    stale_other_file = tmp_path / f".cube.nc.{host}-{pid}.x1y2z3.part"
    alive = tmp_path / f".table.csv.{host}-{os.getpid()}.def456.part"
    unknown_fresh = tmp_path / ".report.ipynb.k2j3h4.part"
    unknown_old = tmp_path / ".notes.txt.q8w9e7.part"
    for path in (stale, stale_other_file, alive, unknown_fresh, unknown_old):
        path.write_text("0.1\n0.2\n")
    two_hours_ago = time.time() - 7200
    os.utime(unknown_old, (two_hours_ago, two_hours_ago))
    with pytest.raises(RecordError, match="temporary .part file of an unfinished write"):
        read_record(stale, dt=0.01)
    write_text_atomic(tmp_path / "table.csv", "a,b\n")
    assert sorted(path.name for path in tmp_path.iterdir()) == sorted([alive.name, unknown_fresh.name, "table.csv"])
