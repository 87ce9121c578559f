"""Loading the workflow configuration (``config/config.yaml``)."""

from __future__ import annotations

import os
from pathlib import Path

import yaml

from stickslip.errors import StickslipError

#: Project root when running from a checkout (``src/stickslip/config.py`` -> root).
PROJECT_ROOT = Path(__file__).resolve().parents[2]
DEFAULT_CONFIG = PROJECT_ROOT / "config" / "config.yaml"


def load_config(path: str | Path | None = None) -> dict:
    """Parse the configuration file; resolve relative paths against the project root.

    ``records_dir`` is overridden by the environment variable ``STICKSLIP_RECORDS_DIR``.
    """
    path = Path(path) if path is not None else DEFAULT_CONFIG
    try:
        config = yaml.safe_load(path.read_text(encoding="utf-8"))
    except OSError as error:
        raise StickslipError(f"{path}: cannot read configuration ({error.strerror})") from None
    except yaml.YAMLError as error:
        raise StickslipError(f"{path}: not valid YAML ({error})") from None
    if not isinstance(config, dict):
        raise StickslipError(f"{path}: expected a mapping of settings at the top level")
    root = path.resolve().parent.parent
    env_dir = os.environ.get("STICKSLIP_RECORDS_DIR")
    if env_dir:
        config["records_dir"] = env_dir
    for key in ("records_dir", "records_manifest"):
        if config.get(key):
            config[key] = str((root / config[key]).resolve()) if not Path(config[key]).is_absolute() else config[key]
    return config
