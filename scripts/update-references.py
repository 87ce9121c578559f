"""Run the workflow on the shared paper records and on .test/, and store their tables in tests/references/.

Usage (from the project root): ``make references``.  Review ``git diff tests/references``
before committing: a changed reference must be an intended change.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

from stickslip.studies.references import REFERENCE_TABLES, write_reference

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))

#: Reference folder -> (configuration, records folder or None for the offline sources).
RUNS = {
    "paper": (ROOT / "config" / "config.yaml",
              os.environ.get("STICKSLIP_RECORDS_DIR") or str(ROOT.parent / "shared" / "records" / "paper")),
    "test_config": (ROOT / ".test" / "config" / "config.yaml", None),
}

#: The environment variables that point the workflow at records folders; the references are made without them.
FOLDER_VARIABLES = ("STICKSLIP_RECORDS_DIR", "STICKSLIP_SLAMMER_DIR", "STICKSLIP_VERIFICATION_DIR",
                    "STICKSLIP_THREE_COMPONENT_DIR")


def main() -> int:
    for name, (configfile, records_dir) in RUNS.items():
        # as the tests run it (tests/conftest.py): no other records folder, the default manifest
        env = {key: value for key, value in os.environ.items() if key not in FOLDER_VARIABLES}
        env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}"
        env["MPLBACKEND"] = "Agg"
        if records_dir:
            env["STICKSLIP_RECORDS_DIR"] = records_dir
        record = yaml.safe_load(configfile.read_text(encoding="utf-8"))["timestep_study"]["record"]
        with tempfile.TemporaryDirectory() as workdir:
            subprocess.run([SNAKEMAKE, "--snakefile", str(ROOT / "Snakefile"), "--directory", workdir,
                            "--configfile", str(configfile), "--cores", "2"],
                           env=env, check=True)
            for table in REFERENCE_TABLES:
                table = table.format(timestep=record)
                print(write_reference(Path(workdir) / "results" / "tables" / table,
                                      ROOT / "tests" / "references" / name / table))
    return 0


if __name__ == "__main__":
    sys.exit(main())
