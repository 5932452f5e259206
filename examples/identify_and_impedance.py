"""Identify a cable from a measured cycle, build a damper with it, plot its impedance.

    PYTHONPATH=build/python /usr/bin/python3 examples/identify_and_impedance.py [output.png]

The cycle (examples/cycle_measured_a.csv) is experiment (a) on a 0.3 m cable: tip
deflection x_m prescribed, tip force force_n measured, with 1 % noise and an offset.
"""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import stockbridge as sb  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def read_cycle(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    return np.array([float(r["x_m"]) for r in rows]), np.array([float(r["force_n"]) for r in rows])


def main(output):
    x, force = read_cycle(os.path.join(HERE, "cycle_measured_a.csv"))
    fit = sb.identify_global("a", 0.3, x, force, method="fit")
    ei, c, h = fit["ei"], fit["jenkin"][0]["c"], fit["jenkin"][0]["h"]
    print(f"identified: ei = {ei:.4g} N m^2, c = {c:.4g} N m^2, h = {h:.4g} N m (L1 error {fit['error']:.3g})")

    # The dissertation's damper geometry (Table 4.1) with the identified cable, 0.1875 m long.
    cable = sb.make_cable(length=0.1875, sections=40, ei=ei, jenkin=[(c, h)])
    arm = {"mass": 0.856, "inertia": 0.001814, "offset": 0.0325, "cable": cable}
    damper = sb.make_damper(clamp_mass=0.7, arms=[dict(arm, name="left"), dict(arm, name="right")])

    frequencies = np.geomspace(2.0, 100.0, 120)
    z = sb.impedance(damper, frequencies, velocity=[0.2, 0.05], threads=2)
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for i, v in enumerate(z["amplitude"]):
        top.loglog(frequencies, np.hypot(z["re_z_n_s_m"][i], z["im_z_n_s_m"][i]), label=f"V = {v:g} m/s")
        bottom.semilogx(frequencies, z["power_w"][i], label=f"V = {v:g} m/s")
    top.set_ylabel("|Z| (N s/m)")
    bottom.set_ylabel("dissipated power (W)")
    bottom.set_xlabel("frequency (Hz)")
    for axis in (top, bottom):
        axis.grid(True, which="both", alpha=0.3)
        axis.legend()
    top.set_title("Damper with the identified cable")
    figure.tight_layout()
    figure.savefig(output, dpi=100)
    print(f"{int(z['converged'].sum())} of {z['converged'].size} points converged; plot in {output}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "identified_damper.png")
