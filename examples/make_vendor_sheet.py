"""Makes examples/vendor_sheet.csv (and vendor_sheet_one_velocity.csv, below): a
synthetic vendor's damper sheet (IEC 61897's characteristic test, MODEL.md 11) of the asymmetric damper
(examples/asymmetric_damper.toml: arms "long" 1.4 kg on 0.22 m and "short" 0.7 kg
on 0.14 m, cable ei 2.8 N m^2, c 20 N m^2, h 0.7 N m): |Z| and phase over 5-60 Hz
(16 frequencies) at the clamp velocity amplitudes 0.05, 0.1 and 0.2 m/s, with 1 %
complex Gaussian scatter on Z (fixed seed), as a vendor prints it.
examples/vendor_damper_start.toml is the damper as the buyer knows it: arm masses
and cable lengths 15-20 % off, the cable guessed; `stockbridge identify impedance
--free arm.long.mass,arm.short.mass,arm.long.cable.length,arm.short.cable.length`
recovers them (docs/identification.md).

    PYTHONPATH=build/python /usr/bin/python3 examples/make_vendor_sheet.py
"""
import cmath
import math
import os

import numpy

import stockbridge as sb

here = os.path.dirname(os.path.abspath(__file__))
damper = sb.load_damper(os.path.join(here, "asymmetric_damper.toml"))
velocities = [0.05, 0.1, 0.2]
frequencies = numpy.geomspace(5.0, 60.0, 16)
z = sb.impedance(damper, frequencies, velocity=velocities)
assert z["converged"].all()
random = numpy.random.default_rng(61897)
with open(os.path.join(here, "vendor_sheet.csv"), "w", encoding="utf-8") as out:
    out.write("frequency_hz,velocity_m_s,abs_z_n_s_m,phase_deg\n")
    for a, velocity in enumerate(velocities):
        for k, f in enumerate(frequencies):
            value = complex(z["re_z_n_s_m"][a, k], z["im_z_n_s_m"][a, k])
            value += abs(value) * 0.01 / math.sqrt(2.0) * complex(*random.standard_normal(2))
            out.write(f"{f:.4f},{velocity},{abs(value):.5g},{math.degrees(cmath.phase(value)):.4f}\n")

# examples/vendor_sheet_one_velocity.csv: the same damper's characteristic test at a
# single constant velocity, 0.1 m/s, as IEC 61897's test often is (24 frequencies,
# 1 % scatter, its own seed): a sheet no interpolation in amplitude can use, which a
# span file balances through the damper's model fitted to it (fit_from, docs/span.md).
one_velocity = numpy.geomspace(5.0, 60.0, 24)
z1 = sb.impedance(damper, one_velocity, velocity=[0.1])
assert z1["converged"].all()
random = numpy.random.default_rng(618971)
with open(os.path.join(here, "vendor_sheet_one_velocity.csv"), "w", encoding="utf-8") as out:
    out.write("frequency_hz,velocity_m_s,abs_z_n_s_m,phase_deg\n")
    for k, f in enumerate(one_velocity):
        value = complex(z1["re_z_n_s_m"][0, k], z1["im_z_n_s_m"][0, k])
        value += abs(value) * 0.01 / math.sqrt(2.0) * complex(*random.standard_normal(2))
        out.write(f"{f:.4f},0.1,{abs(value):.5g},{math.degrees(cmath.phase(value)):.4f}\n")
