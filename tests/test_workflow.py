"""The Snakemake workflow: its DAG builds with both profiles, and a bad config is refused at start."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from conftest import REPO_ROOT

SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))


def dry_run(*args: str, cwd: Path = REPO_ROOT) -> subprocess.CompletedProcess:
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    return subprocess.run(
        [SNAKEMAKE, "--dry-run", "--forceall", "--cores", "2", *args],
        cwd=cwd, env=env, capture_output=True, text=True, timeout=120,
    )


@pytest.mark.parametrize("profile", ["default", "slurm"])
def test_the_whole_workflow_plans_with_each_profile(profile):
    result = dry_run("--profile", f"workflow/profiles/{profile}")
    assert result.returncode == 0, result.stderr[-2000:]
    planned = result.stdout + result.stderr
    for rule in ("fetch_records", "table5", "table6", "table8", "table4", "timestep_study", "report_index"):
        assert rule in planned


def test_a_config_that_breaks_the_schema_is_refused(tmp_path):
    project = tmp_path / "project"
    project.mkdir()
    for name in ("Snakefile", "workflow", "config", "notebooks", "src"):
        source = REPO_ROOT / name
        (shutil.copytree if source.is_dir() else shutil.copy)(source, project / name)
    config_path = project / "config" / "config.yaml"
    config = yaml.safe_load(config_path.read_text(encoding="utf-8"))
    config["block_mass"] = -5.1
    config_path.write_text(yaml.safe_dump(config), encoding="utf-8")
    result = dry_run(cwd=project)
    assert result.returncode != 0
    message = result.stdout + result.stderr  # Snakemake prints the validation error on stdout
    assert "is less than or equal to the minimum of 0" in message
    assert "block_mass" in message and "-5.1" in message
