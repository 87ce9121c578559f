"""Mistakes with the motion options (``--pair``, ``--vertical``) are one line about what the user asked for.

``--pair --ky`` and ``--ky ... --vertical`` name ``--pair`` and ``--vertical``
and where ``--ky`` applies, not a model the user never chose; ``--vertical A
B`` says that ``--vertical`` takes one file, where argparse said
"unrecognized arguments".
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import assert_one_error_line

DT = 0.01


@pytest.fixture
def files(tmp_path):
    time = np.arange(0.0, 6.0, DT)
    paths = {}
    for name, wave in (("wave-000.txt", 2.0 * np.sin(2 * np.pi * 1.3 * time)),
                       ("wave-090.txt", 1.5 * np.cos(2 * np.pi * 0.9 * time)),
                       ("wave-UP.txt", 1.0 * np.sin(2 * np.pi * 4.0 * time))):
        path = tmp_path / name
        path.write_text("\n".join(f"{t:.2f} {a:.9e}" for t, a in zip(time, wave * np.exp(-0.3 * time))) + "\n")
        paths[name[5:-4]] = path
    return paths


@pytest.mark.parametrize(("arguments", "message"), [
    (("--pair", "--ky", "0.1"), "--ky does not apply with --pair (the two horizontal components of one station, "
                                "solved in the plane: --model planar or pendulum or isolated or friction-tmd); it "
                                "applies to --model rigid or decoupled or coupled, on one horizontal component of a "
                                "record"),
    (("--ky", "0.1", "--vertical", "UP"), "--ky does not apply with --vertical (the vertical ground motion in the "
                                          "normal force: --model pendulum or isolated or friction-tmd); it applies to "
                                          "--model rigid or decoupled or coupled, without --vertical"),
    (("--mu", "0.1", "--period", "1", "--vertical", "UP"), "--period does not apply with --vertical (the vertical "
                                                          "ground motion in the normal force: --model pendulum or "
                                                          "isolated or friction-tmd); it applies to --model spring, "
                                                          "without --vertical"),
])
def test_an_option_refused_with_pair_or_vertical_names_them(run_cli, files, arguments, message):
    arguments = [str(files[argument]) if argument in files else argument for argument in arguments]
    paths = [files["000"], files["090"]] if "--pair" in arguments else [files["000"]]
    code, out, err = run_cli("solve", *paths, "--units", "m/s2", *arguments)
    assert (code, out, err) == (2, "", f"stickslip: error: {message}\n")


def test_vertical_with_two_files_is_one_line_saying_what_it_takes(run_cli, files):
    for vertical in (["--vertical", files["UP"]], [f"--vertical={files['UP']}"]):
        assert_one_error_line(*run_cli("solve", files["000"], "--units", "m/s2", "--mu", "0.1", *vertical,
                                       files["090"]),
                              f"--vertical {files['UP']} {files['090']}",
                              "--vertical takes one file, the vertical component of the station whose record (or "
                              "pair, with --pair) the command's paths give: --vertical FILE, with the other files "
                              "before it")
    code, out, err = run_cli("solve", files["000"], "--mu", "0.1", "--vertical", files["UP"], "--bogus")
    assert code == 2 and "unrecognized arguments: --bogus" in err
