"""The flexible sliding block (a soil layer on a sliding surface): its checks, its limits, and SLAMMER's own results.

Without the shared verification data only the first tests run; with them
(``../shared/verification``), the workflow's step is run in-process and the
``slammer`` scheme must reproduce every one of SLAMMER 1.1's flexible values by
pySLAMMER's rules (at least pySLAMMER 0.2.3's own rate), and the group regressions.
"""

from __future__ import annotations

import json

import numpy as np
import xarray as xr
import pytest
from conftest import assert_one_error_line

from stickslip.errors import StickslipError
from stickslip.plumbing.files import read_csv_rows
from stickslip.records.readers import read_record
from stickslip.records.record import Record, RecordMeta
from stickslip.models import solve
from stickslip.models import MODELS
from stickslip.models.layer import solve_flexible
from stickslip.models.layer.layer import Layer, equivalent_linear_properties, foundation_damping
from stickslip.studies.verification import flexible as flexible_verification
from stickslip.units import UNITS

G = 9.80665


@pytest.mark.parametrize(("arguments", "phrase"), [
    ({"height": -5.0}, "layer height H [m]"),
    ({"vs": 0.0}, "shear-wave velocity V_s [m/s]"),
    ({"damping": -0.3}, "the total is -0.1; it must lie in [0, 1)"),
    ({"damping": 0.9}, "the total is 1.1; it must lie in [0, 1)"),
    ({"reference_strain": 0.0}, "reference strain [%]"),
    ({"soil_model": "nonlinear"}, "expected one of linear, equivalent-linear"),
])
def test_a_bad_layer_is_one_clear_error(arguments, phrase):
    with pytest.raises(StickslipError) as error:
        Layer(**{"height": 50.0, "vs": 600.0, "vs_base": 600.0, **arguments})
    assert phrase in str(error.value)


def test_the_foundation_damping_is_capped_and_falls_with_a_stiffer_base():
    assert foundation_damping(600.0, 600.0) == 0.20
    assert foundation_damping(300.0, 1200.0) == pytest.approx(0.55016 * 4.0**-0.9904)
    assert foundation_damping(300.0, 1200.0) < foundation_damping(300.0, 900.0) < 0.20


def test_the_equivalent_linear_rules_soften_and_damp_with_strain():
    small = equivalent_linear_properties(1e-6, 50.0, 600.0, 600.0, 0.05)
    large = equivalent_linear_properties(1e-2, 50.0, 600.0, 600.0, 0.05)
    assert small[0] == pytest.approx(600.0, rel=1e-3) and small[2] == pytest.approx(1.0, abs=0.01)
    assert large[0] < small[0] and large[2] > small[2]
    strain = 100 * 0.65 * 1.57 * 1e-2 / 50.0  # [%]
    assert large[0] == pytest.approx(600.0 / np.sqrt(1.0 + strain / 0.05))


def test_a_stiff_thin_layer_slides_as_the_rigid_block():
    """ω ≫ the record's frequencies: the layer moves with its base, so both analyses approach SLAMMER's rigid block.

    The record is sampled at 1 ms, near the layer's period T = 4H/V_s = 0.67 ms; at 10 ms SLAMMER's coupled
    scheme drifts far from the rigid answer (docs/solvers.md, "The flexible sliding block").
    """
    time = np.arange(0.0, 12.0, 0.001)
    wave = (np.sin(2 * np.pi * 1.1 * time) + 0.4 * np.sin(2 * np.pi * 3.7 * time)) * np.exp(-0.25 * time)
    record = Record(0.6 * G * wave / np.max(np.abs(wave)), 0.001, RecordMeta(record_id="fine wave"))
    rigid = solve(record, ky=0.1, method="slammer", g=G).downslope_displacement
    layer = Layer(0.5, 3000.0, 3000.0, damping=0.0)
    for model in ("decoupled", "coupled"):
        for method in ("exact", "slammer"):
            flexible = solve_flexible(record, 0.1, layer, model, method, g=G)
            assert flexible.kmax == pytest.approx(0.6, rel=1e-3)
            assert flexible.displacement == pytest.approx(rigid, rel=1e-3), (model, method)


def test_no_sliding_below_the_yield_acceleration(two_tone_record):
    layer = Layer(30.0, 400.0, 600.0)
    for model in ("decoupled", "coupled"):
        result = solve_flexible(two_tone_record, 5.0, layer, model, g=G)
        assert result.displacement == 0.0 and result.iterations == 0
        assert result.vs_final == 400.0 and result.damping_final == pytest.approx(0.05 + foundation_damping(400, 600))


def test_the_equivalent_linear_layer_softens_and_the_polarities_differ(two_tone_record):
    layer = Layer(60.0, 400.0, 600.0, soil_model="equivalent-linear", reference_strain=0.05)
    normal = solve_flexible(two_tone_record, 0.1, layer, "coupled", g=G)
    inverse = solve_flexible(two_tone_record, 0.1, layer, "coupled", g=G, inverse=True)
    assert normal.iterations >= 2 and normal.vs_final < 400.0
    assert normal.kmax == inverse.kmax and normal.displacement != inverse.displacement
    assert normal.displacement > 0 and inverse.displacement > 0


@pytest.mark.parametrize("method", ["exact", "slammer"])
def test_the_result_keeps_the_record_s_time_step_and_its_sample_times_are_the_record_s(two_tone_record, method):
    result = solve_flexible(two_tone_record, 0.1, Layer(30.0, 400.0, 600.0), "coupled", method, g=G)
    assert result.dt == two_tone_record.dt
    np.testing.assert_array_equal(result.time, two_tone_record.time)
    assert result.time is result.time and result.time.size == result.block_displacement.size
    np.testing.assert_array_equal(result.to_xarray().time.values, two_tone_record.time)


def test_the_models_are_one_table_and_a_wrong_choice_is_refused(two_tone_record):
    assert list(MODELS)[:5] == ["rigid", "decoupled", "coupled", "planar", "pendulum"]  # registered after: any
    layer = Layer(30.0, 400.0, 600.0)
    with pytest.raises(StickslipError, match="unknown sliding-block model 'flexible'; known: rigid, decoupled, coupled, "
                                             "planar"):
        solve_flexible(two_tone_record, 0.1, layer, "flexible")
    with pytest.raises(StickslipError, match="the coupled model is solved by method exact, slammer, not 'newmark'"):
        solve_flexible(two_tone_record, 0.1, layer, "coupled", method="newmark")
    with pytest.raises(StickslipError, match=r"the rigid model \(.*\) does not take damping, equivalent_linear, "
                                             "height, ledger, vs, vs_base"):
        solve_flexible(two_tone_record, 0.1, layer, "rigid")
    with pytest.raises(StickslipError, match="the planar model takes the two horizontal components of one station "
                                             r"\(--pair\), not one horizontal component of a record"):
        solve_flexible(two_tone_record, 0.1, layer, "planar")


@pytest.fixture(scope="module")
def record_file(tmp_path_factory, two_tone_record):
    """The two-tone test record as a two-column text file in g."""
    path = tmp_path_factory.mktemp("records") / "wave.txt"
    time = np.arange(two_tone_record.npts) * two_tone_record.dt
    path.write_text("\n".join(f"{t:.2f} {a / G:.8f}" for t, a in zip(time, two_tone_record.acceleration)) + "\n",
                    encoding="ascii")
    return path


LAYER = ["--height", "40", "--vs", "300", "--vs-base", "600"]


@pytest.mark.parametrize("model", ["decoupled", "coupled"])
def test_the_command_line_solves_the_flexible_block_as_the_library(model, record_file, run_cli, tmp_path):
    out = tmp_path / "histories.nc"
    code, stdout, stderr = run_cli("solve", record_file, "--units", "g", "--g", str(G), "--ky", "0.1", "--model", model,
                                   *LAYER, "--damping", "0.03", "--equivalent-linear", "--reference-strain", "0.05%",
                                   "--inverse", "--json", "--out", out)
    assert code == 0 and stderr == "", stderr
    document = json.loads(stdout.splitlines()[0])
    layer = Layer(40.0, 300.0, 600.0, 0.03, "equivalent-linear", 0.05)
    expected = solve_flexible(read_record(record_file, units="g", g=G), 0.1, layer, model, g=G, inverse=True)
    assert document["model"] == model and document["method"] == "exact" and document["polarity"] == "inverse"
    assert document["displacement"] == pytest.approx(expected.displacement, rel=1e-12) and expected.displacement > 0
    assert document["vs_final"] == pytest.approx(expected.vs_final) and expected.vs_final < 300.0
    assert document["units"]["displacement"] == "m" and document["units"]["vs_final"] == "m s-1"
    with xr.open_dataset(out) as histories:
        assert histories.block_displacement.attrs["units"] == "m"
        assert float(abs(histories.block_displacement[-1])) == pytest.approx(expected.displacement, rel=1e-12)


@pytest.mark.parametrize(("arguments", "name", "phrase"), [
    (["--model", "decoupled", "--height", "-5", "--vs", "300", "--vs-base", "600"], "--height", "must be a positive finite number"),
    (["--model", "coupled", *LAYER, "--damping", "0.9"], "--damping", "it must lie in [0, 1)"),
    (["--model", "coupled", *LAYER, "--damping", "-0.6"], "--damping", "it must lie in [0, 1)"),
    (["--model", "coupled", *LAYER, "--equivalent-linear", "--reference-strain", "0%"], "--reference-strain",
     "must be a positive finite number"),
    (["--height", "40"], "--height", "applies to --model decoupled or coupled"),
    (["--model", "coupled", "--height", "40"], "--model coupled", "needs --vs, --vs-base"),
    (["--model", "coupled", *LAYER, "--method", "newmark"], "--method newmark", "is solved by method exact, slammer"),
    (["--model", "coupled", *LAYER, "--direction", "both"], "--direction", "does not apply to the coupled model"),
])
def test_a_flexible_mistake_is_one_line(arguments, name, phrase, record_file, run_cli):
    code, stdout, stderr = run_cli("solve", record_file, "--units", "g", "--ky", "0.1", *arguments)
    assert_one_error_line(code, stdout, stderr, name, phrase)


def test_a_coarse_step_for_the_layer_gets_a_note(record_file, run_cli):
    code, stdout, stderr = run_cli("solve", record_file, "--units", "g", "--ky", "0.1", "--model", "decoupled",
                                   "--height", "5", "--vs", "600", "--vs-base", "600", "--method", "slammer")
    assert code == 0
    assert stderr.count("\n") == 1 and "time step 0.01 s is coarse for the layer's period T = 4H/V_s = 0.03333 s" in stderr
    code, stdout, stderr = run_cli("solve", record_file, "--units", "g", "--ky", "0.1", "--model", "decoupled",
                                   "--height", "5", "--vs", "600", "--vs-base", "600")
    assert code == 0 and stderr == ""  # the exact scheme has no such limit


def test_a_sweep_is_a_cube_of_records_yield_coefficients_and_heights(record_file, run_cli, tmp_path):
    out = tmp_path / "flexible.nc"
    code, stdout, stderr = run_cli("sweep", record_file, "--units", "g", "--g", str(G), "--ky", "0.05:0.15:0.05",
                                   "--model", "coupled", "--height", "10,40,160", "--vs", "300", "--vs-base", "600",
                                   "--out", out)
    assert code == 0, stderr
    with xr.open_dataset(out) as cube:
        assert dict(cube.displacement.sizes) == {"record": 1, "ky": 3, "height": 3}
        assert cube.displacement.attrs["units"] == "m" and cube.height.attrs["units"] == "m"
        assert cube.attrs["model"] == "coupled" and cube.attrs["solver"] == "exact"
        one = solve_flexible(read_record(record_file, units="g", g=G), 0.1, Layer(40.0, 300.0, 600.0), "coupled", g=G)
        assert cube.displacement.isel(record=0).sel(ky=0.1, height=40.0).item() == pytest.approx(one.displacement,
                                                                                                rel=1e-12)
        assert cube.kmax.isel(record=0).sel(height=40.0).item() == pytest.approx(one.kmax, rel=1e-12)
        assert np.all(np.diff(cube.displacement.values[0], axis=0) <= 0)  # a stronger block slides less
        case = cube.isel(record=0).sel(ky=0.1, height=40.0)
        for name in ("energy_input_per_mass", "energy_damped_per_mass", "energy_dissipated_per_mass"):
            assert case[name].item() == pytest.approx(one.scalars()[name], rel=1e-12) and case[name].item() > 0
            assert cube[name].attrs["units"] == "J kg-1"
        friction = (cube.ky * G * cube.displacement).transpose(*cube.displacement.dims)
        xr.testing.assert_allclose(cube.energy_dissipated_per_mass, friction, rtol=1e-12)


def test_a_slammer_sweep_has_the_friction_energy_and_no_ledger(record_file, run_cli, tmp_path):
    out = tmp_path / "flexible.nc"
    code, stdout, stderr = run_cli("sweep", record_file, "--units", "g", "--g", str(G), "--ky", "0.05,0.1",
                                   "--model", "decoupled", "--height", "40", "--vs", "300", "--vs-base", "600",
                                   "--method", "slammer", "--out", out)
    assert code == 0, stderr
    with xr.open_dataset(out) as cube:
        assert "energy_input_per_mass" not in cube and "energy_damped_per_mass" not in cube
        friction = (cube.ky * G * cube.displacement).transpose(*cube.displacement.dims)
        xr.testing.assert_allclose(cube.energy_dissipated_per_mass, friction, rtol=1e-12)
        assert (cube.energy_dissipated_per_mass > 0).all()


@pytest.mark.parametrize(("arguments", "name", "phrase"), [
    (["--mu", "0.05:0.1:0.05", "--model", "coupled", *LAYER], "--mu", "does not apply to the coupled model"),
    (["--ky", "0.05:0.1:0.05", "--model", "coupled", "--height", "10,5", "--vs", "300", "--vs-base", "600"],
     "--height '10,5'", "strictly increasing"),
    (["--ky", "0.05:0.1:0.05", "--model", "coupled", *LAYER, "--target-pga", "0.2", "0.4"], "--target-pga",
     "takes one value"),
    (["--ky", "0.05:0.1:0.05", *LAYER], "--height", "apply to --model decoupled or coupled"),
])
def test_a_flexible_sweep_mistake_is_one_line(arguments, name, phrase, record_file, run_cli, tmp_path):
    out = tmp_path / "cube.nc"
    code, stdout, stderr = run_cli("sweep", record_file, "--units", "g", *arguments, "--out", out)
    assert_one_error_line(code, stdout, stderr, name, phrase)
    assert not out.exists()


def test_without_the_reference_the_step_says_why(tmp_path):
    summary, analyses = tmp_path / "flexible_summary.json", tmp_path / "flexible_analyses.csv"
    flexible_verification.write_flexible_verification(summary, analyses, folder=None)
    written = json.loads(summary.read_text())
    assert written["status"] == "not available" and "verification folder" in written["reason"]
    assert read_csv_rows(analyses) == []


@pytest.fixture(scope="module")
def verified(flexible_verification_folder):
    """The workflow's step run in-process on the shared reference (and pySLAMMER's results beside it)."""
    folder = flexible_verification_folder
    return {"rows": read_csv_rows(folder / "flexible_analyses.csv"),
            "summary": json.loads((folder / "flexible_summary.json").read_text(encoding="utf-8"))}


def _group_rows(rows, scheme, name):
    model, soil = name.split(" ")
    return [row for row in rows if row["scheme"] == scheme and row["model"] == model and row["soil_model"] == soil]


def test_the_slammer_scheme_reproduces_every_value_and_beats_or_ties_pyslammer(verified):
    """Scaled as SLAMMER scales (by the PGA its database states), every value to SLAMMER's printed digits."""
    summary, rows = verified["summary"], verified["rows"]
    differences = [abs(float(row["displacement_difference"])) for row in rows if row["scheme"] == "slammer"]
    assert len(differences) == 5040 and max(differences) < 1e-4  # cm; SLAMMER prints 5 decimals
    assert summary["source"]["values"] == 5040 and len(rows) == 2 * 5040
    for name, group in summary["schemes"]["slammer"].items():
        mine = _group_rows(rows, "slammer", name)  # recomputed from the table, independently of the summary
        passed = sum(row["passes"] == "True" for row in mine)
        theirs = sum(row["pyslammer_passes"] == "True" for row in mine)
        assert passed == group["passed"] == len(mine), name
        assert passed >= theirs == group["pyslammer"]["passed"], name
        assert group["passes"], name
        for fit in group["polarities"].values():
            assert abs(fit["slope"] - 1.0) <= 0.01 and abs(fit["intercept"]) <= 0.1 and fit["r_squared"] >= 0.99
        assert {(miss["analysis_id"], miss["polarity"]) for miss in group["misses"]} == {
            (row["analysis_id"], row["polarity"]) for row in mine if row["passes"] != "True"}


def test_every_miss_of_the_exact_scheme_is_slammer_s_time_step(verified):
    """Each exact miss: SLAMMER's scheme at dt/100 closer to the exact answer than SLAMMER 1.1, and within tolerance."""
    summary, rows = verified["summary"], verified["rows"]
    for name, group in summary["schemes"]["exact"].items():
        mine = _group_rows(rows, "exact", name)
        failing = {(row["analysis_id"], row["polarity"]) for row in mine if row["passes"] != "True"}
        assert {(miss["analysis_id"], miss["polarity"]) for miss in group["misses"]} == failing, name
        for miss in group["misses"]:
            finest = miss["scheme_displacements"]["100"]
            exact, reference = miss["exact_displacement"], miss["reference_displacement"]
            assert abs(finest - exact) < abs(reference - exact) and abs(finest - exact) <= miss["tolerance"], miss
        assert group["explained"] == len(group["misses"]), name


def test_the_negative_damping_is_read_as_given(verified):
    reading = verified["summary"]["damping_reading"]
    assert reading["analyses"] == 1620 and reading["stored_damping"] == [-0.05] and reading["stored_final_damping"] == [0.15]
    assert reading["readings"]["as_given"]["pass_rate"] == 1.0
    assert reading["readings"]["absolute_value"]["pass_rate"] < 0.5


def test_slammer_s_other_outputs_agree(verified):
    for name, agreement in verified["summary"]["properties"].items():
        assert agreement["compared"] == 5040 and agreement["largest_relative_difference"] < 2e-4, name  # 5 digits


def test_the_exact_scheme_does_not_depend_on_the_sampling(two_tone_record):
    """Resampling the record linearly to dt/7 leaves the exact answer unchanged, equivalent-linear iteration included."""
    from stickslip.records.process import resample

    finer = resample(two_tone_record, two_tone_record.dt / 7)
    for soil_model in ("linear", "equivalent-linear"):
        layer = Layer(30.0, 250.0, 600.0, soil_model=soil_model)
        for model in ("decoupled", "coupled"):
            coarse = solve_flexible(two_tone_record, 0.12, layer, model, "exact", g=G)
            fine = solve_flexible(finer, 0.12, layer, model, "exact", g=G)
            assert coarse.displacement > 0 and fine.displacement == pytest.approx(coarse.displacement, rel=1e-9)
            assert fine.vs_final == pytest.approx(coarse.vs_final, rel=1e-9)


def test_the_bound_that_skips_a_search_never_hides_an_event():
    """Where the exact scheme's bound says nothing happens over an interval, nothing does: on 10,000 random states
    of the layer, stuck, sliding and alone, the watched function sampled at 2,001 points never crosses."""
    from stickslip.models.layer import exact as kernel

    rng = np.random.default_rng(7)
    ratio, participation = 2.0 / np.pi, 4.0 / np.pi
    tau = np.linspace(0.0, 1.0, 2001)
    proved = {"stuck": 0, "sliding": 0, "alone": 0}
    for _ in range(10_000):
        omega, xi = rng.uniform(2.0, 200.0), rng.uniform(0.0, 0.4)
        decay, damped = xi * omega, omega * np.sqrt(1.0 - xi * xi)
        length = rng.uniform(0.05, 4.0) * 2.0 * np.pi / omega
        a0, slope, threshold = rng.normal(0.0, 3.0), rng.normal(0.0, 300.0), rng.uniform(0.2, 3.0)
        u0, v0 = rng.normal(0.0, 3.0 / omega**2), rng.normal(0.0, 3.0 / omega)
        kind = rng.choice(["stuck", "sliding", "alone"])
        w0 = rng.uniform(0.0, 1.0) if kind == "sliding" else 0.0
        p0, p1 = -participation * a0, -participation * slope
        c0, c1, a, b = kernel._coefficients(u0, v0, omega, decay, damped, p0, p1)
        times = tau * length
        e = np.exp(-decay * times)
        u = c0 + c1 * times + e * (a * np.cos(damped * times) + b * np.sin(damped * times))
        v = c1 + e * ((-decay * a + damped * b) * np.cos(damped * times) + (-decay * b - damped * a) * np.sin(damped * times))
        peak = max(abs(u0), rng.uniform(0.5, 1.5) * np.abs(u).max())
        quiet = kernel._quiet(length, kind != "alone", True, kind == "sliding", c0, c1, a, b, omega, decay, p0, p1, a0,
                              slope, threshold, ratio, u0, v0, w0, u[-1], v[-1], peak)
        if not quiet:
            continue
        proved[kind] += 1
        if kind == "alone":
            assert np.abs(u).max() <= peak * (1 + 1e-12)
        else:
            f = kernel._event_from_state(u, v, times, kind == "sliding", decay, omega, p0, p1, a0, slope, threshold,
                                         ratio, w0, v0)
            assert (f > 0).all() if kind == "sliding" else (f <= 1e-12 * threshold).all()
    assert min(proved.values()) > 500  # the bound proves a good share quiet, so that the check above is exercised


def test_the_slammer_scheme_converges_to_the_exact_one(two_tone_record):
    """SLAMMER's stepping on the record resampled to dt/k: second order for the decoupled block; the coupled one's
    stop, placed by linear interpolation, converges more slowly (measured: 3e-5, 2e-5, 3e-5, 2e-6 relative)."""
    from stickslip.records.process import resample

    layer = Layer(30.0, 250.0, 600.0)
    errors = {}
    for model in ("decoupled", "coupled"):
        exact = solve_flexible(two_tone_record, 0.12, layer, model, "exact", g=G).displacement
        records = [two_tone_record, *(resample(two_tone_record, two_tone_record.dt / k) for k in (10, 100, 1000))]
        errors[model] = [abs(solve_flexible(record, 0.12, layer, model, "slammer", g=G).displacement - exact) / exact
                         for record in records]
    decoupled, coupled = errors["decoupled"], errors["coupled"]
    assert all(finer < coarser / 50 for coarser, finer in zip(decoupled, decoupled[1:])) and decoupled[-1] < 1e-8
    assert coupled[-1] < min(coupled[:-1]) / 5 and coupled[-1] < 1e-5


def test_every_numeric_column_has_units(verified):
    for column in flexible_verification.ANALYSIS_COLUMNS:
        values = [row[column] for row in verified["rows"] if row[column] != ""]
        numeric = all(_is_number(value) for value in values[:50])
        assert not numeric or column in UNITS, column


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return text not in ("True", "False")
