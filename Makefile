# stickslip: the two commands a user needs are `make reproduce` and `make test`.
# Both build .venv from environment.lock first, with uv (pinned and
# hash-checked in scripts/uv-requirements.txt); idempotent: nothing is redone
# while the lock and pyproject.toml are unchanged.

PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
UV := $(BIN)/uv
# --python: the environment is always .venv, whatever VIRTUAL_ENV says.
UV_ENV := --quiet --python $(BIN)/python
# stickslip itself, editable; `uv pip sync` removes it, so it follows every sync.
INSTALL_SELF := $(UV) pip install $(UV_ENV) --no-deps --no-build-isolation -e .
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

$(UV): scripts/uv-requirements.txt
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --require-hashes --no-deps -r scripts/uv-requirements.txt
	touch $@

# Exactly environment.lock (sync removes anything else).
$(STAMP): $(UV) environment.lock pyproject.toml scripts/install-system-packages.sh
	bash scripts/install-system-packages.sh
	$(UV) pip sync $(UV_ENV) --require-hashes environment.lock
	$(INSTALL_SELF)
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
