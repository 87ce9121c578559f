"""A vertical component is taken only as the same station's: a horizontal file, another station's or event's is refused.

What the files' headers and names say decides
(:func:`stickslip.records.vertical.vertical_doubt`): ``STA-090`` names a
horizontal direction, ``OTH-UP`` another station than ``STA-000``'s, and a
horizontal motion that is itself a vertical (``STA-UP`` given as the
horizontal) is refused too.  ``--any-vertical`` (``any_vertical=True``)
takes the file all the same, and every output says what the names said
against it.  Names that say nothing (``wave.txt``) raise no doubt.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr
from conftest import assert_one_error_line

import stickslip
from stickslip.errors import StickslipError
from stickslip.records.pair import RecordPair
from stickslip.records.vertical import WithVertical, vertical_doubt

DT = 0.01
SAMPLES = 1500


def write_motion(path, seed: int, pga_g: float):
    """A random tapered motion of :data:`SAMPLES` samples with the PGA ``pga_g`` [g], as time [s] and acceleration [g]."""
    values = np.random.default_rng(seed).normal(size=SAMPLES) * np.hanning(SAMPLES)
    time = np.arange(SAMPLES) * DT
    np.savetxt(path, np.column_stack([time, pga_g * values / np.max(np.abs(values))]), fmt="%.8f")
    return path


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> dict:
    """Station STA's three components, station OTH's vertical, and two files whose names say nothing."""
    folder = tmp_path_factory.mktemp("components")
    motions = {"STA-000": (1, 0.4), "STA-090": (2, 0.35), "STA-UP": (3, 0.25), "OTH-UP": (4, 0.25),
               "wave": (5, 0.4), "vert": (6, 0.25)}
    return {name: write_motion(folder / f"{name}.txt", seed, pga) for name, (seed, pga) in motions.items()}


def read(path):
    return stickslip.read_record(path, units="g")


@pytest.mark.parametrize(("horizontal", "vertical", "doubt"), [
    ("STA-000", "STA-090", "its file name STA-090 is a horizontal direction"),
    ("STA-000", "OTH-UP", "come from different stations (STA and OTH)"),
    ("STA-UP", "STA-UP", "is itself a vertical component (its file name STA-UP ends in UP)"),
])
def test_a_vertical_its_names_doubt_is_refused_in_one_message(files, horizontal, vertical, doubt):
    with pytest.raises(StickslipError) as raised:
        WithVertical.of(read(files[horizontal]), read(files[vertical]), "up")
    message = str(raised.value)
    assert message.startswith(f"{files[vertical]}: not the same station's vertical component: ")
    assert doubt in message and "--any-vertical" in message


def test_the_same_stations_vertical_and_names_that_say_nothing_are_taken(files):
    pair = RecordPair(read(files["STA-000"]), read(files["STA-090"]))
    for horizontal, vertical in ((read(files["STA-000"]), files["STA-UP"]), (pair, files["STA-UP"]),
                                 (read(files["wave"]), files["vert"])):
        motion = WithVertical.of(horizontal, read(vertical), "up")
        assert motion.doubt is None and motion.any_vertical is False


def test_a_pair_with_another_stations_vertical_is_refused(files):
    pair = RecordPair(read(files["STA-000"]), read(files["STA-090"]))
    assert "different stations (STA and OTH)" in vertical_doubt(pair, read(files["OTH-UP"]))


def test_any_vertical_takes_it_and_keeps_what_the_names_said(files):
    horizontal, vertical = read(files["STA-000"]), read(files["OTH-UP"])
    motion = WithVertical.of(horizontal, vertical, any_vertical=True)
    assert motion.any_vertical is True and "different stations (STA and OTH)" in motion.doubt
    np.testing.assert_array_equal(motion.vertical.acceleration, vertical.acceleration)
    unnamed = WithVertical.of(read(files["wave"]), read(files["vert"]), "up")
    assert (stickslip.solve(motion, mu=0.05, radius=2.0).scalars()["energy_dissipated"] !=
            stickslip.solve(unnamed, mu=0.05, radius=2.0).scalars()["energy_dissipated"])


def test_the_command_line_refuses_another_stations_vertical_in_one_line(run_cli, files):
    assert_one_error_line(*run_cli("solve", files["STA-000"], "--units", "g", "--mu", "0.05", "--radius", "2",
                                   "--vertical", files["OTH-UP"]),
                          files["OTH-UP"], "not the same station's vertical component")
    assert_one_error_line(*run_cli("optimum", files["STA-000"], files["STA-090"], "--pair", "--units", "g",
                                   "--radius", "2", "--vertical", files["STA-090"], "--vertical-positive", "up"),
                          files["STA-090"], "is a horizontal direction")
    assert_one_error_line(*run_cli("solve", files["STA-000"], "--units", "g", "--mu", "0.05", "--any-vertical"),
                          "--any-vertical", "applies with --vertical only")


def test_any_vertical_on_the_command_line_says_so_in_every_output(run_cli, files, tmp_path):
    args = ("solve", files["STA-000"], "--units", "g", "--mu", "0.05", "--radius", "2", "--vertical", files["OTH-UP"],
            "--any-vertical")
    said = "although it and STA-000.txt come from different stations (STA and OTH)"
    code, out, err = run_cli(*args)
    assert code == 0
    assert err == f"stickslip: note: {files['OTH-UP']}: taken as the vertical with --any-vertical, {said}\n"
    assert out.splitlines()[1] == f"vertical taken with --any-vertical, {said}"
    code, out, _ = run_cli(*args, "--json")
    document = json.loads(out)
    assert code == 0 and document["any_vertical"] is True and document["any_vertical_note"] == said
    code, out, _ = run_cli("optimum", *args[1:4], "--radius", "2", "--vertical", files["OTH-UP"], "--any-vertical",
                           "--mu", "0.02:0.2:0.02", "--json")
    assert code == 0 and said in json.loads(out)["records"][0]["with_vertical"]
    for command in ("sweep", "optimum"):  # the cube's configuration names the vertical and how it was taken
        cube = tmp_path / f"{command}.nc"
        code, _, _ = run_cli(command, *args[1:4], "--radius", "2", "--vertical", files["OTH-UP"], "--any-vertical",
                             "--mu", "0.02:0.2:0.02", "--out", cube)
        with xr.open_dataset(cube) as dataset:
            config = json.loads(dataset.attrs["config"])
        assert code == 0 and config["vertical"] == str(files["OTH-UP"]) and config["any_vertical"] is True


def test_the_vertical_is_checked_before_any_page_is_rendered(run_cli, files, tmp_path):
    page = tmp_path / "page.html"
    assert_one_error_line(*run_cli("report", files["STA-000"], "--units", "g", "--radius", "2", "--vertical",
                                   files["OTH-UP"], "--out", page),
                          files["OTH-UP"], "not the same station's vertical component")
    assert not page.exists()


def test_each_station_takes_its_own_vertical_and_refuses_every_other(three_component_sets):
    """The fifteen three-component PEER sets of ../shared: 15 verticals taken, 210 of other stations refused."""
    sets = three_component_sets
    for components in sets.values():
        for horizontal in ("H1", "H2"):
            assert vertical_doubt(components[horizontal], components["UP"]) is None
    refused = [vertical_doubt(sets[one]["H1"], sets[other]["UP"]) for one in sets for other in sets if one != other]
    assert len(refused) == len(sets) * (len(sets) - 1) and None not in refused
