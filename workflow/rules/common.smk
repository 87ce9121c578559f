# Configuration, validated against the schema before any rule runs.
from snakemake.utils import validate

configfile: "config/config.yaml"
validate(config, "../schemas/config.schema.yaml")

CONFIG_FILE = "config/config.yaml"

