# stickslip: the two commands a user needs are `make reproduce` and `make test`.
# Both build .venv first, with uv (pinned and hash-checked in
# scripts/uv-requirements.txt): `make reproduce` installs the runtime,
# environment.lock, and needs no root; `make test` adds the test-only
# environment-test.lock and, when missing, the system libraries of openseespy
# (scripts/install-system-packages.sh). Idempotent: each part is redone only
# when its lock (or pyproject.toml) changes, and one stamp file per part keeps
# switching between the two from reinstalling anything.

PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed-runtime
TEST_STAMP := $(VENV)/.installed-test
UV := $(BIN)/uv
# --python: the environment is always .venv, whatever VIRTUAL_ENV says.
UV_ENV := --quiet --python $(BIN)/python
# stickslip itself, editable; `uv pip sync` removes it, so it follows every sync.
# Everything is byte-compiled at install (--compile-bytecode, and compileall for
# our own sources), so that start-up does not depend on PYTHONDONTWRITEBYTECODE:
# with it set and nothing compiled, every workflow job compiles its imports
# afresh (benchmarks/README.md, "Start-up").  The numba kernels are compiled
# too, into numba's cache beside the sources (src/stickslip/**/__pycache__),
# with the signatures the commands use, so that no first command compiles them
# (stickslip.cli.warm_up; benchmarks/README.md, "First calls").  The test environment
# reinstalls stickslip after its sync but keeps the runtime's numba cache: the
# sources are the same, so it does not warm up a second time.
INSTALL_EDITABLE := $(UV) pip install $(UV_ENV) --no-deps --no-build-isolation -e . \
	&& $(BIN)/python -m compileall -q src/stickslip
INSTALL_SELF := $(INSTALL_EDITABLE) && $(BIN)/python -m stickslip.cli.warm_up
SYNC := $(UV) pip sync $(UV_ENV) --require-hashes --compile-bytecode
# The cores to use: `make reproduce` runs that many Snakemake jobs at once, `make test` that many pytest workers.
CORES ?= 2
export MPLBACKEND := Agg
# One BLAS thread per process: the tests and the workflow's jobs already run one per core, and OpenBLAS's
# idle threads spin after each call, however small (20 calls of scipy.linalg.expm on a 12 x 12 matrix, 50 ms
# apart: 1.15 s of CPU with its threads, 0.00 s with one), taking the core from the other process.
export OPENBLAS_NUM_THREADS ?= 1
# The workflow's rules call the `stickslip` command of the environment.
export PATH := $(abspath $(BIN)):$(PATH)
# Records folder for the workflow: STICKSLIP_RECORDS_DIR if set, else the
# shared folder beside the checkout when it exists (see docs/records.md, "In the workflow").
STICKSLIP_RECORDS_DIR ?= $(wildcard $(abspath ../shared/records/paper))
export STICKSLIP_RECORDS_DIR
# The SLAMMER library for the collection study (docs/collections.md): likewise.
STICKSLIP_SLAMMER_DIR ?= $(wildcard $(abspath ../shared/records/slammer))
export STICKSLIP_SLAMMER_DIR
# The three-component records of the vertical-motion study (docs/studies.md): likewise.
STICKSLIP_THREE_COMPONENT_DIR ?= $(wildcard $(abspath ../shared/records/three_component))
export STICKSLIP_THREE_COMPONENT_DIR
# SLAMMER 1.1's own results for the verification (docs/solvers.md): likewise.
STICKSLIP_VERIFICATION_DIR ?= $(wildcard $(abspath ../shared/verification))
export STICKSLIP_VERIFICATION_DIR

.PHONY: help env test test-slurm reproduce report references lint lock benchmark clean-results

help:
	@echo "make env            build .venv from environment.lock (byte-compiled, numba kernels compiled); then use .venv/bin/stickslip,"
	@echo "                    or 'source .venv/bin/activate' to have stickslip, snakemake and papermill on PATH"
	@echo "make reproduce      build the environment, then run the whole Snakemake workflow (results/, reports/)"
	@echo "make test           build the environment with the test packages, then run the test suite, one pytest worker per core (CORES=2)"
	@echo "make report         Snakemake's own report of the last run (reports/snakemake-report.html)"
	@echo "make benchmark      run the speed benchmarks in benchmarks/ (not part of CI)"
	@echo "make lint           snakemake --lint on the workflow"
	@echo "make references     store the workflow's tables as the test suite's references (review the diff)"
	@echo "make lock           regenerate environment.lock and environment-test.lock (needs uv)"
	@echo "make test-slurm     start a single-node SLURM cluster here (root), run the .test/ workflow on it (not CI)"
	@echo "make clean-results  remove results/, reports/ and logs/"

env: $(STAMP)

$(UV): scripts/uv-requirements.txt
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --require-hashes --no-deps -r scripts/uv-requirements.txt
	touch $@

# The runtime: exactly environment.lock (sync removes anything else).
$(STAMP): $(UV) environment.lock pyproject.toml
	$(SYNC) environment.lock
	$(INSTALL_SELF)
	$(BIN)/python -m ipykernel install --sys-prefix --name python3 > /dev/null
	touch $(STAMP)

# The tests: the runtime plus environment-test.lock.
$(TEST_STAMP): $(STAMP) environment-test.lock scripts/install-system-packages.sh
	bash scripts/install-system-packages.sh
	$(SYNC) environment.lock environment-test.lock
	$(INSTALL_EDITABLE)
	touch $(TEST_STAMP)

# One pytest-xdist worker per core (CORES), each taking whole test modules (--dist loadfile): a module's
# fixtures are built once, and the tests of tests/test_workflow.py that edit the project's files run one after
# the other with those that plan a rerun of the finished workflow.  The modules start in the order that
# tests/conftest.py gives them, those with a slow test first (--no-loadscope-reorder: not the most tests first).
# What several modules read (the .test/ and the paper's workflow runs, the flexible block's verification) is
# made once for all workers: the first that needs it makes it, the others wait on a lock (made_once in
# tests/conftest.py).  docs/workflow.md ("The suite runs on ...") gives the modules' times.
test: $(TEST_STAMP)
	$(BIN)/python -m pytest --numprocesses $(CORES) --dist loadfile --no-loadscope-reorder

# The SLURM profile on a real SLURM: a single-node cluster on this machine
# (scripts/start-slurm-cluster.sh, needs root), then the small .test/ workflow
# through workflow/profiles/slurm in a temporary folder.  Passes when every job
# but the final `all` went through sbatch (each SLURM job id has its SLURM log)
# and the tables and the index are there.  Not part of `make test` (CI).
# The test cluster has no accounts; first status check after 5 s, not 40.
SLURM_TEST_FLAGS := --slurm-no-account --slurm-init-seconds-before-status-checks 5 --slurm-keep-successful-logs
test-slurm: $(STAMP)
	bash scripts/start-slurm-cluster.sh
	@set -e; start=$$(date +%s); tmp=$$(mktemp -d "$${TMPDIR:-/tmp}/stickslip-slurm.XXXXXX"); \
	fail() { echo "test-slurm: FAILED: $$1 (working folder kept: $$tmp)" >&2; exit 1; }; \
	echo "test-slurm: the .test/ workflow through workflow/profiles/slurm in $$tmp"; \
	env -u STICKSLIP_RECORDS_DIR $(BIN)/snakemake --snakefile Snakefile --directory "$$tmp" \
	    --configfile .test/config/config.yaml \
	    --profile workflow/profiles/slurm $(SLURM_TEST_FLAGS) > "$$tmp/snakemake.out" 2>&1 \
	    || { tail -n 30 "$$tmp/snakemake.out" >&2; fail "snakemake exited non-zero, see $$tmp/snakemake.out"; }; \
	log=$$(ls -t "$$tmp"/.snakemake/log/*.snakemake.log | head -n 1); \
	ids=$$(sed -n 's/.*has been submitted with SLURM jobid \([0-9][0-9]*\).*/\1/p' "$$log"); \
	[ -n "$$ids" ] || fail "no job submitted through sbatch in $$log"; \
	! grep '^localrule ' "$$log" | grep -v '^localrule all:' || fail "jobs ran outside SLURM, see $$log"; \
	for id in $$ids; do \
	    find "$$tmp/.snakemake/slurm_logs" -name "$$id.log" | grep -q . || fail "no SLURM log for SLURM job $$id"; \
	done; \
	ls "$$tmp"/results/tables/*.csv > /dev/null 2>&1 || fail "no tables in $$tmp/results/tables"; \
	[ -s "$$tmp/reports/index.html" ] || fail "no reports/index.html"; \
	grep -m 1 'has been submitted with SLURM jobid' "$$log"; \
	echo "test-slurm: passed: $$(echo $$ids | wc -w) jobs submitted through sbatch (SLURM jobs $$(echo $$ids | tr ' ' '\n' | sort -n | head -n 1)-$$(echo $$ids | tr ' ' '\n' | sort -n | tail -n 1)), $$(ls "$$tmp"/results/tables/*.csv | wc -l) tables, in $$(( $$(date +%s) - start )) s"; \
	rm -rf "$$tmp"

# A run that was killed leaves Snakemake's lock behind: release it first (the
# profile's rerun-incomplete then redoes whatever the killed run left unfinished).
reproduce: $(STAMP)
	$(BIN)/snakemake --unlock --cores 1 > /dev/null
	$(BIN)/snakemake --cores $(CORES) --profile workflow/profiles/default

report: $(STAMP)
	$(BIN)/snakemake --cores 1 --report reports/snakemake-report.html

# Store the studies' tables as the references the test suite compares against.
references: $(STAMP)
	$(BIN)/python scripts/update-references.py

lint: $(STAMP)
	$(BIN)/snakemake --lint

benchmark: $(STAMP)
	$(BIN)/python benchmarks/run.py

# The locks are generated, never edited by hand (uv keeps the current pins
# where it can; the test lock is constrained by environment.lock, so packages
# in both have the same version):
#   uv pip compile requirements.in --generate-hashes --python-version 3.11 \
#       --python-platform x86_64-manylinux_2_28 -o environment.lock
#   uv pip compile requirements-test.in --generate-hashes --python-version 3.11 \
#       --python-platform x86_64-manylinux_2_28 -o environment-test.lock
LOCK_FLAGS := --generate-hashes --python-version 3.11 --python-platform x86_64-manylinux_2_28
lock:
	uv pip compile requirements.in $(LOCK_FLAGS) -o environment.lock
	uv pip compile requirements-test.in $(LOCK_FLAGS) -o environment-test.lock

clean-results:
	rm -rf results reports logs
