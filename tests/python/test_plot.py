"""python3 -m stockbridge.plot on files the stockbridge program writes: each plot
command writes a non-empty PNG of the expected size; bad files get one line and
exit status 2."""

import contextlib
import csv
import io
import json
import math
import os
import pathlib
import re
import shutil
import struct
import subprocess
import sys

import matplotlib.pyplot
import pytest

import stockbridge.plot

CLI = os.environ["STOCKBRIDGE_CLI"]
SOURCE = os.environ["STOCKBRIDGE_SOURCE_DIR"]


def run_cli(*args, cwd):
    subprocess.run([CLI, *args], cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def plot(*args, cwd):
    """`python3 -m stockbridge.plot ARGS` in `cwd`, run in this process: the module's main(),
    which its __main__ calls (test_the_module_runs_as_a_program runs that), with what it
    prints and its exit status. One process for all: matplotlib is imported once."""
    out, err = io.StringIO(), io.StringIO()
    here = os.getcwd()
    os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                status = stockbridge.plot.main([str(a) for a in args])
            except SystemExit as stop:  # argparse's usage errors
                status = stop.code if isinstance(stop.code, int) else 1
    finally:
        os.chdir(here)
        matplotlib.pyplot.close("all")
    return subprocess.CompletedProcess(args, status, out.getvalue(), err.getvalue())


def plot_program(*args, cwd):
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


def test_the_module_runs_as_a_program(files, tmp_path):
    """python3 -m stockbridge.plot itself: a PNG and exit 0; a bad file one line and exit 2."""
    made = plot_program("impedance", "z.csv", "-o", "program.png", cwd=files)
    assert made.returncode == 0 and made.stderr == "", made.stderr
    assert png_size(files / "program.png") == (800, 600)
    (tmp_path / "bad.csv").write_text("frequency_hz,velocity_m_s\n1,0.2\n")
    refused = plot_program("impedance", "bad.csv", "-o", "bad.png", cwd=tmp_path)
    assert refused.returncode == 2 and refused.stderr.count("\n") == 1 and "bad.csv" in refused.stderr, refused.stderr
    assert not (tmp_path / "bad.png").exists()
    usage = plot_program("nonsense", cwd=tmp_path)
    assert usage.returncode == 2 and "invalid choice" in usage.stderr, usage.stderr


def test_impedance_re_im_and_linear_axis(files):
    result = plot("impedance", "z.csv", "--re-im", "--linear", "-o", "reim.png", cwd=files)
    assert result.returncode == 0, result.stderr
    assert png_size(files / "reim.png") == (800, 600)


@pytest.mark.parametrize("command,contents,mention", [
    ("impedance", "frequency_hz,velocity_m_s\n1,0.2\n", "missing column 're_z_n_s_m'"),
    ("impedance", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n", "no data rows"),
    ("impedance", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.2,1\n", "bad.csv:2: 3 cells: expected 4"),
    ("impedance", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.2,,1\n", "'re_z_n_s_m' is empty"),
    ("impedance", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.2,inf,1\n", "expected a finite number"),
    ("impedance", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n0,0.2,1,1\n", "expected a positive frequency"),
    ("impedance", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m,converged\n10,0.2,,,0\n",
     "no converged point to plot"),
    ("loop", "time_s,arm1_x_m,arm1_force_n,arm1_clamp_curvature_per_m,arm1_clamp_section_moment_n_m\n0,,,,\n",
     "no sample to plot"),
    ("loop", "time_s,arm1_x_m\n0,1\n", "missing column 'arm1_force_n'"),
    ("fit", "x_m,force_n,model_force_n\n1,,1\n", "no sample to plot"),
    ("fit", "a,b\n1,2\n", "expected the columns written by identify --fitted"),
    ("loop", "", "empty file"),
    ("loop", "curvature_per_m,moment_n_m\n0.1,abc\n", "'abc'")])
def test_bad_files_get_one_line_and_exit_two(tmp_path, command, contents, mention):
    (tmp_path / "bad.csv").write_text(contents)
    result = plot(command, "bad.csv", "-o", "bad.png", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1 and mention in result.stderr and "bad.csv" in result.stderr, result.stderr
    assert not (tmp_path / "bad.png").exists()


def test_missing_file(tmp_path):
    result = plot("loop", "nowhere.csv", "-o", "x.png", cwd=tmp_path)
    assert result.returncode == 2 and "nowhere.csv" in result.stderr and result.stderr.count("\n") == 1


def test_not_utf8(tmp_path):
    (tmp_path / "bad.csv").write_bytes(b"x_m,force_n\n\xff\xfe,1\n")
    result = plot("loop", "bad.csv", "-o", "x.png", cwd=tmp_path)
    assert result.returncode == 2 and "bad.csv" in result.stderr and result.stderr.count("\n") == 1


# ---------------------------------------------------------------- in-process checks of the figures

def rewrite_csv(source, target, change):
    """A copy of a CSV file with change(header, rows) applied to its rows (lists of cells)."""
    with open(source, newline="") as handle:
        rows = list(csv.reader(handle))
    change(rows[0], rows[1:])
    with open(target, "w", newline="") as handle:
        csv.writer(handle).writerows(rows)


def fail_row(header, row):
    """Make a row look like a point that did not converge: numbers empty, converged = 0."""
    for name in ("re_z_n_s_m", "im_z_n_s_m", "abs_z_n_s_m", "phase_deg", "power_w", "dissipated_power_w",
                 "energy_error", "residual"):
        row[header.index(name)] = ""
    row[header.index("converged")] = "0"


def assert_bad(result, directory, output, *mentions):
    """Exit status 2, exactly one line on stderr naming what was expected, no output file."""
    assert result.returncode == 2, result.stderr
    assert result.stderr.count("\n") == 1 and result.stderr.endswith("\n"), result.stderr
    assert "Traceback" not in result.stderr
    for mention in mentions:
        assert mention in result.stderr, result.stderr
    assert not (directory / output).exists()


@pytest.fixture(scope="module")
def more(files):
    """Impedance files with failed points, a measured file, and response files."""
    example = os.path.join(SOURCE, "examples", "sauter2003.toml")
    subprocess.run([CLI, "impedance", example, "--velocity", "0.2", "--frequencies", "10,20", "--energy-tolerance",
                    "1e-12", "-o", "all_failed.csv"], cwd=files, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    run_cli("impedance", example, "--velocity", "0.2,0.05", "--frequencies", "10,20,30", "-o", "z3.csv", cwd=files)
    subprocess.run([CLI, "response", example, "--frequency", "20", "--velocity", "0.2", "--max-iterations", "2",
                    "-o", "t_last.csv"], cwd=files, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    # measured: frequency, velocity and Z only; every third converged point of z.csv, Re Z a little off
    with open(files / "z.csv", newline="") as handle:
        rows = [row for row in csv.DictReader(handle) if row["converged"] == "1"][::3]
    with open(files / "measured.csv", "w", newline="") as handle:
        handle.write("frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n")
        for row in rows:
            handle.write(f"{row['frequency_hz']},{row['velocity_m_s']},{1.1 * float(row['re_z_n_s_m'])},"
                         f"{row['im_z_n_s_m']}\n")
    rewrite_csv(files / "t.csv", files / "t_named.csv", lambda header, rows: header.__setitem__(
        slice(None), [n.replace("arm1_", "left_").replace("arm2_", "right_") for n in header]))
    return files


def test_all_points_failed_is_bad_input(more):
    with open(more / "all_failed.csv") as handle:
        assert [row["converged"] for row in csv.DictReader(handle)] == ["0", "0"]  # the premise
    result = plot("impedance", "all_failed.csv", "-o", "all_failed.png", cwd=more)
    assert_bad(result, more, "all_failed.png", "all_failed.csv", "no converged point to plot")
    for extra in (["--power"], ["--re-im"], ["--linear"]):  # in this process: quicker
        assert stockbridge.plot.main(["impedance", str(more / "all_failed.csv"), *extra,
                                   "-o", str(more / "all_failed.png")]) == 2
        assert not (more / "all_failed.png").exists()
    # a file of one point that failed (the case a reviewer saw end in "Data has no positive values")
    rewrite_csv(more / "z3.csv", more / "one_failed.csv", lambda header, rows: [fail_row(header, rows[0])])
    with open(more / "one_failed.csv") as handle:
        lines = handle.readlines()[:2]
    (more / "one_failed.csv").write_text("".join(lines))
    result = plot("impedance", "one_failed.csv", "-o", "all_failed.png", cwd=more)
    assert_bad(result, more, "all_failed.png", "one_failed.csv", "no converged point to plot")
    # and among other files
    result = plot("impedance", "z.csv", "all_failed.csv", "-o", "all_failed.png", cwd=more)
    assert_bad(result, more, "all_failed.png", "all_failed.csv", "no converged point to plot")


@pytest.mark.parametrize("failed", [[1], [0], [2], [3, 4, 5], [0, 1, 2, 3, 4]])
def test_some_failed_points_plot_the_converged_ones(more, failed):
    """z3.csv has rows (0.2 m/s: 10, 20, 30 Hz), (0.05 m/s: 10, 20, 30 Hz): a failed point in
    the middle, first, last, a whole run failed, or a single converged point left."""
    name = f"failed_{'_'.join(map(str, failed))}.csv"
    rewrite_csv(more / "z3.csv", more / name,
                lambda header, rows: [fail_row(header, rows[i]) for i in failed])
    result = plot("impedance", name, "--power", "-o", "some_failed.png", cwd=more)
    assert result.returncode == 0, result.stderr
    assert png_size(more / "some_failed.png") == (800, 600)
    for extra in ([], ["--re-im", "--linear"]):  # in this process: quicker
        assert stockbridge.plot.main(["impedance", str(more / name), *extra, "-o", str(more / "some_failed.png")]) == 0
    figure = stockbridge.plot.impedance_figure([stockbridge.plot.Sweep(str(more / name))])
    top, bottom = figure.axes
    assert sum(len(line.get_xdata()) for line in top.get_lines()) == 6 - len(failed)
    crosses = [line for line in bottom.get_lines() if line.get_marker() == "x"]
    assert sum(len(line.get_xdata()) for line in crosses) == len(failed)


@pytest.mark.parametrize("output,mention", [
    ("nodir/x.png", "nodir/x.png: cannot write"), (".", "cannot write"), ("x.xyz", "x.xyz: unknown image format")])
def test_unwritable_output_gets_one_line(files, output, mention):
    for command, source in (("impedance", "z.csv"), ("loop", "t.csv"), ("fit", "fitted_local.csv")):
        result = plot(command, source, "-o", output, cwd=files)
        assert result.returncode == 2 and result.stderr.count("\n") == 1 and mention in result.stderr, result.stderr
    assert not (files / "nodir").exists() and not (files / "x.xyz").exists()


def test_a_failing_plot_leaves_an_existing_output_alone(files):
    (files / "keep.png").write_bytes(b"old")
    result = plot("impedance", "nowhere.csv", "-o", "keep.png", cwd=files)
    assert result.returncode == 2 and (files / "keep.png").read_bytes() == b"old"


def test_usage_errors_get_one_line(files):
    for args in (["impedance"], ["nothing"], ["impedance", "z.csv", "z.csv", "--label", "a", "-o", "u.png"]):
        result = plot(*args, cwd=files)
        assert_bad(result, files, "u.png")


def test_measured_file_with_z_only(more):
    result = plot("impedance", "measured.csv", "--power", "-o", "measured.png", cwd=more)
    assert result.returncode == 0, result.stderr
    assert png_size(more / "measured.png") == (800, 600)
    sweep = stockbridge.plot.Sweep(str(more / "measured.csv"))
    assert all(sweep.converged) and len(sweep.re) > 3


def test_every_measured_form_identify_impedance_reads(more):
    """|Z| and phase, displacement instead of velocity: the same curves as Re, Im and velocity."""
    with open(more / "z.csv", newline="") as handle:
        rows = [row for row in csv.DictReader(handle) if row["converged"] == "1"]
    with open(more / "sheet.csv", "w", newline="") as handle:
        handle.write("frequency_hz,displacement_m,abs_z_n_s_m,phase_deg\n")
        for row in rows:
            handle.write(f"{row['frequency_hz']},{row['displacement_m']},{row['abs_z_n_s_m']},{row['phase_deg']}\n")
    result = plot("impedance", "sheet.csv", "--power", "-o", "sheet.png", cwd=more)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""  # typical values: no warning
    assert png_size(more / "sheet.png") == (800, 600)
    sheet = stockbridge.plot.Sweep(str(more / "sheet.csv"))
    assert [label for label, _ in sheet.runs] == ["V = 0.2 m/s", "V = 0.05 m/s"]
    for i, row in enumerate(rows):
        assert sheet.re[i] == pytest.approx(float(row["re_z_n_s_m"]), rel=1e-9, abs=1e-9)
        assert sheet.im[i] == pytest.approx(float(row["im_z_n_s_m"]), rel=1e-9)
        assert sheet.velocity[i] == pytest.approx(float(row["velocity_m_s"]), rel=1e-12)


def test_a_measured_sheet_in_wrong_units_is_drawn_with_the_librarys_warnings(more):
    """Velocities in mm/s and phases in radians: one warning line each, as identify impedance prints them."""
    with open(more / "z.csv", newline="") as handle:
        rows = [row for row in csv.DictReader(handle) if row["converged"] == "1"]
    with open(more / "slipped.csv", "w", newline="") as handle:
        handle.write("frequency_hz,velocity_m_s,abs_z_n_s_m,phase_deg\n")
        for row in rows:
            handle.write(f"{row['frequency_hz']},{1000 * float(row['velocity_m_s']):g},{row['abs_z_n_s_m']},"
                         f"{math.radians(float(row['phase_deg']))}\n")
    result = plot("impedance", "slipped.csv", "-o", "slipped.png", cwd=more)
    assert result.returncode == 0, result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 2, result.stderr
    assert lines[0].startswith("warning: slipped.csv:2: column 'velocity_m_s' = 200: outside the typical 0.001 to 2 m/s "
                               "of the clamp velocity amplitude (in mm/s? 200 mm/s = 0.2 m/s)"), lines[0]
    assert "phase_deg looks like radians" in lines[1], lines[1]
    program = subprocess.run([CLI, "identify", "impedance", "--damper", os.path.join(SOURCE, "examples", "sauter2003.toml"),
                              "--input", "slipped.csv", "--rms-limit", "100", "--allow-unusual"], cwd=more,
                             capture_output=True, text=True)
    assert [line for line in program.stderr.splitlines() if line.startswith("warning: slipped.csv")] == lines


def test_abs_phase_and_power_agree_with_the_program(files):
    """|Z|, phase and Re Z V^2 / 2 computed from Re and Im Z against the program's own columns."""
    sweep = stockbridge.plot.Sweep(str(files / "z.csv"))
    with open(files / "z.csv") as handle:
        rows = list(csv.DictReader(handle))
    checked = 0
    for i, row in enumerate(rows):
        if row["converged"] == "1":
            assert sweep.abs_z(i) == pytest.approx(float(row["abs_z_n_s_m"]), rel=1e-12)
            assert sweep.phase_deg(i) == pytest.approx(float(row["phase_deg"]), abs=1e-9)
            assert sweep.power_w(i) == pytest.approx(float(row["power_w"]), rel=1e-12)
            checked += 1
    assert checked > 10


def test_overlay_of_several_files(more):
    result = plot("impedance", "z.csv", "measured.csv", "--label", "computed", "--label", "measured", "--power",
                  "-o", "overlay.png", cwd=more)
    assert result.returncode == 0, result.stderr
    assert png_size(more / "overlay.png") == (800, 600)
    module = stockbridge.plot
    sweeps = [module.Sweep(str(more / "z.csv"), "computed"), module.Sweep(str(more / "measured.csv"), "measured")]
    figure = module.impedance_figure(sweeps, power=True)
    assert len(figure.axes) == 3
    for axis in figure.axes:
        curves = [line for line in axis.get_lines() if line.get_marker() != "x"]
        assert len(curves) == 4  # two files, two amplitudes each
    legend = [text.get_text() for text in figure.axes[0].get_legend().get_texts()]
    assert legend == ["computed: V = 0.2 m/s", "computed: V = 0.05 m/s", "measured: V = 0.2 m/s",
                      "measured: V = 0.05 m/s"]
    default = module.impedance_figure([module.Sweep(str(more / "z.csv")), module.Sweep(str(more / "measured.csv"))])
    assert [t.get_text() for t in default.axes[0].get_legend().get_texts()][::2] == [
        "z.csv: V = 0.2 m/s", "measured.csv: V = 0.2 m/s"]


def test_closed_appends_the_first_sample():
    assert stockbridge.plot.closed([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]) == ([1.0, 2.0, 3.0, 1.0], [4.0, 5.0, 6.0, 4.0])


def line_points(figure):
    return [list(zip(axis.get_lines()[0].get_xdata(), axis.get_lines()[0].get_ydata()))
            for axis in figure.axes if axis.get_visible()]


@pytest.mark.parametrize("source,panels", [("t.csv", 4), ("t_named.csv", 4)])
def test_response_loops_are_closed(more, source, panels):
    rows = len((more / source).read_text().splitlines()) - 1
    loops = line_points(stockbridge.plot.loop_figure(str(more / source)))
    assert len(loops) == panels
    for points in loops:
        assert len(points) == rows + 1 and points[0] == points[-1]
        assert points[0] != points[-2]  # the file's own last sample is not its first


def test_response_arms_found_by_suffix(more):
    titles = [axis.get_title() for axis in stockbridge.plot.loop_figure(str(more / "t_named.csv")).axes]
    assert titles == ["left: force over deflection", "left: clamp section", "right: force over deflection",
                      "right: clamp section"]


@pytest.mark.parametrize("source", ["c.csv", "mk.csv"])
def test_cycle_and_loop_files_are_not_closed(files, source):
    rows = len((files / source).read_text().splitlines()) - 1
    for points in line_points(stockbridge.plot.loop_figure(str(files / source))):
        assert len(points) == rows and points[0] != points[-1]


def test_unconverged_response_plots_and_says_so(more):
    assert (more / "t_last.csv").exists()
    result = plot("loop", "t_last.csv", "-o", "t_last.png", cwd=more)
    assert result.returncode == 0, result.stderr
    figure = stockbridge.plot.loop_figure(str(more / "t_last.csv"))
    assert "not converged" in figure._suptitle.get_text()


@pytest.mark.parametrize("source", ["t.csv", "c.csv"])
def test_tick_labels_do_not_run_into_each_other(files, source):
    """At least 20 pixels between neighbouring x tick labels (the four panels in one row
    left 6 pixels between -0.0025 and 0.0000)."""
    figure = stockbridge.plot.loop_figure(str(files / source))
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    for axis in figure.axes:
        low, high = sorted(axis.get_xlim())
        boxes = sorted((label.get_window_extent(renderer) for tick, label in zip(axis.get_xticks(),
                        axis.get_xticklabels()) if low <= tick <= high and label.get_text()), key=lambda b: b.x0)
        assert len(boxes) >= 3
        for left, right in zip(boxes, boxes[1:]):
            assert right.x0 - left.x1 >= 20, (axis.get_title(), [label.get_text() for label in axis.get_xticklabels()])


# ---------------------------------------------------------------- span

@pytest.fixture(scope="module")
def span_files(tmp_path_factory):
    d = tmp_path_factory.mktemp("span")
    run_cli("span", os.path.join(SOURCE, "examples", "aster570_400m.toml"), "--points", "15", "-o", "span.csv", cwd=d)
    return d


def test_span_plot_writes_a_png(span_files):
    result = plot("span", "span.csv", "-o", "span.png", cwd=span_files)
    assert result.returncode == 0, result.stderr
    assert os.path.getsize(span_files / "span.png") > 10000
    assert png_size(span_files / "span.png") == (800, 839)  # three panels: amplitude, stress, strain


def test_span_plot_draws_damped_undamped_and_the_endurance_limit(span_files):
    module = stockbridge.plot
    with open(span_files / "span.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    figure = module.span_figure(str(span_files / "span.csv"))
    amplitude, stress, strain = figure.axes
    labels = [line.get_label() for line in stress.get_lines()]
    assert labels[:2] == ["undamped", "with dampers"]
    limit = float(rows[0]["endurance_limit_mpa"])
    assert labels[2] == f"endurance limit {limit:.3g} MPa"
    assert list(stress.get_lines()[2].get_ydata()) == [limit, limit]
    assert list(stress.get_lines()[1].get_ydata()) == pytest.approx([float(r["stress_fymax_mpa"]) for r in rows])
    assert list(amplitude.get_lines()[0].get_ydata()) == pytest.approx([1e3 * float(r["undamped_amplitude_m"]) for r in rows])
    assert stress.get_xscale() == "log"
    # The strain panel: 2 sigma_ps / E_a in microstrain, and the limit in microstrain.
    assert list(strain.get_lines()[1].get_ydata()) == pytest.approx(
        [float(r["bending_strain_pp_microstrain"]) for r in rows])
    limit_strain = float(rows[0]["endurance_limit_pp_microstrain"])
    assert list(strain.get_lines()[2].get_ydata()) == [limit_strain, limit_strain]
    assert limit_strain == pytest.approx(2 * limit * 1e6 / 68e9 * 1e6)
    module.plt.close(figure)


def test_span_plot_marks_points_that_did_not_converge(span_files, tmp_path):
    def fail_second(header, rows):
        for name in ("amplitude_m", "stress_fymax_mpa", "undamped_amplitude_m", "undamped_stress_fymax_mpa"):
            rows[1][header.index(name)] = ""
        rows[1][header.index("converged")] = "0"
    rewrite_csv(span_files / "span.csv", tmp_path / "failed.csv", fail_second)
    module = stockbridge.plot
    figure = module.span_figure(str(tmp_path / "failed.csv"))
    assert "not converged" in [line.get_label() for line in figure.axes[1].get_lines()]
    assert len(figure.axes[1].get_lines()[1].get_xdata()) == 14
    module.plt.close(figure)


SPAN_HEADER = "frequency_hz,amplitude_m,undamped_amplitude_m,stress_fymax_mpa,undamped_stress_fymax_mpa,converged,endurance_limit_mpa\n"


@pytest.mark.parametrize("contents,mention", [
    ("frequency_hz,amplitude_m,converged\n10,0.01,1\n", "missing column"),
    (SPAN_HEADER + "10,,,,,0,8.7\n", "no converged point to plot"),
    (SPAN_HEADER + "10,0.01,0.02,5,9,1,8.7\n20,0.01,0.02,5,9,1,9.7\n", "endurance_limit_mpa differs"),
    (SPAN_HEADER + "10,0.01,0.02,5,9,1,\n", "'endurance_limit_mpa' is empty"),
    (SPAN_HEADER + "0,0.01,0.02,5,9,1,8.7\n", "expected a positive frequency"),
    (SPAN_HEADER + "10,0.01,0.02,abc,9,1,8.7\n", "'abc'")])
def test_span_bad_files_get_one_line_and_exit_two(tmp_path, contents, mention):
    (tmp_path / "bad.csv").write_text(contents)
    result = plot("span", "bad.csv", "-o", "bad.png", cwd=tmp_path)
    assert_bad(result, tmp_path, "bad.png", mention, "bad.csv")


def test_log_axes_label_values_below_one(span_files):
    """The damped amplitude falls below 1 mm: its log axis labels 0.1 as 0.1, never as 0."""
    module = stockbridge.plot
    figure = module.span_figure(str(span_files / "span.csv"))
    figure.canvas.draw()
    amplitude = figure.axes[0]
    low, high = sorted(amplitude.get_ylim())
    labels = [label.get_text() for tick, label in zip(amplitude.get_yticks(), amplitude.get_yticklabels())
              if low <= tick <= high and label.get_text()]
    assert amplitude.get_yscale() == "log" and labels
    assert all(float(text) > 0 for text in labels), labels
    module.plt.close(figure)


# ---------------------------------------------------------------- design

@pytest.fixture(scope="module")
def design_files(tmp_path_factory):
    """The design CSV of examples/design_aster570.toml cut to seconds (8 frequencies per
    band, 3 samples, one polish of at most 4 evaluations)."""
    d = tmp_path_factory.mktemp("design")
    for name in ("sauter2003.toml", "aster570_400m.toml"):
        shutil.copy(os.path.join(SOURCE, "examples", name), d / name)
    with open(os.path.join(SOURCE, "examples", "design_aster570.toml"), encoding="utf-8") as handle:
        text = handle.read()
    for key, value in (("samples", 3), ("polish", 1), ("polish_evaluations", 4)):
        text = re.sub(rf"^{key} = \S+", f"{key} = {value}", text, flags=re.M)
    (d / "design.toml").write_text("points = 8\n" + text)
    run_cli("design", "design.toml", "--quiet", "-o", "designs.csv", "--best", "best.toml", cwd=d)
    return d


def test_design_plot_writes_a_png(design_files):
    result = plot("design", "designs.csv", "-o", "design.png", cwd=design_files)
    assert result.returncode == 0, result.stderr
    assert os.path.getsize(design_files / "design.png") > 10000
    assert png_size(design_files / "design.png") == (800, 600)


def marker_points(axis, label):
    """The (x, y) of the markers the axis draws under a legend label."""
    return [point for line in axis.get_lines() if line.get_label() == label
            for point in zip(line.get_xdata(), line.get_ydata())]


def test_design_plot_draws_each_variable_and_marks_the_best(design_files):
    module = stockbridge.plot
    with open(design_files / "designs.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    variables = ["arm.left.mass", "arm.left.cable.length", "position"]
    figure = module.design_figure(str(design_files / "designs.csv"))
    panels = [axis for axis in figure.axes if axis.get_visible() and axis.axison]
    assert [axis.get_xlabel() for axis in panels] == ["arm.left.mass (kg)", "arm.left.cable.length (m)", "position (m)"]
    assert panels[0].get_ylabel() == "largest stress / endurance limit (-)"
    feasible = [r for r in rows if r["feasible"] == "1"]
    best = min(feasible, key=lambda r: float(r["objective"]))
    label = f"best ({best['stage']} {best['run']})" if best["stage"] != "base" else "best (base)"
    for axis, name in zip(panels, variables):
        assert marker_points(axis, label) == [(float(best[name]), float(best["objective"]))]
        drawn = sorted(p for line in axis.get_lines() if line.get_label().split(" ")[0] not in ("best", "not")
                       for p in zip(line.get_xdata(), line.get_ydata()))
        assert drawn == sorted((float(r[name]), float(r["objective"])) for r in rows if r["converged"] == "1")
        for line in axis.get_lines():  # feasible filled, infeasible hollow
            if "infeasible" in line.get_label():
                assert line.get_markerfacecolor() == "none"
            elif "feasible" in line.get_label():
                assert line.get_markerfacecolor() != "none"
    labels = [line.get_label() for line in panels[0].get_lines()]
    assert any(label.startswith("polishes") for label in labels)  # the polish stage has its own markers
    legend = [text.get_text() for axis in figure.axes for text in (axis.get_legend().get_texts() if axis.get_legend() else [])]
    assert label in legend and ("base, feasible" in legend or "base, infeasible" in legend)
    module.plt.close(figure)


DESIGN_HEADER = ("stage,run,position,objective,max_stress_ratio,max_stress_mpa,frequency_at_max_hz,total_mass_kg,"
                 "messenger_curvature_max_per_m,shortest_life_years,converged,feasible\n")


def test_design_plot_of_a_life_study_draws_infinite_lives_at_the_top(tmp_path):
    (tmp_path / "life.csv").write_text(DESIGN_HEADER + "base,0,1.5,40,0.9,8,12,2.4,0.2,40,1,1\n"
                                       "sample,0,0.7,inf,0.4,3,20,2.4,0.1,inf,1,1\n"
                                       "sample,1,2.2,3000,0.7,6,15,2.4,0.3,3000,1,1\n"
                                       "sample,2,2.5,,,,,2.4,,,0,0\n")
    result = plot("design", "life.csv", "-o", "life.png", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    module = stockbridge.plot
    figure = module.design_figure(str(tmp_path / "life.csv"))
    axis = figure.axes[0]
    assert axis.get_ylabel() == "shortest life (years)" and axis.get_yscale() == "log"
    assert marker_points(axis, "best (sample 0)") == [(0.7, 0.97)]  # the infinite life, at the top (axes units)
    assert marker_points(axis, "not converged") == [(2.5, 0.03)]
    assert "infinite lives at the top" in figure._suptitle.get_text()
    module.plt.close(figure)


@pytest.mark.parametrize("contents,mention", [
    ("stage,run,objective,converged,feasible\nbase,0,1,1,1\n", "missing column"),
    (DESIGN_HEADER, "no data rows"),
    (DESIGN_HEADER + "base,0,1.5,,,,,2.4,,,0,0\n", "no converged candidate to plot"),
    (DESIGN_HEADER + "start,0,1.5,0.9,0.9,8,12,2.4,0.2,,1,1\n", "stage = 'start'"),
    (DESIGN_HEADER + "base,0,1.5,0.9,0.9,8,12,2.4,0.2,,1,2\n", "feasible = 2"),
    (DESIGN_HEADER + "base,0,1.5,0.9,0.9,8,12,2.4,0.2,,0,1\n", "feasible = 1 but converged = 0"),
    (DESIGN_HEADER + "base,0,,0.9,0.9,8,12,2.4,0.2,,1,1\n", "'position' is empty"),
    (DESIGN_HEADER + "base,0,1.5,0.5,0.9,8,12,2.4,0.2,,1,1\n", "neither max_stress_ratio nor shortest_life_years"),
    (DESIGN_HEADER + "base,0,1.5,abc,0.9,8,12,2.4,0.2,,1,1\n", "'abc'"),
    (DESIGN_HEADER.replace("run,position,", "run,") + "base,0,0.9,0.9,8,12,2.4,0.2,,1,1\n", "the variables")])
def test_design_bad_files_get_one_line_and_exit_two(tmp_path, contents, mention):
    (tmp_path / "bad.csv").write_text(contents)
    result = plot("design", "bad.csv", "-o", "bad.png", cwd=tmp_path)
    assert_bad(result, tmp_path, "bad.png", mention, "bad.csv")


def test_impedance_fit_plot_overlays_measured_and_fitted_curves(tmp_path):
    damper = os.path.join(SOURCE, "examples", "sauter2003.toml")
    run_cli("impedance", damper, "--velocity", "0.05,0.2", "--fmin", "5", "--fmax", "60", "--points", "6",
            "-o", "measured.csv", cwd=tmp_path)
    run_cli("identify", "impedance", "--damper", damper, "--input", "measured.csv", "--fitted", "z_fit.csv", cwd=tmp_path)
    result = plot("fit", "z_fit.csv", "-o", "fit.png", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert png_size(tmp_path / "fit.png") == (800, 600)
    module = stockbridge.plot
    figure = module.impedance_fit_figure(module.Table(str(tmp_path / "z_fit.csv")))
    labels = [line.get_label() for line in figure.axes[0].get_lines()]
    assert labels == ["measured, V = 0.05 m/s", "fitted model, V = 0.05 m/s", "measured, V = 0.2 m/s",
                      "fitted model, V = 0.2 m/s"]
    measured, model = figure.axes[0].get_lines()[:2]
    assert len(measured.get_xdata()) == len(model.get_xdata()) == 6
    for a, b in zip(measured.get_ydata(), model.get_ydata()):  # the fit reproduces its own curve
        assert abs(a / b - 1) < 1e-4


# ---------------------------------------------------------------- line

SCHEDULE_HEADER = ("id,length_m,dampers_per_end,max_stress_mpa,undamped_max_stress_mpa,endurance_limit_mpa,stress_ratio,"
                   "margin_percent,verdict,converged\n")
# Five spans as stockbridge line writes them: one unsafe (T3-T4), one whose balance
# did not converge (T4-T5: its stresses empty, verdict unknown), one without dampers.
SCHEDULE = SCHEDULE_HEADER + ("T1-T2,300,2,6.65,39.2,8.73,0.762,23.8,safe,1\n"
                              "T2-T3,420,1,7.9,40.9,8.73,0.905,9.5,safe,1\n"
                              "T3-T4,250,3,9.4,48.7,8.73,1.077,-7.7,unsafe,1\n"
                              "T4-T5,380,2,,,8.73,,,unknown,0\n"
                              "T5-T6,310,0,1.96,1.96,8.73,0.225,77.5,safe,1\n")


def test_line_plot_writes_a_png(tmp_path):
    (tmp_path / "schedule.csv").write_text(SCHEDULE)
    result = plot("line", "schedule.csv", "-o", "schedule.png", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert os.path.getsize(tmp_path / "schedule.png") > 10000
    assert png_size(tmp_path / "schedule.png") == (800, 600)


def test_line_plot_draws_the_stresses_the_limit_and_the_dampers_per_span(tmp_path):
    from matplotlib.colors import to_rgba
    (tmp_path / "schedule.csv").write_text(SCHEDULE)
    module = stockbridge.plot
    figure = module.line_figure(str(tmp_path / "schedule.csv"))
    stress, dampers = figure.axes
    assert stress.get_ylabel() == "largest fymax stress (MPa)" and stress.get_yscale() == "log"
    assert dampers.get_ylabel() == "dampers per end" and "span" in dampers.get_xlabel()
    lines = {line.get_label(): line for line in stress.get_lines()}
    assert list(lines) == ["without dampers", "with the dampers", "endurance limit"]
    nan = float("nan")
    assert list(lines["with the dampers"].get_xdata()) == [0, 1, 2, 3, 4]
    assert list(lines["with the dampers"].get_ydata()) == pytest.approx([6.65, 7.9, 9.4, nan, 1.96], nan_ok=True)
    assert list(lines["without dampers"].get_ydata()) == pytest.approx([39.2, 40.9, 48.7, nan, 1.96], nan_ok=True)
    assert set(lines["endurance limit"].get_ydata()) == {8.73}
    assert list(lines["endurance limit"].get_xdata())[::9] == [-0.5, 4.5]  # across every span's width
    bars = dampers.containers[0]  # the bars (the shading is among the patches too)
    assert [bar.get_height() for bar in bars] == [2, 1, 3, 2, 0]
    colours = {"safe": "C2", "unsafe": "C3", "unknown": "0.6"}
    for bar, verdict in zip(bars, ["safe", "safe", "unsafe", "unknown", "safe"]):
        assert bar.get_facecolor() == to_rgba(colours[verdict]), verdict
    assert [label.get_text() for label in dampers.get_xticklabels()] == ["T1-T2", "T2-T3", "T3-T4", "T4-T5", "T5-T6"]
    shaded = sorted((round((p.get_xy()[:, 0].min() + p.get_xy()[:, 0].max()) / 2, 9), p.get_facecolor()[:3])
                    for p in stress.patches)  # (middle, colour) of each span's shading
    assert shaded == [(2.0, to_rgba("C3")[:3]), (3.0, to_rgba("0.6")[:3])]  # the unsafe and the unknown span
    legend = [text.get_text() for text in stress.get_legend().get_texts()]
    assert legend[-2:] == ["unsafe span", "unknown span"]
    assert stress.get_title().split("\n") == [f"{tmp_path / 'schedule.csv'}: unsafe: 5 spans, 3 safe, 1 unsafe, 1 unknown",
                                              "unsafe: T3-T4; unknown: T4-T5"]
    assert notes(figure) == []  # no lives: no note on them
    module.plt.close(figure)


def test_line_plot_of_a_long_line_labels_some_spans(tmp_path):
    rows = "".join(f"T{k}-T{k + 1},300,2,7,40,8.73,0.8,20,safe,1\n" for k in range(1, 61))
    (tmp_path / "long.csv").write_text(SCHEDULE_HEADER + rows)
    module = stockbridge.plot
    figure = module.line_figure(str(tmp_path / "long.csv"))
    axis = figure.axes[1]
    labels = [label.get_text() for label in axis.get_xticklabels()]
    assert labels == [f"T{k}-T{k + 1}" for k in range(1, 61, 3)]  # every third of 60: at most 24
    assert set(axis.get_xticks()) | set(axis.get_xticks(minor=True)) == set(range(60))  # every span a tick
    module.plt.close(figure)


@pytest.mark.parametrize("contents,mention", [
    ("id,verdict,dampers_per_end\nT1,safe,2\n", "missing column 'max_stress_mpa'"),
    (SCHEDULE_HEADER, "no data rows"),
    (SCHEDULE_HEADER + "T1,300,2,7,40,8.73,0.8,20,fine,1\n", "verdict = 'fine'"),
    (SCHEDULE_HEADER + "T1,300,1.5,7,40,8.73,0.8,20,safe,1\n", "dampers_per_end = 1.5"),
    (SCHEDULE_HEADER + "T1,300,,7,40,8.73,0.8,20,safe,1\n", "'dampers_per_end' is empty"),
    (SCHEDULE_HEADER + "T1,300,2,0,40,8.73,0.8,20,safe,1\n", "max_stress_mpa = 0"),
    (SCHEDULE_HEADER + "T1,300,2,,,8.73,,,unknown,0\n", "no stress to plot"),
    (SCHEDULE_HEADER + "T1,300,2,abc,40,8.73,0.8,20,safe,1\n", "'abc'")])
def test_line_bad_files_get_one_line_and_exit_two(tmp_path, contents, mention):
    (tmp_path / "bad.csv").write_text(contents)
    result = plot("line", "bad.csv", "-o", "bad.png", cwd=tmp_path)
    assert_bad(result, tmp_path, "bad.png", mention, "bad.csv")


# ---------------------------------------------------------------- verdicts in the titles, overlays, units, wind speed

def unwrapped(title):
    """A title with its wrapped lines (continued with an indent) joined again."""
    return title.replace("\n    ", " ")


def load_json(path):
    with open(path) as handle:
        return json.load(handle)


def notes(figure):
    """The figure's texts other than its title: the note on lives."""
    return [text.get_text() for text in figure.texts if text is not figure._suptitle]


def span_rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def largest_stress(rows):
    peak = max((r for r in rows if r["converged"] == "1"), key=lambda r: float(r["stress_fymax_mpa"]))
    return float(peak["stress_fymax_mpa"]), float(peak["frequency_hz"])


@pytest.fixture(scope="module")
def runs(span_files):
    """span.csv (one damper at 1 m) with its summary, the span without dampers, the
    damper at the position the search finds, and Drake (another conductor, no climate)."""
    d = span_files
    aster = os.path.join(SOURCE, "examples", "aster570_400m.toml")
    for name, extra in (("damped", []), ("bare", ["--no-dampers"]), ("best", ["--optimize-position", "0.5:3"])):
        with open(d / f"{name}.json", "w") as out:
            subprocess.run([CLI, "span", aster, "--points", "15", "--quiet", "-o", f"{name}.csv", "--json", *extra],
                           cwd=d, check=True, stdout=out)
    with open(d / "drake.json", "w") as out:
        subprocess.run([CLI, "span", os.path.join(SOURCE, "examples", "drake_300m.toml"), "--points", "15", "--quiet",
                        "-o", "drake.csv", "--json"], cwd=d, check=True, stdout=out)
    return d


def test_span_title_carries_the_verdict_and_the_largest_stress(runs, tmp_path):
    module = stockbridge.plot
    rows = span_rows(runs / "damped.csv")
    stress, frequency = largest_stress(rows)
    limit = float(rows[0]["endurance_limit_mpa"])
    assert stress > limit  # the premise: one damper at 1 m is not enough on ASTER570
    figure = module.span_figure(str(runs / "damped.csv"))
    assert unwrapped(figure.axes[0].get_title()) == (f"{runs / 'damped.csv'}: unsafe, max {stress:.3g} MPa at {frequency:.3g} Hz "
                                          f"(limit {limit:.3g} MPa)")
    module.plt.close(figure)

    def scale(header, rows, fail=()):  # every stress a tenth: within the limit
        for k, row in enumerate(rows):
            row[header.index("stress_fymax_mpa")] = str(float(row[header.index("stress_fymax_mpa")]) / 10)
            if k in fail:
                row[header.index("converged")] = "0"
                for name in ("amplitude_m", "stress_fymax_mpa", "undamped_amplitude_m", "undamped_stress_fymax_mpa"):
                    row[header.index(name)] = ""
    rewrite_csv(runs / "damped.csv", tmp_path / "safe.csv", scale)
    rewrite_csv(runs / "damped.csv", tmp_path / "gaps.csv", lambda header, rows: scale(header, rows, fail=(3, 7)))
    rewrite_csv(runs / "damped.csv", tmp_path / "lower.csv", lambda header, rows: [
        fail_span_row(header, rows[k]) for k in (9,)])
    expected = {"safe.csv": "safe, max {:.3g} MPa", "gaps.csv": "unknown (2 points missing), max {:.3g} MPa",
                "lower.csv": "unsafe, max {:.3g} MPa"}
    for name, start in expected.items():
        rows = span_rows(tmp_path / name)
        figure = module.span_figure(str(tmp_path / name), labels=["x"])
        title = unwrapped(figure.axes[0].get_title())
        assert title.startswith("x: " + start.format(largest_stress(rows)[0])), title
        assert title.endswith("1 point missing") == (name == "lower.csv"), title
        module.plt.close(figure)


def fail_span_row(header, row):
    row[header.index("converged")] = "0"
    for name in ("amplitude_m", "stress_fymax_mpa", "undamped_amplitude_m", "undamped_stress_fymax_mpa"):
        row[header.index(name)] = ""


def test_span_summary_adds_the_positions_and_the_life(runs, tmp_path):
    module = stockbridge.plot
    summary = load_json(runs / "damped.json")
    assert summary["positions_m"] == [1] and summary["life_years"] > 0  # the premise: the span file has a climate
    figure = module.span_figure(str(runs / "damped.csv"), summaries=[str(runs / "damped.json")])
    lines = unwrapped(figure.axes[0].get_title()).split("\n")
    assert len(lines) == 2 and lines[0].startswith(f"{runs / 'damped.csv'}: unsafe (safe-border-line criterion), max ")
    assert lines[1] == (f"damper at 1 m, life {module.years(summary['life_years'])} years "
                        f"({module.years(summary['undamped_life_years'])} without dampers)")
    assert notes(figure) == [module.LIVES_NOTE]
    assert "comparative" in module.LIVES_NOTE
    module.plt.close(figure)
    assert module.years(2.0748) == "2.1" and module.years(1.02) == "1.0" and module.years(29.42) == "29"
    # No life: the span file has no climate (Drake), or the life is not known
    figure = module.span_figure(str(runs / "drake.csv"), summaries=[str(runs / "drake.json")])
    assert unwrapped(figure.axes[0].get_title()).split("\n")[1] == "damper at 1 m" and notes(figure) == []
    module.plt.close(figure)
    for change, text in (({"life_years": None, "damage_per_year": 0}, "no fatigue damage"),
                         ({"life_years": None, "damage_per_year": None, "life_missing_points": 2},
                          "life unknown (2 points missing)"),
                         ({"positions_m": [1.2, 2.45], "position_optimized": True}, "dampers at 1.2, 2.45 m (optimized)")):
        (tmp_path / "changed.json").write_text(json.dumps(dict(summary, **change)))
        figure = module.span_figure(str(runs / "damped.csv"), summaries=[str(tmp_path / "changed.json")])
        assert text in unwrapped(figure.axes[0].get_title()), figure.axes[0].get_title()
        module.plt.close(figure)


def test_span_plot_overlays_several_files(runs):
    result = plot("span", "damped.csv", "best.csv", "bare.csv", "--summary", "damped.json", "--summary", "best.json",
                  "--summary", "bare.json", "-o", "overlay.png", cwd=runs)
    assert result.returncode == 0 and result.stderr == "", result.stderr
    assert png_size(runs / "overlay.png") == (800, 839)
    module = stockbridge.plot
    figure = module.span_figure([str(runs / name) for name in ("damped.csv", "best.csv", "bare.csv")],
                                labels=["1 m", "best", "none"])
    amplitude, stress, strain = figure.axes
    for axis in figure.axes:  # the undamped curve once: the three runs share it
        assert [line.get_label() for line in axis.get_lines()][:4] == ["undamped", "1 m", "best", "none"]
    assert [text.get_text() for text in amplitude.get_legend().get_texts()] == ["undamped", "1 m", "best", "none"]
    limit = float(span_rows(runs / "damped.csv")[0]["endurance_limit_mpa"])
    assert [text.get_text() for text in stress.get_legend().get_texts()] == [f"endurance limit {limit:.3g} MPa"]
    assert len([line for line in stress.get_lines() if line.get_label().startswith("endurance limit")]) == 1
    title = amplitude.get_title().split("\n")
    assert [line.split(":")[0] for line in title] == ["1 m", "best", "none"]
    assert "limit" not in amplitude.get_title()  # shared: the legend gives it
    best = load_json(runs / "best.json")
    stress_best, frequency_best = largest_stress(span_rows(runs / "best.csv"))
    assert title[1] == f"best: {best['verdict']}, max {stress_best:.3g} MPa at {frequency_best:.3g} Hz"
    module.plt.close(figure)
    # Another conductor: its own undamped curve, no common wind speed axis
    result = plot("span", "damped.csv", "drake.csv", "-o", "two.png", cwd=runs)
    assert result.returncode == 0, result.stderr
    assert result.stderr.count("\n") == 1 and "no wind speed axis" in result.stderr, result.stderr
    figure = module.span_figure([str(runs / "damped.csv"), str(runs / "drake.csv")])
    labels = [line.get_label() for line in figure.axes[1].get_lines()]
    assert labels[:4] == ["damped, undamped", "damped", "drake, undamped", "drake"]
    assert figure.axes[0].child_axes == []
    module.plt.close(figure)


def test_span_overlay_of_different_limits_draws_each(runs, tmp_path):
    def limit(header, rows):
        for row in rows:
            row[header.index("endurance_limit_mpa")] = "30"
    rewrite_csv(runs / "damped.csv", tmp_path / "lax.csv", limit)
    module = stockbridge.plot
    figure = module.span_figure([str(runs / "damped.csv"), str(tmp_path / "lax.csv")])
    limits = [line for line in figure.axes[1].get_lines() if "endurance limit" in line.get_label()]
    assert [line.get_label() for line in limits] == ["damped: endurance limit 8.73 MPa", "lax: endurance limit 30 MPa"]
    title = unwrapped(figure.axes[0].get_title()).split("\n")
    assert title[0].endswith("(limit 8.73 MPa)") and title[1].startswith("lax: safe") and "(limit 30 MPa)" in title[1]
    module.plt.close(figure)


def test_span_wind_speed_axis_maps_the_frequencies_to_the_csvs_wind_speeds(runs):
    module = stockbridge.plot
    rows = span_rows(runs / "damped.csv")
    figure = module.span_figure(str(runs / "damped.csv"))
    figure.canvas.draw()
    bottom = figure.axes[0]
    (top,) = bottom.child_axes
    assert top.get_xlabel() == "wind speed U = f D / St (m/s)"
    for row in (rows[0], rows[7], rows[-1]):
        at_f = bottom.transData.transform((float(row["frequency_hz"]), 1.0))[0]
        at_u = top.transData.transform((float(row["wind_speed_m_s"]), 1.0))[0]
        assert abs(at_f - at_u) < 0.01, row["frequency_hz"]
    low, high = float(rows[0]["wind_speed_m_s"]), float(rows[-1]["wind_speed_m_s"])
    labels = [float(label.get_text()) for tick, label in zip(top.get_xticks(), top.get_xticklabels())
              if low <= tick <= high and label.get_text()]
    assert labels == [1, 2, 3, 4, 5, 6, 7]  # the example's band, 1 to 7 m/s, in plain numbers
    module.plt.close(figure)


def test_span_without_a_wind_speed_column_has_no_top_axis(tmp_path):
    (tmp_path / "s.csv").write_text(SPAN_HEADER + "10,0.01,0.02,5,9,1,8.7\n20,0.01,0.02,6,9,1,8.7\n")
    module = stockbridge.plot
    figure = module.span_figure(str(tmp_path / "s.csv"))
    assert figure.axes[0].child_axes == []
    assert unwrapped(figure.axes[0].get_title()) == f"{tmp_path / 's.csv'}: safe, max 6 MPa at 20 Hz (limit 8.7 MPa)"
    module.plt.close(figure)


@pytest.mark.parametrize("args,contents,mention", [
    (["damped.csv", "bare.csv", "--summary", "damped.json"], None, "1 --summary for 2 span CSV files"),
    (["damped.csv", "--label", "a", "--label", "b"], None, "2 --label for 1 span CSV files"),
    (["damped.csv", "--summary", "bare.json"], None, "bare.json: max_stress_fymax_mpa = "),
    (["damped.csv", "bare.csv", "--summary", "bare.json", "--summary", "damped.json"], None, "bare.json: max_stress"),
    (["damped.csv", "--summary", "x.json"], "verdict: safe\n", "x.json:1: not JSON"),
    (["damped.csv", "--summary", "x.json"], "[1, 2]", "x.json: a JSON list, not an object"),
    (["damped.csv", "--summary", "x.json"], '{"verdict": "unsafe"}', "x.json: missing key 'positions_m'"),
    (["damped.csv", "--summary", "x.json"], '{"verdict": "fine"}', "x.json: verdict = 'fine'"),
    (["damped.csv", "--summary", "x.json"], '{"verdict": "unsafe", "positions_m": ["1"]}', 'positions_m holds "1"'),
    (["damped.csv", "--summary", "nowhere.json"], None, "nowhere.json: cannot read")])
def test_span_bad_summaries_get_one_line_and_exit_two(runs, args, contents, mention):
    if contents is not None:
        (runs / "x.json").write_text(contents)
    result = plot("span", *args, "-o", "bad.png", cwd=runs)
    assert_bad(result, runs, "bad.png", mention)


@pytest.mark.parametrize("name,unit", [
    ("arm.left.mass", "kg"), ("arm[0].inertia", "kg m²"), ("arm.right.offset", "m"), ("arm.left.cable.length", "m"),
    ("arm.left.cable.ei", "N m²"), ("arm.left.cable.jenkin[0].c", "N m²"), ("arm.left.cable.jenkin[1].h", "N m"),
    ("arm.left.cable.jenkin[0].k0", "N"), ("clamp.mass", "kg"), ("position", "m"), ("mass_kg", "kg"),
    ("length_m", "m"), ("stress_mpa", "MPa"), ("frequency_hz", "Hz"), ("force_n", "N"), ("ei_n_m2", "N m²"),
    ("life_years", "years"), ("curvature_per_m", "1/m"), ("speed_m_s", "m/s"), ("something", None)])
def test_units_of_design_variables(name, unit):
    assert stockbridge.plot.unit_of(name) == unit


UNIT = re.compile(r"\((-|[^()]*[A-Za-z%°²][^()]*)\)")


def test_every_axis_of_every_plot_has_its_unit(files, runs, design_files, tmp_path):
    module = stockbridge.plot
    (tmp_path / "schedule.csv").write_text(SCHEDULE)
    figures = {"impedance": module.impedance_figure([module.Sweep(str(files / "z.csv"))], power=True),
               "impedance re im": module.impedance_figure([module.Sweep(str(files / "z.csv"))], re_im=True),
               "loop c": module.loop_figure(str(files / "c.csv")), "loop t": module.loop_figure(str(files / "t.csv")),
               "loop mk": module.loop_figure(str(files / "mk.csv")),
               "span": module.span_figure(str(runs / "damped.csv")),
               "design": module.design_figure(str(design_files / "designs.csv")),
               "line": module.line_figure(str(tmp_path / "schedule.csv"))}
    for name, figure in figures.items():
        labelled = 0
        for axis in figure.axes:
            if not axis.get_visible() or not axis.axison:
                continue
            for label in (axis.get_xlabel(), axis.get_ylabel()) + tuple(child.get_xlabel() for child in axis.child_axes):
                if label and not label.startswith(("span (id)", "dampers per end")):  # the line's ids and counts
                    assert UNIT.search(label), (name, label)
                    labelled += 1
        assert labelled >= (1 if name == "line" else 2), name
        module.plt.close(figure)


def test_design_title_carries_the_best_candidates_verdict(design_files):
    module = stockbridge.plot
    rows = span_rows(design_files / "designs.csv")
    feasible = [r for r in rows if r["feasible"] == "1"]
    best = min(feasible, key=lambda r: float(r["objective"]))
    name = "base" if best["stage"] == "base" else f"{best['stage']} {best['run']}"
    ratio = float(best["max_stress_ratio"])
    figure = module.design_figure(str(design_files / "designs.csv"))
    title = unwrapped(figure._suptitle.get_text()).split("\n")
    assert title == [f"{design_files / 'designs.csv'}: best {name}, {'safe' if ratio <= 1 else 'unsafe'}: max "
                     f"{float(best['max_stress_mpa']):.3g} MPa at {float(best['frequency_at_max_hz']):.3g} Hz, "
                     f"{ratio:.3g} x the endurance limit; mass {float(best['total_mass_kg']):.3g} kg",
                     f"{len(feasible)} of {len(rows)} candidates feasible"]
    assert notes(figure) == []
    module.plt.close(figure)


def test_design_title_of_a_life_study(tmp_path):
    (tmp_path / "life.csv").write_text(DESIGN_HEADER + "base,0,1.5,40,0.9,8,12,2.4,0.2,40,1,1\n"
                                       "sample,0,0.7,3000,1.2,11,20,2.4,0.1,3000,1,1\n"
                                       "sample,2,2.5,,,,,2.4,,,0,0\n")
    module = stockbridge.plot
    figure = module.design_figure(str(tmp_path / "life.csv"))
    assert unwrapped(figure._suptitle.get_text()) == (f"{tmp_path / 'life.csv'}: best sample 0, unsafe: shortest life 3,000 years, "
                                           "max 11 MPa at 20 Hz, 1.2 x the endurance limit; mass 2.4 kg\n"
                                           "2 of 3 candidates feasible, 1 not converged")
    assert notes(figure) == [module.LIVES_NOTE]
    module.plt.close(figure)


def test_line_title_names_the_unsafe_spans_and_the_shortest_life(tmp_path):
    lines = SCHEDULE.splitlines()
    lives = ["", "120", "35.5", "2.25", "", "inf"]
    (tmp_path / "lives.csv").write_text("\n".join(f"{line},{life}" if k else f"{line},life_years"
                                                  for k, (line, life) in enumerate(zip(lines, lives))) + "\n")
    module = stockbridge.plot
    figure = module.line_figure(str(tmp_path / "lives.csv"))
    assert figure.axes[0].get_title().split("\n")[1] == "unsafe: T3-T4; unknown: T4-T5; shortest life 2.2 years (T3-T4)"
    assert notes(figure) == [module.LIVES_NOTE]
    module.plt.close(figure)
    rows = "".join(f"T{k}-T{k + 1},300,2,9,40,8.73,0.8,20,unsafe,1\n" for k in range(1, 9))
    (tmp_path / "bad_line.csv").write_text(SCHEDULE_HEADER + rows)
    figure = module.line_figure(str(tmp_path / "bad_line.csv"))
    assert figure.axes[0].get_title().split("\n") == [
        f"{tmp_path / 'bad_line.csv'}: unsafe: 8 spans, 0 safe, 8 unsafe, 0 unknown",
        "unsafe: T1-T2, T2-T3, T3-T4, T4-T5, T5-T6, T6-T7 and 2 more"]
    module.plt.close(figure)


# ---------------------------------------------------------------- figures of the module's results

def compiled():
    """The package with its compiled part (stockbridge.span, line, impedance)."""
    pytest.importorskip("stockbridge._core")
    import stockbridge
    return stockbridge


def drawn(figure):
    """What each axes of a figure draws: its lines' labels and data, and its filled
    areas' labels and outlines (a measured sheet's band), in drawing order."""
    return [([(line.get_label(), list(line.get_xdata()), list(line.get_ydata())) for line in axis.get_lines()],
             [(area.get_label(), [list(path.vertices.ravel()) for path in area.get_paths()])
              for area in axis.collections])
            for axis in figure.axes]


def assert_same_drawing(one, other):
    assert len(one) == len(other)
    for (lines, areas), (other_lines, other_areas) in zip(one, other):
        assert [label for label, *_ in lines] == [label for label, *_ in other_lines]
        for (_, x, y), (_, other_x, other_y) in zip(lines, other_lines):
            assert x == pytest.approx(other_x, rel=1e-12, nan_ok=True)
            assert y == pytest.approx(other_y, rel=1e-12, nan_ok=True)
        assert [label for label, _ in areas] == [label for label, _ in other_areas]
        for (_, outlines), (_, other_outlines) in zip(areas, other_areas):
            assert len(outlines) == len(other_outlines)
            for outline, other_outline in zip(outlines, other_outlines):
                assert outline == pytest.approx(other_outline, rel=1e-12)


def sheet_span_file(directory):
    """aster570_400m.toml with a vendor's measured sheet as its damper: its CSV has the
    sheet's band (stress_fymax_low_mpa, stress_fymax_high_mpa)."""
    with open(os.path.join(SOURCE, "examples", "aster570_400m.toml")) as handle:
        text = handle.read()
    sheet = os.path.join(SOURCE, "examples", "vendor_sheet.csv")
    assert 'file = "sauter2003.toml"' in text
    (directory / "sheet_span.toml").write_text(text.replace('file = "sauter2003.toml"', f'impedance = "{sheet}"'))
    return directory / "sheet_span.toml"


@pytest.fixture(scope="module")
def results(runs):
    """The module's results of the runs whose CSVs the other tests plot: the span of
    damped.csv and damped.json, a span on a measured sheet (and its CSV and summary),
    and the sweep of z.csv."""
    sb = compiled()
    span_file = sheet_span_file(runs)
    with open(runs / "sheet.json", "w") as out:
        subprocess.run([CLI, "span", str(span_file), "--points", "15", "--quiet", "-o", "sheet.csv", "--json"],
                       cwd=runs, check=True, stdout=out)
    damper = sb.load_damper(os.path.join(SOURCE, "examples", "sauter2003.toml"))
    return {"span": sb.span(os.path.join(SOURCE, "examples", "aster570_400m.toml"), points=15),
            "sheet": sb.span(str(span_file), points=15),
            "impedance": sb.impedance(damper, velocity=[0.2, 0.05], fmin=5, fmax=50, points=12)}


def test_a_span_result_draws_what_its_csv_and_summary_draw(runs, results):
    module = stockbridge.plot
    for name in ("damped", "sheet"):
        result = results["span" if name == "damped" else name]
        from_result = module.span(result)
        from_csv = module.span_figure(str(runs / f"{name}.csv"), summaries=[str(runs / f"{name}.json")])
        assert_same_drawing(drawn(from_result), drawn(from_csv))
        title = unwrapped(from_csv.axes[0].get_title())
        assert unwrapped(from_result.axes[0].get_title()) == "span" + title[title.index(":"):]
        assert [text.get_text() for text in from_result.texts] == [module.LIVES_NOTE]
        module.plt.close(from_result)
        module.plt.close(from_csv)


def test_an_impedance_result_draws_what_its_csv_draws(files, results):
    module = stockbridge.plot
    for options in ({}, {"power": True}, {"re_im": True, "linear": True}):
        from_result = module.impedance(results["impedance"], **options)
        from_csv = module.impedance_figure([module.Sweep(str(files / "z.csv"))], **options)
        assert_same_drawing(drawn(from_result), drawn(from_csv))
        assert [line.get_label() for line in from_result.axes[0].get_lines()] == ["V = 0.2 m/s", "V = 0.05 m/s"]
        assert from_result.axes[0].get_title() == "Impedance at the clamp"
        module.plt.close(from_result)
        module.plt.close(from_csv)
    two = module.impedance([results["impedance"], results["impedance"]], labels=["a", "b"])
    assert [line.get_label() for line in two.axes[0].get_lines()][::2] == ["a: V = 0.2 m/s", "b: V = 0.2 m/s"]
    assert two.axes[0].get_title() == "Impedance at the clamp (a, b)"
    module.plt.close(two)


def schedule_result(text):
    """A schedule CSV's text as stockbridge.line() returns it: text columns as lists of
    str, counts as int arrays, flags as bool arrays, the rest float arrays with NaN
    where the CSV's cell is empty; with the line's summary beside it."""
    import numpy
    rows = list(csv.DictReader(text.splitlines()))
    columns = {}
    for name in rows[0]:
        cells = [row[name] for row in rows]
        if name in ("id", "verdict"):
            columns[name] = cells
        elif name == "dampers_per_end":
            columns[name] = numpy.array([int(c) for c in cells])
        elif name == "converged":
            columns[name] = numpy.array([c == "1" for c in cells])
        else:
            columns[name] = numpy.array([float(c) if c else numpy.nan for c in cells])
    return {"schedule": columns, "summary": {"spans": len(rows)}, "bill": {}, "warnings": []}


def test_a_line_result_draws_what_its_schedule_csv_draws(tmp_path):
    from matplotlib.colors import to_rgba
    module = stockbridge.plot
    (tmp_path / "schedule.csv").write_text(SCHEDULE)
    from_csv = module.line_figure(str(tmp_path / "schedule.csv"))
    result = schedule_result(SCHEDULE)
    for given in (result, result["schedule"]):  # the whole result or its schedule
        from_result = module.line(given, label="my line")
        assert_same_drawing(drawn(from_result), drawn(from_csv))
        assert [bar.get_height() for bar in from_result.axes[1].containers[0]] == [2, 1, 3, 2, 0]
        title = from_csv.axes[0].get_title()
        assert from_result.axes[0].get_title() == "my line" + title[title.index(":"):]
        module.plt.close(from_result)
    # uncertain and a verdict the module does not know: counted, named and coloured
    result["schedule"]["verdict"][:2] = ["uncertain", "marginal"]
    figure = module.line(result)
    assert figure.axes[0].get_title().split("\n") == [
        "line: unsafe: 5 spans, 1 safe, 1 unsafe, 1 unknown, 1 uncertain, 1 marginal",
        "unsafe: T3-T4; uncertain: T1-T2; unknown: T4-T5; marginal: T2-T3"]
    bars = figure.axes[1].containers[0]
    assert bars[0].get_facecolor() == to_rgba("C1") and bars[1].get_facecolor() == to_rgba("C4")
    assert [text.get_text() for text in figure.axes[0].get_legend().get_texts()][-4:] == [
        "unsafe span", "uncertain span", "unknown span", "marginal span"]
    module.plt.close(figure)


def test_an_uncertain_span_in_a_schedule_csv(tmp_path):
    (tmp_path / "schedule.csv").write_text(SCHEDULE.replace("T2-T3,420,1,7.9,40.9,8.73,0.905,9.5,safe",
                                                            "T2-T3,420,1,7.9,40.9,8.73,0.905,9.5,uncertain"))
    assert plot("line", "schedule.csv", "-o", "schedule.png", cwd=tmp_path).returncode == 0
    module = stockbridge.plot
    figure = module.line_figure(str(tmp_path / "schedule.csv"))
    assert "unsafe: T3-T4; uncertain: T2-T3; unknown: T4-T5" in figure.axes[0].get_title()
    module.plt.close(figure)


def fill_labels(axis):
    return [area.get_label() for area in axis.collections if not area.get_label().startswith("_")]


def all_finite(values):
    return all(math.isfinite(v) for v in values)


def test_the_sheets_band_is_drawn_where_the_run_has_one(runs, results):
    """From a result and from its CSV: the band between stress_fymax_low_mpa and
    stress_fymax_high_mpa where they are given, nothing where they are NaN (empty)."""
    module = stockbridge.plot
    sheet = results["sheet"]
    assert all_finite(sheet["stress_fymax_high_mpa"]) and not all_finite(
        results["span"]["stress_fymax_high_mpa"])  # the premise: a band with the sheet only
    for figure in (module.span(sheet), module.span_figure(str(runs / "sheet.csv"))):
        stress = figure.axes[1]
        assert fill_labels(stress) == ["measured sheet's band"]
        (band,) = [area for area in stress.collections if area.get_label() == "measured sheet's band"]
        outline = band.get_paths()[0].vertices
        assert max(outline[:, 1]) == pytest.approx(max(sheet["stress_fymax_high_mpa"]))
        assert min(outline[:, 1]) == pytest.approx(min(sheet["stress_fymax_low_mpa"]))
        module.plt.close(figure)
    for figure in (module.span(results["span"]), module.span_figure(str(runs / "damped.csv"))):
        assert fill_labels(figure.axes[1]) == []
        module.plt.close(figure)
    both = module.span([sheet, results["span"]], labels=["sheet", "sauter"])
    assert fill_labels(both.axes[1]) == ["sheet: measured sheet's band"]
    module.plt.close(both)


def test_an_uncertain_verdict_is_the_titles(runs, results):
    """The summary's verdict, uncertain (a measured sheet's band reaching the limit), is
    the title's with how high the band reaches; from a summary file too; a verdict the
    plot does not know is shown as it is."""
    module = stockbridge.plot
    sheet = dict(results["sheet"], summary=dict(results["sheet"]["summary"], verdict="uncertain", criterion="stress"))
    top = max(sheet["stress_fymax_high_mpa"])
    figure = module.span(sheet, labels="vendor sheet")
    head, more = figure.axes[0].get_title().split("\n")[:2]
    assert head.startswith("vendor sheet: uncertain (stress criterion), max ")
    assert more.endswith(f"the sheet's band up to {top:.3g} MPa")
    module.plt.close(figure)
    (runs / "uncertain.json").write_text(json.dumps(sheet["summary"]))
    result = plot("span", "sheet.csv", "--summary", "uncertain.json", "-o", "uncertain.png", cwd=runs)
    assert result.returncode == 0 and result.stderr == "", result.stderr
    figure = module.span_figure(str(runs / "sheet.csv"), summaries=[str(runs / "uncertain.json")])
    assert unwrapped(figure.axes[0].get_title()).split("\n")[0].startswith(f"{runs / 'sheet.csv'}: uncertain")
    module.plt.close(figure)
    odd = dict(results["span"], summary=dict(results["span"]["summary"], verdict="marginal"))
    figure = module.span(odd)
    assert figure.axes[0].get_title().startswith("span: marginal (safe-border-line criterion), max ")
    module.plt.close(figure)


def test_a_figure_of_a_result_is_saved_where_asked(results, tmp_path):
    module = stockbridge.plot
    figure = module.span(results["span"], tmp_path / "span.png")
    assert png_size(tmp_path / "span.png") == (800, 839) and figure.axes[0].get_title().startswith("span: ")
    figure = module.impedance(results["impedance"], str(tmp_path / "z.svg"))
    assert (tmp_path / "z.svg").read_text().lstrip().startswith("<?xml") and len(figure.axes) == 2
    with pytest.raises(module.PlotError, match="z.bmpx: unknown image format"):
        module.impedance(results["impedance"], str(tmp_path / "z.bmpx"))


@pytest.mark.parametrize("call,mention", [
    (lambda m, r: m.span({"frequency": [1.0]}), "span: expected the dict stockbridge.span() returns, got a dict "
                                                "without 'frequency_hz'"),
    (lambda m, r: m.span("span.csv"), "span: expected the dict stockbridge.span() returns, got str"),
    (lambda m, r: m.line(r["span"]), "line: expected the dict stockbridge.line() returns"),
    (lambda m, r: m.impedance(r["span"]), "impedance: converged has shape (15,): expected (amplitudes, frequencies)"),
    (lambda m, r: m.span([r["span"], r["span"]], labels=["one"]), "1 labels for 2 results"),
    (lambda m, r: m.span(dict(r["span"], converged=r["span"]["converged"] & False)), "span: no converged point")])
def test_a_result_the_figure_cannot_use_raises_one_line(results, call, mention):
    module = stockbridge.plot
    with pytest.raises(module.PlotError) as error:
        call(module, results)
    assert mention in str(error.value) and "\n" not in str(error.value)


def labelled_ticks(axis):
    low, high = sorted(axis.get_xlim())
    return [(tick, label) for tick, label in zip(axis.get_xticks(), axis.get_xticklabels())
            if low <= tick <= high and label.get_text()]


@pytest.mark.parametrize("band", [(5, 50), (5.96, 41.7), (6.6, 46), (10, 100), (15, 30), (20, 28), (1, 100), (2, 400),
                                  (1, 1e4)])
def test_log_frequency_axes_are_labelled_across_the_band(band):
    """Five or more labelled frequencies inside any band (a 15-30 Hz band had 20 and 30
    only), in plain numbers, at least 8 pixels apart."""
    import numpy
    module = stockbridge.plot
    figure, axis = module.plt.subplots(figsize=module.FIGURE_SIZE)
    f = numpy.geomspace(*band, 30)
    axis.plot(f, f)
    module.frequency_scale(axis)
    figure.canvas.draw()
    ticks = labelled_ticks(axis)
    assert len(ticks) >= 5, [label.get_text() for _, label in ticks]
    assert all(float(label.get_text()) == pytest.approx(tick) for tick, label in ticks)
    boxes = sorted((label.get_window_extent() for _, label in ticks), key=lambda box: box.x0)
    assert all(right.x0 - left.x1 >= 8 for left, right in zip(boxes, boxes[1:]))
    module.plt.close(figure)


def test_every_log_frequency_axis_is_labelled_across_the_band(files, span_files, tmp_path):
    """The span, impedance and fit figures' frequency axes: five or more labels over
    their bands (the span CSV's 5.96-41.7 Hz, the impedance's 5-50 Hz)."""
    module = stockbridge.plot
    figures = [module.span_figure(str(span_files / "span.csv")),
               module.impedance_figure([module.Sweep(str(files / "z.csv"))], power=True)]
    for figure in figures:
        figure.canvas.draw()
        for axis in figure.axes:
            if axis.get_xscale() == "log" and axis.xaxis.get_ticklabels():
                assert len(labelled_ticks(axis)) >= 5, [label.get_text() for _, label in labelled_ticks(axis)]
        module.plt.close(figure)


def test_span_profile_plot_marks_the_attachments(tmp_path):
    example = os.path.join(SOURCE, "examples", "aster570_400m.toml")
    text = pathlib.Path(example).read_text().replace('file = "sauter2003.toml"',
                                                     f'file = "{os.path.join(SOURCE, "examples", "sauter2003.toml")}"')
    (tmp_path / "spheres.toml").write_text(text + '\n[[mass]]\nname = "sphere"\nmass = 10.0\npositions = [100, 300]\n')
    run_cli("span", "spheres.toml", "--frequencies", "15,30", "-o", "s.csv", "--profile", "along.csv", cwd=tmp_path)
    result = plot("span-profile", "along.csv", "-o", "along.png", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert png_size(tmp_path / "along.png") == (800, 600)
    (tmp_path / "bad.csv").write_text("x_m,displacement_m\n1,2\n")
    bad = plot("span-profile", "bad.csv", "-o", "bad.png", cwd=tmp_path)
    assert bad.returncode == 2 and "missing column 'envelope_m'" in bad.stderr
    assert not os.path.exists(tmp_path / "bad.png")
