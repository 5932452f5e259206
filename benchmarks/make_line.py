#!/usr/bin/env python3
"""Writes a line of N spans for the line benchmark: LINE.toml and LINE_spans.csv.

Usage: make_line.py N OUT_PREFIX [--damper PATH]

The spans are drawn (a fixed seed: the same line every time) like a real line's:
lengths 150 to 700 m (mostly 250 to 480), three conductor sections (AAAC ASTER570,
ACSR Drake, ACSR Linnet), tensions as a fraction of the RTS (15 to 24 %) or as H/w
(1500 to 2300 m) alternately, terrains 1 and 2; one damper type (the shipped
verification damper unless --damper names another).
"""
import argparse
import os
import random


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("spans", type=int)
    p.add_argument("prefix")
    p.add_argument("--damper", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples",
                                                    "sauter2003.toml"))
    args = p.parse_args()
    rng = random.Random(2026)
    rows = ["id,length_m,tension_fraction,catenary_parameter_m,conductor,terrain"]
    for k in range(args.spans):
        r = rng.random()
        length = rng.uniform(150, 250) if r < 0.1 else rng.uniform(560, 700) if r > 0.95 else rng.uniform(250, 480)
        section = (k * 3) // args.spans
        conductor = ["", "ACSR Drake", "ACSR Linnet"][section]
        terrain = 2 if k % 3 else 1
        if k % 2 == 0:
            rows.append(f"S{k + 1:05d},{length:.0f},{rng.uniform(0.15, 0.24):.3f},,{conductor},{terrain}")
        else:
            rows.append(f"S{k + 1:05d},{length:.0f},,{rng.uniform(1500, 2300):.0f},{conductor},{terrain}")
    spans = args.prefix + "_spans.csv"
    with open(spans, "w") as f:
        f.write("\n".join(rows) + "\n")
    damper = os.path.abspath(args.damper)
    with open(args.prefix + ".toml", "w") as f:
        f.write(f"""# {args.spans} spans made by benchmarks/make_line.py
spans = "{os.path.basename(spans)}"

[line]
name = "benchmark line of {args.spans} spans"

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
wind_weibull = {{ shape = 2.0, scale = 4.0 }}
aeolian_fraction = 0.3

[dampers]
types = [ {{ name = "sb1", file = "{damper}" }} ]
max_per_end = 3
""")


if __name__ == "__main__":
    main()
