"""The workflow configuration (``config/config.yaml`` in a checkout): loading and the checks on it.

The workflow reads its configuration itself (Snakemake's ``configfile:`` and
``validate``) and calls :func:`check_config_semantics` for what a schema cannot
say; :func:`load_config` does the same for a caller outside the workflow.
Nothing here reads a file that the caller did not name.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import yaml

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.grids import checked_range, positive_increasing, range_values


def load_config(path: str | Path, schema: str | Path | None = None) -> dict:
    """Parse the configuration file ``path``, check it against ``schema`` when given, resolve relative paths.

    ``schema`` is a JSON schema written in YAML (the workflow's is
    ``workflow/schemas/config.schema.yaml``); a file that is not valid YAML,
    or that does not follow the schema, raises :class:`StickslipError` naming
    the file and the first problem.

    A relative ``records_dir`` or ``records_manifest`` in the file is taken from
    the project root (the folder above the configuration file's folder).  The
    environment variable ``STICKSLIP_RECORDS_DIR``, when set, overrides
    ``records_dir``; a relative value there is taken from the current directory.
    """
    path = Path(path)
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
    if schema is not None:
        validate_config(config, path, schema)
    root = path.resolve().parent.parent
    for key in ("records_dir", "records_manifest"):
        if config.get(key) and not Path(config[key]).is_absolute():
            config[key] = str((root / config[key]).resolve())
    env_dir = os.environ.get("STICKSLIP_RECORDS_DIR")
    if env_dir:
        config["records_dir"] = str(Path(env_dir).resolve())
    return config


def validate_config(config: dict, source: str | Path, schema_path: str | Path) -> None:
    """Check ``config`` against the schema file ``schema_path``; StickslipError naming ``source`` and the first problem."""
    import jsonschema

    schema = yaml.safe_load(Path(schema_path).read_text(encoding="utf-8"))
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


def check_config_semantics(config: dict, manifest_ids) -> None:
    """What the schema cannot check: increasing grids, ranges, and record ids that the manifest knows.

    Raises :class:`StickslipError` with every problem found, each naming its
    key and what is allowed.  ``manifest_ids`` are the ids of the record manifest.
    """
    problems = []
    known = set(manifest_ids)

    def checked(check, *arguments, **keywords) -> None:
        try:
            check(*arguments, **keywords)
        except StickslipError as error:
            problems.append(str(error))

    def increasing(key: str, values, zero_allowed: bool = False) -> None:
        if values is not None:
            checked(positive_increasing, values, key, zero_allowed=zero_allowed)

    def start_stop_step(key: str, grid) -> None:
        if grid:
            checked(checked_range, grid["start"], grid["stop"], grid["step"], key, min_values=2)

    def records(key: str, ids) -> None:
        unknown = [record_id for record_id in ids or [] if record_id not in known]
        if unknown:
            problems.append(f"{key}: unknown record id(s) {', '.join(map(repr, unknown))}; allowed: the ids of "
                            f"the manifest {config.get('records_manifest', '')} (`stickslip records list`)")

    increasing("mu_grid", config.get("mu_grid"))
    increasing("scaling.target_pga_g", config.get("scaling", {}).get("target_pga_g"))
    increasing("mass_study.masses", config.get("mass_study", {}).get("masses"))
    start_stop_step("fine_mu", config.get("fine_mu"))
    timestep = config.get("timestep_study", {})
    steps = sorted(timestep.get("time_steps", []))
    for step in steps[1:]:
        if abs(step / steps[0] - round(step / steps[0])) > 1e-9 or step == steps[0]:
            problems.append(f"timestep_study.time_steps: {step} is not a distinct whole multiple of the smallest, "
                            f"{steps[0]} s")
    study = config.get("collection_study", {})
    start_stop_step("collection_study.mu", study.get("mu"))
    increasing("collection_study.pga_bands_g", study.get("pga_bands_g"), zero_allowed=True)
    increasing("jibson2007.critical_accelerations_g", config.get("jibson2007", {}).get("critical_accelerations_g"))
    estimates = config.get("estimates", {})
    increasing("estimates.ky", estimates.get("ky"))
    increasing("estimates.site_periods", estimates.get("site_periods"))
    solved = config.get("jibson2007", {}).get("critical_accelerations_g") or []
    unsolved = [ky for ky in estimates.get("ky") or [] if not any(abs(ky - value) <= 1e-12 for value in solved)]
    if unsolved:
        problems.append(f"estimates.ky: {', '.join(map(str, unsolved))} not among jibson2007.critical_accelerations_g "
                        f"({', '.join(map(str, solved))}), whose rigid D_n the study reuses")
    vertical = config.get("vertical_study", {})
    ranges = vertical.get("mu") or []
    for index, grid in enumerate(ranges):
        start_stop_step(f"vertical_study.mu[{index}]", grid)
    if ranges and not problems and "reference_mu" in vertical:
        values = [value for grid in ranges for value in range_values(grid["start"], grid["stop"], grid["step"])]
        if not any(abs(value - vertical["reference_mu"]) <= 1e-12 for value in values):
            problems.append(f"vertical_study.reference_mu: {vertical['reference_mu']} is not a value of "
                            "vertical_study.mu, where the demands are compared")
    codes = config.get("code_vs_exact", {})
    increasing("code_vs_exact.radii", codes.get("radii"))
    increasing("code_vs_exact.mu", codes.get("mu"))
    increasing("code_vs_exact.d_over_r_edges", codes.get("d_over_r_edges"))
    periods, radii = codes.get("spectrum_periods"), codes.get("radii") or []
    if periods and radii and math.isfinite(max(radii)):
        swing = 2.0 * math.pi * math.sqrt(max(radii) / config.get("gravity", STANDARD_GRAVITY))
        if not periods["shortest"] < swing <= periods["longest"]:
            problems.append(f"code_vs_exact.spectrum_periods: {periods['shortest']:g}-{periods['longest']:g} s must "
                            f"hold the free swing's period 2 pi sqrt(R/g) = {swing:.3f} s of the largest radius, the "
                            "longest T_eff")
    elif radii and not math.isfinite(max(radii)):
        problems.append("code_vs_exact.radii: each must be finite [m] (the codes design a curved surface)")
    if study.get("collection") == "folder" and not study.get("folder"):
        problems.append("collection_study.folder: a folder collection needs the folder of its .AT2 files")
    records("paper_records", config.get("paper_records"))
    records("scaling.records", config.get("scaling", {}).get("records"))
    records("mass_study.records", config.get("mass_study", {}).get("records"))
    records("report_records", config.get("report_records"))
    records("timestep_study.record", [timestep["record"]] if "record" in timestep else [])
    model = config.get("model_response", {})
    for key in ("fig3", "seismic"):
        records(f"model_response.{key}.record", [model[key]["record"]] if "record" in model.get(key, {}) else [])
    if problems:
        raise StickslipError("configuration: " + "; ".join(problems))
