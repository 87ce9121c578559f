"""``python -m stickslip.cli.warm_up``: compile every model's numba kernels into numba's cache, as ``make env`` does.

It runs :func:`stickslip.models.warm_up.warm_up` and says on stderr what it
warmed up and in how long [s]; a warning is one ``stickslip: warning:`` line,
as the command line prints it.
"""

from __future__ import annotations

import sys
import time
import warnings

from stickslip.cli import _show_warning
from stickslip.models.warm_up import warm_up


def main() -> int:
    """Warm up, and say what and in how long."""
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.showwarning = _show_warning
        done = warm_up()
    print(f"numba kernels compiled or loaded for {', '.join(done)} and the bulk reader in "
          f"{time.perf_counter() - start:.0f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
