"""Makes examples/self_damping_tests.csv: synthetic self-damping tests of ACSR Drake
(IEEE 563 / IEC 62567, the power method on a laboratory span), for
`stockbridge identify self-damping` (docs/measurements.md).

No published test points were at hand (RTE's dohl ships the laws' exponents,
damping_power_data.yaml, not the points), so the points follow a published law:
Noiseux (1991), P = k Y^2.44 f^5.63 / (T/1000)^2.76 W/m, with Lilien's
k = D[mm] / sqrt(m[kg/m] RTS[kN]) for Drake (28.14 mm, 1.628 kg/m, 138.8 kN:
k = 1.872), as the program's span files use it. The design: 3 tensions (15, 20 and
25 % RTS), 5 frequencies (10 to 50 Hz) and 3 amplitudes at each, at f Y = 25, 50
and 100 mm Hz (antinode velocity amplitudes 0.16 to 0.63 m/s, as a test holds
them), 45 points; each P times a lognormal scatter of 10 % (sigma 0.1 in ln P,
fixed seed), as a laboratory's repeatability.

    /usr/bin/python3 examples/make_self_damping_tests.py
"""
import math
import os

import numpy

here = os.path.dirname(os.path.abspath(__file__))
diameter_mm, mass, rts_kn = 28.14, 1.628, 138.8
k = diameter_mm / math.sqrt(mass * rts_kn)
l, m, n = 2.44, 5.63, 2.76
tensions = [round(fraction * rts_kn * 1000.0) for fraction in (0.15, 0.20, 0.25)]
frequencies = [10.0, 20.0, 30.0, 40.0, 50.0]
velocity_products = [0.025, 0.05, 0.1]  # f Y, m Hz
sigma = 0.1
random = numpy.random.default_rng(62567)
with open(os.path.join(here, "self_damping_tests.csv"), "w", encoding="utf-8") as out:
    out.write("tension_n,frequency_hz,amplitude_m,power_w_per_m\n")
    for tension in tensions:
        for f in frequencies:
            for product in velocity_products:
                amplitude = product / f
                power = k * amplitude**l * f**m / (tension / 1000.0) ** n
                power *= math.exp(sigma * random.standard_normal())
                out.write(f"{tension},{f:g},{amplitude:.6g},{power:.5g}\n")
