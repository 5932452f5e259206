"""The Python binding: the same numbers as the program for the same file, errors as
Python exceptions with the library's message, arrays of the documented shapes and
dtypes, and the example script."""

import csv
import json
import os
import re
import shutil
import subprocess
import sys
import warnings

import numpy as np
import pytest

import stockbridge as sb

CLI = os.environ["STOCKBRIDGE_CLI"]
SOURCE = os.environ["STOCKBRIDGE_SOURCE_DIR"]
EXAMPLE = os.path.join(SOURCE, "examples", "sauter2003.toml")
CABLE = os.path.join(SOURCE, "examples", "cable_sauter2003.toml")


def test_impedance_equals_the_program_for_the_same_file(tmp_path):
    frequencies = [8.0, 12.5, 20.0, 45.0]
    subprocess.run([CLI, "impedance", EXAMPLE, "--velocity", "0.2,0.05", "--frequencies", "8,12.5,20,45", "-o", "z.csv"],
                   cwd=tmp_path, check=True, capture_output=True)
    with open(tmp_path / "z.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    z = sb.impedance(sb.load_damper(EXAMPLE), frequencies, velocity=[0.2, 0.05])
    for k, row in enumerate(rows):
        a, i = divmod(k, len(frequencies))
        assert float(row["frequency_hz"]) == frequencies[i]
        assert z["re_z_n_s_m"][a, i] == pytest.approx(float(row["re_z_n_s_m"]), rel=1e-12)
        assert z["im_z_n_s_m"][a, i] == pytest.approx(float(row["im_z_n_s_m"]), rel=1e-12)
        assert z["power_w"][a, i] == pytest.approx(float(row["power_w"]), rel=1e-12, abs=1e-15)
        for column in ("abs_z_n_s_m", "phase_deg", "iterations", "messenger_curvature_max_per_m", "left_power_w",
                       "left_mass_amplitude_m", "right_power_w", "right_mass_amplitude_m"):
            assert z[column][a, i] == pytest.approx(float(row[column]), rel=1e-12, abs=1e-15), column
    assert z["arms"] == ["left", "right"]


def test_version_is_the_programs():
    out = subprocess.run([CLI, "--version"], check=True, capture_output=True, text=True).stdout
    assert out == f"stockbridge {sb.__version__}\n"


def documented_keys(function, arms):
    """The keys docs/python.md gives for what `function` returns: every name in
    backticks in its row's second cell, <arm> standing for each of `arms`."""
    with open(os.path.join(SOURCE, "docs", "python.md")) as handle:
        row = next(line for line in handle if line.startswith(f"| `{function}("))
    cell = row.split("|")[2]
    names = [name.strip() for span in re.findall(r"`([^`]*)`", cell) for name in span.split(",")]
    return {name.replace("<arm>", arm) for name in names for arm in arms}


def test_impedance_and_response_return_the_documented_keys_only():
    damper = sb.load_damper(os.path.join(SOURCE, "examples", "asymmetric_damper.toml"))
    z = sb.impedance(damper, [10.0, 30.0], velocity=0.1)
    assert set(z) == documented_keys("impedance", ["long", "short"])
    assert {"abs_z_n_s_m", "phase_deg", "iterations", "messenger_curvature_max_per_m", "short_mass_amplitude_m"} <= set(z)
    r = sb.response(damper, 30.0, velocity=0.1)
    assert set(r) == documented_keys("response", ["long", "short"])
    # The response's figures are the sweep's at its frequency (the same library function), though
    # the sweep reached 30 Hz from 10 Hz and the response started cold: to the solver's tolerance.
    for key in ("messenger_curvature_max_per_m", "long_power_w", "long_mass_amplitude_m", "short_power_w",
                "short_mass_amplitude_m"):
        assert z[key].shape == (1, 2) and z[key][0, 1] > 0, key
        assert r[key] == pytest.approx(z[key][0, 1], rel=1e-6), key
    assert r["long_power_w"] + r["short_power_w"] == pytest.approx(r["power_w"], rel=1e-9)


def test_arrays_have_the_documented_shapes_and_dtypes():
    damper = sb.load_damper(EXAMPLE)
    z = sb.impedance(damper, np.array([10.0, 20.0, 30.0]), velocity=0.1)
    assert z["re_z_n_s_m"].shape == (1, 3) and z["re_z_n_s_m"].dtype == np.float64
    assert z["converged"].dtype == np.bool_ and z["converged"].all()
    r = sb.response(damper, 20.0, velocity=0.2)
    assert r["time_s"].shape == (144,) and r["x_m"].shape == (2, 144) and r["force_n"].dtype == np.float64
    assert isinstance(r["impedance"], complex)
    assert r["power_w"] == pytest.approx(r["dissipated_power_w"], rel=1e-3)
    c = sb.cycle(sb.load_cable(CABLE), "a", 0.03, cycles=2, points=400)
    assert c["force_n"].shape == (801,) and c["converged"].all()


def test_identification_and_a_damper_built_from_python_values():
    cable = sb.make_cable(length=0.3, sections=40, ei=2.8, jenkin=[(20.0, 0.7)])
    c = sb.cycle(cable, "a", 0.03)
    fit = sb.identify_global("a", 0.3, c["x_m"], c["force_n"])
    assert fit["ei"] == pytest.approx(2.8, rel=1e-6)
    assert fit["jenkin"][0]["c"] == pytest.approx(20.0, rel=1e-6)
    kappa = 0.08 * np.sin(np.linspace(0.0, 6.0 * np.pi, 1201))
    local = sb.identify_local(kappa, 2.8 * kappa + np.clip(20.0 * kappa, -0.7, 0.7))  # a virgin-like record is enough
    assert local["ei"] > 0 and len(local["jenkin"]) == 1
    arm = {"mass": 0.856, "inertia": 0.001814, "offset": 0.0325, "cable": fit["cable"]}
    damper = sb.make_damper(0.7, [arm, arm])
    assert sb.impedance(damper, [15.0], velocity=0.2)["converged"].all()
    ei_min, ei_max = sb.strand_bounds(0.001, [(6, 0.001, 0.002, 0.06), (12, 0.001, 0.004, 0.1)])
    assert ei_min == pytest.approx(3.1337, rel=1e-4) and ei_max > ei_min


def test_a_point_without_a_periodic_solution_is_nan_with_the_reason():
    # An undamped linear arm at its first natural frequency: a singular Jacobian.
    elastic = sb.make_cable(length=0.1875, sections=40, ei=22.8, jenkin=[])
    arm = {"mass": 0.856, "inertia": 0.001814, "offset": 0.0325, "cable": elastic}
    z = sb.impedance(sb.make_damper(0.7, [arm]), [20.0, 21.1726198299174], velocity=0.2)
    assert z["converged"].tolist() == [[True, False]]
    for key in ("re_z_n_s_m", "im_z_n_s_m", "power_w", "energy_error", "residual", "messenger_curvature_max_per_m",
                "arm1_power_w", "arm1_mass_amplitude_m"):
        assert np.isfinite(z[key][0, 0]) and np.isnan(z[key][0, 1]), key
    assert "singular Jacobian" in z["messages"][0][1]


def test_errors_are_python_exceptions_with_the_library_message(tmp_path):
    with pytest.raises(sb.InputError, match="no such file"):
        sb.load_damper(str(tmp_path / "missing.toml"))
    (tmp_path / "bad.toml").write_text("[cable]\nlength = -0.3\nsections = 40\nei = 2.8\n")
    with pytest.raises(sb.InputError, match="cable.length = -0.3"):
        sb.load_cable(str(tmp_path / "bad.toml"))
    with pytest.raises(sb.InvalidParameter, match="ei = -1"):
        sb.make_cable(0.3, 40, -1.0)
    with pytest.raises(sb.InvalidParameter, match="either velocity"):
        sb.impedance(sb.load_damper(EXAMPLE), [10.0])
    with pytest.raises(ValueError):  # both error types are ValueErrors
        sb.impedance(sb.load_damper(EXAMPLE), [10.0], velocity=0.2, method="euler")


def test_example_script_runs(tmp_path):
    script = os.path.join(SOURCE, "examples", "identify_and_impedance.py")
    result = subprocess.run([sys.executable, script, str(tmp_path / "example.png")], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert "240 of 240 points converged" in result.stdout
    assert os.path.getsize(tmp_path / "example.png") > 10000


def read_csv(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


@pytest.mark.parametrize("flags, keywords", [
    (["--method", "collocation", "--harmonics", "20", "--max-iterations", "60", "--energy-tolerance", "0.02"],
     dict(method="collocation", harmonics=20, max_iterations=60, energy_tolerance=0.02)),
    (["--method", "time", "--steps", "64", "--max-periods", "500"], dict(method="time", steps=64, max_periods=500)),
    (["--fmin", "9", "--fmax", "30", "--points", "3", "--samples", "256", "--threads", "2"],
     dict(fmin=9.0, fmax=30.0, points=3, samples=256, threads=2)),
    (["--full-period", "--harmonics", "9"], dict(full_period=True, harmonics=9)),
])
def test_every_cli_option_has_the_same_python_keyword(tmp_path, flags, keywords):
    frequencies = [] if "--fmin" in flags else ["--frequencies", "12,40"]
    subprocess.run([CLI, "impedance", EXAMPLE, "--velocity", "0.1", *frequencies, *flags, "-o", "z.csv"],
                   cwd=tmp_path, check=True, capture_output=True)
    rows = read_csv(tmp_path / "z.csv")
    z = sb.impedance(sb.load_damper(EXAMPLE), None if "--fmin" in flags else [12.0, 40.0], velocity=0.1, **keywords)
    assert z["frequency_hz"].tolist() == [float(row["frequency_hz"]) for row in rows]
    for i, row in enumerate(rows):
        for column in ("re_z_n_s_m", "im_z_n_s_m", "iterations", "periods"):
            assert z[column][0, i] == pytest.approx(float(row[column]), rel=1e-12), column


def test_a_setting_the_method_does_not_use_is_an_error():
    with pytest.raises(sb.InvalidParameter, match="steps = 64: not used by this method"):
        sb.impedance(sb.load_damper(EXAMPLE), [20.0], velocity=0.1, method="hb", steps=64)


def test_non_convergence_is_a_result_not_an_exception():
    damper = sb.load_damper(EXAMPLE)
    r = sb.response(damper, 20.0, velocity=0.2, energy_tolerance=1e-12)  # the sampled balance is about 1e-5
    assert r["converged"] is False and r["termination"] == "energy_mismatch"
    assert "energy balance off by" in r["message"]
    assert np.isnan(r["power_w"]) and np.isnan(r["impedance"].real)
    assert np.isfinite(r["x_m"]).all()  # the last iterate is there to inspect
    z = sb.impedance(damper, [20.0], velocity=0.2, energy_tolerance=1e-12)
    assert z["termination"][0][0] == "energy_mismatch" and np.isnan(z["re_z_n_s_m"][0, 0])


def test_values_from_python_are_checked_as_a_file_is():
    cable = sb.make_cable(0.1875, ei=2.8, jenkin=[(20.0, 0.7)])
    arm = dict(name="a", mass=0.856, inertia=0.001814, offset=0.0325, cable=cable)
    with pytest.raises(sb.InvalidParameter, match="unknown key 'arm\\[0\\].colour'"):
        sb.make_damper(0.7, [dict(arm, colour=1)])
    with pytest.raises(sb.InvalidParameter, match="missing key 'inertia' in \\[arm\\[0\\]\\]"):
        sb.make_damper(0.7, [{k: v for k, v in arm.items() if k != "inertia"}])
    with pytest.raises(sb.InvalidParameter, match="arm\\[0\\].cable.jenkin\\[0\\].h = -0.7"):
        sb.make_damper(0.7, [dict(arm, cable=dict(length=0.1875, sections=40, ei=2.8, jenkin=[dict(c=20.0, h=-0.7)]))])
    with pytest.raises(sb.InvalidParameter, match="cable.lenght"):
        sb.make_cable(0.3, ei=2.8, lenght=0.2)
    # A cable from Python and the same numbers from a file are the same damper.
    from_python = sb.make_damper(0.7, [arm, dict(arm, name="b")])
    z = sb.impedance(from_python, [15.0], velocity=0.2)
    assert z["re_z_n_s_m"][0, 0] == pytest.approx(sb.impedance(sb.load_damper(EXAMPLE), [15.0], velocity=0.2)["re_z_n_s_m"][0, 0],
                                                  rel=1e-12)


def test_numpy_values_and_any_text_go_through_make_cable_and_make_damper():
    cable = sb.make_cable(np.float64(0.1875), sections=np.int64(40), ei=np.float64(2.8),
                          jenkin=[(np.float64(20.0), np.float32(0.7))])
    assert cable.sections == 40 and cable.ei == pytest.approx(2.8)
    damper = sb.make_damper(np.float64(0.7), [dict(name="bras \U0001F600", mass=np.float64(0.856), inertia=0.001814,
                                                   offset=0.0325, cable=cable)])
    assert damper.arms == ["bras \U0001F600"]
    with pytest.raises(ValueError):
        sb.make_cable(0.3, ei=2.8, jenkin=[(20.0, 0.7, 5.0)])  # a third value is not silently dropped


def test_loop_and_the_strand_loader_equal_the_program(tmp_path):
    subprocess.run([CLI, "loop", "--ei", "2.8", "--jenkin", "20:0.7", "--amplitude", "0.05", "-o", "loop.csv"],
                   cwd=tmp_path, check=True, capture_output=True)
    rows = read_csv(tmp_path / "loop.csv")
    loop = sb.loop(2.8, [(20.0, 0.7)], 0.05)
    assert loop["moment_n_m"].shape == (len(rows),)
    assert loop["moment_n_m"] == pytest.approx([float(r["moment_n_m"]) for r in rows], rel=1e-12, abs=1e-15)
    # One element: 4 h (ka - h/c) per cycle (the section law's closed form).
    assert loop["last_cycle_dissipation_j_per_m"] == pytest.approx(4 * 0.7 * (0.05 - 0.7 / 20.0), rel=1e-9)
    strand_file = os.path.join(SOURCE, "examples", "strand_19wire.toml")
    out = subprocess.run([CLI, "strand", strand_file, "--json"], check=True, capture_output=True, text=True).stdout
    assert sb.load_strand(strand_file) == pytest.approx(json.loads(out), rel=1e-15)
    with pytest.raises(sb.InvalidParameter, match="law = 'smooth'"):
        sb.loop(2.8, [(20.0, 0.7)], 0.05, law="smooth")


def test_a_bouc_wen_loop_equals_the_program_and_its_closed_form(tmp_path):
    subprocess.run([CLI, "loop", "--law", "bouc-wen", "--ei-min", "5", "--ei-max", "40", "--chi0", "0.15",
                    "--amplitude", "0.5", "--cycles", "4", "-o", "bw.csv"], cwd=tmp_path, check=True, capture_output=True)
    rows = read_csv(tmp_path / "bw.csv")
    loop = sb.loop(law="bouc-wen", ei_min=5.0, ei_max=40.0, chi0=0.15, amplitude=0.5, cycles=4)
    assert loop["moment_n_m"] == pytest.approx([float(r["moment_n_m"]) for r in rows], rel=1e-12, abs=1e-15)
    # 4 (EI_max - EI_min) chi0 (chi_a - chi0 tanh(chi_a / chi0)) per steady cycle (MODEL.md 13)
    assert loop["last_cycle_dissipation_j_per_m"] == pytest.approx(4 * 35 * 0.15 * (0.5 - 0.15 * np.tanh(0.5 / 0.15)),
                                                                  rel=1e-9)
    with pytest.raises(sb.InvalidParameter, match="ei and jenkin are the Masing law's"):
        sb.loop(2.8, law="bouc-wen", ei_min=5.0, ei_max=40.0, chi0=0.15, amplitude=0.5)
    with pytest.raises(sb.InvalidParameter, match="are the Bouc-Wen law's"):
        sb.loop(2.8, chi0=0.15, amplitude=0.5)


def test_an_iwan_loop_dissipates_its_closed_form_and_its_cable_has_its_numbers():
    loop = sb.loop(law="iwan", ei=2.8, slip_moment=0.7, tangent_stiffness=20.0, exponent=-0.5, beta=0.2,
                   amplitude=0.05, cycles=3)
    chi = -0.5
    c = 0.2 + (chi + 1) / (chi + 2)
    phi_max = 0.7 * 1.2 / (20.0 * c)
    r = 0.7 * (chi + 1) / (phi_max ** (chi + 2) * c)
    # 4 R a^(chi+3) / ((chi+2)(chi+3)) per steady cycle (MODEL.md 17)
    assert loop["last_cycle_dissipation_j_per_m"] == pytest.approx(4 * r * 0.05 ** (chi + 3) / ((chi + 2) * (chi + 3)),
                                                                  rel=1e-9)
    cable = sb.make_cable(0.1875, law="iwan", ei=2.8, slip_moment=0.7, tangent_stiffness=20.0, exponent=-0.5, beta=0.2)
    assert (cable.law, cable.ei, cable.slip_moment, cable.exponent, cable.beta, cable.ei_min) == \
        ("iwan", 2.8, 0.7, -0.5, 0.2, None)
    assert 'law = "iwan"' in cable.toml()
    with pytest.raises(sb.InvalidParameter, match="law = 'iwan' needs ei"):
        sb.loop(law="iwan", ei=2.8, amplitude=0.05)


ARM = {"mass": 0.856, "inertia": 0.001814, "offset": 0.0325}


def test_one_identified_cable_cut_to_each_arms_length_through_python_and_files(tmp_path):
    identified = sb.make_cable(0.3, ei=2.8, jenkin=[(20.0, 0.7)])
    cut = identified.with_length(0.1875)
    assert (cut.length, identified.length) == (0.1875, 0.3)  # a copy; the identified cable keeps its length
    from_length = sb.make_damper(0.7, [dict(ARM, name="left", cable=identified, length=0.1875),
                                       dict(ARM, name="right", cable=cut)])
    identified.save(str(tmp_path / "identified.toml"), "identified on 0.3 m")
    assert sb.load_cable(str(tmp_path / "identified.toml")).toml() == identified.toml()
    arm = '[[arm]]\nname = "{}"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n' \
          '[arm.cable]\nfile = "identified.toml"\nlength = 0.1875\n'
    (tmp_path / "damper.toml").write_text("[clamp]\nmass = 0.7\n" + arm.format("left") + arm.format("right"))
    from_file = sb.load_damper(str(tmp_path / "damper.toml"))
    frequencies = [8.0, 20.0, 40.0]
    expected = sb.impedance(sb.load_damper(EXAMPLE), frequencies, velocity=0.2)["re_z_n_s_m"]
    for damper in (from_length, from_file):
        assert np.array_equal(sb.impedance(damper, frequencies, velocity=0.2)["re_z_n_s_m"], expected)
    with pytest.raises(sb.InvalidParameter, match="length"):
        sb.make_damper(0.7, [dict(ARM, cable={"length": 0.3, "ei": 2.8}, length=0.2)])
    with pytest.raises(sb.InvalidParameter, match="length = -1"):
        identified.with_length(-1.0)


def test_values_outside_the_typical_ranges_warn_with_the_programs_words(tmp_path):
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the shipped files say nothing
        sb.load_damper(EXAMPLE)
        sb.load_cable(CABLE)
    # A unit slip is refused (UnusualValueError, an InputError) naming the key and the
    # likely unit; allow_unusual=True takes it as given with the program's warning.
    arm = dict(ARM, mass=856, cable={"length": 0.1875, "sections": 40, "ei": 2.8})
    with pytest.raises(sb.UnusualValueError, match=r"arm\[0\]\.mass = 856: outside the typical 0.05 to 20 kg of the arm "
                                                   r"mass \(in g\? 856 g = 0.856 kg\) \(allow_unusual=True takes it"):
        sb.make_damper(0.7, [arm])
    with pytest.warns(sb.UnusualValueWarning, match=r"arm\[0\]\.mass = 856: outside the typical 0.05 to 20 kg"):
        sb.make_damper(0.7, [arm], allow_unusual=True)
    text = open(EXAMPLE).read().replace("length = 0.1875", "length = 187.5", 1)
    (tmp_path / "mm.toml").write_text(text)
    with pytest.raises(sb.InputError, match=r"mm.toml:16: arm\[0\]\.cable\.length = 187.5"):
        sb.load_damper(str(tmp_path / "mm.toml"))
    with pytest.warns(sb.UnusualValueWarning) as record:
        sb.load_damper(str(tmp_path / "mm.toml"), allow_unusual=True)
    assert [str(w.message) for w in record] == [
        f"{tmp_path / 'mm.toml'}:16: arm[0].cable.length = 187.5: outside the typical 0.03 to 1 m of the damper cable "
        "length (in mm? 187.5 mm = 0.1875 m)"]


def test_unusual_sweep_and_response_values_warn_as_the_program_does():
    damper = sb.load_damper(EXAMPLE)
    with pytest.raises(sb.UnusualValueError, match=r"^velocity = 100: outside the typical 0.001 to 2 m/s .*in mm/s"):
        sb.impedance(damper, [20.0], velocity=100.0)
    with pytest.warns(sb.UnusualValueWarning, match=r"^velocity = 100: outside the typical 0.001 to 2 m/s"):
        sb.impedance(damper, [20.0], velocity=100.0, allow_unusual=True)
    with pytest.warns(sb.UnusualValueWarning, match=r"^frequency = 2000: outside the typical 0.5 to 500 Hz"):
        sb.response(damper, 2000.0, velocity=0.1)


def test_modes_equal_the_programs_json():
    out = subprocess.run([CLI, "modes", EXAMPLE, "--json"], check=True, capture_output=True, text=True).stdout
    modes = sb.modes(sb.load_damper(EXAMPLE))
    assert modes == json.loads(out)  # the same keys and, in shortest round-trip form, the same numbers
    # MODEL.md section 4: each arm 21.2 / 68.2 Hz sticking, 7.4 / 23.9 Hz slipping.
    assert [arm["name"] for arm in modes["arms"]] == ["left", "right"]
    for arm in modes["arms"]:
        assert arm["stick_hz"] == pytest.approx([21.2, 68.2], abs=0.05)
        assert arm["slip_hz"] == pytest.approx([7.4, 23.9], abs=0.05)
    # The whole damper, clamp free: 2 x 2 elastic modes (the rigid-body one left out);
    # the identical arms' antisymmetric modes keep the clamp still at the arm's frequencies.
    whole = modes["damper"]
    assert len(whole["stick_hz"]) == 4 and whole["stick_hz"] == sorted(whole["stick_hz"])
    assert whole["stick_hz"][0] == pytest.approx(modes["arms"][0]["stick_hz"][0], rel=1e-9)
    assert whole["slip_hz"][2] == pytest.approx(modes["arms"][0]["slip_hz"][1], rel=1e-9)
    assert whole["stick_modes"][0]["dominant_arm"] == "left"  # a tie between identical arms: the first
    for mode in whole["slip_modes"]:
        shares = mode["clamp_energy_share"] + sum(arm["energy_share"] for arm in mode["arms"])
        assert shares == pytest.approx(1.0, rel=1e-12)
    one_arm = sb.make_damper(0.0, [dict(name="a", mass=0.856, inertia=0.001814, offset=0.0325,
                                        cable=dict(length=0.1875, sections=8, ei=2.8, jenkin=[{"c": 20.0, "h": 0.7}]))])
    assert len(sb.modes(one_arm)["damper"]["slip_hz"]) == 1  # a massless clamp: one mode at infinity left out


SPAN = os.path.join(SOURCE, "examples", "aster570_400m.toml")


def test_span_equals_the_programs_csv_and_json(tmp_path):
    out = subprocess.run([CLI, "span", SPAN, "--points", "12", "--json", "-o", "span.csv"], cwd=tmp_path, check=True,
                         capture_output=True, text=True).stdout
    rows = read_csv(tmp_path / "span.csv")
    s = sb.span(SPAN, points=12)
    assert s["columns"] == list(rows[0].keys())
    assert s["dampers"] == ["sauter2003"]
    assert s["converged"].dtype == bool and s["converged"].all()
    for column in s["columns"]:
        values = [float(row[column]) if row[column] else float("nan") for row in rows]
        expected = np.array(values)
        got = s[column].astype(float)
        assert got.shape == (12,), column
        assert np.allclose(got, expected, rtol=1e-12, atol=0, equal_nan=True), column
    summary = json.loads(out)
    del summary["seconds"]  # the program's wall time
    assert s["summary"] == summary
    assert s["summary"]["max_stress_fymax_mpa"] < s["summary"]["undamped_max_stress_fymax_mpa"]


def test_span_returns_the_documented_keys_and_takes_the_cli_options(tmp_path):
    s = sb.span(SPAN, frequencies=[10.0, 20.0, 30.0, 40.0], no_dampers=True)
    assert set(s) == set(s["columns"]) | {"termination", "messages", "notes", "dampers", "columns", "summary",
                                          "profile", "governing_place"}
    documented = documented_keys("span", ["sauter2003"])
    assert {"converged", "several_states", "termination", "messages", "notes", "dampers", "columns", "summary"} <= documented
    # MODEL.md section 9's undamped check numbers.
    assert s["amplitude_m"] == pytest.approx([26.5e-3, 10.6e-3, 3.04e-3, 1.58e-3], rel=0.005)
    assert np.array_equal(s["amplitude_m"], s["undamped_amplitude_m"])
    assert s["summary"]["dampers"] == 0 and s["summary"]["position_m"] is None
    subprocess.run([CLI, "span", SPAN, "--frequencies", "12,25", "--damper-model", "weak", "--threads", "2", "-o",
                    "weak.csv"], cwd=tmp_path, check=True, capture_output=True)
    weak = sb.span(SPAN, frequencies=[12.0, 25.0], damper_model="weak", threads=2)
    rows = read_csv(tmp_path / "weak.csv")
    assert weak["stress_fymax_mpa"].tolist() == pytest.approx([float(r["stress_fymax_mpa"]) for r in rows], rel=1e-12)
    assert weak["summary"]["damper_model"] == "weak"


def test_span_from_text_and_its_errors(tmp_path):
    text = open(SPAN).read().replace('file = "sauter2003.toml"', f'file = "{os.path.join(SOURCE, "examples", "sauter2003.toml")}"')
    s = sb.span(text=text, frequencies=[15.0])
    assert s["converged"].tolist() == [True]
    with pytest.raises(sb.InputError, match=r"^span\(text=\.\.\.\): span\.length = -400"):
        sb.span(text=text.replace("length = 400", "length = -400"), frequencies=[15.0])
    with pytest.raises(sb.InputError, match="none.toml: no such file"):
        sb.span(os.path.join(tmp_path, "none.toml"))
    with pytest.raises(sb.InvalidParameter, match=r"frequencies\[1\] = 10"):
        sb.span(SPAN, frequencies=[20.0, 10.0])
    with pytest.raises(sb.InvalidParameter, match="either file"):
        sb.span()
    with pytest.raises(sb.InvalidParameter, match="optimize_position = 3:0.5"):
        sb.span(SPAN, optimize_position=(3.0, 0.5))


def test_span_overrides_without_editing_text(tmp_path):
    f = [10.0, 20.0]
    base = sb.span(SPAN, frequencies=f)
    # H/w for the same tension (T = H/w m g) gives the same balance.
    same = sb.span(SPAN, frequencies=f, catenary_parameter=27795.0 / (1.571 * 9.80665))
    assert same["stress_fymax_mpa"] == pytest.approx(base["stress_fymax_mpa"], rel=1e-9)
    assert same["summary"]["tension_n"] == pytest.approx(27795.0, rel=1e-12)
    # The file's tables as a dict, the damper file relative to `base`: the same again.
    import tomllib
    with open(SPAN, "rb") as handle:
        spec = tomllib.load(handle)
    assert sb.span(spec=spec, base=os.path.dirname(SPAN), frequencies=f)["stress_fymax_mpa"].tolist() == \
        pytest.approx(base["stress_fymax_mpa"].tolist(), rel=1e-12)
    # Positions: one damper per position, of the file's damper; the length and the
    # conductor by its type, as the span file would say them.
    two = sb.span(SPAN, frequencies=f, positions=[1.0, 2.0])
    assert two["summary"]["dampers"] == 2
    drake = sb.span(SPAN, frequencies=f, conductor_type="ACSR Drake", tension_fraction=0.2, length=300.0)
    assert drake["summary"]["tension_n"] == pytest.approx(0.2 * sb.conductor("ACSR Drake")["rated_tensile_strength_n"])
    # A measured sheet for the damper: the model's own Z at its velocities.
    subprocess.run([CLI, "impedance", os.path.join(SOURCE, "examples", "sauter2003.toml"), "--velocity",
                    "0.02,0.05,0.1,0.2,0.5", "--fmin", "5", "--fmax", "60", "--points", "40", "-o", "sheet.csv"],
                   cwd=tmp_path, check=True, capture_output=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sb.UnusualValueWarning)
        sheet = sb.span(SPAN, frequencies=f, damper=tmp_path / "sheet.csv")
    assert sheet["dampers"] == ["sheet"] and sheet["summary"]["sheet_error_estimate"] is not None
    # Relative paths of text start at `base`, and the message names it.
    with pytest.raises(sb.InputError, match=r"relative paths start at .*the text's base folder"):
        sb.span(text=open(SPAN).read(), base=str(tmp_path), frequencies=f)
    with pytest.raises(sb.InvalidParameter, match="one of tension, tension_fraction and catenary_parameter"):
        sb.span(SPAN, tension=3e4, catenary_parameter=1800.0)
    with pytest.raises(sb.InvalidParameter, match="give one of file"):
        sb.span(SPAN, spec=spec, length=300.0)


def test_span_masses_and_profile_are_the_programs(tmp_path):
    f = [12.0, 24.0]
    # Two 10 kg spheres, as the program reads them from a span file's [[mass]].
    text = open(SPAN).read().replace('file = "sauter2003.toml"',
                                     f'file = "{os.path.join(SOURCE, "examples", "sauter2003.toml")}"')
    spheres = text + '\n[[mass]]\nname = "sphere"\nmass = 10.0\npositions = [100, 250]\n'
    (tmp_path / "spheres.toml").write_text(spheres)
    out = subprocess.run([CLI, "span", "spheres.toml", "--frequencies", "12,24", "--json", "-o", "s.csv",
                          "--profile", "along.csv", "--report", "r.html"], cwd=tmp_path, check=True,
                         capture_output=True, text=True).stdout
    # The report draws the natural mode nearest the governing frequency: one span --modes lists.
    html = (tmp_path / "r.html").read_text()
    modes = json.loads(subprocess.run([CLI, "span", "spheres.toml", "--modes", "--json", "-o", "m.csv"], cwd=tmp_path,
                                      check=True, capture_output=True, text=True).stdout)
    shown = re.findall(r"mode (\d+), ([0-9.]+) Hz", html)
    assert len(shown) == 1 and "the natural mode nearest" in html
    for number, frequency in shown:
        assert float(frequency) == pytest.approx(modes["frequencies_hz"][int(number) - 1], rel=1e-3)
    s = sb.span(SPAN, frequencies=f, masses=[(10.0, [100.0, 250.0], "sphere")])
    rows = read_csv(tmp_path / "s.csv")
    assert s["columns"] == list(rows[0].keys())
    assert "sphere_at_100m_clamp_stress_mpa" in s["columns"]
    assert s["governing_stress_mpa"].tolist() == pytest.approx([float(r["governing_stress_mpa"]) for r in rows],
                                                               rel=1e-12)
    assert json.loads(out)["governing_place"] == s["summary"]["governing_place"]
    along = read_csv(tmp_path / "along.csv")
    profile = s["profile"]
    assert profile["x_m"].tolist() == pytest.approx([float(r["x_m"]) for r in along], rel=1e-12)
    assert [r["attachment"] for r in along if r["attachment"]] == [a for a in profile["attachment"] if a]
    assert "sphere (mass)" in list(profile["attachment"])
    assert profile["frequency_hz"] == s["summary"]["governing_frequency_hz"]
    # masses=[] is the span without them; no_attachments drops the masses too.
    bare = sb.span(SPAN, frequencies=f)
    assert sb.span(SPAN, frequencies=f, masses=[])["stress_fymax_mpa"].tolist() == \
        pytest.approx(bare["stress_fymax_mpa"].tolist(), rel=1e-12)
    dropped = sb.span(text=spheres, frequencies=f, no_attachments=True)
    assert dropped["stress_fymax_mpa"].tolist() == pytest.approx(bare["stress_fymax_mpa"].tolist(), rel=1e-12)
    with pytest.raises(sb.InvalidParameter, match=r"masses\[0\]"):
        sb.span(SPAN, frequencies=f, masses=[10.0])


def test_span_verdict_criterion_and_inputs_are_the_programs(tmp_path):
    """The example Drake span with the vendor's sheet for its damper (nothing solved):
    uncertain by the Safe Border Line (every stress within 8.73 MPa, the sheet's band
    reaching above it), unsafe by the IEEE's 150 microstrain; Python's summary, its
    criterion and its inputs included, is the program's JSON."""
    shutil.copy(os.path.join(SOURCE, "examples", "vendor_sheet.csv"), tmp_path / "vendor_sheet.csv")
    text = open(os.path.join(SOURCE, "examples", "drake_300m.toml")).read()
    text = text.replace('file = "sauter2003.toml"', 'impedance = "vendor_sheet.csv"')
    for criterion, verdict in (("safe-border-line", "uncertain"), ("microstrain", "unsafe")):
        (tmp_path / "span.toml").write_text(text.replace("cycles = 5e8", f'criterion = "{criterion}"'
                                                         if criterion == "microstrain" else "cycles = 5e8"))
        out = subprocess.run([CLI, "span", "span.toml", "--json", "--quiet", "-o", "span.csv"], cwd=tmp_path,
                             check=True, capture_output=True, text=True).stdout
        expected = json.loads(out)
        del expected["seconds"]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", sb.UnusualValueWarning)
            s = sb.span(tmp_path / "span.toml")
        assert s["summary"] == expected
        summary = s["summary"]
        assert summary["criterion"] == criterion and summary["verdict"] == verdict
        assert summary["inputs"]["fatigue"]["criterion"] == criterion
        assert summary["inputs"]["conductor"]["source"] == "the catalogue's ACSR Drake"
        assert summary["inputs"]["tension"]["fraction_of_rts"] == pytest.approx(0.2, rel=1e-12)
        if verdict == "uncertain":
            assert summary["max_judged_stress_mpa"] < summary["endurance_limit_mpa"] < summary["max_judged_stress_high_mpa"]
            assert summary["max_judged_stress_high_mpa"] == pytest.approx(np.nanmax(s["stress_fymax_high_mpa"]), rel=1e-12)
        else:
            assert summary["endurance_limit_mpa"] == pytest.approx(0.5e-6 * 150 * 68.9e3, rel=1e-12)
            assert summary["max_judged_stress_mpa"] == pytest.approx(np.nanmax(s["stress_ps_mpa"]), rel=1e-12)


def test_line_chooses_the_cheaper_type_and_leaves_a_span_to_tb273(tmp_path):
    """A line of two short spans and the vendor's sheet as two types (one lighter, one
    cheaper): under fewest-then-cheapest the cheaper, its price in the bill; under
    undamped_rule = "tb273" the span within its terrain's limit gets no damper."""
    sheet = os.path.join(SOURCE, "examples", "vendor_sheet.csv")
    text = f"""[line]
points = 20
search_points = 12
[conductor]
type = "AAAC ASTER570"
[wind]
law = "cigre"
[self_damping]
law = "noiseux-1991"
[fatigue]
cycles = 5e8
[dampers]
types = [ {{ name = "light-dear", impedance = "{sheet}", mass = 2.0, price = 60 }},
          {{ name = "heavy-cheap", impedance = "{sheet}", mass = 3.0, price = 40 }} ]
max_per_end = 1
position_max = 4.0
choose = "fewest-then-cheapest"
undamped_rule = "tb273"
[[span]]
id = "A"
length = 150
catenary_parameter = 1300
terrain = 4
[[span]]
id = "B"
length = 150
catenary_parameter = 1300
"""
    out = sb.line(text=text, base=tmp_path)
    s = out["schedule"]
    assert s["damper_type"] == ["", "heavy-cheap"]
    assert s["no_damper_basis"] == ["tb273", ""]
    assert s["verdict"] == ["safe", "safe"] and s["undamped_verdict"] == ["unsafe", "unsafe"]
    assert s["dampers_per_end"].tolist() == [0, 1]
    assert out["bill"]["damper_type"] == ["light-dear", "heavy-cheap"]
    assert out["bill"]["price"].tolist() == [0.0, 80.0]
    assert out["bill"]["mass_kg"].tolist() == [0.0, 6.0]
    summary = out["summary"]
    assert (summary["choose"], summary["undamped_rule"], summary["accept_uncertain"]) == \
        ("fewest-then-cheapest", "tb273", False)
    with pytest.raises(sb.InputError, match=r"dampers\.types\[1\]\.price: missing"):
        sb.line(text=text.replace(", price = 40", ""), base=tmp_path)


def test_span_position_search_takes_the_spacing_and_objective_as_the_program(tmp_path):
    """spacing_min and objective are --spacing-min and --objective: every damper's
    position searched (each its own), the same summary as the program's."""
    shutil.copy(os.path.join(SOURCE, "examples", "sauter2003.toml"), tmp_path / "sauter2003.toml")
    two = open(SPAN).read() + '\n[[damper]]\nfile = "sauter2003.toml"\nposition = 2.0\nends = "both"\n'
    (tmp_path / "two.toml").write_text(two)
    out = subprocess.run([CLI, "span", "two.toml", "--points", "12", "--optimize-position", "0.5:5",
                          "--spacing-min", "1.5", "--objective", "life", "--json", "-o", "s.csv"],
                         cwd=tmp_path, check=True, capture_output=True, text=True).stdout
    s = sb.span(tmp_path / "two.toml", points=12, optimize_position=(0.5, 5.0), spacing_min=1.5, objective="life")
    summary = json.loads(out)
    del summary["seconds"]  # the program's wall time
    assert s["summary"] == summary
    positions = s["summary"]["positions_m"]
    assert len(positions) == 2 and s["summary"]["position_optimized"] is True
    assert all(0.5 <= x <= 5.0 for x in positions) and abs(positions[1] - positions[0]) >= 1.5 - 1e-9
    with pytest.raises(sb.InvalidParameter, match='objective = "lifetime"'):
        sb.span(SPAN, points=12, optimize_position=(0.5, 5.0), objective="lifetime")
    with pytest.raises(sb.InvalidParameter, match="spacing_min = -1"):
        sb.span(SPAN, points=12, optimize_position=(0.5, 5.0), spacing_min=-1.0)


# A line of four spans (three conductors, the tension in each of its forms), cut to
# seconds: 30 frequencies per balance, 20 for the position search, at most 2 dampers
# per end within 5 m of the clamp (tests/cli/line_cli_test.cpp's small line).
SMALL_LINE = """[line]
name = "test line"
points = 30
search_points = 20

[conductor]
type = "AAAC ASTER570"

[wind]
law = "cigre"
speed_min = 1.0
speed_max = 7.0

[self_damping]
law = "noiseux-1991"

[fatigue]
cycles = 5e8
wind_weibull = { shape = 2.0, scale = 4.0 }
aeolian_fraction = 0.3

[dampers]
types = [ { name = "sb1", file = "sauter2003.toml" } ]
max_per_end = 2
position_max = 5.0

[[span]]
id = "T1-T2"
length = 300
tension_fraction = 0.12

[[span]]
id = "T2-T3"
length = 420
catenary_parameter = 1500
terrain = 2

[[span]]
id = "T3-T4"
length = 250
tension = 30000
conductor = "ACSR Drake"

[[span]]
id = "T4-T5"
length = 380
tension_fraction = 0.2
conductor = "ACSR Linnet"
"""
SMALL_LINE_IDS = ["T1-T2", "T2-T3", "T3-T4", "T4-T5"]


@pytest.fixture(scope="module")
def line_runs(tmp_path_factory):
    """The small line scheduled twice (about 8 s each): from its file on one thread,
    and from its text (the damper file relative to `base`) on two."""
    folder = tmp_path_factory.mktemp("line")
    shutil.copy(os.path.join(SOURCE, "examples", "sauter2003.toml"), folder / "sauter2003.toml")
    (folder / "line.toml").write_text(SMALL_LINE)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nothing unusual in the small line
        one = sb.line(folder / "line.toml")
    two = sb.line(text=SMALL_LINE, base=folder, threads=2, report=folder / "line.html")
    return one, two, folder / "line.html"


def test_span_and_line_write_the_report_the_program_writes(line_runs, tmp_path):
    """span(report=...) and line(report=...) write the command's HTML page: its title,
    the run's verdict and figures, nothing fetched from outside the page."""
    out = sb.span(SPAN, points=20, report=tmp_path / "span.html")
    assert "report_html" not in out
    html = (tmp_path / "span.html").read_text(encoding="utf-8")
    assert "<h1>Span energy balance: ASTER570, 400 m span</h1>" in html
    assert "<strong>%s</strong>" % out["summary"]["verdict"] in html
    assert "%.3g MPa at" % out["summary"]["max_stress_fymax_mpa"] in html
    assert html.count("<figure>") == 3 and "src=" not in html and "<script" not in html
    assert "report_html" not in sb.span(SPAN, points=5)  # made only when asked for
    _, two, line_html = line_runs
    page = line_html.read_text(encoding="utf-8")
    assert "<h1>Damper schedule: line " in page
    for span_id in SMALL_LINE_IDS:
        assert "<td>%s</td>" % span_id in page
    counts = two["summary"]
    assert "%d / %d / %d" % (counts["spans_safe"], counts["spans_unsafe"], counts["spans_unknown"]) in page


def test_line_returns_the_schedule_bill_and_summary(line_runs):
    out, _, _ = line_runs
    assert set(out) == {"schedule", "bill", "summary", "warnings"}
    assert set(out) <= documented_keys("line", ["-"])
    assert out["warnings"] == []
    s = out["schedule"]
    assert list(s)[:8] == ["id", "conductor", "undamped_verdict", "damper_type", "positions_m", "verdict",
                           "no_damper_basis", "warnings"]
    assert s["id"] == SMALL_LINE_IDS
    assert s["conductor"] == ["AAAC ASTER570", "AAAC ASTER570", "ACSR Drake", "ACSR Linnet"]
    assert s["dampers_per_end"].dtype == np.int64 and s["dampers_per_end"].shape == (4,)
    assert all(0 <= n <= 2 for n in s["dampers_per_end"])
    assert all(v in ("safe", "unsafe", "unknown", "uncertain") for v in s["verdict"] + s["undamped_verdict"])
    assert s["converged"].dtype == bool and s["max_stress_mpa"].dtype == np.float64
    assert s["length_m"].tolist() == [300.0, 420.0, 250.0, 380.0]
    assert s["tension_n"][2] == 30000.0 and s["catenary_parameter_m"][1] == 1500.0
    for n, text, kind, warning in zip(s["dampers_per_end"], s["positions_m"], s["damper_type"], s["warnings"]):
        assert isinstance(text, str) and isinstance(warning, str)
        positions = [float(x) for x in text.split(";")] if text else []  # one end's, ';'-separated
        assert len(positions) == n and positions == sorted(positions)
        assert all(0 < x <= 5.0 for x in positions)
        assert kind == ("sb1" if n > 0 else "")
    for verdict, ratio in zip(s["verdict"], s["stress_ratio"]):  # a safe span's stress is below the endurance limit
        assert ratio < 1 if verdict == "safe" else not ratio < 1
    assert np.allclose(s["stress_ratio"], s["max_stress_mpa"] / s["endurance_limit_mpa"], rtol=1e-12, equal_nan=True)
    assert out["bill"]["damper_type"] == (["sb1"] if s["dampers_per_end"].any() else [])


def test_line_on_two_threads_equals_one(line_runs):
    one, two, _ = line_runs
    for table in ("schedule", "bill"):
        assert list(one[table]) == list(two[table])
        for column, values in one[table].items():
            if isinstance(values, list):
                assert values == two[table][column], column
            else:
                assert values.dtype == two[table][column].dtype, column
                assert np.array_equal(values, two[table][column], equal_nan=values.dtype == np.float64), column
    assert one["summary"] == two["summary"]


def test_line_summary_counts_the_schedule(line_runs):
    out, _, _ = line_runs
    s, summary = out["schedule"], out["summary"]
    assert summary["line"] == "test line" and summary["spans"] == 4
    for verdict in ("safe", "unsafe", "unknown"):
        assert summary[f"spans_{verdict}"] == s["verdict"].count(verdict)
    assert summary["spans_safe"] + summary["spans_unsafe"] + summary["spans_unknown"] == 4
    assert summary["governing_span"] in SMALL_LINE_IDS
    assert summary["governing_stress_ratio"] == np.nanmax(s["stress_ratio"])
    counts = {entry["dampers_per_end"]: entry["spans"] for entry in summary["dampers_per_end"]}
    assert counts == {n: int((s["dampers_per_end"] == n).sum()) for n in set(s["dampers_per_end"].tolist())}
    bill = out["bill"]
    assert summary["bill"] == [{"damper_type": t, "dampers": int(d), "spans": int(n), "mass_kg": m, "price": None}
                               for t, d, n, m in zip(bill["damper_type"], bill["dampers"], bill["spans"], bill["mass_kg"])]
    assert np.isnan(bill["price"]).all()  # no type's price given
    assert sum(entry["dampers"] for entry in summary["bill"]) == 2 * s["dampers_per_end"].sum()  # both ends


def test_line_errors_are_those_of_a_span_file(tmp_path):
    """A bad line is refused before anything is computed, with the exception a bad span
    file gets and a message naming the key."""
    shutil.copy(os.path.join(SOURCE, "examples", "sauter2003.toml"), tmp_path / "sauter2003.toml")
    missing = SMALL_LINE.replace("tension = 30000\n", "")
    with pytest.raises(ValueError) as span_error:
        sb.span(text=open(SPAN).read().replace("tension_fraction = 0.15", ""), frequencies=[15.0])
    with pytest.raises(ValueError, match=r"^line\(text=\.\.\.\): missing key 'tension'") as line_error:
        sb.line(text=missing, base=tmp_path)
    assert type(line_error.value) is type(span_error.value) is sb.InputError
    assert "tension" in str(span_error.value)
    (tmp_path / "line.toml").write_text(SMALL_LINE.replace("length = 250", "length = -250"))
    with pytest.raises(sb.InputError, match=r"line.toml:\d+: .*length = -250"):
        sb.line(tmp_path / "line.toml")
    with pytest.raises(sb.InputError, match="none.toml: no such file"):
        sb.line(tmp_path / "none.toml")
    with pytest.raises(sb.InvalidParameter, match="either file"):
        sb.line()
    with pytest.raises(sb.InvalidParameter, match="either file"):
        sb.line(tmp_path / "line.toml", text=SMALL_LINE)
    with pytest.raises(sb.InvalidParameter, match="threads = 0"):
        sb.line(text=SMALL_LINE, threads=0)


DESIGN = os.path.join(SOURCE, "examples", "design_aster570.toml")


def tiny_design(folder, **settings):
    """examples/design_aster570.toml cut to seconds (8 frequencies per band, 3 samples, one
    short polish; `settings` change more of its top-level keys), written as design.toml
    next to copies of the damper and span files it reads. Returns its path."""
    for name in ("sauter2003.toml", "aster570_400m.toml"):
        shutil.copy(os.path.join(SOURCE, "examples", name), folder / name)
    text = open(DESIGN).read()
    for key, value in {"samples": 3, "polish": 1, "polish_evaluations": 4, **settings}.items():
        text, count = re.subn(rf"^{key} = \S+", f"{key} = {value}", text, flags=re.M)
        if count == 0:
            text = f"{key} = {value}\n" + text  # a top-level key: before the tables
    (folder / "design.toml").write_text("points = 8\n" + text)
    return folder / "design.toml"


@pytest.fixture(scope="module")
def design_run(tmp_path_factory):
    """The tiny study run by the program (CSV, --json, best.toml) and by design() on two threads."""
    folder = tmp_path_factory.mktemp("design")
    path = tiny_design(folder)
    out = subprocess.run([CLI, "design", "design.toml", "--json", "--quiet", "-o", "designs.csv", "--best", "best.toml"],
                         cwd=folder, check=True, capture_output=True, text=True).stdout
    return folder, json.loads(out), sb.design(path, threads=2)


def test_design_returns_the_documented_keys(design_run):
    folder, _, d = design_run
    assert d["variables"] == ["arm.left.mass", "arm.left.cable.length", "position"]
    assert d["columns"][:4] == ["stage", "governing_span", "governing_place", "run"]
    assert d["columns"][4:7] == d["variables"]
    assert set(d) == set(d["columns"]) | {"columns", "variables", "summary", "best_damper"}
    documented = {name.replace("<span>", "aster570_400m") for name in documented_keys("design", ["-"])}
    assert "<variable>" in documented
    assert set(d) == documented - {"<variable>"} | set(d["variables"])
    assert d["governing_span"].tolist() == ["aster570_400m" if ok else "" for ok in d["converged"]]
    assert all(place.startswith("span clamp") if ok else place == ""
               for place, ok in zip(d["governing_place"].tolist(), d["converged"]))
    assert d["aster570_400m_worse_than_undamped"].dtype == bool
    n = d["summary"]["evaluations"]
    assert n == len(d["stage"]) == 1 + 3 + len([s for s in d["stage"] if s == "polish"])
    assert d["stage"].tolist()[:4] == ["base", "sample", "sample", "sample"]
    assert d["run"].dtype == np.int64 and d["converged"].dtype == bool and d["feasible"].dtype == bool
    assert d["objective"].dtype == np.float64 and d["objective"].shape == (n,)


def test_design_equals_the_programs_csv_json_and_best_file(design_run):
    folder, summary, d = design_run
    rows = read_csv(folder / "designs.csv")
    assert d["columns"] == list(rows[0].keys())
    for column in ("stage", "governing_span", "governing_place"):
        assert d[column].tolist() == [row[column] for row in rows], column
    for column in d["columns"][3:]:
        expected = np.array([float(row[column]) if row[column] else np.nan for row in rows])
        assert np.array_equal(d[column].astype(float), expected, equal_nan=True), column  # exactly: threads change nothing
    del summary["seconds"]  # the program's wall time
    assert d["summary"] == dict(summary, threads=2)  # the program ran on one thread
    assert d["best_damper"] == (folder / "best.toml").read_text()


def test_design_summary_names_the_best_feasible_row(design_run):
    _, _, d = design_run
    feasible = np.flatnonzero(d["feasible"])
    assert len(feasible) > 0 and d["summary"]["best"] is not None
    best = feasible[np.argmin(d["objective"][feasible])]
    assert d["summary"]["best"]["objective"] == d["objective"][best]
    assert d["summary"]["best_stage"] == d["stage"][best]
    assert d["summary"]["best"]["variables"] == {name: d[name][best] for name in d["variables"]}
    assert d["summary"]["feasible"] == len(feasible) and d["summary"]["objective"] == "max_stress"
    assert d["summary"]["best"]["objective"] <= d["summary"]["base"]["objective"]
    assert np.array_equal(d["objective"][d["converged"]], d["max_stress_ratio"][d["converged"]])


def test_design_errors_and_warnings(tmp_path):
    with pytest.raises(sb.InputError, match="none.toml: no such file"):
        sb.design(tmp_path / "none.toml")
    path = tiny_design(tmp_path)
    with pytest.raises(sb.InvalidParameter, match="samples = 0"):
        sb.design(path, samples=0)
    with pytest.raises(sb.InvalidParameter, match="threads = 0"):
        sb.design(path, threads=0)
    text = path.read_text()
    (tmp_path / "misspelt.toml").write_text(text.replace('name = "position"', 'name = "positon"'))
    with pytest.raises(ValueError, match="positon"):
        sb.design(tmp_path / "misspelt.toml")
    (tmp_path / "bad.toml").write_text(text.replace("min = 0.5\nmax = 3.0", "min = 3.0\nmax = 0.5"))
    with pytest.raises(ValueError, match="min"):
        sb.design(tmp_path / "bad.toml")
    # A damper value outside the typical ranges: the reader's warning, located; the search still runs.
    damper = (tmp_path / "sauter2003.toml").read_text().replace("mass = 0.7 ", "mass = 0.01", 1)
    (tmp_path / "sauter2003.toml").write_text(damper)
    with pytest.warns(sb.UnusualValueWarning, match=r"sauter2003.toml:8: clamp.mass = 0.01: outside the typical"):
        d = sb.design(path, samples=1)
    assert d["stage"].tolist()[:2] == ["base", "sample"]


@pytest.fixture(scope="module")
def impedance_fit(tmp_path_factory):
    """The shipped example identified by the program (--json, --fitted, -o) and by identify_impedance()."""
    folder = tmp_path_factory.mktemp("identify-impedance")
    damper = os.path.join(SOURCE, "examples", "damper_to_identify.toml")
    measured = os.path.join(SOURCE, "examples", "measured_impedance.csv")
    out = subprocess.run([CLI, "identify", "impedance", "--damper", damper, "--input", measured, "--json",
                          "-o", "cable.toml", "--fitted", "z_fit.csv"],
                         cwd=folder, check=True, capture_output=True, text=True).stdout
    return folder, json.loads(out), sb.identify_impedance(sb.load_damper(damper), measured)


def test_identify_impedance_equals_the_program_and_returns_the_documented_keys(impedance_fit):
    folder, summary, fit = impedance_fit
    assert set(fit) == documented_keys("identify_impedance", ["-"])
    assert {key: fit[key] for key in summary} == summary  # exactly: the same fit
    rows = read_csv(folder / "z_fit.csv")
    assert list(fit["fitted"]) == list(rows[0].keys())
    for column, values in fit["fitted"].items():
        assert np.array_equal(values.astype(float), [float(row[column]) for row in rows]), column
    assert fit["cable_files"] == [(folder / "cable.toml").read_text()]
    assert abs(fit["cable"].ei / 2.8 - 1) < 0.01 and fit["cable"].length == 0.1875


def test_identify_impedance_fits_the_dampers_numbers_as_the_program(tmp_path):
    """free: the program's --free; the fitted damper and its file hold the numbers."""
    start = os.path.join(SOURCE, "examples", "damper_to_identify.toml")
    with open(start) as handle:
        text = handle.read().replace("mass = 0.856", "mass = 0.75", 1)  # the first arm's mass 12 % low
    (tmp_path / "start.toml").write_text(text)
    measured = os.path.join(SOURCE, "examples", "measured_impedance.csv")
    out = subprocess.run([CLI, "identify", "impedance", "--damper", "start.toml", "--input", measured, "--json",
                          "--free", "arm.left.mass", "--fitted-damper", "fitted.toml"],
                         cwd=tmp_path, check=True, capture_output=True, text=True).stdout
    summary = json.loads(out)
    fit = sb.identify_impedance(sb.load_damper(str(tmp_path / "start.toml")), measured, free="arm.left.mass")
    assert fit["geometry"] == summary["geometry"] and fit["parameters"] == summary["parameters"]
    assert abs(fit["geometry"]["arm.left.mass"] / 0.856 - 1) < 0.01 and fit["poor_fit"] is False
    assert [p["geometry"] for p in fit["parameters"]] == [False, False, False, True]
    assert fit["damper_file"] == (tmp_path / "fitted.toml").read_text()
    assert f"mass = {fit['geometry']['arm.left.mass']!r}" in fit["damper_file"]
    assert fit["damper"].arms == ["left", "right"]
    with pytest.raises(sb.InvalidParameter, match=r"free = arm.middle.mass: no arm is named 'middle'"):
        sb.identify_impedance(fit["damper"], measured, free=["arm.middle.mass"])
    with pytest.raises(sb.InvalidParameter, match="rms_limit = -1"):
        sb.identify_impedance(fit["damper"], measured, rms_limit=-1)


def test_identify_impedance_from_arrays_equals_the_file(impedance_fit):
    _, _, fit = impedance_fit
    f = fit["fitted"]
    again = sb.identify_impedance(sb.load_damper(os.path.join(SOURCE, "examples", "damper_to_identify.toml")),
                                  frequency=f["frequency_hz"], velocity=f["velocity_m_s"],
                                  z=f["re_z_n_s_m"] + 1j * f["im_z_n_s_m"])
    assert again["ei"] == fit["ei"] and again["jenkin"] == fit["jenkin"]
    with pytest.raises(sb.InvalidParameter, match="either input"):
        sb.identify_impedance(again["damper"], "x.csv", frequency=[10.0])
    with pytest.raises(sb.InvalidParameter, match="expected as many of each"):
        sb.identify_impedance(again["damper"], frequency=[10.0, 20.0], velocity=[0.1], z=[1j, 2j])
    with pytest.raises(sb.InvalidParameter, match=r"frequency\[0\] = -10"):
        sb.identify_impedance(again["damper"], frequency=[-10.0, 20.0], velocity=[0.1, 0.1], z=[1j, 2j])
    with pytest.raises(sb.InvalidParameter, match="elements = 0"):
        sb.identify_impedance(again["damper"], frequency=[10.0, 20.0], velocity=[0.1, 0.1], z=[1j, 2j], elements=0)


def test_identify_impedance_tests_the_lack_of_fit_against_the_stated_scatter_as_the_program(impedance_fit, tmp_path):
    """scatter: the program's --scatter; lack_of_fit the same; the default 1 %, assumed."""
    _, summary, fit = impedance_fit
    assert fit["lack_of_fit"]["scatter"] == 0.01 and fit["lack_of_fit"]["scatter_assumed"] is True
    assert fit["lack_of_fit"]["significant"] is False and fit["lack_of_fit"]["suspects"] == []
    damper = os.path.join(SOURCE, "examples", "damper_to_identify.toml")
    measured = os.path.join(SOURCE, "examples", "measured_impedance.csv")
    out = subprocess.run([CLI, "identify", "impedance", "--damper", damper, "--input", measured, "--json",
                          "--scatter", "0.02"], cwd=tmp_path, check=True, capture_output=True, text=True).stdout
    stated = sb.identify_impedance(sb.load_damper(damper), measured, scatter=0.02)
    assert stated["lack_of_fit"] == json.loads(out)["lack_of_fit"]
    lack = stated["lack_of_fit"]
    assert lack["scatter"] == 0.02 and lack["scatter_assumed"] is False and lack["significant"] is False
    assert lack["ratio"] == pytest.approx(stated["rms_relative_error"] / 0.02, rel=1e-12)
    assert lack["statistic"] == pytest.approx(2 * stated["points"] * lack["ratio"] ** 2, rel=1e-12)
    assert lack["degrees_of_freedom"] == 2 * stated["points"] - 3
    # At 2 % stated the standard errors are the stated scatter's, twice the residuals' own 1 %.
    assert lack["error_inflation"] == 1.0
    for p, q in zip(stated["parameters"], summary["parameters"]):
        assert p["standard_error"] > 1.5 * q["standard_error"], p["name"]
        assert p["confounded_by"] is None
    with pytest.raises(sb.InvalidParameter, match="scatter = 2: expected a fraction"):
        sb.identify_impedance(stated["damper"], measured, scatter=2)


def test_identify_impedance_of_a_bouc_wen_damper_gives_its_numbers_back():
    """A start of law "bouc-wen" fits ei_min, ei_max and chi0 (the summary names the
    law); the fitted cable is a Bouc-Wen Cable."""
    def damper(ei_min, ei_max, chi0):
        cable = sb.make_cable(0.1875, sections=12, law="bouc-wen", ei_min=ei_min, ei_max=ei_max, chi0=chi0)
        arm = dict(name="left", mass=0.856, inertia=0.001814, offset=0.0325, cable=cable)
        return sb.make_damper(0.7, [arm, dict(arm, name="right")])
    frequencies = [4.0, 7.0, 10.0, 15.0, 25.0, 40.0]
    z = sb.impedance(damper(2.5, 25.0, 0.03), frequencies=frequencies, velocity=0.2)
    fit = sb.identify_impedance(damper(2.0, 30.0, 0.04), frequency=frequencies, velocity=[0.2] * len(frequencies),
                                z=z["re_z_n_s_m"][0] + 1j * z["im_z_n_s_m"][0])
    assert set(fit) == documented_keys("identify_impedance", ["-"]) - {"ei", "jenkin"} | {"law", "ei_min", "ei_max", "chi0"}
    assert fit["law"] == "bouc-wen" and fit["stick_stiffness"] == []
    for key, truth in (("ei_min", 2.5), ("ei_max", 25.0), ("chi0", 0.03)):
        assert fit[key] == pytest.approx(truth, rel=1e-5), key
    assert [p["name"] for p in fit["parameters"]] == ["ei_min", "ei_max", "chi0"]
    assert fit["cable"].law == "bouc-wen" and fit["cable"].chi0 == fit["chi0"]
    assert 'law = "bouc-wen"' in fit["cable_files"][0]
    with pytest.raises(sb.InvalidParameter, match="elements = 2: Jenkin elements belong to the Masing law"):
        sb.identify_impedance(fit["damper"], frequency=frequencies, velocity=[0.2] * len(frequencies),
                              z=z["re_z_n_s_m"][0] + 1j * z["im_z_n_s_m"][0], elements=2)


def test_the_conductor_catalogue_equals_the_programs_json(tmp_path):
    out = subprocess.run([CLI, "conductors", "ACSR Drake", "--json"], check=True, capture_output=True, text=True).stdout
    drake = sb.conductor("acsr-drake")  # case, spaces and hyphens aside
    assert drake == json.loads(out)
    assert drake["type"] == "ACSR Drake"
    assert drake["ei_min_n_m2"] == pytest.approx(44.25, abs=0.005)  # MODEL.md section 11
    assert drake["aluminium_layers"] == 2
    listed = json.loads(subprocess.run([CLI, "conductors", "--json"], check=True, capture_output=True, text=True).stdout)
    assert sb.conductors() == listed["conductors"]
    # A conductor file (the catalogue's own format) and a span's type = ... from text.
    shutil.copy(os.path.join(SOURCE, "data", "conductors", "acsr_drake.toml"), tmp_path / "drake.toml")
    assert sb.load_conductor(str(tmp_path / "drake.toml")) == drake
    with pytest.raises(sb.InvalidParameter, match=r'type = "ACSR Drak": expected a conductor of the catalogue: '):
        sb.conductor("ACSR Drak")


def test_a_bouc_wen_cable_from_python_is_the_cable_files_law(tmp_path):
    """make_cable(law="bouc-wen") reads as a cable file's table does: the Cable
    names its law and numbers, a damper of it gives the program's impedance of the
    same damper as a file to round-off, and a key of the other law is refused by name."""
    cable = sb.make_cable(0.1875, law="bouc-wen", ei_min=2.5, ei_max=25.0, chi0=0.03)
    assert (cable.law, cable.ei, cable.ei_min, cable.ei_max, cable.chi0) == ("bouc-wen", None, 2.5, 25.0, 0.03)
    masing = sb.make_cable(0.1875, ei=2.8, jenkin=[(20.0, 0.7)])
    assert (masing.law, masing.ei, masing.ei_min) == ("masing", 2.8, None)
    arm = dict(name="left", mass=0.856, inertia=0.001814, offset=0.0325, cable=cable)
    damper = sb.make_damper(0.7, [arm, dict(arm, name="right")])
    z = sb.impedance(damper, frequencies=[15.0, 40.0], velocity=0.2)
    assert z["converged"].all()
    assert (z["re_z_n_s_m"] > 0).all()
    arm_text = "mass = 0.856\ninertia = 0.001814\noffset = 0.0325\n[arm.cable]\n" + cable.toml()
    (tmp_path / "damper.toml").write_text("[clamp]\nmass = 0.7\n[[arm]]\nname = \"left\"\n" + arm_text +
                                          "[[arm]]\nname = \"right\"\n" + arm_text)
    subprocess.run([CLI, "impedance", "damper.toml", "--velocity", "0.2", "--frequencies", "15,40", "-o", "z.csv"],
                   cwd=tmp_path, check=True, capture_output=True)
    with open(tmp_path / "z.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    for i, row in enumerate(rows):
        assert z["re_z_n_s_m"][0, i] == pytest.approx(float(row["re_z_n_s_m"]), rel=1e-12)
        assert z["im_z_n_s_m"][0, i] == pytest.approx(float(row["im_z_n_s_m"]), rel=1e-12)
    with pytest.raises(sb.InvalidParameter, match=r"cable\.ei: is a number of the Masing and Iwan laws"):
        sb.make_cable(0.1875, law="bouc-wen", ei=2.5, ei_min=2.5, ei_max=25.0, chi0=0.03)
    with pytest.raises(sb.InvalidParameter, match=r"cable\.chi0: is a number of the Bouc-Wen law"):
        sb.make_cable(0.1875, ei=2.8, jenkin=[(20.0, 0.7)], chi0=0.03)
    with pytest.raises(sb.InvalidParameter, match=r"cable\.ei_max = 2 at s = 0 m: below ei_min"):
        sb.make_cable(0.1875, law="bouc-wen", ei_min=2.5, ei_max=2.0, chi0=0.03)


def test_identify_local_fits_the_bouc_wen_law_of_its_own_loop():
    loop = sb.loop(law="bouc-wen", ei_min=2.5, ei_max=25.0, chi0=0.03, amplitude=0.1, cycles=3)
    fit = sb.identify_local(loop["curvature_per_m"], loop["moment_n_m"], law="bouc-wen")
    assert fit["law"] == "bouc-wen"
    assert fit["ei_min"] == pytest.approx(2.5, rel=1e-6)
    assert fit["ei_max"] == pytest.approx(25.0, rel=1e-6)
    assert fit["chi0"] == pytest.approx(0.03, rel=1e-6)
    with pytest.raises(sb.InvalidParameter, match="elements = 2: Jenkin elements belong to the Masing law"):
        sb.identify_local(loop["curvature_per_m"], loop["moment_n_m"], law="bouc-wen", elements=2)


def test_identify_global_takes_the_bouc_wen_law_with_the_fit_only():
    with pytest.raises(sb.InvalidParameter, match="the four steps identify the Masing law"):
        sb.identify_global("a", 0.3, [0.0, 0.01, -0.01, 0.01], [0.0, 1.0, -1.0, 1.0], method="four-step", law="bouc-wen")
