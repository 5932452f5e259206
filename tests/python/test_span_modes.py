"""stockbridge.span_modes: the program's numbers for the same file (the modes CSV,
the shapes CSV, the --json summary), the shapes as numpy arrays, errors as the
library's exceptions, and the plot of the result and of the program's files."""

import csv
import json
import math
import os
import re
import struct
import subprocess
import sys

import numpy as np
import pytest

import stockbridge as sb
import stockbridge.plot

CLI = os.environ["STOCKBRIDGE_CLI"]
SOURCE = os.environ["STOCKBRIDGE_SOURCE_DIR"]
SPHERE = '\n[[mass]]\nname = "sphere"\nmass = 15.0\npositions = [150.0, 250.0]\n'


@pytest.fixture(scope="module")
def span_file(tmp_path_factory):
    """The example span with a warning sphere at two positions, beside its damper file."""
    folder = tmp_path_factory.mktemp("span_modes")
    with open(os.path.join(SOURCE, "examples", "aster570_400m.toml")) as handle:
        text = handle.read()
    (folder / "span.toml").write_text(text + SPHERE)
    (folder / "sauter2003.toml").write_text(open(os.path.join(SOURCE, "examples", "sauter2003.toml")).read())
    return folder / "span.toml"


def read_columns(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    return {key: [row[key] for row in rows] for key in rows[0]}


def test_span_modes_equals_the_programs_csvs_and_json(span_file):
    folder = span_file.parent
    run = subprocess.run([CLI, "span", str(span_file), "--modes", "--fmax", "4", "--shapes", "shapes.csv", "--json",
                          "-o", "modes.csv"], cwd=folder, check=True, capture_output=True, text=True)
    summary = json.loads(run.stdout)
    out = sb.span_modes(span_file, fmax=4)
    modes = read_columns(folder / "modes.csv")
    assert out["columns"] == list(modes)
    for column in out["columns"]:
        assert out[column] == pytest.approx([float(v) for v in modes[column]], rel=1e-15, abs=1e-300), column
    summary.pop("seconds")
    assert out["summary"] == summary
    shapes = read_columns(folder / "shapes.csv")
    assert out["x_m"] == pytest.approx([float(v) for v in shapes["x_m"]], rel=1e-15)
    assert out["shapes"].shape == (len(out["mode"]), len(out["x_m"]))
    for i, number in enumerate(out["mode"]):
        assert out["shapes"][i] == pytest.approx([float(v) for v in shapes[f"mode_{number}"]], rel=1e-15, abs=1e-300)
    assert [name for name in shapes["attachment"] if name] == ["sauter2003", "sphere", "sphere", "sauter2003"]


def test_span_modes_arrays_and_attachments(span_file):
    out = sb.span_modes(span_file, fmax=4, dampers="removed")
    assert out["mode"].dtype == np.int64 or out["mode"].dtype == np.float64
    assert [a["name"] for a in out["summary"]["attachments"]] == ["sphere", "sphere"]
    assert out["attachment_deflection"].shape == (len(out["mode"]), 2)
    positions = [a["position_m"] for a in out["summary"]["attachments"]]
    for k, x in enumerate(positions):
        column = out["x_m"].tolist().index(x)
        assert out["attachment_deflection"][:, k] == pytest.approx(out["shapes"][:, column], rel=1e-15)
    assert np.all(np.abs(out["shapes"]) <= 1.0 + 1e-12)
    assert np.all(out["shapes"][:, 0] == 0.0)
    assert np.all(np.abs(out["shapes"][:, -1]) < 1e-9)
    no_shapes = sb.span_modes(span_file, fmax=4, dampers="removed", shapes=False)
    assert no_shapes["shapes"].shape == (len(out["mode"]), 0)
    assert no_shapes["frequency_hz"] == pytest.approx(out["frequency_hz"], rel=0, abs=0)


def test_span_modes_returns_the_documented_keys(span_file):
    with open(os.path.join(SOURCE, "docs", "python.md")) as handle:
        row = next(line for line in handle if line.startswith("| `span_modes("))
    documented = {name.strip() for span in re.findall(r"`([^`]*)`", row.split("|")[2]) for name in span.split(",")}
    out = sb.span_modes(span_file, fmax=2)
    columns = {a["column"] for a in out["summary"]["attachments"]}
    expanded = {name.replace("<attachment>", column) for name in documented for column in columns}
    assert set(out) <= expanded, set(out) - expanded
    assert {"sphere_1_deflection", "sauter2003_2_deflection", "x_m", "shapes", "summary"} <= set(out)


def test_span_modes_default_fmax_is_the_wind_bands_top(span_file):
    out = sb.span_modes(span_file, shapes=False)
    assert out["summary"]["fmax_from_wind_band"] is True
    assert out["summary"]["fmax_hz"] == pytest.approx(0.185 * 7.0 / 0.03105, rel=1e-12)
    assert out["summary"]["clamp_still_modes"] == 2  # Sauter's identical arms at 21.17 Hz, both ends


def test_span_modes_errors_name_the_setting(span_file):
    with pytest.raises(sb.InvalidParameter, match=r"fmax = -1"):
        sb.span_modes(span_file, fmax=-1)
    with pytest.raises(sb.InvalidParameter, match=r"dampers = 'stick': expected removed"):
        sb.span_modes(span_file, dampers="stick")
    with pytest.raises(sb.InvalidParameter, match=r"give either file"):
        sb.span_modes()


def png_size(path):
    with open(path, "rb") as handle:
        header = handle.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG file"
    return struct.unpack(">II", header[16:24])


def test_plot_span_modes_of_the_result_and_of_the_files(span_file, tmp_path):
    out = sb.span_modes(span_file, fmax=4)
    figure = stockbridge.plot.span_modes(out, tmp_path / "result.png", modes=[1, 2, 5])
    assert len(figure.axes) == 4
    assert png_size(tmp_path / "result.png") == (800, 600)
    folder = span_file.parent
    subprocess.run([CLI, "span", str(span_file), "--modes", "--fmax", "4", "--shapes", "shapes.csv", "-o", "modes.csv"],
                   cwd=folder, check=True, capture_output=True)
    plot = [sys.executable, "-m", "stockbridge.plot", "span-modes", "modes.csv"]
    done = subprocess.run(plot + ["--shapes", "shapes.csv", "-o", str(tmp_path / "files.png")], cwd=folder,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert png_size(tmp_path / "files.png") == (800, 600)
    frequencies_only = subprocess.run(plot + ["-o", str(tmp_path / "ratio.png")], cwd=folder, capture_output=True,
                                      text=True)
    assert frequencies_only.returncode == 0, frequencies_only.stderr
    bad = subprocess.run(plot + ["--shapes", "shapes.csv", "--modes", "999", "-o", str(tmp_path / "bad.png")],
                         cwd=folder, capture_output=True, text=True)
    assert bad.returncode == 2
    assert bad.stderr.count("\n") == 1 and "no mode 999" in bad.stderr, bad.stderr
    assert not os.path.exists(tmp_path / "bad.png")
    assert math.isfinite(out["frequency_hz"][0])
