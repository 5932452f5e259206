"""Makes examples/measured_impedance.csv: a measured-like impedance curve of
D. Sauter's verification damper (examples/sauter2003.toml, cable ei 2.8 N m^2,
c 20 N m^2, h 0.7 N m), as a shaker test would give it: 16 frequencies over
5-80 Hz at clamp velocity amplitudes 0.05 and 0.2 m/s, with 1 % complex Gaussian
scatter on Z (fixed seed). `stockbridge identify impedance` on it should recover
the cable within about 1 % (docs/identification.md).

    PYTHONPATH=build/python /usr/bin/python3 examples/make_measured_impedance.py
"""
import os

import numpy

import stockbridge as sb

here = os.path.dirname(os.path.abspath(__file__))
damper = sb.load_damper(os.path.join(here, "sauter2003.toml"))
frequencies = numpy.geomspace(5.0, 80.0, 16)
z = sb.impedance(damper, frequencies, velocity=[0.05, 0.2])
assert z["converged"].all()
random = numpy.random.default_rng(2003)
with open(os.path.join(here, "measured_impedance.csv"), "w", encoding="utf-8") as out:
    out.write("frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n")
    for a, velocity in enumerate([0.05, 0.2]):
        for k, f in enumerate(frequencies):
            value = complex(z["re_z_n_s_m"][a, k], z["im_z_n_s_m"][a, k])
            value += abs(value) * 0.01 / numpy.sqrt(2.0) * complex(*random.standard_normal(2))
            out.write(f"{f:.4f},{velocity},{value.real:.5g},{value.imag:.5g}\n")
