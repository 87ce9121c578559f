"""A result that declares its end results, histories and ledger terms gets the common methods from the base."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from stickslip.models.result import Result
from stickslip.units import CF_CONVENTIONS


@dataclass(frozen=True)
class DeclaredResult(Result):
    """A block of 2 kg whose kernel's end results and histories are per unit mass."""

    model = "declared"
    method = "exact"
    scalar_table = {"energy_dissipated": ("J", "energy dissipated by friction at the end"),
                    "balance_residual": ("J", "largest |residual| over the record"),
                    "n_slip_episodes": ("1", "number of stick-to-slip transitions"),
                    "peak_relative_displacement": ("m", "largest |x|")}
    history_table = {"relative_displacement": ("m", "block displacement relative to the base"),
                     "energy_dissipated": ("J", "cumulative energy dissipated by friction"),
                     "balance_residual": ("J", "energy balance residual")}
    ledger_terms = ("energy_dissipated", "balance_residual")
    mass = 2.0

    @property
    def time(self) -> np.ndarray:
        return np.array([0.0, 0.5, 1.0])

    def end_values(self) -> dict[str, float]:
        return {"energy_dissipated": 0.75, "n_slip_episodes": 3.0, "peak_relative_displacement": 0.25}

    def histories(self) -> dict[str, np.ndarray]:
        return {"relative_displacement": np.array([0.0, 0.25, 0.125]),
                "energy_dissipated": self.mass * np.array([0.0, 0.5, 0.75]),
                "balance_residual": self.mass * np.array([0.0, -0.125, 0.0625])}

    def describe(self) -> str:
        return "a declared block"

    def case(self) -> dict:
        return {"model": self.model, "method": self.method, "mu": 0.1, "vertical": None}


def test_the_end_results_scale_energies_by_the_mass_and_take_the_residual_from_the_ledger():
    scalars = DeclaredResult().scalars()
    assert list(scalars) == list(DeclaredResult.scalar_table)
    assert scalars == {"energy_dissipated": 1.5, "balance_residual": 0.25, "n_slip_episodes": 3,
                       "peak_relative_displacement": 0.25}
    assert isinstance(scalars["n_slip_episodes"], int)


def test_units_and_long_names_come_from_the_declaration():
    result = DeclaredResult()
    assert result.scalar_units() == {"energy_dissipated": "J", "balance_residual": "J", "n_slip_episodes": "1",
                                     "peak_relative_displacement": "m"}
    assert result.scalar_attrs()["peak_relative_displacement"] == ("m", "largest |x|")


def test_the_ledger_is_the_declared_terms_of_the_histories_in_order():
    ledger = DeclaredResult().energy_ledger()
    assert list(ledger) == ["energy_dissipated", "balance_residual"]
    np.testing.assert_array_equal(ledger["energy_dissipated"], [0.0, 1.0, 1.5])


def test_a_result_that_declares_no_ledger_has_none():
    @dataclass(frozen=True)
    class NoLedger(DeclaredResult):
        ledger_terms = ()

    assert NoLedger().energy_ledger() is None


def test_the_dataset_keeps_a_history_whose_last_value_is_an_end_result():
    pytest.importorskip("xarray")
    dataset = DeclaredResult().to_xarray()
    assert dataset["energy_dissipated"].dims == ("time",)
    np.testing.assert_array_equal(dataset["energy_dissipated"].values, [0.0, 1.0, 1.5])
    assert dataset["energy_dissipated"].attrs == {"units": "J", "long_name": "cumulative energy dissipated by friction"}
    assert dataset["n_slip_episodes"].dims == ()
    assert int(dataset["n_slip_episodes"]) == 3
    assert dataset["peak_relative_displacement"].attrs == {"units": "m", "long_name": "largest |x|"}
    assert dataset["time"].attrs["units"] == "s"
    assert dataset.attrs["Conventions"] == CF_CONVENTIONS
    assert dataset.attrs["mu"] == 0.1
    assert dataset.attrs["vertical"] == ""
    assert "stickslip_version" in dataset.attrs


@dataclass(frozen=True)
class ForTheMass(DeclaredResult):
    """The same block whose end results are for its mass already, kept as attributes, with a ledger-only residual,
    a counted iteration, a title and its own case attributes."""

    per_unit_mass = False
    counts = ("n_slip_episodes", "iterations")
    scalars_as_attributes = True
    time_attrs = {"units": "s", "long_name": "time"}
    scalar_table = {**DeclaredResult.scalar_table, "iterations": ("1", "iterations run")}
    history_table = {name: DeclaredResult.history_table[name] for name in ("relative_displacement",
                                                                            "energy_dissipated")}

    def end_values(self) -> dict[str, float]:
        return {**super().end_values(), "iterations": 4.0}

    def title(self) -> str:
        return "a block for its mass"

    def case_attrs(self) -> dict:
        return {"mu": 0.1, "mass_units": "kg"}


def test_end_results_for_the_mass_are_not_scaled_again_and_every_declared_count_is_whole():
    scalars = ForTheMass().scalars()
    assert scalars["energy_dissipated"] == 0.75  # not 2 kg x 0.75
    assert scalars["balance_residual"] == 0.25  # the ledger's histories are for the mass: max |2 x (-0.125)|
    assert scalars["iterations"] == 4 and isinstance(scalars["iterations"], int)


def test_a_ledger_term_the_histories_table_leaves_out_is_in_the_ledger_only():
    pytest.importorskip("xarray")
    result = ForTheMass()
    np.testing.assert_array_equal(result.energy_ledger()["balance_residual"], [0.0, -0.25, 0.125])
    assert "balance_residual" not in result.to_xarray().data_vars


def test_end_results_as_attributes_with_the_title_time_and_case_declared():
    pytest.importorskip("xarray")
    dataset = ForTheMass().to_xarray()
    assert set(dataset.data_vars) == {"relative_displacement", "energy_dissipated"}
    assert dataset.attrs["peak_relative_displacement"] == 0.25
    assert dataset.attrs["peak_relative_displacement_units"] == "m"
    assert dataset.attrs["n_slip_episodes"] == 3
    assert list(dataset.attrs)[:4] == ["title", "Conventions", "mu", "mass_units"]
    assert dataset.attrs["title"] == "a block for its mass"
    assert "vertical" not in dataset.attrs
    assert dataset["time"].attrs == {"units": "s", "long_name": "time"}
