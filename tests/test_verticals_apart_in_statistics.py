"""Statistics over many records summarise horizontal shaking: vertical components are solved, listed, left out of
the medians, percentiles and means, and named apart with the reason (``optimum``, ``displacements``)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from stickslip.records.verticals_apart import left_out_line, verticals_apart

DT = 0.01
#: Three components of one station: (file name, component in the header, PGA [g], frequency [Hz]).
COMPONENTS = (("STA-090.AT2", "090", 0.45, 1.2), ("STA-000.AT2", "000", 0.30, 2.1), ("STA-UP.AT2", "UP", 0.25, 6.0))


def write_at2(path, component: str, acceleration_g: np.ndarray) -> None:
    """A PEER NGA-West2 AT2 file of ``acceleration_g`` [g] whose header names ``component``."""
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD", f"Somewhere, 1/1/2001, Station, {component}",
             "ACCELERATION TIME SERIES IN UNITS OF G", f"NPTS= {acceleration_g.size:6d}, DT= {DT:.4f} SEC,"]
    lines += ["".join(f"{value:15.7E}" for value in acceleration_g[start:start + 5])
              for start in range(0, acceleration_g.size, 5)]
    path.write_text("\n".join(lines) + "\n", encoding="ascii")


@pytest.fixture(scope="module")
def station(tmp_path_factory) -> list:
    folder = tmp_path_factory.mktemp("station")
    time = np.arange(0.0, 12.0, DT)
    paths = []
    for name, component, pga, frequency in COMPONENTS:
        motion = np.sin(2 * np.pi * frequency * time) * time * np.exp(-0.4 * time)
        write_at2(folder / name, component, pga * motion / np.max(np.abs(motion)))
        paths.append(folder / name)
    return paths


def test_verticals_apart_names_each_vertical_and_its_reason():
    included, apart = verticals_apart([("A-090", "a/A-090.AT2", None), ("A-UP", "a/A-UP.AT2", "its component is UP")])
    assert included.tolist() == [True, False]
    assert apart == [{"record": "A-UP", "source": "a/A-UP.AT2", "reason": "a vertical component: its component is UP"}]
    assert left_out_line(apart) == ("left out of the statistics, apart from the horizontal shaking they summarise: "
                                    "1 record: A-UP (a vertical component: its component is UP)")
    assert left_out_line([]) is None


def test_optimum_s_percentiles_are_over_the_horizontal_components_and_name_the_vertical(run_cli, station):
    code, out, err = run_cli("optimum", *station, "--mu", "0.05:0.3:0.05", "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert [row["vertical"] for row in printed["records"]] == [None, None, "its component is UP"]
    assert printed["left_out_of_statistics"] == [{"record": "STA-UP", "source": str(station[2]),
                                                  "reason": "a vertical component: its component is UP"}]
    statistics = printed["statistics"]
    assert statistics["records"] == 2
    mu = statistics["mu"]
    import stickslip

    energies = np.array([[stickslip.solve(stickslip.read_record(path), mu=value).scalars()["energy_dissipated"]
                          for value in mu] for path in station])
    np.testing.assert_allclose(statistics["energy_dissipated"], np.percentile(energies[:2], [50, 84], axis=0),
                               rtol=1e-9)
    assert not np.allclose(statistics["energy_dissipated"], np.percentile(energies, [50, 84], axis=0), rtol=1e-3)
    code, out, err = run_cli("optimum", *station, "--mu", "0.05:0.3:0.05")
    assert code == 0, err
    assert "over the 2 records, at each mu" in out
    assert ("left out of the statistics, apart from the horizontal shaking they summarise: 1 record: STA-UP (a "
            "vertical component: its component is UP)") in out


def test_optimum_with_one_horizontal_component_gives_no_statistics_and_says_why(run_cli, station):
    code, out, err = run_cli("optimum", station[0], station[2], "--mu", "0.05:0.3:0.05", "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert printed["statistics"] is None and len(printed["left_out_of_statistics"]) == 1
    code, out, err = run_cli("optimum", station[0], station[2], "--mu", "0.05:0.3:0.05")
    assert "no statistics over the records: 1 horizontal record(s), they need two" in out
    assert "1 record: STA-UP (a vertical component: its component is UP)" in out
    code, out, err = run_cli("optimum", station[0], station[1], "--mu", "0.05:0.3:0.05", "--json")
    assert json.loads(out)["left_out_of_statistics"] == [] and json.loads(out)["statistics"]["records"] == 2


def test_displacements_statistics_are_over_the_horizontal_components_and_name_the_vertical(run_cli, station):
    code, out, err = run_cli("displacements", *station, "--ky", "0.05,0.1", "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert printed["left_out_of_statistics"] == [{"record": "STA-UP", "source": str(station[2]),
                                                  "reason": "a vertical component: its component is UP"}]
    assert len(printed["records"]) == 6  # the vertical is solved and listed
    for statistic in printed["statistics"]:
        rows = [row for row in printed["records"] if row["ky"] == statistic["ky"]]
        horizontal = np.array([row["newmark_displacement_mean"] for row in rows if row["record"] != "STA-UP"])
        expected = {"mean": np.mean(horizontal), "median": np.median(horizontal), "std": np.std(horizontal, ddof=1)}
        assert statistic["records"] == 2
        assert statistic["newmark_displacement_mean"] == pytest.approx(expected[statistic["statistic"]], rel=1e-12)
    vertical = [row["newmark_displacement_mean"] for row in printed["records"] if row["record"] == "STA-UP"]
    assert vertical[0] > 0.0  # it slides, so leaving it in would move the mean
    code, out, err = run_cli("displacements", *station, "--ky", "0.05,0.1")
    assert code == 0, err
    assert "over the 2 records (the horizontal components):" in out
    assert "1 record: STA-UP (a vertical component: its component is UP)" in out


def test_the_design_chart_s_median_leaves_the_vertical_component_out(run_cli, station, tmp_path, monkeypatch):
    from stickslip.models.pendulum import chart

    charted = []
    design_chart = chart.design_chart

    def recorded(motions, radius, mu, **keywords):
        charted.append([motion.meta.record_id for motion in motions])
        return design_chart(motions, radius, mu, **keywords)

    monkeypatch.setattr(chart, "design_chart", recorded)
    arguments = ("--radius", "2", "--mu", "0.05:0.2:0.05", "--chart-radii", "1,2", "--chart")
    code, out, err = run_cli("optimum", *station, *arguments, tmp_path / "chart.png")
    assert code == 0, err
    assert charted == [["STA-090", "STA-000"]] and (tmp_path / "chart.png").stat().st_size > 0
    assert "1 record: STA-UP (a vertical component: its component is UP)" in out
    code, out, err = run_cli("optimum", station[2], *arguments, tmp_path / "alone.png")
    assert code == 0, err
    assert charted[-1] == ["STA-UP"]  # the one record given: its own chart
