"""A ``--vertical-positive`` that contradicts the vertical file's label is refused unless ``--any-vertical``.

A PEER file labelled ``DWN`` (or ``UP``) says which way its positive axis
points; a ``--vertical-positive`` that says otherwise would silently flip the
vertical (V/W +15 % at one station).  It is one error line naming the label,
unless ``--any-vertical`` takes the option's sense all the same; the output
(text and ``--json``) says which sense was used and what said so: the label
or the option.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from conftest import assert_one_error_line

from stickslip.errors import StickslipError
from stickslip.records.record import Record, RecordMeta
from stickslip.records.vertical import WithVertical

DT = 0.01


def record(acceleration, component: str, source: str) -> Record:
    return Record(np.asarray(acceleration, dtype=float), DT,
                  RecordMeta(record_id=source.split(".")[0], source=source, component=component, event="Wave",
                             station="Here"))


@pytest.fixture
def motions():
    time = np.arange(0.0, 8.0, DT)
    horizontal = record(3.0 * np.sin(2 * np.pi * 1.3 * time) * np.exp(-0.3 * time), "000", "wave-000.txt")
    down = record(-4.0 * np.sin(2 * np.pi * 4.1 * time) * np.exp(-0.4 * time), "DWN", "wave-DWN.txt")
    return horizontal, down


def test_a_sense_given_against_the_label_is_refused_unless_any_vertical(motions):
    horizontal, down = motions
    with pytest.raises(StickslipError) as caught:
        WithVertical.of(horizontal, down, "up")
    assert str(caught.value) == ("wave-DWN.txt: --vertical-positive up contradicts its label: DWN in its component says "
                                 "positive down; leave the option out, or read it positive up all the same with "
                                 "--any-vertical (any_vertical=True)")
    by_label = WithVertical.of(horizontal, down)
    agreeing = WithVertical.of(horizontal, down, "down")
    overridden = WithVertical.of(horizontal, down, "up", any_vertical=True)
    assert (by_label.positive, by_label.sense_from, by_label.against_label) == ("down", "label", None)
    assert by_label.sense == "positive down (DWN in its component), turned positive up"
    assert (agreeing.sense_from, agreeing.sense) == ("label", "positive down (DWN in its component, as given), turned "
                                                              "positive up")
    assert (overridden.positive, overridden.sense_from, overridden.against_label) == ("up", "option",
                                                                                      "DWN in its component")
    assert overridden.sense == "positive up (as given, against DWN in its component)"
    np.testing.assert_array_equal(agreeing.vertical.acceleration, -down.acceleration)
    np.testing.assert_array_equal(overridden.vertical.acceleration, down.acceleration)


@pytest.fixture
def files(tmp_path, motions):
    paths = {}
    for motion in motions:
        path = tmp_path / motion.meta.source
        time = np.arange(motion.npts) * DT
        path.write_text("\n".join(f"{t:.2f} {a:.9e}" for t, a in zip(time, motion.acceleration)) + "\n")
        paths[motion.meta.component] = path
    return paths


def test_the_command_line_refuses_the_contradiction_and_says_which_sense_it_used(run_cli, files):
    solve = ("solve", files["000"], "--units", "m/s2", "--mu", "0.05", "--radius", "2", "--vertical", files["DWN"])
    assert_one_error_line(*run_cli(*solve, "--vertical-positive", "up"), "wave-DWN",
                          "--vertical-positive up contradicts its label: DWN in its file name says positive down")
    code, out, err = run_cli(*solve, "--json")
    assert code == 0 and err == "", err
    document = json.loads(out)
    assert (document["vertical_positive"], document["vertical_sense_from"]) == ("down", "label")
    assert document["vertical_sense"] == "positive down (DWN in its file name), turned positive up"
    code, out, err = run_cli(*solve, "--vertical-positive", "up", "--any-vertical", "--json")
    assert code == 0 and err == (f"stickslip: note: {files['DWN']}: taken as the vertical with --any-vertical, read positive "
                                 "up (--vertical-positive) against DWN in its file name\n")
    overridden = json.loads(out)
    assert (overridden["vertical_positive"], overridden["vertical_sense_from"]) == ("up", "option")
    assert overridden["any_vertical_note"] == "read positive up (--vertical-positive) against DWN in its file name"
    assert overridden["energy_dissipated"] != document["energy_dissipated"]
    code, out, err = run_cli(*solve, "--vertical-positive", "up", "--any-vertical")
    assert code == 0 and "with its vertical read positive up (as given, against DWN in its file name)" in out
    assert "vertical taken with --any-vertical, read positive up (--vertical-positive) against DWN in its file name" in out
