"""Run every study on the shared paper records and store its tables in tests/references/.

Usage (from the project root): ``make references``.  Review ``git diff tests/references``
before committing: a changed reference must be an intended change.
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

from stickslip.config import load_config
from stickslip.studies import study_module
from stickslip.studies.references import REFERENCE_TABLES, write_reference

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    config = load_config()
    records_dir = os.environ.get("STICKSLIP_RECORDS_DIR") or str(ROOT.parent / "shared" / "records" / "paper")
    config["records_dir"] = records_dir
    with tempfile.TemporaryDirectory() as out_dir:
        for study, tables in REFERENCE_TABLES.items():
            study_module(study).run(config, Path(out_dir))
            for table in tables:
                print(write_reference(Path(out_dir) / "tables" / table, ROOT / "tests" / "references" / table))
    return 0


if __name__ == "__main__":
    sys.exit(main())
