"""The test suite on several pytest-xdist workers (``make test``): one workflow run shared by all, slow modules first."""

from __future__ import annotations

import subprocess
import threading
import time
from pathlib import Path
from types import SimpleNamespace

import pytest

import conftest


class Base:
    """A stand-in for pytest's ``tmp_path_factory``: only its base folder."""

    def __init__(self, path: Path):
        path.mkdir(parents=True, exist_ok=True)
        self.path = path

    def getbasetemp(self) -> Path:
        return self.path


@pytest.fixture
def runs(monkeypatch) -> list[Path]:
    """The working folders the workflow was run in; a run takes 0.3 s and fails when its config file says so."""
    calls = []

    def snakemake(workdir: Path, configfile: Path, **kwargs) -> subprocess.CompletedProcess:
        calls.append(workdir)
        time.sleep(0.3)
        (workdir / "results").mkdir()
        failed = configfile.name == "broken.yaml"
        return subprocess.CompletedProcess([], 1 if failed else 0, "", "config broken: no such key" if failed else "")

    monkeypatch.setattr(conftest, "snakemake", snakemake)
    return calls


def test_two_workers_share_one_run_of_the_workflow(tmp_path, runs, monkeypatch):
    monkeypatch.setenv("PYTEST_XDIST_WORKER", "gw0")
    folders = {}

    def ask(worker):
        folder = conftest.workflow_run_once(Base(tmp_path / f"popen-{worker}"), "test_workflow", Path("test.yaml"))
        folders[worker] = (folder, (folder / "results").is_dir())  # given only once the run has finished

    threads = [threading.Thread(target=ask, args=(worker,)) for worker in ("gw0", "gw1")]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert runs == [tmp_path / "test_workflow"]  # in the run's folder, the workers' parent, once
    assert folders == {"gw0": (tmp_path / "test_workflow", True), "gw1": (tmp_path / "test_workflow", True)}


def test_without_xdist_the_run_is_in_the_session_s_own_folder(tmp_path, runs, monkeypatch):
    monkeypatch.delenv("PYTEST_XDIST_WORKER", raising=False)
    session = Base(tmp_path / "pytest-7")
    assert conftest.workflow_run_once(session, "paper_workflow", Path("config.yaml")) == session.path / "paper_workflow"
    assert conftest.workflow_run_once(session, "paper_workflow", Path("config.yaml")) == session.path / "paper_workflow"
    assert runs == [session.path / "paper_workflow"]


def test_a_failed_run_fails_every_test_that_needs_it_with_its_output_and_is_not_run_again(tmp_path, runs,
                                                                                          monkeypatch):
    monkeypatch.delenv("PYTEST_XDIST_WORKER", raising=False)
    session = Base(tmp_path)
    for _ in range(2):
        with pytest.raises(pytest.fail.Exception, match="the workflow run broken failed:\nconfig broken: no such key"):
            conftest.workflow_run_once(session, "broken", Path("broken.yaml"))
    assert runs == [tmp_path / "broken"]


def test_anything_made_once_is_shared_and_an_exception_fails_the_later_tests_too(tmp_path, monkeypatch):
    monkeypatch.delenv("PYTEST_XDIST_WORKER", raising=False)
    session, made = Base(tmp_path), []

    def verify(folder: Path) -> None:
        made.append(folder)
        (folder / "summary.json").write_text("{}", encoding="utf-8")

    for _ in range(2):
        assert conftest.made_once(session, "verified", verify, "the verification") == tmp_path / "verified"
    assert made == [tmp_path / "verified"] and (tmp_path / "verified" / "summary.json").is_file()

    def crash(folder: Path) -> None:
        raise ZeroDivisionError("no reference")

    with pytest.raises(ZeroDivisionError, match="no reference"):
        conftest.made_once(session, "crashed", crash, "the crashed step")
    with pytest.raises(pytest.fail.Exception, match=r"the crashed step failed:\nit did not finish \(see the test"):
        conftest.made_once(session, "crashed", crash, "the crashed step")


def test_the_modules_with_a_slow_test_come_first_each_whole_and_in_its_order():
    def item(module: str, name: str, slow: bool = False):
        return SimpleNamespace(path=Path(module), name=name,
                               get_closest_marker=lambda mark: object() if slow and mark == "slow" else None)

    items = [item("a.py", "a1"), item("a.py", "a2"), item("b.py", "b1"), item("b.py", "b2", slow=True),
             item("c.py", "c1"), item("d.py", "d1", slow=True)]
    conftest.pytest_collection_modifyitems(items)
    assert [entry.name for entry in items] == ["b1", "b2", "d1", "a1", "a2", "c1"]
