# Configuration, checked before any job runs, and what every rule file shares:
# which records each stage works on, the sweep grids, and the library files
# each step depends on (so that a rule reruns when, and only when, the code it
# uses changes).
import os
import sys
from pathlib import Path

from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

from stickslip.config import check_config_semantics
from stickslip.dependencies import library_sources
from stickslip.errors import StickslipError
from stickslip.records.manifest import load_manifest


# The project's configuration, whatever the working folder: a user's
# --configfile (or --config) is merged over it, key by key, so it need only
# hold the keys it changes.
configfile: str(Path(workflow.basedir) / "config" / "config.yaml")


validate(config, "../schemas/config.schema.yaml")

#: The Python of the environment Snakemake runs in (papermill and nbconvert are run as its modules).
PYTHON = sys.executable
#: The project (the folder of the Snakefile): notebooks and the step script live there.
PROJECT = Path(workflow.basedir)
STEP = str(PROJECT / "workflow" / "scripts" / "step.py")
#: The paper's printed values: an input of the comparison rules only.
PAPER_REFERENCE = str(PROJECT / "src" / "stickslip" / "reference" / "paper.yaml")

# A relative records_manifest is read from the working folder, else from the project.
if not Path(config["records_manifest"]).is_file() and (PROJECT / config["records_manifest"]).is_file():
    config["records_manifest"] = str(PROJECT / config["records_manifest"])
try:
    MANIFEST = load_manifest(config["records_manifest"])
    check_config_semantics(config, MANIFEST)
except StickslipError as error:
    raise WorkflowError(str(error)) from None

#: Local records folder: STICKSLIP_RECORDS_DIR overrides the config's records_dir.
RECORDS_DIR = os.environ.get("STICKSLIP_RECORDS_DIR") or config.get("records_dir")
RECORDS_DIR = str(Path(RECORDS_DIR).resolve()) if RECORDS_DIR else None

PAPER_RECORDS = list(config["paper_records"])
SCALING_RECORDS = list(config["scaling"]["records"] or PAPER_RECORDS)
MASS_RECORDS = list(config["mass_study"]["records"])
TIMESTEP_RECORD = config["timestep_study"]["record"]
REPORT_RECORDS = list(config.get("report_records", []))
#: The records of the single solved cases: Fig. 3's substitute and the shaking-table seismic record.
FIG3_RECORD = config["model_response"]["fig3"]["record"]
SEISMIC_RECORD = config["model_response"]["seismic"]["record"]

#: Sweep grids: what each one computes over, and the records it covers (in table order).
SWEEP_GRIDS = {
    "paper": {"mu": config["mu_grid"]},
    "fine": {"mu": config["fine_mu"], "refine": True},
    "scaled": {"mu": config["mu_grid"], "target_pga": [value * config["gravity"] for value in config["scaling"]["target_pga_g"]]},
    "mass": {"mu": config["fine_mu"], "masses": config["mass_study"]["masses"]},
}
GRID_RECORDS = {
    "paper": list(dict.fromkeys(PAPER_RECORDS + SCALING_RECORDS)),
    "fine": list(dict.fromkeys(PAPER_RECORDS + REPORT_RECORDS)),
    "scaled": SCALING_RECORDS,
    "mass": MASS_RECORDS,
}
#: Every record some stage needs.
ALL_RECORDS = list(dict.fromkeys(
    PAPER_RECORDS + SCALING_RECORDS + MASS_RECORDS + [TIMESTEP_RECORD] + REPORT_RECORDS + [FIG3_RECORD, SEISMIC_RECORD]
))


wildcard_constraints:
    record="[A-Za-z0-9_.-]+",
    grid="|".join(SWEEP_GRIDS),


def library(step):
    """The library files a step (``"module:function"``) depends on."""
    return library_sources([step])


def local_record_files(wildcards):
    """The record's files present in the records folder: a new or changed one reruns its acquisition."""
    if RECORDS_DIR is None:
        return []
    names = MANIFEST[wildcards.record].local_files
    return [str(Path(RECORDS_DIR) / name) for name in names if (Path(RECORDS_DIR) / name).is_file()]
