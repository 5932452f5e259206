"""stockbridge.simulate: the program's numbers for the same file (the history CSV and
the --json summary), errors as the library's exceptions, and the plot of the result
and of the program's files."""

import csv
import json
import os
import re
import struct
import subprocess
import sys

import pytest

import stockbridge as sb
import stockbridge.plot

CLI = os.environ["STOCKBRIDGE_CLI"]
SOURCE = os.environ["STOCKBRIDGE_SOURCE_DIR"]
# A coarse mesh and step, a row a period: seconds, not minutes.
COARSE = ["--elements-per-wavelength", "10", "--steps-per-period", "40", "--every", "40"]


@pytest.fixture(scope="module")
def span_file(tmp_path_factory):
    """The example span beside its damper file."""
    folder = tmp_path_factory.mktemp("simulate")
    for name in ("aster570_400m.toml", "sauter2003.toml"):
        (folder / name).write_text(open(os.path.join(SOURCE, "examples", name)).read())
    return folder / "aster570_400m.toml"


@pytest.fixture(scope="module")
def result(span_file):
    return sb.simulate(span_file, frequency=20, elements_per_wavelength=10, steps_per_period=40, every=40)


def read_columns(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    return {key: [row[key] for row in rows] for key in rows[0]}


def test_simulate_equals_the_programs_csv_and_json(span_file, result):
    folder = span_file.parent
    run = subprocess.run([CLI, "simulate", str(span_file), "--frequency", "20", *COARSE, "--json", "-o", "history.csv"],
                         cwd=folder, check=True, capture_output=True, text=True)
    summary = json.loads(run.stdout)
    history = read_columns(folder / "history.csv")
    assert result["columns"] == list(history)
    assert result["columns"][:2] == ["time_s", "y_at_89mm_m"]
    for column in result["columns"]:
        assert result[column] == pytest.approx([float(v) for v in history[column]], rel=1e-15, abs=1e-300), column
    summary.pop("seconds")
    result["summary"].pop("seconds")
    assert result["summary"] == summary
    assert result["summary"]["settled"] is True
    assert len(result["time_s"]) == result["summary"]["periods"]


def test_simulate_returns_the_documented_keys(result):
    with open(os.path.join(SOURCE, "docs", "python.md")) as handle:
        row = next(line for line in handle if line.startswith("| `simulate("))
    documented = {name.strip() for span in re.findall(r"`([^`]*)`", row.split("|")[2]) for name in span.split(",")}
    expanded = {name.replace("<mm>", mm).replace("<i>", i) for name in documented for mm in ("89", "1000", "200000",
                                                                                              "399000") for i in "12"}
    assert set(result) <= expanded, set(result) - expanded
    assert {"time_s", "y_at_200000mm_m", "damper_2_velocity_m_s", "columns", "summary"} <= set(result)


def test_simulate_errors_name_the_setting(span_file):
    with pytest.raises(sb.InvalidParameter, match="frequency = 0"):
        sb.simulate(span_file, frequency=0)
    with pytest.raises(sb.InvalidParameter, match="ends = 'hinged'"):
        sb.simulate(span_file, frequency=20, ends="hinged")
    with pytest.raises(sb.InvalidParameter, match=r"probes\[0\] = 500"):
        sb.simulate(span_file, frequency=20, probes=[500])
    text = open(span_file).read() + '\n[[mass]]\nname = "sphere"\nmass = 15.0\npositions = [150.0]\n'
    with pytest.raises(sb.InvalidParameter, match=r"mass\[0\]"):
        sb.simulate(text=text, base=span_file.parent, frequency=20)


def png_size(path):
    with open(path, "rb") as handle:
        header = handle.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG file"
    return struct.unpack(">II", header[16:24])


def test_plot_simulate_of_the_result_and_of_the_files(span_file, result, tmp_path):
    figure = stockbridge.plot.simulate(result, tmp_path / "result.png")
    assert len(figure.axes) == 3
    assert png_size(tmp_path / "result.png") == (800, 600)
    folder = span_file.parent
    run = subprocess.run([CLI, "simulate", str(span_file), "--frequency", "20", *COARSE, "--json", "-o", "h.csv"],
                         cwd=folder, check=True, capture_output=True, text=True)
    (folder / "h.json").write_text(run.stdout)
    plot = [sys.executable, "-m", "stockbridge.plot", "simulate", "h.csv"]
    done = subprocess.run(plot + ["--summary", "h.json", "-o", str(tmp_path / "files.png")], cwd=folder,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert png_size(tmp_path / "files.png") == (800, 600)
    history_only = subprocess.run(plot + ["-o", str(tmp_path / "history.png")], cwd=folder, capture_output=True,
                                  text=True)
    assert history_only.returncode == 0, history_only.stderr
    (folder / "other.csv").write_text("frequency_hz,x\n1,2\n")
    bad = subprocess.run([sys.executable, "-m", "stockbridge.plot", "simulate", "other.csv", "-o",
                          str(tmp_path / "bad.png")], cwd=folder, capture_output=True, text=True)
    assert bad.returncode == 2
    assert bad.stderr.count("\n") == 1 and "time_s" in bad.stderr, bad.stderr
    assert not os.path.exists(tmp_path / "bad.png")


@pytest.fixture(scope="module")
def coarse_span_file(span_file):
    """The example span with a [time] table of the coarse mesh and step."""
    path = span_file.parent / "coarse.toml"
    path.write_text(open(span_file).read() + "\n[time]\nelements_per_wavelength = 10\nsteps_per_period = 40\n")
    return path


def test_span_check_time_equals_the_programs_json(coarse_span_file, tmp_path):
    folder = coarse_span_file.parent
    run = subprocess.run([CLI, "span", str(coarse_span_file), "--points", "10", "--check-time", "20", "--json", "-o",
                          "s.csv"], cwd=folder, check=True, capture_output=True, text=True)
    expected = json.loads(run.stdout)["check_time"]
    with pytest.warns(UserWarning, match="check in time at 20 Hz"):
        out = sb.span(coarse_span_file, points=10, check_time=[20], report=tmp_path / "span.html")
    assert out["summary"]["check_time"] == expected
    row = expected[0]
    assert row["asked_frequency_hz"] == 20 and row["settled"] is True
    assert row["antinode_amplitude_ratio"] == pytest.approx(row["antinode_amplitude_m"] / row["ebm_antinode_amplitude_m"])
    assert row["agrees"] is False  # the coarse mesh: 0.906 and 1.125 (docs/time-domain.md)
    page = (tmp_path / "span.html").read_text()
    assert "Checked in time" in page and "check in time at 20 Hz" in page
    with pytest.raises(sb.InvalidParameter, match=r"check_time\[0\] = -1"):
        sb.span(coarse_span_file, points=10, check_time=[-1])


def test_simulate_takes_the_span_files_settings_and_writes_the_report(coarse_span_file, tmp_path):
    out = sb.simulate(coarse_span_file, frequency=20, every=100000, report=tmp_path / "simulate.html")
    summary = out["summary"]
    assert summary["dt_s"] * summary["frequency_hz"] == pytest.approx(1 / 40)
    assert summary["ends"] == "clamped"
    assert len(summary["antinode_along_m"]) == len(summary["x_m"])
    # The local antinode amplitude bounds |y| at every node, and equals Y at mid-span.
    assert all(a >= y - 1e-15 for a, y in zip(summary["antinode_along_m"], summary["amplitude_m"]))
    page = (tmp_path / "simulate.html").read_text()
    assert "Span in time" in page and "In time beside the balance" in page
    assert f"{summary['antinode_amplitude_m_ratio']:.3f}" in page
    pinned = sb.simulate(coarse_span_file, frequency=20, ends="pinned", duration=0.2)
    assert pinned["summary"]["ends"] == "pinned" and pinned["summary"]["settled"] is False
