"""The command line's block is 1 kg unless --mass says otherwise: its energies are then per kg (J/kg) in the text
it prints, and the paper's 5.1 kg block gives 5.1 times them in J; JSON keeps J with the mass beside it."""

from __future__ import annotations

import json

import numpy as np
import pytest

import stickslip
from stickslip.constants import DEFAULT_BLOCK_MASS
from stickslip.models.parameters import MASS
from stickslip.units import energy_units, per_unit_mass


@pytest.fixture(scope="module")
def record_file(tmp_path_factory):
    """A pulse in g, two columns (time, acceleration), that slides the block at μ = 0.1."""
    path = tmp_path_factory.mktemp("mass") / "pulse.txt"
    time = np.arange(0.0, 6.0, 0.01)
    np.savetxt(path, np.column_stack([time, 0.4 * np.sin(2 * np.pi * 1.1 * time) * np.exp(-((time - 2.5) / 1.0) ** 2)]))
    return path


def test_the_default_mass_is_one_kilogram_for_the_command_line_and_the_library():
    assert DEFAULT_BLOCK_MASS == 1.0 and MASS.default == DEFAULT_BLOCK_MASS
    assert "default 1: energies per kg of the block, J/kg" in MASS.help
    assert (energy_units(1.0), energy_units(5.1)) == ("J kg-1", "J")
    assert per_unit_mass("E_df,max [J]", 1.0) == "E_df,max [J/kg]" and per_unit_mass("E_df [J]", 5.1) == "E_df [J]"


def test_solve_labels_the_default_block_s_energies_per_kg_and_the_paper_s_block_in_joules(run_cli, record_file):
    code, out, err = run_cli("solve", record_file, "--units", "g", "--mu", "0.1")
    assert code == 0, err
    lines = out.splitlines()
    assert "mu = 0.1, mass = 1 kg" in lines[0]
    energy = next(line for line in lines if line.startswith("energy_dissipated"))
    assert energy.endswith("J kg-1")
    per_kg = float(energy.split()[1])
    code, out, err = run_cli("solve", record_file, "--units", "g", "--mu", "0.1", "--mass", "5.1")
    assert code == 0, err
    paper = next(line for line in out.splitlines() if line.startswith("energy_dissipated"))
    assert paper.endswith(" J") and float(paper.split()[1]) == pytest.approx(5.1 * per_kg, rel=1e-5)
    code, out, err = run_cli("solve", record_file, "--units", "g", "--mu", "0.1", "--json")
    document = json.loads(out)
    assert document["mass"] == 1.0 and document["units"]["energy_dissipated"] == "J"
    record = stickslip.read_record(record_file, units="g")
    assert document["energy_dissipated"] == pytest.approx(stickslip.solve(record, mu=0.1).energy_dissipated,
                                                          rel=1e-12)


def test_optimum_heads_its_energies_per_kg_for_the_default_block(run_cli, record_file):
    code, out, err = run_cli("optimum", record_file, "--units", "g", "--mu", "0.02:0.3:0.02")
    assert code == 0, err
    assert "block 1 kg" in out.splitlines()[0] and "E_df,max [J/kg]" in out and "[J]" not in out
    code, out, err = run_cli("optimum", record_file, "--units", "g", "--mu", "0.02:0.3:0.02", "--mass", "5.1")
    assert code == 0, err
    assert "block 5.1 kg" in out.splitlines()[0] and "E_df,max [J]" in out and "[J/kg]" not in out
