"""stockbridge.recorder: the same bins and summary as `stockbridge recorder`, the
damage equal to a Miner sum over the returned columns, refusals as exceptions, and
plot.recorder's figure."""

import math

import numpy as np
import pytest

import stockbridge as sb
import stockbridge.plot as sbplot

SPAN = ("[conductor]\nname = \"ASTER570\"\nmass_per_length = 1.571\ndiameter = 0.03105\n"
        "rated_tensile_strength = 185300\nei_min = 28.28\nouter_wire_diameter = 0.00345\nouter_wire_modulus = 68e9\n"
        "aluminium_layers = 4\n[span]\nlength = 400\ntension_fraction = 0.15\n[wind]\nlaw = \"foti\"\n"
        "turbulence_intensity = 0.15\n[self_damping]\nlaw = \"noiseux-1991\"\n[fatigue]\ncycles = 5e8\n"
        "wind_weibull = { shape = 2.0, scale = 4.0 }\naeolian_fraction = 0.3\n")
COUNTS = ("yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n"
          "0.2,0.3,8,12,20000\n0.3,0.45,8,12,50000\n0.1,0.15,12,18,30000\n0.15,0.25,12,18,60000\n"
          "0.05,0.1,18,27,80000\n")


@pytest.fixture
def files(tmp_path):
    (tmp_path / "span.toml").write_text(SPAN)
    (tmp_path / "counts.csv").write_text(COUNTS)
    return tmp_path / "span.toml", tmp_path / "counts.csv"


def test_damage_is_the_miner_sum_of_the_columns(files):
    r = sb.recorder(*files, days=30)
    assert r["columns"][:5] == ["yb_pp_mm_low", "yb_pp_mm_high", "frequency_hz_low", "frequency_hz_high", "cycles"]
    np.testing.assert_allclose(r["damage"], r["cycles"] / r["cycles_to_failure"], rtol=1e-12)
    assert math.isclose(r["measured"]["damage"], float(np.sum(r["damage"])), rel_tol=1e-12)
    assert math.isclose(r["measured"]["damage_per_year"], r["measured"]["damage"] * 365.25 / 30, rel_tol=1e-12)
    assert r["calibrated"] is None
    assert len(r["predicted"]["bands"]) == 3


def test_calibration_lowers_the_residual(files):
    r = sb.recorder(*files, days=30, calibrate="wind.turbulence_intensity")
    c = r["calibrated"]
    assert c["residual_after"] < c["residual_before"]
    assert c["wind.turbulence_intensity"]["start"] == 0.15


def test_refusals_are_exceptions(files, tmp_path):
    with pytest.raises(sb.InvalidParameter):
        sb.recorder(*files, days=0)
    bad = tmp_path / "bad.csv"
    bad.write_text(COUNTS + "0.4,0.3,8,12,5\n")
    with pytest.raises(sb.InputError, match="bad.csv:7"):
        sb.recorder(files[0], bad, days=30)


def test_plot_recorder(files, tmp_path):
    r = sb.recorder(*files, days=30)
    out = tmp_path / "r.png"
    sbplot.recorder(r, out)
    assert out.stat().st_size > 1000
