"""The package surface: public names, atomic output, provenance."""

from __future__ import annotations

import os
import stat

import numpy as np
import pytest

import stickslip
from stickslip.io import atomic_path, provenance


def test_public_functions_survive_importing_their_modules():
    import stickslip.solution  # noqa: F401  (binds the submodule on the package)
    import stickslip.sweeps  # noqa: F401

    record = stickslip.Record(np.array([0.0, 3.0, -3.0, 0.0]), 0.01)
    first = stickslip.solve(record, 0.1).energy_dissipated
    assert stickslip.solve(record, 0.1).energy_dissipated == first > 0
    assert callable(stickslip.sweep)


def test_atomic_path_keeps_the_old_file_when_the_body_fails(tmp_path):
    target = tmp_path / "table.csv"
    target.write_text("old\n")
    with pytest.raises(RuntimeError):
        with atomic_path(target) as tmp:
            tmp.write_text("half")
            raise RuntimeError("interrupted")
    assert target.read_text() == "old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["table.csv"]


def test_atomic_path_gives_the_file_the_usual_permissions(tmp_path):
    mask = os.umask(0o022)
    try:
        with atomic_path(tmp_path / "out.txt") as tmp:
            tmp.write_text("x")
    finally:
        os.umask(mask)
    assert stat.S_IMODE((tmp_path / "out.txt").stat().st_mode) == 0o644


def test_provenance_names_the_version_and_commit():
    attrs = provenance()
    assert attrs["stickslip_version"] == stickslip.__version__
    assert attrs["git_commit"] == "unknown" or len(attrs["git_commit"]) == 40
