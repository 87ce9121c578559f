"""The package surface: public names, atomic output, provenance."""

from __future__ import annotations

import os
import stat

import numpy as np
import pytest

import stickslip
from stickslip.plumbing.files import atomic_path, provenance


def test_public_functions_survive_importing_their_modules():
    import stickslip.models  # noqa: F401  (binds the submodule on the package)
    import stickslip.sweeps  # noqa: F401

    record = stickslip.Record(np.array([0.0, 3.0, -3.0, 0.0]), 0.01)
    first = stickslip.solve(record, mu=0.1).energy_dissipated
    assert stickslip.solve(record, mu=0.1).energy_dissipated == first > 0
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


def test_the_package_stands_alone_outside_the_checkout(tmp_path):
    """A copy of the package with no checkout around it knows the paper's records and has its report notebook."""
    import shutil
    import subprocess
    import sys
    from pathlib import Path

    package = Path(stickslip.__file__).parent
    shutil.copytree(package, tmp_path / "stickslip", ignore=shutil.ignore_patterns("__pycache__"))
    environment = {**os.environ, "PYTHONPATH": str(tmp_path), "PYTHONDONTWRITEBYTECODE": "1"}
    environment.pop("STICKSLIP_RECORDS_DIR", None)
    code = ("import stickslip, pathlib; from stickslip.records.manifest import DEFAULT_MANIFEST, load_manifest; "
            "from stickslip.reports.record_report import NOTEBOOK; from stickslip.reference import paper_record_ids; "
            "print(pathlib.Path(stickslip.__file__).parent); print(DEFAULT_MANIFEST.parent.parent); "
            "print(NOTEBOOK.is_file()); print(set(paper_record_ids()) <= set(load_manifest())); print(len(load_manifest()))")
    run = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=environment, capture_output=True, text=True,
                         check=True)
    copied, manifest_package, notebook_found, ids_known, count = run.stdout.split()
    assert copied == manifest_package == str(tmp_path / "stickslip")
    assert notebook_found == ids_known == "True" and int(count) == 26
    listing = subprocess.run([sys.executable, "-m", "stickslip", "records", "list"], cwd=tmp_path, env=environment,
                             capture_output=True, text=True, check=True)
    assert listing.stdout.splitlines()[1].startswith("cape_mendocino")


def test_the_package_root_holds_the_public_api_and_no_plumbing():
    from pathlib import Path

    root_modules = {path.stem for path in Path(stickslip.__file__).parent.glob("*.py")}
    assert not root_modules & {"config", "io", "workflow_step", "dependencies"}
    assert all(getattr(stickslip, name) is not None for name in stickslip.__all__)
    assert {"solve", "sweep", "read_record", "RecordPair", "WithVertical"} <= set(dir(stickslip))
