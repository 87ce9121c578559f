"""``stickslip study NAME``: run one of the paper's studies and write its tables."""

from __future__ import annotations

from pathlib import Path

from stickslip.config import load_config
from stickslip.io import check_output_dir
from stickslip.studies import STUDIES, study_module


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "study",
        help="run one of the paper's studies (tables under results/)",
        description="Run one of the paper's studies and write its tables atomically.",
    )
    parser.add_argument("name", choices=sorted(STUDIES), help="the study to run")
    parser.add_argument("--config", type=Path, default=None, help="configuration file (default: config/config.yaml)")
    parser.add_argument(
        "--out-dir", type=Path, default=Path("results"),
        help="results folder: tables go to OUT_DIR/tables, cubes to OUT_DIR/sweeps (default: results)",
    )
    parser.set_defaults(func=run)


def run(args) -> int:
    config = load_config(args.config)
    for folder in (args.out_dir, args.out_dir / "tables", args.out_dir / "sweeps"):
        check_output_dir(folder, "the results")
    for path in study_module(args.name).run(config, args.out_dir):
        print(path)
    return 0
