"""identify_self_damping: the fit on the shipped example equals an independent least
squares on the logs (numpy.linalg.lstsq), arrays give the file's fit, the table it
returns is the law a span takes, the command's JSON is the same, and bad input is
named."""

import json
import os
import subprocess

import numpy as np
import pytest

import stockbridge as sb

CLI = os.environ["STOCKBRIDGE_CLI"]
SOURCE = os.environ["STOCKBRIDGE_SOURCE_DIR"]
TESTS = os.path.join(SOURCE, "examples", "self_damping_tests.csv")


def _columns():
    data = np.genfromtxt(TESTS, delimiter=",", names=True)
    return data["tension_n"], data["frequency_hz"], data["amplitude_m"], data["power_w_per_m"]


def _lstsq(tension, frequency, amplitude, power):
    x = np.column_stack([np.ones(len(power)), np.log(amplitude), np.log(frequency), -np.log(tension / 1000.0)])
    y = np.log(power)
    beta = np.linalg.lstsq(x, y, rcond=None)[0]
    residual = y - x @ beta
    s2 = residual @ residual / (len(y) - x.shape[1])
    se = np.sqrt(np.diag(s2 * np.linalg.inv(x.T @ x)))
    return beta, se, residual


def test_the_fit_is_least_squares_on_the_logs():
    tension, frequency, amplitude, power = _columns()
    beta, se, residual = _lstsq(tension, frequency, amplitude, power)
    fit = sb.identify_self_damping(TESTS)
    for name, j in (("l", 1), ("m", 2), ("n", 3)):
        assert abs(fit[name]["value"] - beta[j]) < 2e-4, name
        assert fit[name]["standard_error"] == pytest.approx(se[j], rel=1e-6), name
    assert fit["ln_k"]["value"] == pytest.approx(beta[0], abs=1e-8)
    assert fit["k"]["value"] == pytest.approx(np.exp(beta[0]), rel=1e-8)
    assert fit["k"]["standard_error"] == pytest.approx(np.exp(beta[0]) * se[0], rel=1e-6)
    assert fit["residual_rms_ln_p"] == pytest.approx(np.sqrt(np.mean(residual**2)), rel=1e-8)
    y = np.log(power)
    assert fit["r_squared"] == pytest.approx(1.0 - residual @ residual / np.sum((y - y.mean()) ** 2), rel=1e-10)
    assert fit["points"] == len(power) and not fit["n_given"] and fit["notes"] == []
    assert fit["tensions_n"] == sorted(set(tension.tolist()))


def test_arrays_give_the_files_fit_and_the_table_is_the_span_law():
    tension, frequency, amplitude, power = _columns()
    from_file = sb.identify_self_damping(TESTS)
    from_arrays = sb.identify_self_damping(tension=tension, frequency=frequency, amplitude=amplitude, power=power)
    for name in ("k", "l", "m", "n"):
        assert from_arrays[name]["value"] == pytest.approx(from_file[name]["value"], rel=1e-12)
    values = {}
    for line in from_file["table"].splitlines():
        if "=" in line and not line.startswith("#"):
            key, value = (part.strip() for part in line.split("=", 1))
            values[key] = value
    assert values["law"] == '"power"'
    k, l, m, n = (float(values[key]) for key in ("k", "l", "m", "n"))
    assert (k, l, m, n) == tuple(from_file[key]["value"] for key in ("k", "l", "m", "n"))
    # The span law at the measured points gives the fit's P: the residuals' RMS again.
    fitted = k * amplitude**l * frequency**m / (tension / 1000.0) ** n
    assert np.sqrt(np.mean(np.log(power / fitted) ** 2)) == pytest.approx(from_file["residual_rms_ln_p"], rel=1e-9)


def test_the_commands_json_is_the_same(tmp_path):
    run = subprocess.run([CLI, "identify", "self-damping", TESTS, "--json"], cwd=tmp_path, capture_output=True,
                         text=True, check=True)
    command = json.loads(run.stdout)
    fit = sb.identify_self_damping(TESTS)
    fit.pop("table")
    assert command == fit


def test_one_tension_needs_n_and_slips_are_refused():
    tension, frequency, amplitude, power = _columns()
    one = tension == tension[0]
    args = dict(tension=tension[one], frequency=frequency[one], amplitude=amplitude[one], power=power[one])
    with pytest.raises(sb.InvalidParameter, match=r"^n: not determined"):
        sb.identify_self_damping(**args)
    fit = sb.identify_self_damping(**args, n=2.76)
    assert fit["n_given"] and fit["n"]["standard_error"] is None
    assert "n is not determined" in fit["notes"][0]
    with pytest.raises(sb.UnusualValueError, match=r"amplitude\[0\] = 2\.5: .*in mm\?"):
        sb.identify_self_damping(tension=tension, frequency=frequency, amplitude=amplitude * 1000.0, power=power)
    with pytest.warns(sb.UnusualValueWarning, match=r"amplitude\[0\]"):
        sb.identify_self_damping(tension=tension, frequency=frequency, amplitude=amplitude * 1000.0, power=power,
                                 allow_unusual=True)
    with pytest.raises(sb.InvalidParameter, match="either file"):
        sb.identify_self_damping(TESTS, tension=tension)
