# stickslip: the two commands a user needs are `make reproduce` and `make test`.
# Both build .venv from environment.lock first (idempotent: nothing is redone
# while the lock and pyproject.toml are unchanged).

PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
CORES ?= 2
export MPLBACKEND := Agg
# The workflow's rules call the `stickslip` command of the environment.
export PATH := $(abspath $(BIN)):$(PATH)
# Records folder for the workflow: STICKSLIP_RECORDS_DIR if set, else the
# shared folder beside the checkout when it exists (see README, "Records").
STICKSLIP_RECORDS_DIR ?= $(wildcard $(abspath ../shared/records/paper))
export STICKSLIP_RECORDS_DIR

.PHONY: help env test reproduce references lint lock benchmark clean-results

help:
	@echo "make reproduce   build the environment, then run the whole Snakemake workflow"
	@echo "make test        build the environment, then run the test suite"
	@echo "make benchmark   run the speed benchmarks in benchmarks/ (not part of CI)"
	@echo "make references  store the studies' tables as the test suite's references"
	@echo "make lock        regenerate environment.lock from requirements.in (needs uv)"

env: $(STAMP)

$(STAMP): environment.lock pyproject.toml scripts/install-system-packages.sh
	bash scripts/install-system-packages.sh
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --require-hashes --no-deps -r environment.lock
	$(BIN)/python -m pip install --quiet --no-deps --no-build-isolation -e .
	$(BIN)/python -m ipykernel install --sys-prefix --name python3 > /dev/null
	touch $(STAMP)

test: $(STAMP)
	$(BIN)/python -m pytest

reproduce: $(STAMP)
	$(BIN)/snakemake --cores $(CORES) --profile workflow/profiles/default

# Store the studies' tables as the references the test suite compares against.
references: $(STAMP)
	$(BIN)/python scripts/update-references.py

lint: $(STAMP)
	$(BIN)/snakemake --lint

benchmark: $(STAMP)
	$(BIN)/python benchmarks/run.py

# The lock is generated, never edited by hand:
#   uv pip compile requirements.in --generate-hashes --python-version 3.11 \
#       --python-platform x86_64-manylinux_2_28 -o environment.lock
lock:
	uv pip compile requirements.in --generate-hashes --python-version 3.11 \
	    --python-platform x86_64-manylinux_2_28 -o environment.lock

clean-results:
	rm -rf results reports
