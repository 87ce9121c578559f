"""Every option a command accepts is recorded in what it writes: its ``--json`` document, or its cube's attributes.

The options come from the command line's own parser (:func:`stickslip.cli.build_parser`), every sub-command's,
so an option added later is checked without a change here: it must either be given in one of the command's
:data:`RUNS` (and then be found, by its name, in the output of that run) or be in :data:`NOT_RECORDED` with the
reason it need not be.  A user who reads a result must be able to tell every setting that produced it; an
option that the output does not name is one that may be silently ignored (as ``--mu-slow`` once was by
``optimum``).

What a command writes: ``solve``, ``measures``, ``spectrum``, ``displacements``, ``estimate``, ``optimum`` and
``isolation design`` their ``--json`` document (every key at any depth); ``sweep`` its cube's attributes, with
the JSON of its ``config`` attribute; ``report`` the parameters its notebook renders the page from (the page
states them).
"""

from __future__ import annotations

import argparse
import json
import math

import numpy as np
import pytest

from stickslip.cli import build_parser
from stickslip.sweeps import read_cube

G = 9.81

#: Options that need not appear in the output, with the reason; by option, for every command, or by
#: "command option" for one command.
NOT_RECORDED = {
    "--json": "chooses the form of the output (a JSON document instead of the table)",
    "--csv": "writes the same rows to a file as well",
    "--out": "names the file written (the output itself)",
    "--chart": "names the design chart's PNG, which states its radii and friction grid on its axes",
    "--chart-radii": "the radii of the design chart's PNG, which are its horizontal axis",
    "--chart-values": "the values of the design chart's PNG beside mu, which are its horizontal axis",
    "--plot": "names a figure's PNG (the spectra's, the suite's), which states its settings in its title",
    "--chart-levels": "the contour levels of the design chart's PNG, which its colour bar and labels state",
    "--page": "names the folder of the suite's page, which shows the same document",
    "--max-file-size": "a guard on the input's size: a file within it gives the same numbers, one beyond it stops "
                       "the command with one line",
    "--memory-limit": "a guard on memory: a run within it gives the same numbers, one beyond it stops with one line",
    "records list": "prints the records its options select (the listing is the selection): no settings to record",
    "records validate": "prints what it read of each file, file by file (format, dt and where from, units, PGA "
                        "in g): no settings block",
    "records fetch": "copies the records its options select into a folder and lists them: no settings to record",
    "report --keep-going": "renders a page for each readable file and lists the others on stderr (exit 2): the pages "
                           "written are the record of it, and no number on a page changes",
}

#: Where an option's value may be recorded under another name than its own (``--g`` as ``gravity`` in a cube).
RECORDED_AS = {
    "g": ("g", "gravity"),
    "mass": ("mass", "block_mass"),
    "method": ("method", "solver"),
    "time_step": ("time_step", "solver_time_step"),
    "mu": ("mu", "mu_fast", "mu_start"),  # the velocity law's mu_fast; the report's grid from its start
    "q": ("q", "near_optimal_fraction"),
    "inverse": ("inverse", "polarity"),
    "equivalent_linear": ("equivalent_linear", "soil_model"),
    "ky_table": ("ky_table", "ky_displacement"),
    "pair": ("pair", "second"),  # a pair's name; the report's second file
    "vertical": ("vertical_source", "vertical", "with_vertical"),
    "vertical_positive": ("vertical_positive", "vertical_sense", "with_vertical"),
    "mw": ("mw", "magnitude"),
    "ts": ("ts", "site_period"),
    "tm": ("tm", "mean_period"),
    "sa": ("sa", "spectral_acceleration"),
    "sa13": ("sa13", "spectral_acceleration_13"),
    "fs": ("fs", "factor_of_safety"),
    "asce_table": ("asce_table",),
    "exceed": ("exceed", "exceed_displacement"),
    "arias": ("arias", "arias_intensity"),
}
#: What an unset flag is recorded as, where it is recorded as a word (``--inverse``: the polarity ``normal``).
UNSET_FLAG_WORDS = ("normal", "linear")


def commands() -> dict[str, argparse.ArgumentParser]:
    """Every leaf command's parser, by its name (``records validate``)."""
    found = {}

    def walk(parser, name):
        subcommands = [action for action in parser._actions if isinstance(action, argparse._SubParsersAction)]
        for action in subcommands:
            for sub, subparser in action.choices.items():
                walk(subparser, f"{name} {sub}".strip())
        if not subcommands:
            found[name] = parser

    walk(build_parser(), "")
    return found


def options(parser: argparse.ArgumentParser) -> dict[str, str]:
    """A parser's options (not its positional arguments or --help), the long spelling -> its dest."""
    return {action.option_strings[-1]: action.dest for action in parser._actions
            if action.option_strings and not isinstance(action, (argparse._HelpAction, argparse._VersionAction))}


def write_motion(path, frequency: float, peak: float, seconds: float = 3.0) -> None:
    """A decaying two-tone motion [m/s²] as time/acceleration text, sampled every 0.01 s."""
    time = np.arange(0.0, seconds, 0.01)
    values = (np.sin(2 * np.pi * frequency * time) + 0.4 * np.sin(2 * np.pi * 3.7 * time)) * np.exp(-0.3 * time)
    values = peak * values / np.max(np.abs(values))
    path.write_text("\n".join(f"{t:.2f} {a:.9e}" for t, a in zip(time, values)) + "\n")


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> dict[str, str]:
    folder = tmp_path_factory.mktemp("options")
    paths = {}
    for name, frequency, peak in (("wave-000.txt", 1.1, 5.0), ("wave-090.txt", 0.8, 4.0), ("wave-UP.txt", 2.3, 2.0)):
        write_motion(folder / name, frequency, peak, 3.0 if name != "wave-UP.txt" else 2.9)
        paths[name] = str(folder / name)
    (folder / "mcer.csv").write_text("period [s],S_a [g]\n0.0,0.6\n0.2,1.5\n0.6667,1.5\n1.0,1.0\n2.0,0.5\n"
                                     "3.0,0.33333\n")
    paths["mcer.csv"] = str(folder / "mcer.csv")
    paths["folder"] = str(folder)
    return paths


#: What a file is read with: every run gives these.
READ = ("--format", "two_column", "--dt", "0.01", "--units", "m/s2")
#: A small grid of friction ratios.
MU = ("--mu", "0.05:0.15:0.05")

#: The runs that give each option of each command, a run being its arguments after the command (``H`` the
#: horizontal file, ``H2`` the second, ``V`` the vertical).
RUNS = {
    "measures": [("H", *READ, "--g", "9.80665", "--keep-going", "--json")],
    "solve": [
        ("H", *READ, "--model", "rigid", "--method", "newmark", "--time-step", "0.002", "--mu", "0.1", "--mass", "2",
         "--g", "9.80665", "--scale", "1.5", "--keep-going", "--json"),
        ("H", *READ, "--ky", "0.1", "--direction", "both", "--thrust-angle", "10", "--inverse", "--target-pga", "0.3",
         "--json"),
        ("H", *READ, "--ky-table", "0:0.15,0.1:0.1", "--method", "slammer", "--json"),
        ("H", *READ, "--model", "decoupled", "--ky", "0.1", "--height", "20", "--vs", "300", "--vs-base", "800",
         "--damping", "0.1", "--equivalent-linear", "--reference-strain", "0.05%", "--json"),
        ("H", *READ, "--radius", "2", "--mu-slow", "0.05", "--mu-fast", "0.1", "--rate", "20", "--json"),
        ("H", *READ, "--radius", "2", "--mu", "0.1", "--mu-slow-ratio", "0.5", "--rate", "20", "--vertical", "V",
         "--vertical-positive", "up", "--any-vertical", "--pad", "--json"),
        ("H", *READ, "--model", "spring", "--mu", "0.1", "--period", "1", "--initial-velocity", "0.1", "--json"),
        ("H", *READ, "--mu", "0.06", "--model", "isolated", "--superstructure-period", "0.5", "--stories", "2", "--superstructure-damping", "0.03",
         "--damping-model", "rayleigh", "--mass-ratio", "3", "--json"),
        ("H", *READ, "--mu", "0.1", "--model", "friction-tmd", "--structure-period", "1", "--stories", "2", "--damper-story", "1",
         "--structure-damping", "0.03", "--json"),
        ("H", "H2", *READ, "--pair", "--any-pair", "--mu", "0.1", "--json"),
    ],
    "spectrum": [("H", *READ, "--g", "9.80665", "--damping", "0.05", "--periods", "0.5,1,2", "--json"),
                 ("H", "H2", *READ, "--pair", "--pad", "--any-pair", "--json")],
    "isolation design": [
        ("--sms", "1.5", "--sm1", "1.0", "--tl", "8", "--radius", "2", "--mu", "0.06", "--lambda-max", "1.8",
         "--lambda-min", "0.6", "--as", "0.6", "--sds", "1.5", "--sd1", "1.0", "--ag", "0.5", "--ground", "C",
         "--spectrum-type", "2", "--soil-factor", "1.15", "--tb", "0.2", "--tc", "0.6", "--td", "2",
         "--weight-ratio", "0.8", "--ri", "2", "--plan", "30", "40", "--offset", "10", "--eccentricity", "0.5",
         "--period-ratio", "1.2", "--g", "9.80665", "--json"),
        ("--asce-table", "TABLE", "--sms", "1.5", "--sm1", "1.0", "--tl", "8", "--recentring-period", "2.8",
         "--mu", "0.06", "--json"),
    ],
    "isolation suite": [
        ("H", "H2", *READ, "--pair", "--pad", "--any-pair", "--vertical", "V", "--vertical-positive", "up",
         "--any-vertical", "--radius", "2", "--mu", "0.06", "--lambda-max", "1.8", "--lambda-min", "0.6", "--sms",
         "1.5", "--sm1", "1.0", "--tl", "8", "--as", "0.6", "--sds", "1.5", "--sd1", "1.0", "--code", "aashto",
         "--scaling", "common", "--g", "9.80665", "--json"),
        ("H", "H2", *READ, "--pair", "--any-pair", "--recentring-period", "2.8", "--mu", "0.06", "--asce-table",
         "TABLE", "--sms", "1.5", "--sm1", "1.0", "--tl", "8", "--ag", "0.5", "--ground", "C", "--spectrum-type", "2",
         "--soil-factor", "1.15", "--tb", "0.2", "--tc", "0.6", "--td", "2", "--code", "en1998_2", "--json"),
    ],
    "displacements": [("H", *READ, "--ky", "0.1,0.2", "--method", "slammer", "--g", "9.80665", "--keep-going",
                       "--json"),
                      ("H", *READ, "--fs", "1.2", "--slope-angle", "30", "--json")],
    "estimate": [
        ("H", *READ, "--ky", "0.1", "--mw", "7", "--ts", "0.3", "--vs", "300", "--vs-base", "800", "--damping", "0.1",
         "--exceed", "0.05m", "--g", "9.80665", "--json"),
        ("H", *READ, "--ky", "0.1", "--height", "20", "--vs", "300", "--vs-base", "800", "--json"),
        ("--ky", "0.1", "--pga", "0.5", "--pgv", "30cm/s", "--arias", "1.2", "--tm", "0.5", "--sa", "0.6", "--sa13",
         "0.5", "--json"),
        ("H", *READ, "--fs", "1.2", "--slope-angle", "30", "--json"),
    ],
    "optimum": [
        ("H", *READ, "--model", "rigid", "--method", "newmark", "--time-step", "0.002", *MU, "--mass", "2",
         "--g", "9.80665", "--scale", "1", "1.5", "--q", "0.9", "--reference-mu", "0.1", "--range-points", "2",
         "--objective", "energy", "--keep-going", "--json"),
        ("H", *READ, "--ky-list", "0.1", "0.2", "--direction", "both", "--thrust-angle", "10", "--inverse",
         "--target-pga", "0.3", "--reference-ky", "0.1", "--json"),
        ("H", *READ, "--radius", "2", "--mu-list", "0.05", "0.1", "--mu-slow-ratio", "0.5", "--rate", "20",
         "--vertical", "V", "--vertical-positive", "up", "--any-vertical", "--pad", "--json"),
        ("H", *READ, "--model", "spring", *MU, "--period", "1", "--initial-velocity", "0.1", "--json"),
        ("H", *READ, *MU, "--model", "isolated", "--superstructure-period", "0.5", "--stories", "2", "--superstructure-damping", "0.03",
         "--damping-model", "rayleigh", "--mass-ratio", "3", "--json"),
        ("H", *READ, *MU, "--model", "friction-tmd", "--structure-period", "1", "--stories", "2", "--damper-story", "1",
         "--structure-damping", "0.03", "--json"),
        ("H", "H2", *READ, "--pair", "--any-pair", *MU, "--angles", "45", "--json"),
    ],
    "sweep": [
        ("H", *READ, "--model", "rigid", "--method", "newmark", "--time-step", "0.002", *MU, "--mass", "2",
         "--g", "9.80665", "--scale", "1", "1.5", "--q", "0.9", "--reference-mu", "0.1", "--keep-going"),
        ("H", *READ, "--ky-list", "0.1", "0.2", "--direction", "both", "--thrust-angle", "10", "--inverse",
         "--target-pga", "0.3", "--reference-ky", "0.1"),
        ("H", *READ, "--ky", "0.1:0.2:0.1", "--model", "decoupled", "--height-list", "20", "--vs", "300",
         "--vs-base", "800", "--damping", "0.1", "--equivalent-linear", "--reference-strain", "0.05%"),
        ("H", *READ, "--ky", "0.1", "--model", "coupled", "--height", "10:20:10", "--vs", "300", "--vs-base",
         "800"),
        ("H", *READ, "--radius", "2", "--mu-list", "0.05", "0.1", "--mu-slow-ratio", "0.5", "--rate", "20",
         "--vertical", "V", "--vertical-positive", "up", "--any-vertical", "--pad"),
        ("H", *READ, "--model", "spring", *MU, "--period", "1", "--initial-velocity", "0.1"),
        ("H", *READ, *MU, "--model", "isolated", "--superstructure-period", "0.5", "--stories", "2", "--superstructure-damping", "0.03",
         "--damping-model", "rayleigh", "--mass-ratio", "3"),
        ("H", *READ, *MU, "--model", "friction-tmd", "--structure-period", "1", "--stories", "2", "--damper-story", "1",
         "--structure-damping", "0.03"),
        ("H", "H2", *READ, "--pair", "--any-pair", *MU, "--angles", "45"),
    ],
    "report": [
        ("H", *READ, "--model", "rigid", "--method", "newmark", *MU, "--mass", "2", "--g", "9.80665", "--q", "0.9",
         "--reference-mu", "0.1", "--range-points", "2", "--mu-case", "0.1"),
        ("H", *READ, "--radius", "2", "--mu-slow-ratio", "0.5", "--rate", "20", "--vertical", "V",
         "--vertical-positive", "up", "--any-vertical", "--pad"),
        ("H", *READ, "--inverse"),
        ("H", *READ, "--model", "spring", "--period", "1", "--initial-velocity", "0.1"),
        ("H", *READ, "--model", "isolated", "--superstructure-period", "0.5", "--stories", "2", "--superstructure-damping", "0.03",
         "--damping-model", "rayleigh", "--mass-ratio", "3"),
        ("H", *READ, "--model", "friction-tmd", "--structure-period", "1", "--stories", "2", "--damper-story", "1",
         "--structure-damping", "0.03"),
        ("H", "H2", *READ, "--pair", "--any-pair", *MU),
    ],
}


#: Runs that a command refuses, in one line naming what it refuses (the option, or what chose the model it does
#: not solve): options it accepts at parsing but not in the combination given.  (command, arguments, the text
#: the error line names.)
REFUSED = [
    ("optimum", ("H", *READ, "--ky", "0.1:0.2:0.1", "--model", "decoupled", "--height", "20", "--height-list", "30",
                 "--vs", "300", "--vs-base", "800", "--damping", "0.1", "--equivalent-linear", "--reference-strain",
                 "0.05%"), "--model decoupled"),
    ("optimum", ("H", *READ, "--radius", "2", "--mu-slow", "0.05", "--mu-fast", "0.1", "--rate", "20"), "--mu-slow"),
    ("optimum", ("H", *READ, "--radius", "2", "--mu-fast", "0.1", "--rate", "20"), "--mu-fast"),
    ("sweep", ("H", *READ, "--radius", "2", "--mu-slow", "0.05", "--mu-fast", "0.1", "--rate", "20", "--out",
               "CUBE"), "--mu-slow"),
    ("sweep", ("H", *READ, "--radius", "2", "--mu-fast", "0.1", "--rate", "20", "--out", "CUBE"), "--mu-fast"),
    ("report", ("H", *READ, "--radius", "2", "--mu-slow", "0.05", "--mu-fast", "0.1", "--rate", "20", "--out",
                "PAGE"), "--mu-slow"),
    ("report", ("H", *READ, "--radius", "2", "--mu-fast", "0.1", "--rate", "20", "--out", "PAGE"), "--mu-fast"),
    ("report", ("H", *READ, "--method", "newmark", "--time-step", "0.002", "--out", "PAGE"), "--time-step"),
    ("report", ("H", *READ, "--mu-list", "0.05", "0.1", "--out", "PAGE"), "--mu-list"),
    ("report", ("H", *READ, "--ky", "0.1", "--direction", "both", "--thrust-angle", "10", "--out", "PAGE"), "--ky"),
    ("report", ("H", *READ, "--ky-list", "0.1", "0.2", "--out", "PAGE"), "--ky"),
    ("report", ("H", *READ, "--reference-ky", "0.1", "--out", "PAGE"), "--reference-ky"),
    ("report", ("H", *READ, "--model", "decoupled", "--ky", "0.1", "--height", "20", "--height-list", "30", "--vs",
                "300", "--vs-base", "800", "--damping", "0.1", "--equivalent-linear", "--reference-strain", "0.05%",
                "--out", "PAGE"), "--model decoupled"),
]


def not_recorded(command: str, option: str) -> str | None:
    """Why ``option`` of ``command`` need not be recorded, or None."""
    return NOT_RECORDED.get(command) or NOT_RECORDED.get(f"{command} {option}") or NOT_RECORDED.get(option)


def test_every_option_of_every_command_is_given_in_a_run_or_excused():
    missing = []
    for command, parser in commands().items():
        given = {argument for run in RUNS.get(command, ()) for argument in run}
        given |= {argument for refused, run, _ in REFUSED if refused == command for argument in run}
        missing += [f"stickslip {command} {option}" for option in options(parser)
                    if option not in given and not_recorded(command, option) is None]
    assert not missing, (
        "options that no run of tests/test_options_recorded.py gives, and that NOT_RECORDED does not excuse: "
        + "; ".join(missing) + ". Record each in the command's --json output (or its cube's attributes), add a run "
        "to RUNS that gives it, or add it to NOT_RECORDED with the reason it changes no number")


def keys_and_values(document, found: dict | None = None) -> dict[str, list]:
    """Every key at any depth of a JSON document (and of JSON text in its strings), with its values."""
    found = {} if found is None else found
    if isinstance(document, dict):
        for key, value in document.items():
            found.setdefault(key, []).append(value)
            keys_and_values(value, found)
    elif isinstance(document, list):
        for value in document:
            keys_and_values(value, found)
    elif isinstance(document, str) and document.startswith("{"):
        try:
            keys_and_values(json.loads(document), found)
        except ValueError:
            pass
    return found


def written(command: str, arguments: list[str], run_cli, monkeypatch, tmp_path) -> dict[str, list]:
    """Run ``command`` with ``arguments``; what it wrote, every key with its values."""
    if command == "sweep":
        cube_path = tmp_path / "cube.nc"
        code, out, err = run_cli(command, *arguments, "--out", cube_path)
        assert code == 0, err
        cube = read_cube(cube_path)
        return keys_and_values({**cube.attrs, **{name: cube[name].values.tolist() for name in cube.coords}})
    if command == "report":
        rendered = []
        import stickslip.reports.pair_report as pair_report
        import stickslip.reports.record_report as record_report

        monkeypatch.setattr(record_report, "render_record_report", lambda parameters: rendered.append(parameters)
                            or "<html></html>")
        monkeypatch.setattr(pair_report, "render_pair_report", lambda parameters: rendered.append(parameters)
                            or "<html></html>")
        code, out, err = run_cli(command, *arguments, "--out", tmp_path / "page.html")
        assert code == 0, err
        return keys_and_values(rendered)
    code, out, err = run_cli(*command.split(), *arguments)
    assert code == 0, err
    return keys_and_values([json.loads(line) for line in out.splitlines() if line.strip()])


def given_options(command: str, arguments: list[str]) -> dict[str, list[str]]:
    """The options among ``arguments``, each with the values that follow it."""
    known = options(commands()[command])
    found: dict[str, list[str]] = {}
    current = None
    for argument in arguments:
        if argument in known:
            current = argument
            found[current] = []
        elif current is not None:
            found[current].append(argument)
    return found


def matches(recorded: list, given: list[str]) -> bool:
    """Whether the values recorded under an option's names hold the value given: a flag set (true, or a word
    other than an unset flag's), a number given as a number recorded (or, for an acceleration given in g, that many
    times g), a text (a choice, a file, a table, a grid) as a text that holds it or in a parsed form (a number, a
    list); a mapping (such as the ``units`` of a document) never."""
    values = [value for value in recorded if value is not None and value is not False and not isinstance(value, dict)]
    if not given:
        return any(value is True or (isinstance(value, str) and value and value not in UNSET_FLAG_WORDS)
                   for value in values)
    numbers = []
    for text in given:
        try:
            numbers.append(float(text.rstrip("%")))
        except ValueError:
            return any((not isinstance(value, str)) or text in value or value in text for value in values)
    plain = [float(value) for value in np.asarray(values, dtype=object).ravel().tolist()
             if isinstance(value, (int, float)) and not isinstance(value, bool)] if values else []
    plain += [float(item) for value in values if isinstance(value, list) for item in np.ravel(value).tolist()
              if isinstance(item, (int, float)) and not isinstance(item, bool)]
    return all(any(math.isclose(value, number, rel_tol=1e-9) or math.isclose(value, number * G, rel_tol=1e-3)
                   for value in plain) for number in numbers)


@pytest.mark.parametrize(("command", "arguments", "named"), REFUSED,
                         ids=[f"{command}-{named.split()[-1].lstrip('-')}" for command, _, named in REFUSED])
def test_an_option_a_command_does_not_apply_is_refused_in_one_line(command, arguments, named, files, run_cli,
                                                                   tmp_path):
    names = {"H": files["wave-000.txt"], "CUBE": tmp_path / "cube.nc", "PAGE": tmp_path / "page.html"}
    code, out, err = run_cli(command, *[names.get(argument, argument) for argument in arguments])
    assert code == 2 and out == "" and not list(tmp_path.iterdir())
    assert len(err.splitlines()) == 1 and err.startswith(f"stickslip: error: {named}"), err


def run_ids():
    return [(command, index) for command, runs in RUNS.items() for index in range(len(runs))]


@pytest.mark.parametrize(("command", "index"), run_ids(), ids=[f"{command}-{index}" for command, index in run_ids()])
def test_each_option_given_is_recorded_in_the_output(command, index, files, run_cli, monkeypatch, tmp_path):
    names = {"H": files["wave-000.txt"], "H2": files["wave-090.txt"], "V": files["wave-UP.txt"],
             "TABLE": files["mcer.csv"]}
    arguments = [names.get(argument, argument) for argument in RUNS[command][index]]
    recorded = written(command, arguments, run_cli, monkeypatch, tmp_path)
    dests = options(commands()[command])
    dropped = []
    for option, values in given_options(command, arguments).items():
        if not_recorded(command, option) is not None:
            continue
        dest = dests[option].removesuffix("_list")  # --mu-list gives the values of mu
        keys = RECORDED_AS.get(dest, (dest,))
        found = [value for key in keys for value in recorded.get(key, [])]
        if not matches(found, values):
            shown = f"{option} {' '.join(values)}".strip()
            dropped.append(f"stickslip {command} {shown}: not recorded (looked for {' or '.join(keys)}"
                           + (f", found {found[:3]}" if found else "") + ")")
    assert not dropped, ("options accepted but not recorded in the output: " + "; ".join(dropped)
                         + ". Record each where the command writes its settings, or add it to NOT_RECORDED with the "
                           "reason it changes no number")
