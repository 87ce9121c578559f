"""Each study lives in one package, ``stickslip.studies.<study>``, wired by ``workflow/rules/<study>.smk``.

A study's computation, figures and index section sit in its package; the workflow file of the same name
calls only that package's steps; the package index (``stickslip.studies``) names every study; and
``stickslip.reports`` keeps only what several pages share.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import REPO_ROOT

import stickslip.studies

STUDIES = Path(stickslip.studies.__file__).resolve().parent
RULES = REPO_ROOT / "workflow" / "rules"
#: The workflow files that serve every study and so have no package: configuration, acquisition, pages.
SHARED_RULES = {"common", "records", "reports"}
#: A step or an index section named in a workflow file: ``"stickslip.studies.<study>[.<module>]:<function>"``.
STEP = re.compile(r"\"stickslip\.studies\.([a-z0-9_]+)[a-z0-9_.]*:[a-z_]+\"")


def study_packages(folder: Path = STUDIES) -> set[str]:
    """The names of the study packages under ``folder``."""
    return {path.parent.name for path in folder.glob("*/__init__.py")}


def study_rules(folder: Path = RULES) -> set[str]:
    """The names of the workflow files of studies under ``folder`` (``<study>.smk``)."""
    return {path.stem for path in folder.glob("*.smk")} - SHARED_RULES


def steps_elsewhere(rules: Path) -> list[str]:
    """The steps and index sections that ``rules`` calls from another study's package than its own."""
    return [match.group(0) for match in STEP.finditer(rules.read_text(encoding="utf-8"))
            if match.group(1) != rules.stem]


def test_every_study_package_has_its_workflow_file_and_every_workflow_file_its_package():
    assert study_packages() == study_rules()
    assert len(study_packages()) == 21


def test_a_workflow_file_calls_the_steps_of_its_own_study_only():
    assert {rules.stem: steps_elsewhere(rules) for rules in RULES.glob("*.smk") if steps_elsewhere(rules)} == {}


def test_the_check_sees_a_step_of_another_study(tmp_path):
    rules = tmp_path / "planar.smk"
    rules.write_text('STEP = "stickslip.studies.vertical.sweep:write_direction_sweep"\n'
                     'OWN = "stickslip.studies.planar.sweep:gather_planar_study"\n', encoding="utf-8")
    assert steps_elsewhere(rules) == ['"stickslip.studies.vertical.sweep:write_direction_sweep"']


def test_the_layout_check_sees_a_package_without_its_workflow_file(tmp_path):
    (tmp_path / "studies" / "orphan").mkdir(parents=True)
    (tmp_path / "studies" / "orphan" / "__init__.py").write_text('"""A study nothing runs."""\n', encoding="utf-8")
    (tmp_path / "rules").mkdir()
    (tmp_path / "rules" / "common.smk").write_text("", encoding="utf-8")
    assert study_packages(tmp_path / "studies") == {"orphan"}
    assert study_rules(tmp_path / "rules") == set()


@pytest.mark.parametrize("study", sorted(study_packages()))
def test_the_package_index_names_every_study(study):
    assert f":mod:`~stickslip.studies.{study}`" in stickslip.studies.__doc__


def test_reports_keeps_no_study_index_section():
    names = {path.stem for path in (STUDIES.parent / "reports").glob("*.py")}
    assert {name for name in names if name.endswith("_index")} == {"pages_index"}
