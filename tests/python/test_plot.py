"""python3 -m stockbridge.plot on files the stockbridge program writes: each plot
command writes a non-empty PNG of the expected size; bad files get one line and
exit status 2."""

import os
import struct
import subprocess
import sys

import pytest

CLI = os.environ["STOCKBRIDGE_CLI"]
SOURCE = os.environ["STOCKBRIDGE_SOURCE_DIR"]


def run_cli(*args, cwd):
    subprocess.run([CLI, *args], cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def plot(*args, cwd):
    return subprocess.run([sys.executable, "-m", "stockbridge.plot", *args], cwd=cwd, capture_output=True, text=True)


def png_size(path):
    with open(path, "rb") as handle:
        header = handle.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG file"
    return struct.unpack(">II", header[16:24])


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("plots")
    example = os.path.join(SOURCE, "examples", "sauter2003.toml")
    cable = os.path.join(SOURCE, "examples", "cable_sauter2003.toml")
    run_cli("impedance", example, "--velocity", "0.2,0.05", "--fmin", "5", "--fmax", "50", "--points", "12", "-o", "z.csv", cwd=d)
    run_cli("response", example, "--frequency", "20", "--velocity", "0.2", "-o", "t.csv", cwd=d)
    run_cli("cycle", cable, "--experiment", "a", "--amplitude", "0.03", "-o", "c.csv", cwd=d)
    run_cli("loop", "--ei", "2.8", "--jenkin", "20:0.7", "--amplitude", "0.08", "--cycles", "3", "-o", "mk.csv", cwd=d)
    run_cli("identify", "global", "--experiment", "a", "--length", "0.3", "--input", "c.csv", "--method", "four-step",
            "--fitted", "fitted_global.csv", cwd=d)
    run_cli("identify", "local", "--input", "mk.csv", "--fitted", "fitted_local.csv", cwd=d)
    return d


@pytest.mark.parametrize("command,source", [
    ("impedance", "z.csv"), ("loop", "c.csv"), ("loop", "t.csv"), ("loop", "mk.csv"),
    ("fit", "fitted_global.csv"), ("fit", "fitted_local.csv")])
def test_plot_writes_a_png_of_the_expected_size(files, command, source):
    result = plot(command, source, "-o", "out.png", cwd=files)
    assert result.returncode == 0, result.stderr
    assert os.path.getsize(files / "out.png") > 10000
    assert png_size(files / "out.png") == (800, 600)


def test_impedance_re_im_and_linear_axis(files):
    result = plot("impedance", "z.csv", "--re-im", "--linear", "-o", "reim.png", cwd=files)
    assert result.returncode == 0, result.stderr
    assert png_size(files / "reim.png") == (800, 600)


@pytest.mark.parametrize("command,contents,mention", [
    ("impedance", "frequency_hz,velocity_m_s\n1,0.2\n", "missing column 're_z_n_s_m'"),
    ("fit", "a,b\n1,2\n", "expected the columns written by identify --fitted"),
    ("loop", "", "empty file"),
    ("loop", "curvature_per_m,moment_n_m\n0.1,abc\n", "'abc'")])
def test_bad_files_get_one_line_and_exit_two(tmp_path, command, contents, mention):
    (tmp_path / "bad.csv").write_text(contents)
    result = plot(command, "bad.csv", "-o", "bad.png", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1 and mention in result.stderr, result.stderr
    assert not (tmp_path / "bad.png").exists()


def test_missing_file(tmp_path):
    result = plot("loop", "nowhere.csv", "-o", "x.png", cwd=tmp_path)
    assert result.returncode == 2 and "nowhere.csv" in result.stderr
