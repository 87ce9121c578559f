# Configuration, validated against the schema before any rule runs.
from pathlib import Path

from snakemake.utils import validate

configfile: "config/config.yaml"
validate(config, "../schemas/config.schema.yaml")

CONFIG_FILE = "config/config.yaml"
TIMESTEP_RECORD = config["timestep_study"]["record"]

# Every rule that computes depends on the package's code, so a change to the
# library reruns what it may have changed.
PACKAGE_SOURCES = sorted(str(path) for path in Path("src/stickslip").rglob("*.py"))

