"""Sweep cubes: structure, units, provenance, NetCDF round trip, atomic writes, μ_max oracles, CLI."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import assert_one_error_line
import xarray as xr

from stickslip.analysis import mu_max_on_grid
from stickslip.grids import Grid
from stickslip.models.rigid import RIGID
from stickslip.optimum import refine_mu_max
from stickslip.errors import StickslipError
from stickslip.records.record import Record, RecordMeta
from stickslip.solvers.harmonic import harmonic_record, mu_max
from stickslip.models import sweep
from stickslip.models.rigid.sweep import VARIABLES
from stickslip.sweeps import MEASURE_ATTRS, write_cube

MU = [0.05, 0.10, 0.15, 0.20]


def pulse_record(record_id: str, amplitude: float, seed: int) -> Record:
    """A short, hand-made noisy pulse [m/s²] at dt = 0.01 s."""
    rng = np.random.default_rng(seed)
    time = np.arange(600) * 0.01
    acceleration = amplitude * np.sin(2 * np.pi * 1.7 * time) * np.exp(-((time - 2.5) / 1.2) ** 2)
    acceleration += 0.05 * amplitude * rng.standard_normal(time.size)
    meta = RecordMeta(record_id=record_id, event=f"event {record_id}", station="S", component="090", sha256="ab" * 32)
    return Record(acceleration, 0.01, meta)


@pytest.fixture(scope="module")
def records():
    return [pulse_record("a", 4.0, 1), pulse_record("b", 7.0, 2)]


@pytest.fixture(scope="module")
def cube(records):
    return sweep(records, mu=MU, mass=5.1, config={"study": "test"})


def test_cube_has_named_dimensions_and_record_coordinates(cube, records):
    assert dict(cube.sizes) == {"record": 2, "mu": 4}
    assert cube.record.values.tolist() == ["a", "b"]
    np.testing.assert_allclose(cube.mu.values, MU)
    assert set(VARIABLES) <= set(cube.data_vars)
    for name in ("event", "station", "component", "sha256", *MEASURE_ATTRS):
        assert cube[name].dims == ("record",)
    assert cube.event.values.tolist() == ["event a", "event b"]
    assert cube.pga.values == pytest.approx([np.abs(r.acceleration).max() for r in records])
    assert cube.n_slip_episodes.dtype.kind == "i"


def test_every_variable_has_units_and_long_name(cube):
    for name, variable in cube.variables.items():
        assert variable.attrs.get("long_name"), name
        if variable.dtype.kind == "f":
            assert variable.attrs.get("units"), name
    assert cube.energy_dissipated.attrs["units"] == "J"
    assert cube.sliding_path.attrs["units"] == "m"
    assert cube.pga.attrs["units"] == "m s-2"


def test_cube_carries_provenance(cube):
    for key in ("stickslip_version", "git_commit", "solver", "block_mass", "gravity", "config", "Conventions"):
        assert key in cube.attrs
    assert cube.attrs["solver"] == "exact"
    assert cube.attrs["block_mass"] == 5.1
    assert '"study": "test"' in cube.attrs["config"]


def test_energies_scale_with_mass_and_balance(records, cube):
    light = sweep(records, mu=MU, mass=1.0)
    np.testing.assert_allclose(cube.energy_dissipated, 5.1 * light.energy_dissipated, rtol=1e-12)
    np.testing.assert_allclose(cube.sliding_path, light.sliding_path, rtol=1e-12)
    # E_df = μ·m·g·path and E_I = E_df + E_k (absolute energy balance).
    friction_work = (cube.mu * 5.1 * 9.81 * cube.sliding_path).transpose(*cube.energy_dissipated.dims)
    np.testing.assert_allclose(cube.energy_dissipated, friction_work, rtol=1e-9)
    np.testing.assert_allclose(cube.energy_input, cube.energy_dissipated + cube.kinetic_energy_final, rtol=1e-8, atol=1e-9)


def test_netcdf_round_trip_keeps_values_and_attributes(cube, tmp_path):
    path = write_cube(cube, tmp_path / "sub" / "cube.nc")
    back = xr.load_dataset(path, engine="netcdf4")
    xr.testing.assert_equal(back, cube)
    assert back.energy_dissipated.attrs == cube.energy_dissipated.attrs
    assert back.attrs["git_commit"] == cube.attrs["git_commit"]
    assert back.energy_dissipated.encoding["zlib"] is True


def test_interrupted_write_leaves_the_old_file_and_no_partial(cube, tmp_path, monkeypatch):
    target = tmp_path / "cube.nc"
    target.write_bytes(b"previous contents")
    original = xr.Dataset.to_netcdf

    def write_then_interrupt(self, path, *args, **kwargs):
        original(self, path, *args, **kwargs)
        raise KeyboardInterrupt

    monkeypatch.setattr(xr.Dataset, "to_netcdf", write_then_interrupt)
    with pytest.raises(KeyboardInterrupt):
        write_cube(cube, target)
    assert target.read_bytes() == b"previous contents"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cube.nc"]


def test_interrupted_first_write_leaves_nothing(cube, tmp_path, monkeypatch):
    def fail(self, path, *args, **kwargs):
        path.write_bytes(b"half a cube")
        raise OSError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", fail)
    with pytest.raises(OSError):
        write_cube(cube, tmp_path / "cube.nc")
    assert list(tmp_path.iterdir()) == []


def test_scale_dimension_holds_factors(records):
    scaled = sweep(records, mu=MU, scale=[0.5, 2.0])
    assert scaled.energy_dissipated.dims == ("record", "scale", "mu")
    assert scaled.scale.attrs["units"] == "1"
    np.testing.assert_allclose(scaled.pga.sel(scale=2.0), 4.0 * scaled.pga.sel(scale=0.5), rtol=1e-12)
    np.testing.assert_allclose(scaled.pga.sel(scale=0.5), [0.5 * np.abs(r.acceleration).max() for r in records], rtol=1e-12)


def test_target_pga_dimension_holds_targets_and_factors(records):
    scaled = sweep(records, mu=MU, target_pga=[5.886, 9.81])
    assert scaled.energy_dissipated.dims == ("record", "target_pga", "mu")
    assert "scale" not in scaled.dims
    assert scaled.target_pga.attrs["units"] == "m s-2"
    assert scaled.scale_factor.dims == ("record", "target_pga")
    np.testing.assert_allclose(scaled.pga.sel(record="a"), [5.886, 9.81], rtol=1e-12)
    original_pga = np.abs(records[0].acceleration).max()
    np.testing.assert_allclose(scaled.scale_factor.sel(record="a"), np.array([5.886, 9.81]) / original_pga, rtol=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"mu": [0.1, 0.05]}, "strictly increasing"),
        ({"mu": [0.0, 0.1]}, "positive finite"),
        ({"mu": MU, "method": "rk4"}, "the rigid model is solved by method exact, newmark, slammer, not 'rk4'"),
        ({"mu": MU, "scale": [1.0], "target_pga": [5.0]}, "not both"),
        ({"mu": MU, "mass": -1.0}, "block mass"),
    ],
)
def test_bad_sweep_arguments_raise_one_clear_error(records, kwargs, message):
    with pytest.raises(StickslipError, match=message):
        sweep(records, **kwargs)


def test_duplicate_record_ids_are_refused(records):
    with pytest.raises(StickslipError, match="'a' appears twice"):
        sweep([records[0], records[0]], mu=MU)


def test_newmark_sweep_is_close_to_exact(records):
    exact = sweep(records[:1], mu=MU)
    newmark = sweep(records[:1], mu=MU, method="newmark")
    assert newmark.attrs["solver"] == "newmark"
    np.testing.assert_allclose(newmark.energy_dissipated, exact.energy_dissipated, rtol=0.05)


@pytest.fixture(scope="module")
def harmonic():
    """60 s of 1.5 Hz, 20 mm harmonic base motion, ramped over two cycles."""
    return harmonic_record(0.020, 1.5, 60.0, 0.002, ramp_cycles=2.0)


def test_mu_max_of_a_long_harmonic_record_matches_eq_6(harmonic):
    expected = mu_max(0.020, 1.5, 9.81)  # Eq. 6: f_f,max·u_g0·(2πf0)²/g ≈ 0.0815
    grid = np.round(np.arange(0.050, 0.120, 0.0005), 6)
    cube = sweep([harmonic], mu=grid)
    found = float(mu_max_on_grid(cube.energy_dissipated.sel(record=harmonic.meta.record_id)))
    assert found == pytest.approx(expected, rel=0.01)


def test_continuous_mu_max_agrees_with_the_fine_grid(harmonic):
    grid = np.round(np.arange(0.050, 0.120, 0.001), 6)
    cube = sweep([harmonic], mu=grid, mass=5.1)
    energy = cube.energy_dissipated.isel(record=0).values
    found = refine_mu_max(harmonic, RIGID.design(Grid("mu", grid), mass=5.1), energy)
    assert found.grid_argument == float(grid[np.argmax(energy)])
    assert abs(found.argument - found.grid_argument) <= 0.001
    assert found.value >= energy.max()
    assert found.argument == pytest.approx(mu_max(0.020, 1.5, 9.81), rel=0.01)


def test_cli_sweep_writes_a_cube(run_cli, tmp_path):
    record_file = tmp_path / "pulse.txt"
    record_file.write_text("\n".join(f"{a / 9.81:.6e}" for a in pulse_record("p", 5.0, 3).acceleration) + "\n")
    out = tmp_path / "cube.nc"
    code, stdout, stderr = run_cli("sweep", record_file, "--format", "slammer_1col", "--dt", "0.01", "--units", "g",
                                   "--mu", "0.05:0.2:0.05", "--target-pga", "0.6g", "7.0m/s2", "--out", out)
    assert code == 0, stderr
    assert stderr == ""  # no progress bar in a pipe
    cube = xr.load_dataset(out)
    np.testing.assert_allclose(cube.mu.values, [0.05, 0.10, 0.15, 0.20])
    np.testing.assert_allclose(cube.target_pga.values, [0.6 * 9.81, 7.0])


@pytest.mark.parametrize(
    ("mu_text", "message"),
    [("0.2:0.05:0.025", "0 < START <= STOP"), ("0.05:0.2", "START:STOP:STEP"), ("0.05:0.2:0", "STEP must be")],
)
def test_cli_sweep_rejects_bad_ranges_in_one_line(run_cli, tmp_path, mu_text, message):
    out = tmp_path / "cube.nc"
    code, stdout, stderr = run_cli("sweep", tmp_path / "any.AT2", "--mu", mu_text, "--out", out)
    assert code == 2
    assert message in stderr
    assert len(stderr.strip().splitlines()) == 1
    assert not out.exists()


def test_cli_sweep_names_a_missing_file(run_cli, tmp_path):
    code, stdout, stderr = run_cli("sweep", tmp_path / "absent.AT2", "--mu", "0.05:0.1:0.05", "--out", tmp_path / "c.nc")
    assert code == 2
    assert "absent.AT2" in stderr and "not found" in stderr


def _pulse_file(tmp_path):
    record_file = tmp_path / "pulse.txt"
    record_file.write_text("\n".join(f"{a / 9.81:.6e}" for a in pulse_record("p", 5.0, 3).acceleration) + "\n")
    return record_file



@pytest.mark.parametrize(
    ("make_out", "phrase"),
    [
        (lambda tmp: tmp, "it is a directory"),
        (lambda tmp: tmp / "blocker" / "c.nc", "blocker is a file, not a folder"),
        (lambda tmp: tmp / "blocker" / "deeper" / "c.nc", "blocker is a file, not a folder"),
    ],
)
def test_cli_sweep_checks_the_output_path_before_any_work(run_cli, tmp_path, monkeypatch, make_out, phrase):
    from stickslip.models.rigid import RigidModel

    def no_work(*args, **kwargs):
        raise AssertionError("the sweep ran before the output path was checked")

    monkeypatch.setattr(RigidModel, "sweep", no_work)
    (tmp_path / "blocker").write_text("kept")
    before = sorted(p.name for p in tmp_path.iterdir())
    out = make_out(tmp_path)
    # The record does not exist either: the output path is checked first.
    code, stdout, stderr = run_cli("sweep", tmp_path / "absent.AT2", "--mu", "0.05:0.1:0.05", "--out", out)
    assert_one_error_line(code, stdout, stderr, out, phrase)
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    assert (tmp_path / "blocker").read_text() == "kept"


def test_cli_sweep_refuses_an_unwritable_folder(run_cli, tmp_path, monkeypatch):
    import stickslip.plumbing.files

    locked = tmp_path / "locked"
    locked.mkdir()
    real_access = stickslip.plumbing.files.os.access
    # chmod does not stop root, so say "not writable" the way the OS would for others.
    monkeypatch.setattr(stickslip.plumbing.files.os, "access", lambda p, mode: False if str(p) == str(locked) else real_access(p, mode))
    out = locked / "sub" / "c.nc"
    code, stdout, stderr = run_cli("sweep", _pulse_file(tmp_path), "--format", "slammer_1col", "--dt", "0.01",
                                   "--mu", "0.05:0.1:0.05", "--out", out)
    assert_one_error_line(code, stdout, stderr, out, f"folder {locked} is not writable")
    assert list(locked.iterdir()) == []


def test_cli_turns_an_os_error_while_writing_into_one_line(run_cli, tmp_path, monkeypatch):
    """The backstop: an OSError that the early check did not foresee is one line, exit 2, nothing written."""
    import stickslip.cli.sweep

    monkeypatch.setattr(stickslip.cli.sweep, "check_output_path", lambda *args: None)
    (tmp_path / "blocker").write_text("kept")
    out = tmp_path / "blocker" / "c.nc"
    code, stdout, stderr = run_cli("sweep", _pulse_file(tmp_path), "--format", "slammer_1col", "--dt", "0.01",
                                   "--mu", "0.05:0.1:0.05", "--out", out)
    assert_one_error_line(code, stdout, stderr, tmp_path / "blocker", "File exists")
    assert (tmp_path / "blocker").read_text() == "kept"


def test_cli_keeps_the_traceback_of_a_bug(run_cli, tmp_path, monkeypatch):
    import stickslip.cli.sweep

    def bug(*args):
        raise ValueError("a bug")

    monkeypatch.setattr(stickslip.cli.sweep, "check_output_path", bug)
    with pytest.raises(ValueError, match="a bug"):
        run_cli("sweep", tmp_path / "any.AT2", "--mu", "0.05:0.1:0.05", "--out", tmp_path / "c.nc")


@pytest.mark.parametrize(
    ("mu_text", "phrase"),
    [
        ("0.05:1e9:1e-9", "999,999,999,950,000,001 friction ratios mu; at most 1,000,000 are allowed"),
        ("0.05:1e308:1e-300", "infinitely many friction ratios"),
        ("-0.1:0.2:0.05", "friction ratios mu must be positive, START is -0.1"),
        ("-1e-3:0.2:0.05", "friction ratios mu must be positive"),
    ],
)
@pytest.mark.parametrize("joined", [False, True])
def test_cli_sweep_rejects_huge_or_negative_mu_ranges(run_cli, tmp_path, mu_text, phrase, joined):
    out = tmp_path / "cube.nc"
    mu_args = [f"--mu={mu_text}"] if joined else ["--mu", mu_text]
    code, stdout, stderr = run_cli("sweep", tmp_path / "any.AT2", *mu_args, "--out", out)
    assert_one_error_line(code, stdout, stderr, "--mu", phrase)
    assert list(tmp_path.iterdir()) == []


def test_mu_range_may_hold_exactly_the_cap():
    from stickslip.cli.grid_values import parse_values
    from stickslip.grids import MAX_GRID_VALUES

    def parse_mu_range(text):
        return parse_values(text, "--mu", "friction ratios mu", "0.05:0.2:0.025", float)

    assert parse_mu_range("0.000001:1:0.000001").size == MAX_GRID_VALUES
    with pytest.raises(StickslipError, match="1,000,001 friction ratios"):
        parse_mu_range("0.000001:1.000001:0.000001")


def _legend_clear_of_axes(figure) -> bool:
    """Whether the legend of the figure's axes lies wholly outside the axes (drawn first)."""
    figure.canvas.draw()
    ax = figure.axes[0]
    legend = ax.get_legend().get_window_extent()
    return not legend.overlaps(ax.get_window_extent())


def test_figs_21_and_25_keep_their_legends_clear_and_ring_mu_max_on_the_grid_edge(records):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from stickslip.reports import plots

    grid = sweep(records, mu=MU)
    figure = plots.plot_energy_sweeps(grid)
    FigureCanvasAgg(figure)
    assert _legend_clear_of_axes(figure)
    rows = [{"record": "a", "status": "ok", "rms_acceleration": 1.0, "mu_max": 0.1, "mu_max_on_grid_edge": "False"},
            {"record": "a", "status": "ok", "rms_acceleration": 2.0, "mu_max": 0.2, "mu_max_on_grid_edge": "True"}]
    figure = plots.plot_scaling(rows, "rms_acceleration", "RMS acceleration [m/s²]", "Fig. 25")
    FigureCanvasAgg(figure)
    assert _legend_clear_of_axes(figure)
    labels = [text.get_text() for text in figure.axes[0].get_legend().get_texts()]
    assert plots.GRID_EDGE_LABEL in labels


def test_figs_22_and_23_keep_their_legends_clear():
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from stickslip.reports import plots

    points = [{"label": f"r{k}", "x": float(k), "y": 0.1 + 0.01 * k} for k in range(4)]
    fits = {"mu_max_vs_pga": {"status": "ok", "points": points,
                              "linear_fit": {"slope": 0.01, "intercept": 0.1, "r": 1.0}}}
    figure = plots.plot_mu_max_relation(fits, "mu_max_vs_pga", None, "PGA [m/s²]", "Fig. 22")
    FigureCanvasAgg(figure)
    assert _legend_clear_of_axes(figure)
