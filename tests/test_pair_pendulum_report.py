"""``stickslip report --pair X Y --radius R [--vertical V]``: the friction pendulum in the plane as one page.

The page is the record report's for the pair (its design answer is ``stickslip optimum``'s, number for number),
with each component's measures and acceleration, the slider's path in the plane, the lift-off intervals where the
vertical lifts the slider off, and the design chart over R × μ.  The motion is pyslammer's sample records (two
horizontal axes and a vertical that lifts the slider off), so a stranger without the shared records runs every test.
"""

from __future__ import annotations

import html
import json
import re
from importlib.resources import files as package_files

import numpy as np
import pytest
from conftest import assert_one_error_line

import stickslip
from stickslip.records.pair import RecordPair
from stickslip.records.readers import read_record
from stickslip.records.record import Record, RecordMeta
from stickslip.records.vertical import WithVertical
from stickslip.reports.design_answer import answer_rows, format_number
from stickslip.reports.plots import plot_case_response
from stickslip.reports.record_report import FIGURES, PAIR_FIGURES, figure_alts

SAMPLES = package_files("pyslammer") / "sample_ground_motions"
GRID = ("--mu", "0.02:0.4:0.02")


def _component(values, dt: float, name: str) -> Record:
    return Record(np.ascontiguousarray(values, dtype=float), dt, RecordMeta(record_id=name, component=name[-3:],
                                                                           source=f"{name}.txt"))


@pytest.fixture(scope="module")
def motion() -> dict:
    """Northridge VSP-360 and Loma Prieta HSP-000 as two horizontal axes of one station and Coalinga PVB-045 times −3
    (1.1 g at most downwards: the slider lifts off) as its vertical, positive up; the first 20 s (0.005 s)."""
    first = read_record(SAMPLES / "Northridge_1994_VSP-360.csv")
    second = read_record(SAMPLES / "Loma_Prieta_1989_HSP-000.csv")
    third = read_record(SAMPLES / "Coalinga_1983_PVB-045.csv")
    length, dt = 4001, first.dt
    return {"first": _component(first.acceleration[:length], dt, "STA-000"),
            "second": _component(second.acceleration[:length], dt, "STA-090"),
            "vertical": _component(-3.0 * third.acceleration[:length], dt, "STA-UP")}


@pytest.fixture
def files(tmp_path, motion) -> dict:
    paths = {}
    for key, record in motion.items():
        path = tmp_path / f"{record.meta.record_id}.txt"
        time = np.arange(record.npts) * record.dt
        path.write_text("\n".join(f"{t:.3f} {value:.12e}" for t, value in zip(time, record.acceleration)) + "\n")
        paths[key] = path
    return paths


def _answer_table(page: str) -> dict[str, tuple[str, str]]:
    (table,) = [table for table in re.findall(r"<table.*?</table>", page, re.S) if "μ_max on the grid" in table]
    return {html.unescape(quantity): (value, units) for quantity, value, units
            in re.findall(r"<th>([^<]+)</th>\s*<td>([^<]+)</td>\s*<td>([^<]*)</td>", table)}


def test_the_pair_page_of_the_pendulum_with_its_vertical_is_what_optimum_prints_and_its_response(run_cli, files,
                                                                                                 tmp_path):
    common = (files["first"], files["second"], "--pair", "--radius", "2", "--units", "m/s2", "--vertical",
              files["vertical"], *GRID)
    page_path = tmp_path / "page.html"
    code, out, err = run_cli("report", *common, "--chart-radii", "1.5,2.5", "--out", page_path)
    assert code == 0, err
    assert out.strip() == str(page_path) and "rendering page 1 of 1 (STA-000.txt + STA-090.txt)" in err
    code, printed, err = run_cli("optimum", *common, "--json")
    assert code == 0, err
    answer = json.loads(printed)["records"][0]
    page = page_path.read_text(encoding="utf-8")

    assert "<title>Pair report: STA-000 + STA-090</title>" in page
    assert "source files <code>STA-000.txt</code> and <code>STA-090.txt</code>" in page
    assert "With its vertical component, <code>STA-UP.txt</code>, read positive up" in page
    table = _answer_table(page)
    expected = answer_rows(answer, "mu", 0.95, 0.1, {"peak_base_shear": ("1", "", "V/W")})
    assert list(table) == [quantity for quantity, *_ in expected]
    for quantity, name, value, units in expected:  # V/W at the grid's μ_max and the range's ends among them
        assert table[quantity] == (value, "J/kg" if units == "J" else units), quantity  # the default 1 kg block
    assert "V/W at the grid's μ_max" in table

    first, second, vertical = (stickslip.read_record(files[key], units="m/s2") for key in ("first", "second",
                                                                                          "vertical"))
    pair = WithVertical.of(RecordPair(first, second), vertical)
    shown_mu = format_number(answer["mu_max_continuous"], 5)
    response = stickslip.solve(pair, model="pendulum", mu=float(shown_mu), radius=2.0)
    assert f"Response at μ = {shown_mu} (the record's μ_max, continuous)" in page
    assert response.liftoff.size and f"The slider {html.escape(response.liftoff_notes()[0])}." in page
    demand = format_number(response.scalars()["peak_relative_displacement"], 6)
    assert re.search(r"largest distance of the slider from the surface's centre, max \|u\| \(displacement demand\)"
                     rf"</th>\s*<td>{re.escape(demand)}</td>", page)
    for name in ("energy_vs_mu", "displacement_vs_mu", "design_chart", "acceleration", "response"):
        alt = PAIR_FIGURES[name].format(record="STA-000_STA-090")
        assert f'alt="{alt}"' in page, name
    assert "Not drawn" not in page  # the design chart is drawn over the two radii
    assert re.search(r"<th></th>\s*<th>STA-000</th>\s*<th>STA-090</th>\s*<th>units</th>", page)  # measures of each


def test_several_pairs_of_the_pendulum_need_a_folder_and_a_vertical_is_one_station(run_cli, files, tmp_path):
    pair = (files["first"], files["second"])
    other = tuple(tmp_path / path.name.replace("STA", "STB") for path in pair)  # a second station, a copy
    for source, copy in zip(pair, other):
        copy.write_bytes(source.read_bytes())
    assert_one_error_line(*run_cli("report", *pair, *other, "--pair", "--radius", "2", "--units", "m/s2",
                                   "--out", tmp_path / "two.html"), "--out", "2 pairs give one page each")
    assert_one_error_line(*run_cli("report", *pair, *other, "--pair", "--radius", "2", "--units", "m/s2", "--vertical",
                                   files["vertical"], "--out", tmp_path / "pages"), "--vertical",
                          "the vertical of one station")
    assert not (tmp_path / "two.html").exists() and not (tmp_path / "pages").exists()


def test_the_pair_page_has_the_record_page_s_figures_in_the_pair_s_words():
    assert set(figure_alts("R")) == {f"R_{name}.png" for name in FIGURES}  # what the workflow's record pages declare
    pair = figure_alts("A_B", pair=True)
    assert set(pair) == {f"A_B_{name}.png" for name in FIGURES}
    assert pair["A_B_response.png"] == ("A_B: displacement of the slider along each component and energies against "
                                        "time, and its path in the plane, at the case's friction ratio")


def test_the_response_figure_draws_each_component_shades_the_lift_off_and_draws_the_path(motion):
    pair = WithVertical.of(RecordPair(motion["first"], motion["second"]), motion["vertical"])
    response = stickslip.solve(pair, model="pendulum", mu=0.08, radius=2.0)
    figure = plot_case_response(response)
    top = figure.axes[0]
    assert [line.get_label() for line in top.get_lines()] == ["along 0°", "along 90°"]
    np.testing.assert_array_equal(top.get_lines()[1].get_ydata(), response.relative_displacement[:, 1])
    assert "shaded: sliding (blue), lifted off (orange)" in top.get_title().replace("\n", " ")
    lifted = [patch for patch in top.patches if patch.get_facecolor()[:3] == pytest.approx((1.0, 0.498, 0.055),
                                                                                           abs=1e-3)]
    assert len(lifted) == len(response.liftoff)  # one orange span per interval of lift-off
    path = next(ax for ax in figure.axes if ax.get_title() == "path of the slider in the plane")
    np.testing.assert_array_equal(path.get_lines()[0].get_xydata(), response.relative_displacement)
    assert path.get_xlabel() == "displacement along 0° [m]" and path.get_ylabel() == "displacement along 90° [m]"
