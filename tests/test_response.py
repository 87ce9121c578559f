"""Response: SI quantities for a mass, energy balance, scalars, xarray export, the Fig. 3 plot."""

from __future__ import annotations

import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.reports.plots import plot_response, slip_intervals
from stickslip.records.readers import read_record
from stickslip.models.rigid.response import HISTORY_ATTRS, SCALAR_ATTRS
from stickslip.models import solve
from stickslip.models.rigid.exact import SCALAR_NAMES, sweep_scalars

G = 9.81
MASS = 5.1


@pytest.fixture(scope="module")
def cape_mendocino(paper_records_dir):
    return read_record(paper_records_dir / "SLAMMER_Cape_Mendocino_1992_PET-090.txt")


@pytest.fixture(scope="module")
def response(cape_mendocino):
    return solve(cape_mendocino, mu=0.10, mass=MASS)


def test_scalars_have_exactly_the_documented_keys_and_plain_types(response):
    scalars = response.scalars()
    assert list(scalars) == list(SCALAR_ATTRS)
    assert all(type(value) is float for key, value in scalars.items() if key != "n_slip_episodes")
    assert type(scalars["n_slip_episodes"]) is int


def test_scalars_equal_the_batched_kernel_times_mass(response, cape_mendocino):
    kernel = dict(zip(SCALAR_NAMES, sweep_scalars([cape_mendocino.acceleration], cape_mendocino.dt, [0.10], G)[0, 0]))
    scalars = response.scalars()
    for name in ("energy_dissipated", "energy_input", "kinetic_energy_final"):
        assert scalars[name] == pytest.approx(MASS * kernel[name], rel=1e-15)
    for name in ("residual_displacement", "peak_relative_displacement", "sliding_path", "slip_fraction", "n_slip_episodes"):
        assert scalars[name] == kernel[name]


def test_energy_balance_and_definitions(response):
    assert response.balance_residual / response.energy_input < 1e-9
    assert response.energy_dissipated == pytest.approx(0.10 * MASS * G * response.sliding_path, rel=1e-14)
    np.testing.assert_allclose(response.kinetic_energy, 0.5 * MASS * response.absolute_velocity**2)
    assert response.kinetic_energy[0] == 0.0
    assert response.peak_relative_displacement >= np.max(np.abs(response.relative_displacement))


def test_absolute_motion_and_friction_force(response):
    np.testing.assert_array_equal(response.absolute_displacement, response.ground_displacement + response.relative_displacement)
    np.testing.assert_array_equal(response.absolute_velocity, response.ground_velocity + response.relative_velocity)
    friction_limit = 0.10 * MASS * G
    assert np.max(np.abs(response.friction_force)) <= friction_limit * (1 + 1e-12)
    sliding = response.phase != 0
    assert np.any(sliding)
    # While sliding the friction force is the limit, opposing the relative velocity (Eq. 2).
    np.testing.assert_allclose(response.friction_force[sliding], friction_limit * response.phase[sliding], rtol=1e-12)
    # While sticking the block moves with the base.
    np.testing.assert_allclose(
        response.absolute_acceleration[~sliding], response.ground_acceleration[~sliding], rtol=0, atol=0
    )


def test_to_xarray_labels_everything(response, cape_mendocino):
    dataset = response.to_xarray()
    assert set(dataset.data_vars) == set(HISTORY_ATTRS)
    for name, variable in dataset.variables.items():
        assert variable.dims == ("time",)
        assert variable.attrs["units"] and variable.attrs["long_name"], name
    assert dataset.attrs["mu"] == 0.10 and dataset.attrs["mass"] == MASS and dataset.attrs["g"] == G
    assert dataset.attrs["method"] == "exact"
    assert dataset.attrs["record_id"] == "cape_mendocino"
    assert dataset.attrs["record_sha256"] == cape_mendocino.meta.sha256
    assert dataset.attrs["energy_dissipated"] == response.energy_dissipated
    assert "stickslip_version" in dataset.attrs and "git_commit" in dataset.attrs
    np.testing.assert_array_equal(dataset["energy_dissipated"].values, response.energy_dissipated_history)


def test_mass_scales_energies_and_force_only(cape_mendocino, response):
    light = solve(cape_mendocino, mu=0.10, mass=1.0)
    assert response.energy_dissipated == pytest.approx(MASS * light.energy_dissipated, rel=1e-15)
    np.testing.assert_allclose(response.friction_force, MASS * light.friction_force, rtol=1e-15)
    assert response.residual_displacement == light.residual_displacement


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        ({"mu": 0.0}, "friction ratio mu must be a positive finite number"),
        ({"mu": float("inf")}, "friction ratio mu must be a positive finite number"),
        ({"mu": 0.1, "mass": -5.1}, r"block mass \[kg\] must be a positive"),
        ({"mu": 0.1, "method": "euler"}, "the rigid model is solved by method exact, newmark, slammer, not 'euler'"),
        ({"mu": 0.1, "time_step": 0.001}, "solver 'exact' does not accept option"),
    ],
)
def test_solve_rejects_bad_input(cape_mendocino, arguments, message):
    with pytest.raises(StickslipError, match=message):
        solve(cape_mendocino, **arguments)


def test_newmark_dispatch_agrees_with_exact(cape_mendocino, response):
    newmark = solve(cape_mendocino, mu=0.10, mass=MASS, method="newmark", time_step=0.001)
    assert newmark.method == "newmark"
    assert newmark.energy_dissipated == pytest.approx(response.energy_dissipated, rel=1e-3)
    assert newmark.to_xarray().attrs["solver_time_step"] == 0.001


def test_paper_fig3_layout_png(response, tmp_path):
    """The paper's Fig. 3 case (μ = 0.10), here on Cape Mendocino: several slip episodes, a PNG file."""
    assert response.n_slip_episodes >= 5
    intervals = slip_intervals(response)
    assert len(intervals) >= 5
    assert all(start < end for start, end in intervals)
    target = tmp_path / "fig3.png"
    figure = plot_response(response, path=target)
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert target.stat().st_size > 10_000
    assert len(figure.axes) == 3
    assert [axes.get_ylabel() for axes in figure.axes] == ["displacement [m]", "velocity [m/s]", "acceleration [m/s²]"]


def test_dissipated_energy_is_the_work_of_the_friction_force(paper_records_dir):
    """E_df (μ·m·g·path, exact) against ∫F_f·ẋ dt from the force and velocity histories.

    The quadrature is independent of how E_df is computed; its error shrinks as
    the record is resampled finer, which leaves the exact solution unchanged.
    Measured on Coyote Lake 230: 7e-5 relative at the record's dt, 8e-7 at dt/5.
    """
    from stickslip.records.process import resample
    from stickslip.records.readers import read_record

    record = read_record(paper_records_dir / "SLAMMER_Coyote_Lake_1979_G06-230.txt")
    errors = []
    for factor in (1, 5):
        response = solve(resample(record, record.dt / factor), mu=0.10)
        work = np.trapezoid(response.friction_force * response.relative_velocity, response.time)
        errors.append(abs(work / response.energy_dissipated - 1))
    assert errors[0] < 2e-4
    assert errors[1] < 5e-6
    assert errors[1] < errors[0] / 10
