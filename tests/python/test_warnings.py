"""Python warns as the program does: for the same inputs, each "warning:" line the
program prints on stderr is an UnusualValueWarning in Python with the same words
(the program names a setting by its flag, --amplitude, where Python names the
keyword, amplitude), and the JSON summary lists them."""

import cmath
import csv
import json
import os
import subprocess
import warnings

import pytest

import stockbridge as sb

CLI = os.environ["STOCKBRIDGE_CLI"]
SOURCE = os.environ["STOCKBRIDGE_SOURCE_DIR"]
EXAMPLES = os.path.join(SOURCE, "examples")


def program_warnings(args, cwd):
    """The program's warning lines, as Python words them (a flag as its keyword)."""
    run = subprocess.run([CLI, *args], cwd=cwd, capture_output=True, text=True)
    assert run.returncode in (0, 3), run.stderr
    lines = [line[len("warning: "):] for line in run.stderr.splitlines() if line.startswith("warning: ")]
    keyword = [line[2:].replace("-", "_", line[2:].find(" ")) if line.startswith("--") else line for line in lines]
    return keyword, run.stdout


def program_refusal(args, cwd):
    """The program's one line refusing a unit slip, without its words on how to accept it."""
    run = subprocess.run([CLI, *args], cwd=cwd, capture_output=True, text=True)
    assert run.returncode == 2 and run.stderr.count("\n") == 1, run.stderr
    suffix = " (--allow-unusual takes it as given)\n"
    assert run.stderr.startswith("stockbridge: ") and run.stderr.endswith(suffix), run.stderr
    return run.stderr[len("stockbridge: "):-len(suffix)]


def python_refusal(call):
    """Python's UnusualValueError for the same, without its words on how to accept it."""
    with pytest.raises(sb.UnusualValueError) as error:
        call()
    suffix = " (allow_unusual=True takes it as given)"
    assert str(error.value).endswith(suffix), str(error.value)
    return str(error.value)[:-len(suffix)]


def python_warnings(call):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = call()
    assert all(issubclass(w.category, sb.UnusualValueWarning) for w in caught), [str(w.message) for w in caught]
    return [str(w.message) for w in caught], result


def test_cycle_with_a_large_drive(tmp_path):
    cable = os.path.join(EXAMPLES, "cable_sauter2003.toml")
    expected, stdout = program_warnings(
        ["cycle", cable, "--experiment", "a", "--amplitude", "0.2", "--cycles", "1", "--points", "40", "--json",
         "-o", "c.csv"], tmp_path)
    assert len(expected) == 1 and expected[0].startswith("amplitude = 0.2: more than 0.3 of the cable's length")
    assert json.loads(stdout)["warnings"] == expected
    given, _ = python_warnings(lambda: sb.cycle(sb.load_cable(cable), "a", 0.2, cycles=1, points=40))
    assert given == expected


def test_identify_global_with_a_large_error(tmp_path):
    record = os.path.join(EXAMPLES, "cycle_measured_a.csv")
    expected, stdout = program_warnings(
        ["identify", "global", "--experiment", "a", "--length", "0.3", "--input", record, "--method", "four-step",
         "--json", "-o", "cable.toml"], tmp_path)
    assert len(expected) == 1 and "relative L1 error 0.457 is large" in expected[0]
    assert json.loads(stdout)["warnings"] == expected
    with open(record, newline="") as handle:
        rows = list(csv.DictReader(handle))
    x = [float(row["x_m"]) for row in rows]
    force = [float(row["force_n"]) for row in rows]
    given, result = python_warnings(lambda: sb.identify_global("a", 0.3, x, force, method="four-step"))
    # The program names the record by its file, Python by "the record".
    assert given == [line.replace(record, "the record") for line in expected]
    assert result["warnings"] == given


def test_identify_impedance_with_a_poor_fit(tmp_path):
    # The measured impedance with the sign of Im Z turned: no damper has it.
    with open(os.path.join(EXAMPLES, "measured_impedance.csv"), newline="") as handle:
        rows = list(csv.DictReader(handle))
    for row in rows:
        row["im_z_n_s_m"] = str(-float(row["im_z_n_s_m"]))
    measured = tmp_path / "poor.csv"
    with open(measured, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    damper = os.path.join(EXAMPLES, "damper_to_identify.toml")
    expected, stdout = program_warnings(
        ["identify", "impedance", "--damper", damper, "--input", str(measured), "--json", "-o", "cable.toml"], tmp_path)
    assert any("RMS relative error of Z" in line and "is large (above 10 %)" in line for line in expected), expected
    assert json.loads(stdout)["warnings"] == expected
    given, result = python_warnings(lambda: sb.identify_impedance(sb.load_damper(damper), measured))
    assert given == expected
    assert result["warnings"] == expected
    assert result["poor_fit"] is True and json.loads(stdout)["poor_fit"] is True


def test_a_measured_impedance_in_mm_per_second_and_radians(tmp_path):
    # Four points of the example at each velocity, the velocity in mm/s, Z as |Z| and the phase in radians.
    with open(os.path.join(EXAMPLES, "measured_impedance.csv"), newline="") as handle:
        rows = list(csv.DictReader(handle))[::4]
    measured = tmp_path / "slipped.csv"
    with open(measured, "w", newline="") as handle:
        handle.write("frequency_hz,velocity_m_s,abs_z_n_s_m,phase_deg\n")
        for row in rows:
            z = complex(float(row["re_z_n_s_m"]), float(row["im_z_n_s_m"]))
            handle.write(f"{row['frequency_hz']},{1000 * float(row['velocity_m_s']):g},{abs(z)},{cmath.phase(z)}\n")
    damper = os.path.join(EXAMPLES, "damper_to_identify.toml")
    refused = program_refusal(["identify", "impedance", "--damper", damper, "--input", str(measured)], tmp_path)
    assert refused == python_refusal(lambda: sb.identify_impedance(sb.load_damper(damper), measured))
    expected, stdout = program_warnings(["identify", "impedance", "--damper", damper, "--input", str(measured), "--json",
                                         "--rms-limit", "100", "--allow-unusual"], tmp_path)
    assert expected[0].startswith(f"{measured}:2: column 'velocity_m_s' = 50: outside the typical 0.001 to 2 m/s of the "
                                  "clamp velocity amplitude (in mm/s? 50 mm/s = 0.05 m/s); 7 more rows"), expected
    assert refused == expected[0].split("; 7 more rows")[0] + "; a measured sheet's values lie within it"
    assert "phase_deg looks like radians" in expected[1], expected
    assert json.loads(stdout)["warnings"] == expected
    given, result = python_warnings(
        lambda: sb.identify_impedance(sb.load_damper(damper), measured, rms_limit=100, allow_unusual=True))
    assert given == expected
    assert result["warnings"] == expected


def test_a_span_file_in_wrong_units(tmp_path):
    with open(os.path.join(EXAMPLES, "aster570_400m.toml")) as handle:
        text = handle.read()
    # The diameter in mm and the mass per length in g/m.
    text = text.replace("diameter = 0.03105 ", "diameter = 31.05 ").replace("mass_per_length = 1.571 ",
                                                                            "mass_per_length = 1571 ")
    text = text.replace('file = "sauter2003.toml"', 'file = "%s"' % os.path.join(EXAMPLES, "sauter2003.toml"))
    span_file = tmp_path / "wrong_units.toml"
    span_file.write_text(text)
    refused = program_refusal(["span", str(span_file), "--no-dampers", "--frequencies", "10", "-o", "s.csv"], tmp_path)
    assert refused.startswith(f"{span_file}:10: conductor.diameter = 31.05: "), refused
    assert refused == python_refusal(lambda: sb.span(span_file, frequencies=[10.0], no_dampers=True))
    expected, _ = program_warnings(["span", str(span_file), "--no-dampers", "--frequencies", "10", "-o", "s.csv",
                                    "--allow-unusual"], tmp_path)
    # The mass per length in g/m puts the tension's H/w at 1.8 m: no span hangs so.
    assert [line.split(": ", 1)[1].split(" = ")[0] for line in expected] == ["conductor.diameter",
                                                                             "conductor.mass_per_length",
                                                                             "span.tension_fraction"], expected
    given, _ = python_warnings(lambda: sb.span(span_file, frequencies=[10.0], no_dampers=True, allow_unusual=True))
    assert given == expected
