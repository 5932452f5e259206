"""stockbridge.fatigue_tests: the censored Basquin fit on dohl's Drake tests equals an
independent maximum-likelihood fit (scipy) within 1 % in a and b; the program's JSON
and CSV are the function's; the S-N plot is drawn from the CSV and the summary."""

import csv
import json
import os
import subprocess

import numpy as np
import pytest
from scipy import optimize, stats

import stockbridge as sb
import stockbridge.plot

CLI = os.environ["STOCKBRIDGE_CLI"]
SOURCE = os.environ["STOCKBRIDGE_SOURCE_DIR"]
TESTS = os.path.join(SOURCE, "examples", "fatigue_tests.csv")


def censored_fit(stress_mpa, cycles, failed):
    """Basquin's log10 N = a + b log10 sigma + N(0, s^2), runouts right-censored: scipy's
    minimiser on the negative log-likelihood, from least squares on the failures."""
    x, y, f = np.log10(stress_mpa), np.log10(cycles), np.asarray(failed, dtype=bool)
    b0, a0 = np.polyfit(x[f], y[f], 1)
    s0 = np.std(y[f] - a0 - b0 * x[f])

    def negative(theta):
        a, b, log_s = theta
        s = np.exp(log_s)
        z = (y - a - b * x) / s
        return -(np.sum(stats.norm.logpdf(z[f]) - np.log(s)) + np.sum(stats.norm.logsf(z[~f])))

    best = optimize.minimize(negative, [a0, b0, np.log(s0)], method="Nelder-Mead",
                             options={"xatol": 1e-10, "fatol": 1e-12, "maxiter": 20000, "maxfev": 40000})
    best = optimize.minimize(negative, best.x, method="BFGS", options={"gtol": 1e-9})
    a, b, log_s = best.x
    return a, b, np.exp(log_s), -best.fun


def test_the_drake_fit_equals_an_independent_maximum_likelihood_fit():
    result = sb.fatigue_tests(TESTS, conductor="ACSR Drake")
    table, fit = result["table"], result["fit"]
    assert (fit["failures"], fit["runouts"]) == (12, 13)
    assert set(table["conductor"]) == {"ACSR Drake"}
    a, b, s, log_likelihood = censored_fit(table["stress_ps_mpa"], table["cycles"], table["failed"])
    assert fit["a"] == pytest.approx(a, rel=0.01)
    assert fit["b"] == pytest.approx(b, rel=0.01)
    assert fit["scatter"] == pytest.approx(s, rel=0.01)
    # the program's maximum is no lower than scipy's
    assert fit["log_likelihood"] >= log_likelihood - 1e-6
    assert fit["design_a"] == pytest.approx(fit["a"] - 2 * fit["scatter"], rel=1e-12)


def test_below_the_safe_border_line_is_the_failures_before_its_cycles():
    result = sb.fatigue_tests(TESTS)
    table = result["table"]
    below = table["failed"] & (table["cycles"] < table["sbl_cycles"])
    assert np.array_equal(table["below_sbl"], below)
    assert result["fit"]["below_sbl"]["count"] == int(below.sum())
    assert result["fit"]["below_sbl"]["tests"] == [t for t, b in zip(table["test"], below) if b]
    # the Safe Border Line's cycles: several layers, 450 N^-0.2 above the knee's 16.39 MPa, 263 N^-0.17 below 15.74
    sigma = table["stress_ps_mpa"]
    high, low = sigma > 16.4, sigma < 15.7
    assert np.allclose(table["sbl_cycles"][high], (sigma[high] / 450) ** (-1 / 0.2), rtol=1e-12)
    assert np.allclose(table["sbl_cycles"][low], (sigma[low] / 263) ** (-1 / 0.17), rtol=1e-12)


def test_the_function_is_the_command(tmp_path):
    run = subprocess.run([CLI, "fatigue-tests", TESTS, "--json", "--curve", "curve.toml", "-o", "out.csv"],
                         cwd=tmp_path, check=True, capture_output=True, text=True)
    summary = json.loads(run.stdout)
    result = sb.fatigue_tests(TESTS, curve=tmp_path / "py_curve.toml")
    assert summary["fit"] == result["fit"]
    assert (tmp_path / "curve.toml").read_text() == (tmp_path / "py_curve.toml").read_text()
    with open(tmp_path / "out.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert [r["test"] for r in rows] == list(result["table"]["test"])
    assert np.allclose([float(r["stress_ps_mpa"]) for r in rows], result["table"]["stress_ps_mpa"], rtol=1e-12)


def test_too_few_failures_and_unit_slips_are_refused(tmp_path):
    header = "test,conductor,tension_n,yb_pp_mm,cycles,failed\n"
    slip = tmp_path / "slip.csv"
    slip.write_text(header + "a,ACSR Drake,35,0.8,3e6,true\nb,ACSR Drake,35,0.6,3e7,true\n"
                    "c,ACSR Drake,35,0.7,1e7,true\nd,ACSR Drake,35,0.5,1e8,false\n")
    with pytest.raises(sb.UnusualValueError, match=r"slip\.csv:2: column tension_n = 35: .*in kN\?"):
        sb.fatigue_tests(slip)
    with pytest.warns(sb.UnusualValueWarning, match=r"slip\.csv:2: column tension_n = 35"):
        assert sb.fatigue_tests(slip, allow_unusual=True)["fit"]["failures"] == 3
    few = tmp_path / "few.csv"
    few.write_text(header + "a,ACSR Drake,35000,0.8,3e6,true\nb,ACSR Drake,35000,0.6,3e7,true\n")
    with pytest.raises(sb.InputError, match=r"few\.csv: failed: 2 failure\(s\) at 2 stress\(es\): the fit needs 3"):
        sb.fatigue_tests(few)


def test_the_plot_from_the_csv_and_from_the_result(tmp_path):
    subprocess.run([CLI, "fatigue-tests", TESTS, "--json", "-o", "out.csv"], cwd=tmp_path, check=True,
                   stdout=open(tmp_path / "s.json", "w"))
    assert stockbridge.plot.main(["fatigue-tests", str(tmp_path / "out.csv"), "--summary", str(tmp_path / "s.json"),
                                  "-o", str(tmp_path / "sn.png")]) == 0
    assert (tmp_path / "sn.png").stat().st_size > 10000
    figure = stockbridge.plot.fatigue_tests(sb.fatigue_tests(TESTS, conductor="Drake"), tmp_path / "drake.png")
    labels = [line.get_label() for line in figure.axes[0].get_lines()]
    assert any(label.startswith("Basquin fit") for label in labels)
    assert "the CIGRE Safe Border Line (several aluminium layers)" in labels
