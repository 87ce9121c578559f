# Configuration, checked before any job runs, and what the rule files share,
# which records each stage works on, the sweep grids, and the library files
# each step depends on (so that a rule reruns when, and only when, the code it
# uses changes).
import itertools
import json
import os
import sys
from pathlib import Path

from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

from stickslip.plumbing.config import check_config_semantics
from stickslip.plumbing.dependencies import library_sources
from stickslip.errors import StickslipError
from stickslip.records.manifest import DEFAULT_MANIFEST, load_manifest
from stickslip.studies.sweeps import grid_model


# The project's configuration, whatever the working folder: a user's
# --configfile (or --config) is merged over it, key by key, so it need only
# hold the keys it changes.
configfile: str(Path(workflow.basedir) / "config" / "config.yaml")


validate(config, "../schemas/config.schema.yaml")

#: The Python of the environment Snakemake runs in (papermill and nbconvert are run as its modules).
PYTHON = sys.executable


#: The shell command of every report page, written once: papermill runs {input.notebook} with the page's
#: parameters (one YAML mapping) into {output.notebook} through a .part file, its output to {log}.
PAPERMILL_SHELL = (f"MPLBACKEND=Agg {PYTHON} -m papermill -k python3 --log-output {{input.notebook}} "
                   "{output.notebook}.part.ipynb -y {params.parameters:q} > {log} 2>&1 "
                   "&& mv {output.notebook}.part.ipynb {output.notebook}")

#: Every report page, declared once with report_page() in the rule file of its stage; reports.smk
#: renders each with one rule, and the index page links each and shows its section, in the order of
#: their ranks (report_pages()), whatever the order in which the rule files are included.
REPORT_PAGES = {}
#: Whether reports.smk has made the pages' rules: a page declared after that would have none.
REPORT_RULES_MADE = False


def report_page(name, *, rank, rule_name, title, notebook, inputs, parameters, figures, category, caption,
                figures_dir, each=None, index_section=None, index_inputs=(), rendered=True):
    """Declare a report page: the notebook reports/{name}.ipynb and its page reports/html/{name}.html.

    ``rank``: its place among the pages, a number of its own (smaller first: the order of the index's
    sections); ``rule_name``: the name of its rendering rule; ``title``: its link text on the index;
    ``notebook``: the notebook's path (under the project); ``inputs``: named inputs (files or input functions);
    ``parameters``: the notebook's parameters, values or functions of (wildcards, input, output),
    passed with ``figures_dir`` (reports/figures/{figures_dir}) and ``figure_alts``; ``figures``: the
    PNG names it writes, each with its alternative text (the notebook shows it, the index too), and a
    Snakemake report item of ``category`` with ``caption``, a file of workflow/report/; ``each``: the
    wildcard values of a page rendered once per value, such as {"record": [...]} (names and texts may
    hold those wildcards); ``index_section``: ("module:function", arguments) of its section on the
    index, which reads ``index_inputs``; ``rendered``: False when its data are not here (the section still is).
    """
    where = f"report_page {name!r}"
    if REPORT_RULES_MADE:
        raise WorkflowError(f"{where} is declared after workflow/rules/reports.smk made the pages' rules: "
                            "include its rule file before reports.smk")
    if name in REPORT_PAGES:
        raise WorkflowError(f"{where} is declared twice")
    holder = next((other for other, page in REPORT_PAGES.items() if page["rank"] == rank), None)
    if holder is not None:
        raise WorkflowError(f"{where}: rank {rank} is report_page {holder!r}'s; give it a rank of its own")
    paths = {str(Path("reports/figures", figures_dir, figure)): alt for figure, alt in figures.items()}
    REPORT_PAGES[name] = {
        "rank": rank, "rule": rule_name, "title": title, "notebook": str(PROJECT / notebook), "inputs": dict(inputs),
        "parameters": dict(parameters), "figures": list(paths), "alts": paths,
        "category": category, "caption": f"../report/{caption}", "each": dict(each or {}),
        # a page rendered per wildcard value has its figures grouped by that value in Snakemake's report
        "subcategory": " ".join(f"{{{wildcard}}}" for wildcard in each or {}) or None,
        "index_section": index_section, "index_inputs": list(index_inputs), "rendered": rendered,
    }


def report_pages():
    """The declared pages, ``(name, page)`` in the order of their ranks."""
    return sorted(REPORT_PAGES.items(), key=lambda item: item[1]["rank"])


def page_parameters(page):
    """A params function: the page's notebook parameters, as one JSON (so YAML) mapping for papermill's -y.

    Adds ``figures_dir`` and ``figure_alts`` (each figure's file name and alternative text, wildcards filled).
    """
    def parameters(wildcards, input, output):
        values = {"figures_dir": str(Path(output.figures[0]).parent),
                  "figure_alts": {Path(path.format(**wildcards)).name: alt.format(**wildcards)
                                  for path, alt in page["alts"].items()}}
        for key, value in page["parameters"].items():
            values[key] = value(wildcards, input, output) if callable(value) else value
        return json.dumps(values)

    return parameters


def figure_alts():
    """Every declared figure's path (reports/figures/...) and its alternative text (the index's thumbnails), wildcards filled."""
    alts = {}
    for page in REPORT_PAGES.values():
        for path, alt in page["alts"].items():
            for wildcards in [dict(zip(page["each"], values)) for values in itertools.product(*page["each"].values())]:
                alts[path.format(**wildcards)] = alt.format(**wildcards)
    return alts


def page_html(name):
    """The HTML pages of a declared page (one per value of its ``each`` wildcards)."""
    page = REPORT_PAGES[name]
    return expand(f"reports/html/{name}.html", **page["each"]) if page["rendered"] else []
#: The project (the folder of the Snakefile): notebooks and the step script live there.
PROJECT = Path(workflow.basedir)
STEP = str(PROJECT / "workflow" / "scripts" / "step.py")
#: The paper's printed values: an input of the comparison rules only.
PAPER_REFERENCE = str(PROJECT / "src" / "stickslip" / "reference" / "paper.yaml")

# No records_manifest: the one shipped with stickslip.  A relative one is read
# from the working folder, else from the project.
if not config["records_manifest"]:
    config["records_manifest"] = str(DEFAULT_MANIFEST)
elif not Path(config["records_manifest"]).is_file() and (PROJECT / config["records_manifest"]).is_file():
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

#: Sweep grids: what each one computes over (and, where sweep_grids sets them, its model and the model's
#: parameters), and the records it covers (in table order).
SWEEP_GRIDS = {
    "paper": {"mu": config["mu_grid"]},
    "fine": {"mu": config["fine_mu"], "refine": True, "near_optimal_fraction": config["mu_max"]["near_optimal_fraction"]},
    "scaled": {"mu": config["mu_grid"], "target_pga": [value * config["gravity"] for value in config["scaling"]["target_pga_g"]]},
    "mass": {"mu": config["fine_mu"], "masses": config["mass_study"]["masses"]},
}
for _grid, _model in (config.get("sweep_grids") or {}).items():
    SWEEP_GRIDS[_grid].update(_model)
    try:
        grid_model(SWEEP_GRIDS[_grid], f"configuration: sweep_grids.{_grid}")
    except StickslipError as error:
        raise WorkflowError(str(error)) from None
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


# The collection study (collections.smk, jibson2007.smk): which records, in which chunks.
from stickslip.collections.collection import load_collection, selected_ids, study_collection

STUDY_CONFIG = config["collection_study"]


def resolved_collection(settings):
    """The collection the study runs on: kind, folder (absolute), metadata table, download, a folder's dt and units."""
    slammer_dir = os.environ.get("STICKSLIP_SLAMMER_DIR") or settings["folder"]
    kind = settings["collection"]
    if kind == "auto":
        found = slammer_dir and load_collection("slammer", slammer_dir).has_local_files()
        kind = "slammer" if found else "pyslammer"
    folder = slammer_dir if kind == "slammer" else settings["folder"] if kind == "folder" else None
    return {"kind": kind, "folder": str(Path(folder).resolve()) if folder else None,
            "metadata": str(Path(settings["metadata"]).resolve()) if settings["metadata"] else None,
            "download": bool(settings["download"]), "dt": settings["dt"], "units": settings["units"]}


try:
    COLLECTION = resolved_collection(STUDY_CONFIG)
    STUDY_IDS, STUDY_NOT_HERE = selected_ids(COLLECTION, STUDY_CONFIG["filters"])
except StickslipError as error:
    raise WorkflowError(f"collection_study: {error}") from None
if not STUDY_IDS:
    raise WorkflowError(
        f"collection_study: no record of the {COLLECTION['kind']} collection is here "
        f"({len(STUDY_NOT_HERE)} selected; folder {COLLECTION['folder']}). Set collection_study.folder "
        "(or STICKSLIP_SLAMMER_DIR), or download: true"
    )
STUDY = COLLECTION["kind"]
STUDY_DIR = f"results/collections/{STUDY}"
#: The records in the fewest chunks of at most chunk_size, each as large as the first (521 records in
#: chunks of at most 250: 174, 174 and 173, not 250, 250 and 21), so that the chunks' jobs take about as long.
CHUNK_SIZE = -(-len(STUDY_IDS) // -(-len(STUDY_IDS) // STUDY_CONFIG["chunk_size"]))
STUDY_CHUNKS = [f"{start // CHUNK_SIZE:03d}" for start in range(0, len(STUDY_IDS), CHUNK_SIZE)]


def chunk_ids(wildcards):
    start = int(wildcards.chunk) * CHUNK_SIZE
    return STUDY_IDS[start:start + CHUNK_SIZE]


def chunk_files(wildcards):
    """The chunk's record files here: a changed or new file reruns its acquisition."""
    if COLLECTION["kind"] == "pyslammer":
        return []
    source = study_collection(COLLECTION)
    files = (source.local_file(record_id) for record_id in chunk_ids(wildcards))
    return [str(path) for path in files if path is not None]
