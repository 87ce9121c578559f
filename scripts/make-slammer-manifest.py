#!/usr/bin/env python3
"""Generate the SLAMMER collection's manifest, src/stickslip/data/slammer_library.csv.

Usage:
    python scripts/make-slammer-manifest.py SLAMMER_DIR [OUTPUT]

SLAMMER_DIR holds the library's database ``eq.sql`` and ``sha256.csv`` (the
SHA-256 and size of every record file: ``path,sha256,bytes``), as in
``../shared/records/slammer``.  OUTPUT defaults to the package data file.
The manifest has one row per record of ``eq.sql`` (columns and units:
``stickslip.collections.slammer.MANIFEST_COLUMNS``, docs/collections.md).
"""

import sys
from pathlib import Path

from stickslip.collections.slammer import slammer_manifest
from stickslip.plumbing.files import write_text_atomic

DEFAULT_OUTPUT = Path(__file__).resolve().parent.parent / "src" / "stickslip" / "data" / "slammer_library.csv"


def main(argv: list[str]) -> int:
    if len(argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    folder = Path(argv[1])
    output = Path(argv[2]) if len(argv) == 3 else DEFAULT_OUTPUT
    table = slammer_manifest(folder / "eq.sql", folder / "sha256.csv")
    write_text_atomic(output, table.to_csv(index=False, lineterminator="\n"))
    print(f"{output}: {len(table)} records")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
