# One workflow step: the library function named by the rule's params.step,
# called with the rule's named input, output and params (see stickslip.plumbing.step).
from stickslip.plumbing.step import run_step

run_step(snakemake)  # noqa: F821 (Snakemake defines `snakemake` in scripts)
