#!/usr/bin/env python3
"""Makes examples/recorder_counts.csv (one row per bin) and
examples/recorder_matrix.csv (the same counts as the matrix recorder software
exports) from the span's own balance, as a recorder on examples/aster570_recorder.toml
might have counted them over 90 days, had the site's turbulence intensity been
0.07 rather than the 0.15 the span file assumes:

* the span file with turbulence_intensity = 0.07 is predicted for the record's
  frequency bands by `stockbridge recorder --json` (its `predicted.bands`: the
  cycles and the cycle-weighted mean ln Yb of each band);
* each band's cycles are spread over Yb bins a factor 1.5 wide by a lognormal
  scatter of sigma 0.35 in ln Yb about the band's Yb, the band's centre moved by
  a normal scatter of 0.05 and each count by 10 % (seed 50), rounded.

    PYTHONPATH=build/python python3 examples/make_recorder_counts.py [build/stockbridge]

`stockbridge recorder examples/aster570_recorder.toml examples/recorder_counts.csv
--days 90 --calibrate wind.turbulence_intensity -o bins.csv` then finds the 0.07
back (docs/measurements.md, "Vibration recorders")."""

import json
import math
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SPAN = os.path.join(HERE, "aster570_recorder.toml")
BANDS = [(6, 8), (8, 11), (11, 15), (15, 20), (20, 27), (27, 36), (36, 42)]  # Hz, the recorder's frequency bins
DAYS = 90
TRUE_TURBULENCE = 0.07
SIGMA = 0.35
EDGES = [0.02 * 1.5 ** k for k in range(16)]  # mm, the recorder's Yb bins


def predicted_bands(program):
    with open(SPAN, encoding="utf-8") as handle:
        text = handle.read().replace("turbulence_intensity = 0.15", f"turbulence_intensity = {TRUE_TURBULENCE}")
    with tempfile.TemporaryDirectory() as folder:
        span = os.path.join(folder, "truth.toml")
        with open(span, "w", encoding="utf-8") as handle:
            handle.write(text.replace('file = "sauter2003.toml"', f'file = "{os.path.join(HERE, "sauter2003.toml")}"'))
        layout = os.path.join(folder, "layout.csv")
        with open(layout, "w", encoding="utf-8") as handle:
            handle.write("yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n")
            for lo, hi in BANDS:
                handle.write(f"0.1,0.2,{lo},{hi},1\n")
        run = subprocess.run([program, "recorder", span, layout, "--days", str(DAYS), "--json", "-o",
                              os.path.join(folder, "bins.csv")], capture_output=True, text=True, check=True)
        return json.loads(run.stdout)["predicted"]["bands"]


def main():
    program = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "build", "stockbridge")
    rng = random.Random(50)
    counts = {}  # (band, bin) -> cycles
    for k, band in enumerate(predicted_bands(program)):
        centre = band["predicted_mean_ln_yb_mm"] + rng.gauss(0.0, 0.05)
        for j in range(len(EDGES) - 1):
            cdf = [0.5 * math.erfc(-(math.log(e) - centre) / (SIGMA * math.sqrt(2.0))) for e in EDGES[j:j + 2]]
            n = round(band["predicted_cycles"] * (cdf[1] - cdf[0]) * math.exp(rng.gauss(0.0, 0.1)))
            if n > 0:
                counts[(k, j)] = n
    with open(os.path.join(HERE, "recorder_counts.csv"), "w", encoding="utf-8") as out:
        out.write("yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n")
        for (k, j), n in sorted(counts.items()):
            out.write(f"{EDGES[j]:.4g},{EDGES[j + 1]:.4g},{BANDS[k][0]},{BANDS[k][1]},{n}\n")
    rows = sorted({j for (_, j) in counts})
    with open(os.path.join(HERE, "recorder_matrix.csv"), "w", encoding="utf-8") as out:
        out.write("yb_pp_mm," + ",".join(f"{lo}-{hi} hz" for lo, hi in BANDS) + "\n")
        for j in rows:
            cells = [str(counts.get((k, j), "")) for k in range(len(BANDS))]
            out.write(f"{EDGES[j]:.4g}-{EDGES[j + 1]:.4g}," + ",".join(cells) + "\n")


if __name__ == "__main__":
    main()
