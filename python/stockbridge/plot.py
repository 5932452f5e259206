"""Plots of the stockbridge program's CSV files.

    python3 -m stockbridge.plot impedance z.csv -o z.png [--re-im] [--linear]
    python3 -m stockbridge.plot loop cycle.csv -o loop.png      (cycle, response or loop CSV)
    python3 -m stockbridge.plot fit fitted.csv -o fit.png       (identify ... --fitted)

Errors (a missing file or column) print one line on stderr and exit with status 2.
"""

import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)

FIGURE_SIZE = (8.0, 6.0)  # inches; at DPI this gives 800 x 600 pixels
DPI = 100


class PlotError(Exception):
    """A file the plot cannot use: one line for the user."""


def read_columns(path):
    """The CSV's columns by name, as lists of floats (None for empty cells)."""
    try:
        with open(path, newline="", encoding="utf-8-sig") as handle:
            rows = list(csv.reader(handle))
    except OSError as error:
        raise PlotError(f"{path}: cannot read ({error.strerror})") from error
    if not rows:
        raise PlotError(f"{path}: empty file: expected a header row and data")
    header = [name.strip() for name in rows[0]]
    columns = {name: [] for name in header}
    for line, row in enumerate(rows[1:], start=2):
        if not row:
            continue
        for name, cell in zip(header, row):
            try:
                columns[name].append(float(cell) if cell.strip() else None)
            except ValueError as error:
                raise PlotError(f"{path}:{line}: column '{name}' = '{cell}': expected a number") from error
    return columns


def need(columns, path, *names):
    for name in names:
        if name not in columns:
            raise PlotError(f"{path}: missing column '{name}'")
    return [columns[name] for name in names]


def finish(figure, output):
    figure.tight_layout()
    figure.savefig(output, dpi=DPI)
    plt.close(figure)


def plot_impedance(path, output, re_im=False, linear=False):
    columns = read_columns(path)
    frequency, velocity, re, im, converged = need(
        columns, path, "frequency_hz", "velocity_m_s", "re_z_n_s_m", "im_z_n_s_m", "converged")
    displacement = columns.get("displacement_m")
    # One curve per amplitude: rows are grouped by run, in the order written.
    constant_displacement = displacement is not None and len(set(v for v in velocity)) > len(set(displacement))
    key = displacement if constant_displacement else velocity
    runs = {}
    for i, k in enumerate(key):
        runs.setdefault(round(k, 12), []).append(i)
    figure, (top, bottom) = plt.subplots(2, 1, figsize=FIGURE_SIZE, sharex=True)
    for amplitude, rows in runs.items():
        label = f"X = {amplitude:g} m" if constant_displacement else f"V = {amplitude:g} m/s"
        good = [i for i in rows if converged[i] == 1.0]
        f = [frequency[i] for i in good]
        if re_im:
            top.plot(f, [re[i] for i in good], label=label)
            bottom.plot(f, [im[i] for i in good], label=label)
        else:
            top.plot(f, [math.hypot(re[i], im[i]) for i in good], label=label)
            bottom.plot(f, [math.degrees(math.atan2(im[i], re[i])) for i in good], label=label)
        failed = [frequency[i] for i in rows if converged[i] != 1.0]
        if failed:
            bottom.plot(failed, [0.0] * len(failed), "rx", label=f"{label}: not converged")
    top.set_ylabel("Re Z (N s/m)" if re_im else "|Z| (N s/m)")
    bottom.set_ylabel("Im Z (N s/m)" if re_im else "phase (deg)")
    bottom.set_xlabel("frequency (Hz)")
    if not linear:
        top.set_xscale("log")
        if not re_im:
            top.set_yscale("log")
    for axis in (top, bottom):
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize="small")
    top.set_title(f"Impedance at the clamp ({path})")
    finish(figure, output)


def plot_loop(path, output):
    columns = read_columns(path)
    panels = []  # (x, y, x label, y label, title)
    if "x_m" in columns and "force_n" in columns:
        panels.append((columns["x_m"], columns["force_n"], "tip deflection x (m)", "tip force F (N)", "experiment (a) loop"))
        panels.append((columns["phi_rad"], columns["clamp_moment_n_m"], "tip rotation phi (rad)", "clamp moment T (N m)",
                       "rotation and clamp moment"))
    elif "arm1_x_m" in columns:
        arm = 1
        while f"arm{arm}_x_m" in columns:
            panels.append((columns[f"arm{arm}_x_m"], columns[f"arm{arm}_force_n"], "tip deflection x (m)",
                           "tip force F (N)", f"arm {arm}: force over deflection"))
            panels.append((columns[f"arm{arm}_clamp_curvature_per_m"], columns[f"arm{arm}_clamp_section_moment_n_m"],
                           "curvature (1/m)", "moment (N m)", f"arm {arm}: clamp section"))
            arm += 1
    elif "curvature_per_m" in columns and "moment_n_m" in columns:
        panels.append((columns["curvature_per_m"], columns["moment_n_m"], "curvature (1/m)", "moment (N m)",
                       "section loop"))
    else:
        raise PlotError(f"{path}: expected the columns of a cycle (x_m, force_n), response (arm1_x_m, ...) "
                        "or loop (curvature_per_m, moment_n_m) file")
    figure, axes = plt.subplots(1, len(panels), figsize=FIGURE_SIZE, squeeze=False)
    for axis, (x, y, xlabel, ylabel, title) in zip(axes[0], panels):
        pairs = [(a, b) for a, b in zip(x, y) if a is not None and b is not None]
        axis.plot([p[0] for p in pairs], [p[1] for p in pairs], linewidth=1.0)
        axis.set_xlabel(xlabel)
        axis.set_ylabel(ylabel)
        axis.set_title(title, fontsize="medium")
        axis.grid(True, alpha=0.3)
    finish(figure, output)


FIT_COLUMNS = [("curvature_per_m", "moment_n_m", "model_moment_n_m", "curvature (1/m)", "moment (N m)"),
               ("x_m", "force_n", "model_force_n", "tip deflection x (m)", "tip force F (N)"),
               ("phi_rad", "clamp_moment_n_m", "model_clamp_moment_n_m", "tip rotation phi (rad)", "clamp moment T (N m)")]


def plot_fit(path, output):
    columns = read_columns(path)
    for x_name, y_name, model_name, xlabel, ylabel in FIT_COLUMNS:
        if x_name in columns and model_name in columns:
            x, measured, model = need(columns, path, x_name, y_name, model_name)
            break
    else:
        raise PlotError(f"{path}: expected the columns written by identify --fitted (e.g. x_m, force_n, model_force_n)")
    figure, axis = plt.subplots(figsize=FIGURE_SIZE)
    axis.plot(x, measured, ".", markersize=2, color="0.5", label="measured")
    axis.plot(x, model, "-", linewidth=1.2, color="C3", label="fitted model")
    axis.set_xlabel(xlabel)
    axis.set_ylabel(ylabel)
    axis.set_title(f"Measured and fitted loops ({path})")
    axis.grid(True, alpha=0.3)
    axis.legend()
    finish(figure, output)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m stockbridge.plot", description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True)
    impedance = commands.add_parser("impedance", help="|Z| and phase (or Re and Im) over frequency")
    impedance.add_argument("csv")
    impedance.add_argument("-o", "--output", required=True)
    impedance.add_argument("--re-im", action="store_true", help="plot Re Z and Im Z instead of |Z| and phase")
    impedance.add_argument("--linear", action="store_true", help="linear frequency axis")
    for name, text in (("loop", "hysteresis loops of a cycle, response or loop file"),
                       ("fit", "measured and fitted loops (identify ... --fitted)")):
        command = commands.add_parser(name, help=text)
        command.add_argument("csv")
        command.add_argument("-o", "--output", required=True)
    args = parser.parse_args(argv)
    try:
        if args.command == "impedance":
            plot_impedance(args.csv, args.output, args.re_im, args.linear)
        elif args.command == "loop":
            plot_loop(args.csv, args.output)
        else:
            plot_fit(args.csv, args.output)
    except PlotError as error:
        print(f"stockbridge.plot: {error}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
