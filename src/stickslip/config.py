"""Loading the workflow configuration (``config/config.yaml``)."""

from __future__ import annotations

import os
from pathlib import Path

import yaml

from stickslip.errors import StickslipError

#: Project root when running from a checkout (``src/stickslip/config.py`` -> root).
PROJECT_ROOT = Path(__file__).resolve().parents[2]
DEFAULT_CONFIG = PROJECT_ROOT / "config" / "config.yaml"
#: JSON schema (written in YAML) that a configuration must follow.
CONFIG_SCHEMA = PROJECT_ROOT / "workflow" / "schemas" / "config.schema.yaml"


def load_config(path: str | Path | None = None) -> dict:
    """Parse and validate the configuration file; resolve relative paths.

    The parsed file is checked against ``workflow/schemas/config.schema.yaml``
    (when running from a checkout); a file that is not valid YAML, or that does
    not follow the schema, raises :class:`StickslipError` naming the file and
    the first problem.

    A relative ``records_dir`` or ``records_manifest`` in the file is taken from
    the project root (the folder above the configuration file's folder).  The
    environment variable ``STICKSLIP_RECORDS_DIR``, when set, overrides
    ``records_dir``; a relative value there is taken from the current directory.
    """
    path = Path(path) if path is not None else DEFAULT_CONFIG
    try:
        config = yaml.safe_load(path.read_text(encoding="utf-8"))
    except OSError as error:
        raise StickslipError(f"{path}: cannot read configuration ({error.strerror})") from None
    except UnicodeDecodeError as error:
        raise StickslipError(f"{path}: not a text file (not UTF-8 at byte {error.start})") from None
    except yaml.YAMLError as error:
        raise StickslipError(f"{path}: not valid YAML: {_yaml_problem(error)}") from None
    if not isinstance(config, dict):
        raise StickslipError(f"{path}: expected a mapping of settings at the top level")
    validate_config(config, path)
    root = path.resolve().parent.parent
    for key in ("records_dir", "records_manifest"):
        if config.get(key) and not Path(config[key]).is_absolute():
            config[key] = str((root / config[key]).resolve())
    env_dir = os.environ.get("STICKSLIP_RECORDS_DIR")
    if env_dir:
        config["records_dir"] = str(Path(env_dir).resolve())
    return config


def validate_config(config: dict, source: str | Path) -> None:
    """Check ``config`` against :data:`CONFIG_SCHEMA`; StickslipError naming ``source`` and the first problem.

    Nothing is checked when the schema file is absent (an installed package
    without the project's ``workflow`` folder).
    """
    if not CONFIG_SCHEMA.is_file():
        return
    import jsonschema

    schema = yaml.safe_load(CONFIG_SCHEMA.read_text(encoding="utf-8"))
    validator_class = jsonschema.validators.validator_for(schema)
    errors = sorted(validator_class(schema).iter_errors(config), key=lambda e: (list(e.absolute_path), e.message))
    if errors:
        error = jsonschema.exceptions.best_match(errors)
        where = "/".join(str(part) for part in error.absolute_path)
        raise StickslipError(f"{source}: {f'at {where}: ' if where else ''}{error.message}")


def _yaml_problem(error: yaml.YAMLError) -> str:
    """The first line of a YAML error, with the line and column (1-based) where it was found."""
    problem = getattr(error, "problem", None) or str(error).splitlines()[0]
    mark = getattr(error, "problem_mark", None)
    if mark is not None:
        return f"{problem} at line {mark.line + 1}, column {mark.column + 1}"
    return problem
