"""Run a span, a line and an impedance sweep from Python and plot their results.

    PYTHONPATH=build/python /usr/bin/python3 examples/plot_from_python.py [output_folder]

No CSV file is written: stockbridge.plot.span, line and impedance draw the dicts
stockbridge.span, line and impedance return, the figures python3 -m stockbridge.plot
draws from the program's CSV files. Each returns the matplotlib Figure (here saved as
drake_span.png, line_short.png and sauter2003_impedance.png; plt.show() or a notebook
would show it instead). The line takes some seconds, the rest less than one.
"""

import os
import sys

import stockbridge as sb
import stockbridge.plot

HERE = os.path.dirname(os.path.abspath(__file__))


def main(folder):
    os.makedirs(folder, exist_ok=True)

    span = sb.span(os.path.join(HERE, "drake_300m.toml"), points=40)
    stockbridge.plot.span(span, os.path.join(folder, "drake_span.png"), labels="ACSR Drake, 300 m")
    summary = span["summary"]
    print(f"span: {summary['verdict']}, max {summary['max_stress_fymax_mpa']:.3g} MPa "
          f"(limit {summary['endurance_limit_mpa']:.3g} MPa)")

    line = sb.line(os.path.join(HERE, "line_short.toml"), threads=2)
    stockbridge.plot.line(line, os.path.join(folder, "line_short.png"), label=line["summary"]["line"])
    print(f"line: {line['summary']['spans_safe']} of {line['summary']['spans']} spans safe")

    damper = sb.load_damper(os.path.join(HERE, "sauter2003.toml"))
    z = sb.impedance(damper, velocity=[0.2, 0.05], fmin=5, fmax=100, points=30, threads=2)
    stockbridge.plot.impedance(z, os.path.join(folder, "sauter2003_impedance.png"), power=True,
                               labels="sauter2003")
    print(f"impedance: {int(z['converged'].sum())} of {z['converged'].size} points converged")
    print(f"plots in {folder}: drake_span.png, line_short.png, sauter2003_impedance.png")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
