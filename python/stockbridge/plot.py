"""Plots of the stockbridge program's CSV files.

    python3 -m stockbridge.plot impedance z.csv [more.csv ...] [--label NAME ...] -o z.png
                                [--re-im] [--linear] [--power]
    python3 -m stockbridge.plot loop cycle.csv -o loop.png      (cycle, response or loop CSV)
    python3 -m stockbridge.plot fit fitted.csv -o fit.png       (identify ... --fitted)
    python3 -m stockbridge.plot span span.csv [more.csv ...] [--label NAME ...] [--summary span.json ...] -o span.png
                                (span: damped and undamped, the verdict; --summary: positions, life)
    python3 -m stockbridge.plot design designs.csv -o design.png (design: objective per variable)
    python3 -m stockbridge.plot line schedule.csv -o schedule.png (line: stresses and dampers per span)
    python3 -m stockbridge.plot fatigue-tests out.csv [--summary s.json] -o sn.png
                                (fatigue-tests: S-N, runouts marked; --summary: the fit, its design curve, the SBL)
    python3 -m stockbridge.plot span-modes modes.csv [--shapes shapes.csv] [--modes 1,2,5] -o modes.png
                                (span --modes: the shapes with the attachments marked, f against the bare span's)

Errors (a missing file or column, a cell that is not a number, nothing to plot, an
output that cannot be written) print one line on stderr and exit with status 2,
without writing the output file.

From Python, the same figures of what the module's functions return (no CSV file
needed); each returns the matplotlib Figure and, given an output path, saves it:

    import stockbridge as sb, stockbridge.plot
    stockbridge.plot.span(sb.span("examples/drake_300m.toml", points=40), "span.png")
    stockbridge.plot.line(sb.line("examples/line_short.toml", threads=2), "line.png")
    damper = sb.load_damper("examples/sauter2003.toml")
    stockbridge.plot.impedance(sb.impedance(damper, velocity=[0.2, 0.05], fmin=5, fmax=50, points=20), "z.png")

A result the figure cannot use raises PlotError with the same one line.
"""

import argparse
import csv
import io
import json
import math
import os
import re
import sys
import textwrap
import warnings

import matplotlib
import matplotlib.cm
import matplotlib.colors
import matplotlib.lines
import matplotlib.patches
import matplotlib.pyplot as plt
import numpy
from matplotlib.ticker import FuncFormatter, LogLocator, MaxNLocator, NullFormatter

FIGURE_SIZE = (8.0, 6.0)  # inches; at DPI this gives 800 x 600 pixels
DPI = 100
PROGRAM = "stockbridge.plot"


class PlotError(Exception):
    """A file the plot cannot use: one line for the user."""


# ---------------------------------------------------------------- reading CSV files

class Table:
    """A CSV file's header and rows (as text); numbers are converted per column when used."""

    def __init__(self, path):
        self.path = path
        rows = _read_rows(path)
        if not rows:
            raise PlotError(f"{path}: empty file: expected a header row and data")
        self.header = [name.strip() for name in rows[0]]
        self.rows = [(line, row) for line, row in enumerate(rows[1:], start=2) if any(cell.strip() for cell in row)]
        if not self.rows:
            raise PlotError(f"{path}: no data rows: expected data below the header")
        for line, row in self.rows:
            if len(row) != len(self.header):
                raise PlotError(f"{path}:{line}: {len(row)} cells: expected {len(self.header)} as in the header")

    def __contains__(self, name):
        return name in self.header

    def __len__(self):
        return len(self.rows)

    def where(self, i):
        """Row i's place in messages: "z.csv:12" (the file's line)."""
        return f"{self.path}:{self.rows[i][0]}"

    def column(self, name, infinite=False):
        """The column's numbers, NaN for empty cells; +inf accepted where `infinite`."""
        index = self._index(name)
        return [self._number(i, name, row[index], infinite) for i, (_, row) in enumerate(self.rows)]

    def text(self, name):
        """The column's cells as text, stripped."""
        index = self._index(name)
        return [str(row[index]).strip() for _, row in self.rows]

    def required(self, name, rows=None):
        """The column's numbers; a cell in `rows` (row numbers, default all) must not be empty."""
        values = self.column(name)
        for i in range(len(values)) if rows is None else rows:
            if math.isnan(values[i]):
                raise PlotError(f"{self.where(i)}: column '{name}' is empty: expected a number")
        return values

    def _index(self, name):
        if name not in self.header:
            raise PlotError(f"{self.path}: missing column '{name}'")
        return self.header.index(name)

    def _number(self, i, name, cell, infinite=False):
        """A cell's number: NaN where it is empty; else finite, or +inf where `infinite`."""
        if empty_cell(cell):
            return math.nan
        try:
            value = float(cell)
        except (TypeError, ValueError):
            value = math.nan
        if not (math.isfinite(value) or (infinite and value == math.inf)):
            raise PlotError(f"{self.where(i)}: column '{name}' = '{cell}': expected a finite number")
        return value


def empty_cell(cell):
    """An empty CSV cell, or where a result has NaN or None (its CSV's cell is empty)."""
    if isinstance(cell, str):
        return not cell.strip()
    try:
        return cell is None or math.isnan(cell)
    except TypeError:
        return False


class ResultTable(Table):
    """The columns of a result the package returns (stockbridge.span(), line()['schedule'],
    impedance() flattened) as a Table: the same names as its CSV, one value per row,
    NaN (or None) where the CSV's cell is empty, bools as 1 and 0. `name` stands for
    the file's path in titles and messages ("span[3]: ...": the row's index)."""

    def __init__(self, columns, name, rows):
        self.path = name
        self.header = [key for key, values in columns.items() if _is_column(values, rows)]
        if rows == 0:
            raise PlotError(f"{name}: no rows: expected a result with at least one point")
        cells = [list(columns[key]) for key in self.header]
        self.rows = [(i, [values[i] for values in cells]) for i in range(rows)]

    def where(self, i):
        return f"{self.path}[{i}]"


def _is_column(values, rows):
    """Whether a result's entry is a column of `rows` values (an array or a list, not a
    dict, text or a list of lists)."""
    if isinstance(values, (str, bytes, dict)) or not hasattr(values, "__len__") or len(values) != rows:
        return False
    return getattr(values, "ndim", 1) == 1 and not any(isinstance(v, (list, tuple, dict)) for v in values)


def result_table(result, function, key, name=None):
    """The columns of what stockbridge.<function>() returns as a ResultTable named `name`
    (default the function's name), its rows counted by column `key`."""
    check_result(result, function, key)
    return ResultTable(result, name or function, len(result[key]))


def check_result(result, function, *keys):
    """That `result` is a dict with `keys`, as stockbridge.<function>() returns; else one
    line naming what was expected."""
    if not isinstance(result, dict) or any(key not in result for key in keys):
        got = type(result).__name__ if not isinstance(result, dict) else \
            "a dict without " + ", ".join(repr(key) for key in keys if key not in result)
        raise PlotError(f"{function}: expected the dict stockbridge.{function}() returns, got {got}")


def listed(result, labels):
    """A result or a list of them, and their labels (a name, or one per result; None
    where not given)."""
    results = list(result) if isinstance(result, (list, tuple)) else [result]
    labels = [None] * len(results) if labels is None else [labels] if isinstance(labels, str) else list(labels)
    if len(labels) != len(results):
        raise PlotError(f"{len(labels)} labels for {len(results)} results: expected one per result, in their order")
    return results, labels


def finish(figure, output):
    """The figure, saved to `output` when given (and then closed in pyplot: it stays
    usable, pyplot no longer holds it)."""
    if output is not None:
        save(figure, os.fspath(output))
    return figure


def as_table(source):
    """A Table of a CSV file's path, or the ResultTable given."""
    return source if isinstance(source, Table) else Table(source)


def _read_rows(path):
    try:
        with open(path, newline="", encoding="utf-8-sig") as handle:
            return list(csv.reader(handle))
    except OSError as error:
        raise PlotError(f"{path}: cannot read ({error.strerror or error})") from error
    except UnicodeDecodeError as error:
        raise PlotError(f"{path}: not UTF-8 text: expected a CSV file") from error
    except csv.Error as error:
        raise PlotError(f"{path}: not a CSV file ({error})") from error


def finite(*values):
    return all(math.isfinite(v) for v in values)


# ---------------------------------------------------------------- writing figures

def save(figure, output):
    """Write the figure to `output` (format from its extension, PNG without one); nothing
    is left at `output` when this fails."""
    extension = os.path.splitext(output)[1][1:].lower() or "png"
    if extension not in figure.canvas.get_supported_filetypes():
        plt.close(figure)
        raise PlotError(f"{output}: unknown image format '.{extension}': expected .png, .pdf or .svg")
    buffer = io.BytesIO()
    try:
        figure.savefig(buffer, format=extension, dpi=DPI)
    except (ValueError, OverflowError) as error:
        raise PlotError(f"{output}: cannot draw the data ({error})") from error
    finally:
        plt.close(figure)
    write_file(output, buffer.getvalue())


def write_file(output, data):
    existed = os.path.exists(output)
    try:
        with open(output, "wb") as handle:
            handle.write(data)
    except OSError as error:
        if not existed and os.path.isfile(output):
            os.remove(output)
        raise PlotError(f"{output}: cannot write ({error.strerror or error})") from error


def few_ticks(axis):
    """At most five ticks per axis, so that long numbers do not run into each other."""
    axis.xaxis.set_major_locator(MaxNLocator(nbins=4))
    axis.yaxis.set_major_locator(MaxNLocator(nbins=5))
    axis.ticklabel_format(style="sci", scilimits=(-3, 4), useMathText=True)


def plotted(axes, which):
    """The finite values the axes' lines draw along x or y."""
    return [v for line in axes.get_lines() for v in (line.get_xdata() if which == "x" else line.get_ydata())
            if math.isfinite(v)]


def log_scale(axes, which):
    """A log scale labelled in plain numbers: at 1 to 9 times the powers of ten over less
    than a decade, at 1, 2 and 5 times them over two (the default would label one tick or
    none), at the powers of ten over more; each label the tick's value in its shortest
    form (a fixed number of decimals would print 0.1 as "0")."""
    values = [v for v in plotted(axes, which) if v > 0]
    decades = math.log10(max(values) / min(values)) if values else 3.0
    subs = range(1, 10) if decades < 1 else (1.0, 2.0, 5.0) if decades <= 2 else (1.0,)
    (axes.set_xscale if which == "x" else axes.set_yscale)("log")
    axis = axes.xaxis if which == "x" else axes.yaxis
    axis.set_major_locator(LogLocator(subs=subs))
    axis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    axis.set_minor_formatter(NullFormatter())


FREQUENCY_LABELS = 5  # at least this many labelled frequencies along an axis
FREQUENCY_SUBS = [(1,), (1, 2, 5), (1, 2, 3, 5), range(1, 10), (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 7, 8, 9)]


class FrequencyLocator(LogLocator):
    """The labelled ticks of a log frequency axis: the sparsest of FREQUENCY_SUBS times
    the powers of ten that puts FREQUENCY_LABELS or more inside the view (1, 10, ...,
    10^4; 1, 2, 5, 10, 20, 50, 100; 5, 10, 20, 30, 50; 6, 7, 8, 9, 10, 20, 30, 40;
    12, 15, 20, 25, 30), else evenly spaced round numbers (12, 14, ..., 24; 31, 31.5,
    32, ...). Chosen at each draw, from the axis's limits."""

    def tick_values(self, vmin, vmax):
        vmin, vmax = sorted((vmin, vmax))
        if vmin <= 0:
            return super().tick_values(vmin, vmax)
        for subs in FREQUENCY_SUBS:
            ticks = decade_ticks(vmin, vmax, subs)
            if len(ticks) >= FREQUENCY_LABELS:
                return ticks
        for bins in range(FREQUENCY_LABELS, 4 * FREQUENCY_LABELS):  # so many intervals at most, or one fewer
            ticks = [t for t in MaxNLocator(nbins=bins, steps=[1, 2, 5, 10]).tick_values(vmin, vmax) if t > 0]
            if sum(vmin <= t <= vmax for t in ticks) >= FREQUENCY_LABELS:
                break
        return ticks


def decade_ticks(vmin, vmax, subs):
    """The values sub x 10^k within [vmin, vmax], as exact as their decimal text."""
    low, high = math.floor(math.log10(vmin)), math.ceil(math.log10(vmax))
    values = (float(f"{sub:g}e{k}") for k in range(low, high + 1) for sub in subs)
    return [v for v in values if vmin * (1 - 1e-9) <= v <= vmax * (1 + 1e-9)]


def frequency_scale(axes):
    """A log frequency axis (x) labelled in plain numbers at FrequencyLocator's ticks, the
    other tenths of each decade unlabelled minor ticks."""
    axes.set_xscale("log")
    axes.xaxis.set_major_locator(FrequencyLocator())
    axes.xaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    axes.xaxis.set_minor_formatter(NullFormatter())


def log_if_positive(axes):
    """A log y scale when every plotted value is positive and they span a decade or more
    (else it stays linear)."""
    values = plotted(axes, "y")
    if values and min(values) > 0 and max(values) >= 10 * min(values):
        log_scale(axes, "y")


# ---------------------------------------------------------------- impedance

def measured_file_warnings(path):
    """The library's warnings of a measured impedance file (values outside the typical
    ranges, phases in radians) as UnusualValueWarnings; nothing without the compiled
    module, or for a file its reader refuses (the plot has read it already)."""
    try:
        from . import UnusualValueWarning
        from ._core import Error, _measured_impedance_warnings
    except ImportError:
        return
    try:
        lines = _measured_impedance_warnings(str(path))
    except Error:
        return
    for line in lines:
        warnings.warn(line, UnusualValueWarning, stacklevel=2)


class Sweep:
    """One impedance CSV, or a ResultTable of stockbridge.impedance()'s result (impedance_table):
    per row the frequency, the velocity amplitude, Z and whether it converged.

    Every form identify impedance reads is accepted: the amplitude as velocity_m_s or
    displacement_m, Z as re_z_n_s_m, im_z_n_s_m or abs_z_n_s_m, phase_deg. A file without
    a converged column is a measurement: its curves are its amplitudes within 10 % (as
    identify impedance groups them), and the library's checks of a measured file (units,
    phases in radians) are warned of (UnusualValueWarning) when the compiled module is there."""

    def __init__(self, source, label=None):
        table = as_table(source)
        result = isinstance(table, ResultTable)
        path = self.path = table.path
        self.label = label or os.path.basename(path)
        self.title_name = None if result and label is None else path  # a result is named in the title when labelled
        self.frequency = table.required("frequency_hz")
        for i, f in enumerate(self.frequency):
            if f <= 0:
                raise PlotError(f"{table.where(i)}: frequency_hz = {f:g}: expected a positive frequency")
        self.measured = "converged" not in table
        self.converged = self._converged(table)
        good = [i for i, ok in enumerate(self.converged) if ok]
        if not good:
            raise PlotError(f"{path}: no converged point to plot (converged = 0 in every row)")
        self.velocity, displacement = self._amplitudes(table)
        self.re, self.im = self._impedance(table, good)
        self.runs = self._measured_runs(displacement) if self.measured else self._runs(displacement)
        if self.measured and not result:
            measured_file_warnings(path)

    @staticmethod
    def _converged(table):
        """Missing column: every row converged (a measured file)."""
        if "converged" not in table:
            return [True] * len(table.rows)
        return [value == 1.0 for value in table.required("converged")]

    def _amplitudes(self, table):
        """The velocity amplitude of every row and the displacement column (None where absent);
        a file with displacements only gets its velocities as 2 pi f X."""
        if "velocity_m_s" in table:
            return table.required("velocity_m_s"), table.column("displacement_m") if "displacement_m" in table else None
        if "displacement_m" not in table:
            raise PlotError(f"{self.path}: missing column 'velocity_m_s' (or 'displacement_m'): expected the clamp's "
                            "amplitude in the header")
        displacement = table.required("displacement_m")
        return [2.0 * math.pi * f * x for f, x in zip(self.frequency, displacement)], displacement

    def _impedance(self, table, good):
        """Re Z and Im Z of every row (NaN where not converged), from re/im or |Z|/phase (degrees)."""
        if "re_z_n_s_m" in table:
            return table.required("re_z_n_s_m", good), table.required("im_z_n_s_m", good)
        if "abs_z_n_s_m" not in table:
            raise PlotError(f"{self.path}: missing column 're_z_n_s_m' (or 'abs_z_n_s_m'): expected re_z_n_s_m,"
                            "im_z_n_s_m or abs_z_n_s_m,phase_deg in the header")
        magnitude, phase = table.required("abs_z_n_s_m", good), table.required("phase_deg", good)
        return ([m * math.cos(math.radians(p)) for m, p in zip(magnitude, phase)],
                [m * math.sin(math.radians(p)) for m, p in zip(magnitude, phase)])

    def _runs(self, displacement):
        """Rows grouped by amplitude (velocity, or displacement for constant-displacement sweeps)."""
        by_displacement = (displacement is not None and all(map(math.isfinite, displacement))
                           and len(set(self.velocity)) > len(set(displacement)))
        key, unit = (displacement, "X = {:g} m") if by_displacement else (self.velocity, "V = {:g} m/s")
        runs = {}
        for i, k in enumerate(key):
            runs.setdefault(round(k, 12), []).append(i)
        return [(unit.format(amplitude), rows) for amplitude, rows in runs.items()]

    def _measured_runs(self, displacement):
        """A measurement's curves: the held amplitude's groups within 10 % in the order the file lists
        them, each in frequency order."""
        by_velocity = amplitude_groups(self.velocity)
        by_displacement = amplitude_groups(displacement) if displacement is not None else None
        groups, unit = ((by_displacement, "X = {:g} m") if by_displacement and len(by_displacement) < len(by_velocity)
                        else (by_velocity, "V = {:g} m/s"))
        groups.sort(key=lambda group: min(group[1]))  # in the file's order
        return [(unit.format(amplitude), sorted(rows, key=lambda i: self.frequency[i])) for amplitude, rows in groups]

    def abs_z(self, i):
        return math.hypot(self.re[i], self.im[i])

    def phase_deg(self, i):
        return math.degrees(math.atan2(self.im[i], self.re[i]))

    def power_w(self, i):
        """The mean power into the damper, Re Z V^2 / 2 (what it dissipates in a steady state)."""
        return 0.5 * self.re[i] * self.velocity[i] ** 2


def impedance_panels(re_im, power):
    """(y label, value of a Sweep's row, log scale wanted) per panel, top to bottom."""
    if re_im:
        panels = [("Re Z (N s/m)", lambda s, i: s.re[i], False), ("Im Z (N s/m)", lambda s, i: s.im[i], False)]
    else:
        panels = [("|Z| (N s/m)", Sweep.abs_z, True), ("phase (deg)", Sweep.phase_deg, False)]
    if power:
        panels.append(("dissipated power (W)", Sweep.power_w, True))
    return panels


LINE_STYLES = ["-", "--", ":", "-."]  # per file; the colour tells the amplitude


def impedance_figure(sweeps, re_im=False, linear=False, power=False):
    """The figure of one or more Sweeps: one curve per file and amplitude on every panel."""
    panels = impedance_panels(re_im, power)
    figure, axes = plt.subplots(len(panels), 1, figsize=FIGURE_SIZE, sharex=True, layout="constrained")
    for number, sweep in enumerate(sweeps):
        named = len(sweeps) > 1 or sweep.label != os.path.basename(sweep.path)
        for run, (label, rows) in enumerate(sweep.runs):
            style = {"linestyle": LINE_STYLES[number % len(LINE_STYLES)], "color": f"C{run % 10}"}
            draw_run(axes, panels, sweep, rows, f"{sweep.label}: {label}" if named else label, style)
    finish_impedance_axes(axes, panels, sweeps, linear)
    return figure


def draw_run(axes, panels, sweep, rows, name, style):
    """One amplitude's converged points as a curve on every panel; the others as red
    crosses at zero on the second panel."""
    good = [i for i in rows if sweep.converged[i]]
    f = [sweep.frequency[i] for i in good]
    for axis, (_, value, _) in zip(axes, panels):
        axis.plot(f, [value(sweep, i) for i in good], marker="." if len(good) < 30 else None, label=name, **style)
    failed = [sweep.frequency[i] for i in rows if not sweep.converged[i]]
    if failed:
        axes[1].plot(failed, [0.0] * len(failed), "x", color="red", label=f"{name}: not converged")
        axes[1].legend(fontsize="small")


def finish_impedance_axes(axes, panels, sweeps, linear):
    for axis, (ylabel, _, log) in zip(axes, panels):
        axis.set_ylabel(ylabel)
        if log and not linear:
            log_if_positive(axis)
        axis.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize="small")
    axes[-1].set_xlabel("frequency (Hz)")
    if not linear:
        frequency_scale(axes[0])
    names = ", ".join(sweep.title_name for sweep in sweeps if sweep.title_name)
    axes[0].set_title(f"Impedance at the clamp ({names})" if names else "Impedance at the clamp", fontsize="medium")


def plot_impedance(paths, output, labels=None, re_im=False, linear=False, power=False):
    labels = labels or [None] * len(paths)
    sweeps = [Sweep(path, label) for path, label in zip(paths, labels)]
    save(impedance_figure(sweeps, re_im, linear, power), output)


def impedance_table(result, name=None):
    """What stockbridge.impedance() returns (arrays of amplitudes x frequencies, frequency_hz
    1-D) as the rows of its CSV: amplitude by amplitude, each over the frequencies."""
    check_result(result, "impedance", "frequency_hz", "converged")
    shape = numpy.shape(result["converged"])
    if len(shape) != 2 or shape[1] != len(result["frequency_hz"]):
        raise PlotError(f"impedance: converged has shape {shape}: expected (amplitudes, frequencies) with "
                        f"{len(result['frequency_hz'])} frequencies, as stockbridge.impedance() returns")
    columns = {key: numpy.ravel(value) for key, value in result.items()
               if isinstance(value, numpy.ndarray) and value.shape == shape}
    columns["frequency_hz"] = numpy.tile(numpy.asarray(result["frequency_hz"], dtype=float), shape[0])
    return ResultTable(columns, name or "impedance", shape[0] * shape[1])


def impedance(result, output=None, *, labels=None, re_im=False, linear=False, power=False):
    """plot impedance's figure of what stockbridge.impedance() returns: |Z| and phase (or
    Re Z and Im Z with `re_im`, and the dissipated power with `power`) over frequency, a
    curve per amplitude. A list of results is drawn on one figure, one line style each,
    named in the legend by `labels` (one per result). Returns the matplotlib Figure;
    with `output` (a path: .png, .pdf, .svg) also saves it there."""
    results, labels = listed(result, labels)
    sweeps = [Sweep(impedance_table(r, label), label) for r, label in zip(results, labels)]
    return finish(impedance_figure(sweeps, re_im, linear, power), output)


# ---------------------------------------------------------------- loops

def closed(x, y):
    """A periodic record's samples with the first appended at the end, so that the loop has no gap."""
    return list(x) + list(x[:1]), list(y) + list(y[:1])


def arm_prefixes(table):
    """The arms of a response file, found by their '<arm>_x_m' columns, in file order."""
    return [name[:-len("_x_m")] for name in table.header if name.endswith("_x_m") and len(name) > len("_x_m")]


def loop_panels(table):
    """[(x, y, x label, y label, title)] and whether the record is one period (to be closed)."""
    prefixes = arm_prefixes(table)
    if "time_s" in table and prefixes:
        return [panel for prefix in prefixes for panel in response_panels(table, prefix)], True
    if "x_m" in table and "force_n" in table:
        return [(table.column("x_m"), table.column("force_n"), "tip deflection x (m)", "tip force F (N)",
                 "experiment (a) loop"),
                (table.column("phi_rad"), table.column("clamp_moment_n_m"), "tip rotation phi (rad)",
                 "clamp moment T (N m)", "rotation and clamp moment")], False
    if "curvature_per_m" in table and "moment_n_m" in table:
        return [(table.column("curvature_per_m"), table.column("moment_n_m"), "curvature (1/m)", "moment (N m)",
                 "section loop")], False
    raise PlotError(f"{table.path}: expected the columns of a cycle (x_m, force_n), response (time_s, arm1_x_m, ...) "
                    "or loop (curvature_per_m, moment_n_m) file")


def response_panels(table, prefix):
    name = prefix.replace("arm", "arm ", 1) if prefix[3:].isdigit() else prefix
    return [(table.column(f"{prefix}_x_m"), table.column(f"{prefix}_force_n"), "tip deflection x (m)",
             "tip force F (N)", f"{name}: force over deflection"),
            (table.column(f"{prefix}_clamp_curvature_per_m"), table.column(f"{prefix}_clamp_section_moment_n_m"),
             "curvature (1/m)", "moment (N m)", f"{name}: clamp section")]


def loop_figure(path):
    """The loops of a cycle, response or loop file; a response file's loops are closed."""
    table = Table(path)
    panels, periodic = loop_panels(table)
    if not any(finite(a, b) for x, y, *_ in panels for a, b in zip(x, y)):
        raise PlotError(f"{path}: no sample to plot (every cell of the loop columns is empty)")
    rows = (len(panels) + 1) // 2 if len(panels) > 2 else 1
    figure, axes = plt.subplots(rows, min(len(panels), 2), figsize=FIGURE_SIZE, squeeze=False, layout="constrained")
    for axis, (x, y, xlabel, ylabel, title) in zip(axes.flat, panels):
        axis.plot(*(closed(x, y) if periodic else (x, y)), linewidth=1.0)
        axis.set(xlabel=xlabel, ylabel=ylabel)
        axis.set_title(title, fontsize="medium")
        axis.grid(True, alpha=0.3)
        few_ticks(axis)
    for axis in list(axes.flat)[len(panels):]:
        axis.set_visible(False)
    if "converged" in table and periodic and not all(v == 1.0 for v in table.column("converged")):
        figure.suptitle(f"{path}: not converged (the solver's last iterate)", color="C3")
    return figure


def plot_loop(path, output):
    save(loop_figure(path), output)


# ---------------------------------------------------------------- fitted loops

FIT_COLUMNS = [("curvature_per_m", "moment_n_m", "model_moment_n_m", "curvature (1/m)", "moment (N m)"),
               ("x_m", "force_n", "model_force_n", "tip deflection x (m)", "tip force F (N)"),
               ("phi_rad", "clamp_moment_n_m", "model_clamp_moment_n_m", "tip rotation phi (rad)", "clamp moment T (N m)")]


def amplitude_groups(values):
    """[(smallest, rows)]: the rows whose values lie within 10 % of a group's
    smallest, in increasing amplitude (as identify impedance groups its curves)."""
    groups = []
    for i in sorted(range(len(values)), key=lambda i: values[i]):
        if not groups or values[i] > 1.1 * groups[-1][0]:
            groups.append((values[i], []))
        groups[-1][1].append(i)
    return groups


def impedance_fit_figure(table):
    """Measured Z (markers) and the fitted model's (lines) over frequency, |Z| and
    phase, one colour per measured curve (velocity or displacement amplitude)."""
    frequency = table.required("frequency_hz")
    measured = [complex(r, i) for r, i in zip(table.required("re_z_n_s_m"), table.required("im_z_n_s_m"))]
    model = [complex(r, i) for r, i in zip(table.column("model_re_z_n_s_m"), table.column("model_im_z_n_s_m"))]
    for i, f in enumerate(frequency):
        if f <= 0:
            raise PlotError(f"{table.where(i)}: frequency_hz = {f:g}: expected a positive frequency")
    velocity, displacement = table.required("velocity_m_s"), table.required("displacement_m")
    by_velocity, by_displacement = amplitude_groups(velocity), amplitude_groups(displacement)
    curves, label = ((by_velocity, "V = {:g} m/s") if len(by_velocity) <= len(by_displacement)
                     else (by_displacement, "X = {:g} m"))
    figure, axes = plt.subplots(2, 1, figsize=FIGURE_SIZE, sharex=True, layout="constrained")
    for number, (amplitude, rows) in enumerate(curves):
        rows.sort(key=lambda i: frequency[i])
        colour = f"C{number % 10}"
        f = [frequency[i] for i in rows]
        axes[0].plot(f, [abs(measured[i]) for i in rows], "o", color=colour, markersize=4,
                     label="measured, " + label.format(amplitude))
        axes[1].plot(f, [math.degrees(math.atan2(measured[i].imag, measured[i].real)) for i in rows], "o",
                     color=colour, markersize=4)
        good = [i for i in rows if finite(model[i].real, model[i].imag)]
        axes[0].plot([frequency[i] for i in good], [abs(model[i]) for i in good], "-", color=colour,
                     label="fitted model, " + label.format(amplitude))
        axes[1].plot([frequency[i] for i in good], [math.degrees(math.atan2(model[i].imag, model[i].real))
                                                    for i in good], "-", color=colour)
        failed = [frequency[i] for i in rows if i not in good]
        if failed:
            axes[1].plot(failed, [0.0] * len(failed), "x", color="red", label="model not converged")
    axes[0].set_ylabel("|Z| (N s/m)")
    axes[1].set_ylabel("phase (deg)")
    axes[1].set_xlabel("frequency (Hz)")
    for axis in axes:
        axis.grid(True, which="both", alpha=0.3)
    frequency_scale(axes[0])
    log_if_positive(axes[0])
    axes[0].legend(fontsize="small")
    axes[0].set_title(f"Measured and fitted impedance ({table.path})", fontsize="medium")
    return figure


def plot_fit(path, output):
    table = Table(path)
    if "model_re_z_n_s_m" in table:
        save(impedance_fit_figure(table), output)
        return
    for x_name, y_name, model_name, xlabel, ylabel in FIT_COLUMNS:
        if x_name in table and model_name in table:
            x, measured, model = (table.column(name) for name in (x_name, y_name, model_name))
            break
    else:
        raise PlotError(f"{path}: expected the columns written by identify --fitted (e.g. x_m, force_n, model_force_n, "
                        "or frequency_hz, re_z_n_s_m, model_re_z_n_s_m)")
    if not any(finite(a, b) for a, b in zip(x, measured)):
        raise PlotError(f"{path}: no sample to plot (every cell of {x_name}, {y_name} is empty)")
    figure, axis = plt.subplots(figsize=FIGURE_SIZE, layout="constrained")
    axis.plot(x, measured, ".", markersize=2, color="0.5", label="measured")
    axis.plot(x, model, "-", linewidth=1.2, color="C3", label="fitted model")
    axis.set(xlabel=xlabel, ylabel=ylabel)
    axis.set_title(f"Measured and fitted loops ({path})")
    axis.grid(True, alpha=0.3)
    axis.legend()
    save(figure, output)


# ---------------------------------------------------------------- span

FILE_COLOURS = ["C0", "C1", "C2", "C4", "C5", "C6", "C8", "C9"]  # one per span CSV: red is the limit's, grey the undamped's
TITLE_WIDTH = 100  # characters of a title line before it wraps
LIVES_NOTE = ("Lives are comparative: they rest on the assumed climate (the span file's wind_weibull, "
              "aeolian_fraction) and the Safe Border Line.")
SUMMARY_HINT = "expected the JSON summary that stockbridge span --json prints"


def read_json_summary(path, hint):
    """What a command's --json printed, read from `path`; a PlotError naming the file (and
    the line) and `hint`, what was expected, where it cannot be read."""
    try:
        with open(path, encoding="utf-8") as handle:
            return json.load(handle)
    except OSError as error:
        raise PlotError(f"{path}: cannot read ({error.strerror or error})") from error
    except UnicodeDecodeError as error:
        raise PlotError(f"{path}: not UTF-8 text: {hint}") from error
    except json.JSONDecodeError as error:
        raise PlotError(f"{path}:{error.lineno}: not JSON ({error.msg}): {hint}") from error
VERDICTS = ("safe", "unsafe", "unknown")  # what a span CSV tells by itself: its stresses against the limit
PROGRAM_VERDICTS = ("safe", "unsafe", "uncertain", "unknown")  # uncertain: a measured sheet's band reaches the limit


def years(value):
    """A life in years: whole years from 10 on, else two significant digits (1.0, 0.0015)."""
    return f"{value:,.0f}" if value >= 10 else f"{value:#.2g}"


def points(n):
    return f"{n} point{'' if n == 1 else 's'}"


class SpanRun:
    """One span CSV (stockbridge span -o), or a ResultTable of stockbridge.span()'s
    result: per frequency the antinode amplitude, the fymax stress and (where the CSV
    has them) the bending strain at the span clamp, with the dampers and without; whether
    each point converged; the endurance limit (the same in every row); the measured
    sheet's band (None without its columns); the wind speed over the frequency, D / St
    (None without a wind_speed_m_s column); and the verdict the CSV carries, as the
    program judges it: safe when every point converged within the limit, unsafe when a
    converged point exceeds it, else unknown (a summary's verdict replaces it: judged_by)."""

    NAMES = ["amplitude_m", "undamped_amplitude_m", "stress_fymax_mpa", "undamped_stress_fymax_mpa"]
    STRAIN = ["bending_strain_pp_microstrain", "undamped_bending_strain_pp_microstrain"]

    def __init__(self, source, label=None):
        table = as_table(source)
        path = self.path = table.path
        self.named = label is not None
        self.label = label or os.path.splitext(os.path.basename(path))[0]
        self.criterion = None  # the summary's, where it names one
        self.frequency = table.required("frequency_hz")
        for i, f in enumerate(self.frequency):
            if f <= 0:
                raise PlotError(f"{table.where(i)}: frequency_hz = {f:g}: expected a positive frequency")
        self.converged = [value == 1.0 for value in table.required("converged")]
        self.good = [i for i, ok in enumerate(self.converged) if ok]
        if not self.good:
            raise PlotError(f"{path}: no converged point to plot (converged = 0 in every row)")
        self.strain = "bending_strain_pp_microstrain" in table
        self.columns = {name: table.required(name, self.good) for name in self.NAMES + (self.STRAIN if self.strain else [])}
        limit = table.required("endurance_limit_mpa")
        if len({round(v, 9) for v in limit}) != 1:
            raise PlotError(f"{path}: endurance_limit_mpa differs between rows: expected one value (a span CSV)")
        self.limit = limit[0]
        self.limit_strain = table.required("endurance_limit_pp_microstrain")[0] if self.strain else None
        self.damped = any(name.endswith("_end1_velocity_m_s") for name in table.header)
        self.band = ((table.column("stress_fymax_low_mpa"), table.column("stress_fymax_high_mpa"))
                     if "stress_fymax_low_mpa" in table and "stress_fymax_high_mpa" in table else None)
        self.wind_ratio = self._wind_ratio(table)
        stress = self.columns["stress_fymax_mpa"]
        self.peak = max(self.good, key=lambda i: stress[i])  # the first of the largest
        self.max_stress = stress[self.peak]
        self.missing = len(self.converged) - len(self.good)
        self.verdict = "unsafe" if self.max_stress > self.limit else "unknown" if self.missing else "safe"

    def judged_by(self, summary):
        """The program's verdict and criterion from its summary, in place of the CSV's
        (a measured sheet's band reaching the limit makes it uncertain, which the CSV alone
        does not tell)."""
        self.verdict, self.criterion = summary.verdict, summary.criterion

    def _wind_ratio(self, table):
        """U / f in m (D / St: the frequency is St U / D) from the wind_speed_m_s column;
        None without it, or (with a warning) where it is not proportional to the frequency."""
        if "wind_speed_m_s" not in table:
            return None
        ratios = [u / f for u, f in zip(table.column("wind_speed_m_s"), self.frequency) if math.isfinite(u)]
        if not ratios or ratios[0] <= 0 or any(not math.isclose(r, ratios[0], rel_tol=1e-6) for r in ratios):
            warnings.warn(f"{self.path}: wind_speed_m_s is not proportional to frequency_hz (U = f D / St): "
                          "no wind speed axis")
            return None
        return ratios[0]

    def name(self, several):
        """The run's name in the title: its label among several files or when given, else its path."""
        return self.label if several or self.named else self.path

    def verdict_text(self, limit=True):
        """"safe, max 7.87 MPa at 23.4 Hz (limit 8.73 MPa)" (without the limit unless `limit`);
        "unsafe (microstrain criterion), max ..." where the summary names its criterion; a
        verdict other than the program's as it is given."""
        verdict = f"unknown ({points(self.missing)} missing)" if self.verdict == "unknown" else str(self.verdict)
        if self.criterion:
            verdict += f" ({self.criterion} criterion)"
        lower = f", {points(self.missing)} missing" if self.missing and self.verdict != "unknown" else ""
        return (f"{verdict}, max {self.max_stress:.3g} MPa at {self.frequency[self.peak]:.3g} Hz"
                f"{f' (limit {self.limit:.3g} MPa)' if limit else ''}{lower}")

    def undamped(self, name):
        return self.columns["undamped_" + name]

    def band_rows(self):
        """The converged rows where the measured sheet's band is given."""
        if self.band is None:
            return []
        low, high = self.band
        return [i for i in self.good if not math.isnan(low[i]) and not math.isnan(high[i])]

    def band_text(self):
        """"the sheet's band up to 9.1 MPa": how high the measured sheet's band reaches, for
        an uncertain verdict (None for another, or without a band)."""
        rows = self.band_rows()
        if self.verdict != "uncertain" or not rows:
            return None
        return f"the sheet's band up to {max(self.band[1][i] for i in rows):.3g} MPa"


class SpanSummary:
    """The summary of a span run (the object stockbridge span --json prints, the
    'summary' of stockbridge.span()'s result): the dampers' positions, the lives and
    the program's verdict (and its criterion, where it names one), which the CSV does
    not hold; its endurance limit and largest stress must be its CSV's. `strict`: the
    verdict must be one the program gives (a file's); else any text is shown as it is."""

    def __init__(self, data, path, strict=True):
        self.path = path
        if not isinstance(data, dict):
            raise PlotError(f"{path}: a JSON {type(data).__name__}, not an object: {SUMMARY_HINT}")
        self.data = data
        self.verdict = self._value("verdict", str)
        if strict and self.verdict not in PROGRAM_VERDICTS:
            raise PlotError(f"{path}: verdict = '{self.verdict}': expected {', '.join(PROGRAM_VERDICTS[:-1])} or "
                            f"{PROGRAM_VERDICTS[-1]}")
        criterion = data.get("criterion")
        self.criterion = None if criterion is None else str(criterion)
        self.positions = self._value("positions_m", list)
        for p in self.positions:
            if not self._is_number(p):
                raise PlotError(f"{path}: positions_m holds {json.dumps(p)}: expected positions in m")
        self.optimized = data.get("position_optimized") is True
        self.limit = self._number("endurance_limit_mpa")
        self.max_stress = self._number("max_stress_fymax_mpa", null=True)
        self.has_life = "life_years" in data  # the span file gives a climate
        self.life = self._number("life_years", null=True) if self.has_life else None
        self.damage = self._number("damage_per_year", null=True) if "damage_per_year" in data else None
        self.life_missing = self._number("life_missing_points", null=True) if "life_missing_points" in data else None
        self.undamped_life = (self._number("undamped_life_years", null=True) if "undamped_life_years" in data
                              else None)

    @classmethod
    def read(cls, path):
        """The summary in a JSON file (stockbridge span --json > path)."""
        return cls(read_json_summary(path, SUMMARY_HINT), path)

    @staticmethod
    def _is_number(value):
        return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)

    def _value(self, key, kind):
        if key not in self.data:
            raise PlotError(f"{self.path}: missing key '{key}': {SUMMARY_HINT}")
        value = self.data[key]
        if not isinstance(value, kind):
            raise PlotError(f"{self.path}: {key} = {json.dumps(value)}: expected a "
                            f"{'list' if kind is list else 'string' if kind is str else kind.__name__}")
        return value

    def _number(self, key, null=False):
        if key not in self.data:
            raise PlotError(f"{self.path}: missing key '{key}': {SUMMARY_HINT}")
        value = self.data[key]
        if value is None and null:
            return None
        if not self._is_number(value):
            raise PlotError(f"{self.path}: {key} = {json.dumps(value)}: expected a number")
        return value

    def check(self, run):
        """That this summary is of the run that wrote the CSV (the files given in the same
        order): the same limit and largest stress, and the same verdict where the CSV can
        tell it (safe, unsafe or unknown without a criterion named: stress against the limit)."""
        for key, mine, theirs in (("endurance_limit_mpa", self.limit, run.limit),
                                  ("max_stress_fymax_mpa", self.max_stress, run.max_stress)):
            if mine is None or not math.isclose(mine, theirs, rel_tol=1e-6):
                raise PlotError(f"{self.path}: {key} = {json.dumps(mine)} but {run.path}'s is {theirs:.6g}: expected "
                                "the summary of the run that wrote the CSV (one --summary per CSV, in their order)")
        if self.verdict in VERDICTS and self.criterion is None and self.verdict != run.verdict:
            raise PlotError(f"{self.path}: verdict = '{self.verdict}' but {run.path}'s is '{run.verdict}': expected "
                            "the summary of the run that wrote the CSV (one --summary per CSV, in their order)")

    def dampers_text(self):
        if not self.positions:
            return "no dampers"
        where = ", ".join(f"{p:.3g}" for p in self.positions)
        return f"damper{'s' if len(self.positions) > 1 else ''} at {where} m{' (optimized)' if self.optimized else ''}"

    def life_text(self, undamped=True):
        """"life 29 years (0.0015 without dampers)" (without the undamped life unless
        `undamped`); None without a climate in the span file."""
        if not self.has_life:
            return None
        if self.life is not None:
            text = f"life {years(self.life)} years"
        elif self.damage == 0:
            text = "no fatigue damage (no end of life)"
        elif self.life_missing:
            text = f"life unknown ({points(int(self.life_missing))} missing)"
        else:
            text = "life unknown"
        if undamped and self.positions and self.undamped_life is not None:
            text += f" ({years(self.undamped_life)} without dampers)"
        return text

    def text(self, undamped=True):
        return ", ".join(part for part in (self.dampers_text(), self.life_text(undamped)) if part)


def span_title(runs, summaries, shared_limit=True, shared_undamped=True):
    """A line per file: its name, verdict, largest stress and the limit; with a summary,
    the dampers' positions and the life, and of an uncertain verdict how high the
    measured sheet's band reaches (on a line of their own for one file). Of
    several files, the limit and the undamped life only when they differ between the
    files (else the legend and the undamped curve tell them). Lines longer than
    TITLE_WIDTH wrap."""
    several = len(runs) > 1
    lines = []
    for run, summary in zip(runs, summaries):
        head = f"{run.name(several)}: {run.verdict_text(limit=not several or not shared_limit)}"
        more = [text for text in (summary and summary.text(undamped=not several or not shared_undamped),
                                  run.band_text()) if text]
        if not more:
            lines.append(head)
        elif several:
            lines.append(f"{head}; {', '.join(more)}")
        else:
            lines += [head, ", ".join(more)]
    return "\n".join(textwrap.fill(line, TITLE_WIDTH, subsequent_indent="    ") for line in lines)


def lives_note(figure):
    """The note that lives are comparative, in small grey print under the axes."""
    figure.get_layout_engine().set(rect=(0, 0.035, 1, 0.965))
    figure.text(0.01, 0.008, LIVES_NOTE, fontsize="small", color="0.3", ha="left", va="bottom")


def same_undamped(first, other, names):
    """Whether two runs share their undamped curves: the same frequencies and, where
    both converged, the same undamped values."""
    if len(first.frequency) != len(other.frequency) or not all(
            math.isclose(a, b, rel_tol=1e-9) for a, b in zip(first.frequency, other.frequency)):
        return False
    both = set(first.good) & set(other.good)
    return all(math.isclose(first.undamped(name)[i], other.undamped(name)[i], rel_tol=1e-9, abs_tol=1e-15)
               for name in names for i in both)


def wind_axis(axis, runs):
    """A second x axis on top of a frequency axis: the wind speed U = f D / St that
    sheds vortices at f (m/s), when every run gives the same D / St; None otherwise."""
    ratios = [run.wind_ratio for run in runs]
    if any(r is None for r in ratios):
        return None
    if any(not math.isclose(r, ratios[0], rel_tol=1e-6) for r in ratios):
        warnings.warn(f"{', '.join(run.path for run in runs)}: the wind speed at a frequency differs between the "
                      "files (conductors or Strouhal numbers): no wind speed axis")
        return None
    ratio = ratios[0]
    top = axis.secondary_xaxis("top", functions=(lambda f: f * ratio, lambda u: u / ratio))
    low, high = sorted(axis.get_xlim())
    decades = math.log10(high / low) if axis.get_xscale() == "log" and low > 0 else None
    if decades is not None:
        top.xaxis.set_major_locator(LogLocator(subs=range(1, 10) if decades < 1 else (1.0, 2.0, 5.0) if decades <= 2
                                               else (1.0,)))
        top.xaxis.set_minor_formatter(NullFormatter())
    top.xaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    top.set_xlabel("wind speed U = f D / St (m/s)")
    return top


def span_figure(paths, labels=None, summaries=None):
    """The balance of one or more spans (or arrangements of one): the antinode
    amplitude, the fymax stress at the span clamp and, where every CSV has it, the
    outer wires' bending strain there (microstrain peak-to-peak, what field practice
    quotes), over frequency, with dampers and without, and the endurance limit (the
    CSVs' endurance_limit_mpa column) as a horizontal line; with a damper from a
    measured sheet, the band its interpolation leaves around the stress;
    non-converged frequencies as red crosses. Several files: one colour each, the
    undamped curve and the limit once when the files share them. The wind speed on
    a second x axis on top. The title carries each file's verdict and largest stress,
    and with a summary (stockbridge span --json) the dampers' positions and the life."""
    paths = [paths] if isinstance(paths, (str, os.PathLike)) else list(paths)
    runs = [SpanRun(path, label) for path, label in zip(paths, labels or [None] * len(paths))]
    summaries = [SpanSummary.read(path) for path in summaries] if summaries else [None] * len(runs)
    return spans_figure(runs, summaries)


def spans_figure(runs, summaries):
    """span_figure's figure of SpanRuns, each with its SpanSummary or None (whose
    verdict, checked against the run, is then the run's)."""
    for run, summary in zip(runs, summaries):
        if summary is not None:
            summary.check(run)
            run.judged_by(summary)
    several = len(runs) > 1
    strain = all(run.strain for run in runs)
    size = (FIGURE_SIZE[0], FIGURE_SIZE[1] * (1.4 if strain else 1.0))
    figure, axes = plt.subplots(3 if strain else 2, 1, figsize=size, sharex=True, layout="constrained")
    panels = [(axes[0], "amplitude_m", 1e3, "antinode amplitude Y (mm)"),
              (axes[1], "stress_fymax_mpa", 1.0, "fymax stress at the clamp (MPa)")]
    if strain:
        panels.append((axes[2], "bending_strain_pp_microstrain", 1.0, "strain at the clamp\n(microstrain p-p)"))
    shared = all(same_undamped(runs[0], run, [name for _, name, _, _ in panels]) for run in runs[1:])
    colours = ["C0"] if not several else [FILE_COLOURS[k % len(FILE_COLOURS)] for k in range(len(runs))]
    for axis, name, scale, ylabel in panels:
        if shared:
            first = max(runs, key=lambda run: len(run.good))
            axis.plot([first.frequency[i] for i in first.good], [scale * first.undamped(name)[i] for i in first.good],
                      "--", color="0.4", label="undamped")
        for run, colour in zip(runs, colours):
            f = [run.frequency[i] for i in run.good]
            if not shared:
                axis.plot(f, [scale * run.undamped(name)[i] for i in run.good], "--", color=colour, linewidth=1.0,
                          label=f"{run.label}, undamped")
            label = run.label if several else "with dampers" if run.damped else "balance"
            axis.plot(f, [scale * run.columns[name][i] for i in run.good], "-", color=colour,
                      marker="." if len(run.good) < 30 else None, label=label)
        axis.set_ylabel(ylabel)
        axis.grid(True, which="both", alpha=0.3)
    bands(axes[1], runs, colours)
    limit_lines(axes[1], runs, colours, lambda run: run.limit, "{:.3g} MPa")
    if strain:
        limit_lines(axes[2], runs, colours, lambda run: run.limit_strain, "{:.4g} microstrain")
    for run in runs:
        failed = [run.frequency[i] for i, ok in enumerate(run.converged) if not ok]
        if failed:
            axes[1].plot(failed, [0.0] * len(failed), "x", color="red",
                         label=f"{run.label}: not converged" if several else "not converged")
    curves = {"undamped"} | {run.label for run in runs} | {f"{run.label}, undamped" for run in runs}
    for number, axis in enumerate(axes):
        log_if_positive(axis)
        handles, names = axis.get_legend_handles_labels()
        if several and number > 0:  # the files' curves in the top panel's legend only
            kept = [k for k, n in enumerate(names) if n not in curves]
            handles, names = [handles[k] for k in kept], [names[k] for k in kept]
        axis.legend(handles, names, fontsize="small")
    frequency_scale(axes[0])  # shared; the limit lines are drawn across in axes units
    wind_axis(axes[0], runs)
    axes[-1].set_xlabel("frequency f (Hz)")
    shared_limit = all(math.isclose(run.limit, runs[0].limit, rel_tol=1e-9) for run in runs)
    axes[0].set_title(span_title(runs, summaries, shared_limit, shared), fontsize="medium")
    if any(summary is not None and summary.life_text() for summary in summaries):
        lives_note(figure)
    return figure


def bands(axis, runs, colours):
    """Each run's measured sheet's band (stress_fymax_low_mpa to stress_fymax_high_mpa),
    shaded in its colour where given (a run without a sheet has none)."""
    for run, colour in zip(runs, colours):
        rows = run.band_rows()
        if rows:
            low, high = run.band
            axis.fill_between([run.frequency[i] for i in rows], [low[i] for i in rows], [high[i] for i in rows],
                              color=colour, alpha=0.2, linewidth=0,
                              label=f"{run.label}: measured sheet's band" if len(runs) > 1 else "measured sheet's band")


def limit_lines(axis, runs, colours, limit, unit):
    """The endurance limit as a red horizontal line, once when every run has the same,
    else one per run in its colour, dotted."""
    values = [limit(run) for run in runs]
    if all(math.isclose(v, values[0], rel_tol=1e-9) for v in values):
        axis.axhline(values[0], color="C3", linewidth=1.0, label="endurance limit " + unit.format(values[0]))
        return
    for run, colour, value in zip(runs, colours, values):
        axis.axhline(value, color=colour, linestyle=":", linewidth=1.2,
                     label=f"{run.label}: endurance limit " + unit.format(value))


def plot_span(paths, output, labels=None, summaries=None):
    save(span_figure(paths, labels, summaries), output)


def span(result, output=None, *, labels=None):
    """plot span's figure of what stockbridge.span() returns: the amplitude, the fymax
    stress (with a measured sheet's band, where the result has one) and the strain over
    frequency, with the dampers and without, against the endurance limit; the title
    gives the verdict (the summary's: safe, unsafe, uncertain or unknown), the largest
    stress, the dampers' positions and the life. A list of results (arrangements of a
    span) is drawn on one figure, one colour each, named by `labels` (one per result;
    default "span", or "span 1", "span 2", ...). Returns the matplotlib Figure; with
    `output` (a path: .png, .pdf, .svg) also saves it there."""
    results, labels = listed(result, labels)
    runs, summaries = [], []
    for k, (r, label) in enumerate(zip(results, labels)):
        name = label or ("span" if len(results) == 1 else f"span {k + 1}")
        runs.append(SpanRun(result_table(r, "span", "frequency_hz", name), name))
        summary = r.get("summary")
        summaries.append(None if summary is None else SpanSummary(summary, f"{name}: summary", strict=False))
    return finish(spans_figure(runs, summaries), output)


# ---------------------------------------------------------------- design

DESIGN_FIGURES = ["objective", "max_stress_ratio", "max_stress_mpa", "frequency_at_max_hz", "total_mass_kg",
                  "messenger_curvature_max_per_m", "shortest_life_years", "converged", "feasible"]
DESIGN_STAGES = ("base", "sample", "polish")
LIFE_CAP_YEARS = 1e12  # the search compares an infinite life as this (design/study.cpp)


class Designs:
    """A design CSV (stockbridge design -o): per candidate its stage, run, variables,
    objective and whether it converged and is feasible; the objective's kind (max_stress:
    smaller is better, life: larger) from which column it repeats; the best candidate as
    the search chooses it (the first feasible one with the best objective)."""

    def __init__(self, path):
        table = Table(path)
        self.path = path
        header = table.header
        for name in ["stage", "run"] + DESIGN_FIGURES:
            if name not in table:
                raise PlotError(f"{path}: missing column '{name}': expected a design CSV (stockbridge design -o)")
        start, end = header.index("run") + 1, header.index("objective")
        self.variables = header[start:end]
        if header[0] != "stage" or not self.variables or header[end:end + len(DESIGN_FIGURES)] != DESIGN_FIGURES:
            raise PlotError(f"{path}: expected the columns stage, run, the variables, {', '.join(DESIGN_FIGURES)} "
                            "in this order (a design CSV; governing_span and governing_place before run and each span's figures after "
                            "them are allowed)")
        self.stage = table.text("stage")
        for i, stage in enumerate(self.stage):
            if stage not in DESIGN_STAGES:
                raise PlotError(f"{table.where(i)}: stage = '{stage}': expected base, sample or polish")
        self.converged = self._flags(table, "converged")
        self.feasible = self._flags(table, "feasible")
        for i, (ok, feasible) in enumerate(zip(self.converged, self.feasible)):
            if feasible and not ok:
                raise PlotError(f"{table.where(i)}: feasible = 1 but converged = 0: expected a feasible "
                                "candidate to have converged")
        self.run = table.required("run")
        self.x = {name: table.required(name) for name in self.variables}
        good = [i for i, ok in enumerate(self.converged) if ok]
        if not good:
            raise PlotError(f"{path}: no converged candidate to plot (converged = 0 in every row)")
        self.objective = table.column("objective", infinite=True)  # an infinite life is a result
        for i in good:
            if math.isnan(self.objective[i]):
                raise PlotError(f"{table.where(i)}: column 'objective' is empty: expected a number "
                                "(converged = 1)")
        self.life = self._is_life(table, good)
        self.best = self._best()
        self.ratio, self.stress, self.frequency, self.mass = (
            table.column(name) for name in ("max_stress_ratio", "max_stress_mpa", "frequency_at_max_hz", "total_mass_kg"))

    @staticmethod
    def _flags(table, name):
        values = table.required(name)
        for i, v in enumerate(values):
            if v not in (0.0, 1.0):
                raise PlotError(f"{table.where(i)}: {name} = {v:g}: expected 0 or 1")
        return [v == 1.0 for v in values]

    def _is_life(self, table, good):
        """Whether the objective is the shortest life (else the stress ratio), by the column it repeats."""
        for name, life in (("shortest_life_years", True), ("max_stress_ratio", False)):
            values = table.column(name, infinite=life)
            if all(values[i] == self.objective[i] for i in good):
                return life
        raise PlotError(f"{self.path}: objective is neither max_stress_ratio nor shortest_life_years: expected a "
                        "design CSV")

    def _best(self):
        feasible = [i for i, ok in enumerate(self.feasible) if ok]
        if not feasible:
            return None
        if self.life:
            return max(feasible, key=lambda i: min(self.objective[i], LIFE_CAP_YEARS))
        return min(feasible, key=lambda i: self.objective[i])

    def candidate(self, i):
        """A candidate's name: base, sample 12 or polish 1."""
        return self.stage[i] if self.stage[i] == "base" else f"{self.stage[i]} {self.run[i]:g}"

    def objective_label(self):
        return "shortest life (years)" if self.life else "largest stress / endurance limit (-)"


def design_groups(designs):
    """(label, rows, marker style) of the candidates drawn: the samples and the polishes,
    each feasible (filled) and infeasible (hollow), and the base (a black square)."""
    groups = []
    for stage, name, colour, marker, size in (("sample", "samples", "C0", "o", 5), ("polish", "polishes", "C1", "D", 5),
                                              ("base", "base", "black", "s", 7)):
        for feasible in (True, False):
            rows = [i for i, s in enumerate(designs.stage) if s == stage and designs.converged[i]
                    and designs.feasible[i] == feasible]
            label = f"{name}, {'feasible' if feasible else 'infeasible'}"
            style = {"marker": marker, "color": colour, "markersize": size, "markeredgewidth": 1.0,
                     "markerfacecolor": colour if feasible else "none", "linestyle": "none"}
            groups.append((label, rows, style))
    return groups


def draw_points(axis, x, y, label, style, top_marker="^"):
    """Markers at (x, y); an infinite y (an infinite life) is drawn at the panel's top
    edge, as an upward triangle unless `top_marker` says otherwise."""
    finite_rows = [k for k, v in enumerate(y) if math.isfinite(v)]
    top_rows = [k for k, v in enumerate(y) if v == math.inf]
    if finite_rows or not top_rows:
        axis.plot([x[k] for k in finite_rows], [y[k] for k in finite_rows], label=label, **style)
        label = None
    if top_rows:
        axis.plot([x[k] for k in top_rows], [0.97] * len(top_rows), transform=axis.get_xaxis_transform(),
                  clip_on=False, label=label, **dict(style, marker=top_marker))


def design_figure(path):
    """The objective of every candidate over each variable, one panel per variable
    (sharing the objective's axis): samples (blue circles) and polishes (orange
    diamonds), feasible filled and infeasible hollow, the base a black square, the best
    candidate a red star; candidates that did not converge as red crosses along the
    bottom; the legend in a panel of its own when there is room."""
    designs = Designs(path)
    n = len(designs.variables)
    cells = n + 1 if n > 1 else 1
    columns = 1 if cells == 1 else 2 if cells <= 4 else 3
    rows = -(-cells // columns)
    figure, axes = plt.subplots(rows, columns, figsize=FIGURE_SIZE, squeeze=False, sharey=True, layout="constrained")
    panels = list(axes.flat)
    failed = [i for i, ok in enumerate(designs.converged) if not ok]
    for axis, name in zip(panels, designs.variables):
        x = designs.x[name]
        for label, group, style in design_groups(designs):
            if group:
                draw_points(axis, [x[i] for i in group], [designs.objective[i] for i in group], label, style)
        if designs.best is not None:
            b = designs.best
            draw_points(axis, [x[b]], [designs.objective[b]], f"best ({designs.candidate(b)})",
                        {"marker": "*", "color": "C3", "markersize": 16, "markeredgecolor": "black",
                         "markeredgewidth": 0.8, "linestyle": "none", "zorder": 5}, top_marker="*")
        if failed:
            axis.plot([x[i] for i in failed], [0.03] * len(failed), "x", color="red",
                      transform=axis.get_xaxis_transform(), label="not converged")
        axis.set_xlabel(axis_label(name))
        axis.grid(True, alpha=0.3)
        few_ticks(axis)
    for axis in panels[::columns]:
        axis.set_ylabel(designs.objective_label())
    values = [v for i, v in enumerate(designs.objective) if designs.converged[i] and math.isfinite(v)]
    if designs.life and values and min(values) > 0 and max(values) >= 10 * min(values):
        log_scale(panels[0], "y")  # shared by every panel
    infinite = any(v == math.inf for v in designs.objective)
    if infinite and values:  # room above the finite values for the infinite ones at the top
        low, high = panels[0].get_ylim()
        panels[0].set_ylim(low, high * (high / low) ** 0.15 if panels[0].get_yscale() == "log"
                           else high + 0.15 * (high - low))
    handles, labels = panels[0].get_legend_handles_labels()
    if len(panels) > n:
        panels[n].legend(handles, labels, loc="center", fontsize="small")
        panels[n].axis("off")
        for axis in panels[n + 1:]:
            axis.set_visible(False)
    else:
        panels[0].legend(fontsize="small")
    figure.suptitle(design_title(designs, infinite), fontsize="medium")
    if designs.life:
        lives_note(figure)
    return figure


def design_title(designs, infinite):
    """The best candidate, its verdict (safe: its largest stress within every span's
    endurance limit), its objective, stress and mass; then the counts."""
    b = designs.best
    if b is None:
        head = f"{designs.path}: no feasible candidate"
    else:
        ratio = designs.ratio[b]
        verdict = "unknown" if math.isnan(ratio) else "safe" if ratio <= 1 else "unsafe"
        stress = (f"max {designs.stress[b]:.3g} MPa at {designs.frequency[b]:.3g} Hz, {ratio:.3g} x the endurance "
                  "limit")
        if designs.life:
            life = designs.objective[b]
            stress = ("no fatigue damage" if life >= LIFE_CAP_YEARS else f"shortest life {years(life)} years") + \
                f", {stress}"
        mass = f"; mass {designs.mass[b]:.3g} kg" if math.isfinite(designs.mass[b]) else ""
        head = f"{designs.path}: best {designs.candidate(b)}, {verdict}: {stress}{mass}"
    n = len(designs.stage)
    failed = sum(not ok for ok in designs.converged)
    counts = f"{sum(designs.feasible)} of {n} candidates feasible" + (f", {failed} not converged" if failed else "") + \
        (", infinite lives at the top" if infinite else "")
    return textwrap.fill(head, TITLE_WIDTH, subsequent_indent="    ") + "\n" + counts


UNITS_BY_KEY = {"mass": "kg", "inertia": "kg m²", "offset": "m", "length": "m", "mirror_length": "m",
                "lever_arm_cap": "m", "position": "m", "ei": "N m²", "c": "N m²", "h": "N m", "k0": "N",
                "position_loop_fraction": "of the shortest loop"}
UNITS_BY_SUFFIX = [("_n_m2", "N m²"), ("_kg_m2", "kg m²"), ("_n_s_m", "N s/m"), ("_n_m", "N m"), ("_per_m", "1/m"),
                   ("_m_s", "m/s"), ("_mpa", "MPa"), ("_pa", "Pa"), ("_hz", "Hz"), ("_kg", "kg"), ("_years", "years"),
                   ("_deg", "deg"), ("_rad", "rad"), ("_w", "W"), ("_s", "s"), ("_n", "N"), ("_m", "m"),
                   ("_percent", "%")]


def unit_of(name):
    """The unit of a design variable: by the damper file's key its path ends in
    (arm.left.mass: kg, arm.left.cable.jenkin[0].c: N m², position: m, as
    docs/damper.md and docs/file-formats.md give them), else by the name's suffix
    (_kg, _m, _mpa, _hz, _n, _n_m2, _years, ...); None when neither tells."""
    key = re.sub(r"\[\d+\]$", "", name.split(".")[-1]).lower()
    if key in UNITS_BY_KEY:
        return UNITS_BY_KEY[key]
    return next((unit for suffix, unit in UNITS_BY_SUFFIX if name.lower().endswith(suffix)), None)


def axis_label(name):
    """"arm.left.mass (kg)": a name and its unit (the name alone when it has none)."""
    unit = unit_of(name)
    return f"{name} ({unit})" if unit else name


def plot_design(path, output):
    save(design_figure(path), output)


# ---------------------------------------------------------------- line

VERDICT_COLOURS = {"safe": "C2", "unsafe": "C3", "uncertain": "C1", "unknown": "0.6"}
OTHER_VERDICT_COLOUR = "C4"  # a verdict a result gives that this module does not know
NOT_SAFE = ("unsafe", "uncertain", "unknown")  # the worst first: a line's verdict is its worst span's
LINE_TICK_LABELS = 24  # at most this many span ids along the x axis


class Schedule:
    """A line's schedule CSV (stockbridge line -o): per span its id, the largest fymax
    stress with the recommended dampers and without (MPa, NaN where empty: a balance
    that did not converge throughout), the endurance limit (MPa, per span: it depends
    on the conductor), the dampers per end and the verdict. Or the same columns of
    stockbridge.line()'s schedule (a ResultTable), whose verdicts are taken as they are."""

    def __init__(self, source):
        table = as_table(source)
        path = self.path = table.path
        for name in ("id", "verdict", "dampers_per_end", "max_stress_mpa", "undamped_max_stress_mpa",
                     "endurance_limit_mpa"):
            if name not in table:
                raise PlotError(f"{path}: missing column '{name}': expected a schedule CSV (stockbridge line -o)")
        self.id = table.text("id")
        self.verdict = table.text("verdict")
        for i, verdict in enumerate(self.verdict):
            if verdict not in PROGRAM_VERDICTS and not isinstance(table, ResultTable):
                raise PlotError(f"{table.where(i)}: verdict = '{verdict}': expected safe, unsafe, uncertain or "
                                "unknown")
        self.dampers = table.required("dampers_per_end")
        for i, n in enumerate(self.dampers):
            if n < 0 or n != int(n):
                raise PlotError(f"{table.where(i)}: dampers_per_end = {n:g}: expected a whole number >= 0")
        self.stress = table.column("max_stress_mpa")
        self.undamped = table.column("undamped_max_stress_mpa")
        self.limit = table.column("endurance_limit_mpa")
        for name, values in (("max_stress_mpa", self.stress), ("undamped_max_stress_mpa", self.undamped),
                             ("endurance_limit_mpa", self.limit)):
            for i, v in enumerate(values):
                if v <= 0:
                    raise PlotError(f"{table.where(i)}: {name} = {v:g}: expected a positive stress (MPa)")
        if not any(math.isfinite(v) for v in self.stress + self.undamped):
            raise PlotError(f"{path}: no stress to plot (max_stress_mpa and undamped_max_stress_mpa are empty in "
                            "every row)")
        self.life = table.column("life_years", infinite=True) if "life_years" in table else None

    def count(self, verdict):
        return sum(v == verdict for v in self.verdict)

    def verdicts(self):
        """The verdicts counted: safe, unsafe and unknown, then any other the spans have
        (uncertain), in the order they come."""
        return list(VERDICTS) + list(dict.fromkeys(v for v in self.verdict if v not in VERDICTS))

    def not_safe(self):
        """The verdicts other than safe that spans have, the worst first."""
        present = [v for v in self.verdicts() if v != "safe" and self.count(v)]
        return sorted(present, key=lambda v: NOT_SAFE.index(v) if v in NOT_SAFE else len(NOT_SAFE))

    def shortest_life(self):
        """The row of the shortest life with the dampers (an infinite one when every life
        is); None without a life_years column or a life in it."""
        rows = [i for i, v in enumerate(self.life or []) if not math.isnan(v)]
        return min(rows, key=lambda i: self.life[i]) if rows else None


def span_ticks(axis, ids):
    """Every span a minor tick, at most LINE_TICK_LABELS of them labelled with their
    ids (every k-th, from the first), slanted."""
    n = len(ids)
    step = max(1, math.ceil(n / LINE_TICK_LABELS))
    axis.set_xticks(range(n), minor=True)
    axis.set_xticks(range(0, n, step), [ids[i] for i in range(0, n, step)], rotation=60, ha="right",
                    rotation_mode="anchor", fontsize="small" if n > 12 else None)
    axis.set_xlim(-0.7, n - 0.3)


def verdict_colour(verdict):
    return VERDICT_COLOURS.get(verdict, OTHER_VERDICT_COLOUR)


def line_figure(path):
    """A line's schedule span by span along the line: the largest fymax stress at the
    span clamp with the recommended dampers (filled circles) and without (hollow
    grey circles, joined to it), and each span's endurance limit (a red step); unsafe
    spans shaded red and unknown ones grey on both panels; below, the dampers per
    end as bars coloured by verdict. The title gives the line's counts."""
    return schedule_figure(Schedule(path))


def schedule_figure(schedule):
    """line_figure's figure of a Schedule."""
    n = len(schedule.id)
    x = list(range(n))
    figure, (stress, dampers) = plt.subplots(2, 1, figsize=FIGURE_SIZE, sharex=True, layout="constrained",
                                             gridspec_kw={"height_ratios": [3, 2]})
    for i, verdict in enumerate(schedule.verdict):
        if verdict != "safe":
            for axis in (stress, dampers):
                axis.axvspan(i - 0.5, i + 0.5, color=verdict_colour(verdict), alpha=0.15, linewidth=0)
    both = [i for i in x if finite(schedule.stress[i], schedule.undamped[i])]
    stress.vlines(both, [schedule.stress[i] for i in both], [schedule.undamped[i] for i in both], color="0.75",
                  linewidth=1.0)
    stress.plot(x, schedule.undamped, "o", color="0.45", markerfacecolor="none", markersize=5, label="without dampers")
    stress.plot(x, schedule.stress, "o", color="C0", markersize=5, label="with the dampers")
    edges = [e for i in x for e in (i - 0.5, i + 0.5)]  # each span's limit across its width, joined as steps
    stress.plot(edges, [v for v in schedule.limit for _ in range(2)], color="C3", linewidth=1.2,
                label="endurance limit")
    values = plotted(stress, "y")
    log_scale(stress, "y")  # every value is positive
    low, high = min(values), max(values)
    stress.set_ylim(low / (high / low) ** 0.05, high * (high / low) ** 0.3)  # room for the legend on top
    stress.set_ylabel("largest fymax stress (MPa)")
    stress.grid(True, which="major", axis="y", alpha=0.3)
    handles, labels = stress.get_legend_handles_labels()
    for verdict in schedule.not_safe():
        handles.append(matplotlib.patches.Patch(color=verdict_colour(verdict), alpha=0.15))
        labels.append(f"{verdict} span")
    stress.legend(handles, labels, fontsize="small", ncol=len(handles) if len(handles) <= 5 else 3, loc="upper center")
    colours = [verdict_colour(v) for v in schedule.verdict]
    dampers.bar(x, schedule.dampers, width=0.7, color=colours)
    none = [i for i in x if schedule.dampers[i] == 0]
    if none:  # a span without dampers: its verdict's colour as a flat mark on the axis
        dampers.scatter(none, [0.0] * len(none), marker="_", s=60, linewidths=3,
                        c=[colours[i] for i in none], clip_on=False, zorder=3)
    dampers.set_ylim(0, max(max(schedule.dampers), 1) * 1.25 + 0.6)  # room for the legend on top
    most = int(max(schedule.dampers))
    dampers.set_yticks(range(0, most + 1, max(1, math.ceil(most / 6))))  # none above the largest count
    dampers.set_ylabel("dampers per end")
    dampers.set_xlabel("span (id), along the line")
    dampers.grid(True, axis="y", alpha=0.3)
    verdicts = schedule.verdicts()
    dampers.legend([matplotlib.patches.Patch(color=verdict_colour(v)) for v in verdicts],
                   [f"{v}: {schedule.count(v)}" for v in verdicts], fontsize="small", ncol=len(verdicts),
                   loc="upper left")
    span_ticks(dampers, schedule.id)
    stress.set_title(line_title(schedule), fontsize="medium")
    if schedule.shortest_life() is not None:
        lives_note(figure)
    return figure


LINE_TITLE_IDS = 6  # spans named in the title per verdict, at most


def line_title(schedule):
    """The line's verdict (its worst span's: unsafe if a span is, else uncertain, else
    unknown, else safe) and counts; below, the spans that are not safe by id and the
    shortest life."""
    counts = ", ".join(f"{schedule.count(v)} {v}" for v in schedule.verdicts())
    not_safe = schedule.not_safe()
    verdict = not_safe[0] if not_safe else "safe"
    details = []
    for v in not_safe:
        ids = [i for i, verdict_i in zip(schedule.id, schedule.verdict) if verdict_i == v]
        if ids:
            more = f" and {len(ids) - LINE_TITLE_IDS} more" if len(ids) > LINE_TITLE_IDS else ""
            details.append(f"{v}: {', '.join(ids[:LINE_TITLE_IDS])}{more}")
    shortest = schedule.shortest_life()
    if shortest is not None:
        i = shortest
        details.append("no fatigue damage on any span" if schedule.life[i] == math.inf else
                       f"shortest life {years(schedule.life[i])} years ({schedule.id[i]})")
    title = f"{schedule.path}: {verdict}: {len(schedule.id)} spans, {counts}"
    if details:
        title += "\n" + textwrap.fill("; ".join(details), TITLE_WIDTH, subsequent_indent="    ")
    return title


def plot_line(path, output):
    save(line_figure(path), output)


def line(result, output=None, *, label=None):
    """plot line's figure of what stockbridge.line() returns (or its 'schedule'): the
    largest stress of each span with the recommended dampers and without, against its
    endurance limit, and the dampers per end coloured by verdict; the title names the
    line (`label`, default "line"), its verdict and counts. Returns the matplotlib
    Figure; with `output` (a path: .png, .pdf, .svg) also saves it there."""
    schedule = result.get("schedule", result) if isinstance(result, dict) else result
    table = result_table(schedule, "line", "id", label or "line")
    return finish(schedule_figure(Schedule(table)), output)


# ---------------------------------------------------------------- span profile

def profile_figure(table, name="span", frequency=None):
    """The standing wave along the span (|Y(x)| and each stretch's antinode
    amplitude), the masses and dampers marked where they hang."""
    x = table.required("x_m")
    y = [1e3 * v for v in table.required("displacement_m")]
    envelope = [1e3 * v for v in table.required("envelope_m")]
    places = table.text("attachment")
    figure, axis = plt.subplots(1, 1, figsize=FIGURE_SIZE, layout="constrained")
    axis.plot(x, y, color="C0", linewidth=0.6, label="|Y(x)|")
    axis.plot(x, envelope, color="C1", linestyle="--", label="stretch's antinode |A| + |B|")
    top = 1.08 * max(envelope)
    marked = set()
    for i, place in enumerate(places):
        if not place:
            continue
        for item in place.split("; "):
            mass = item.endswith("(mass)")
            kind = "masses" if mass else "dampers"
            axis.axvline(x[i], color="C3" if mass else "C2", linewidth=0.8, alpha=0.6,
                         label=None if kind in marked else kind)
            axis.plot([x[i]], [top], marker="s" if mass else "o", color="C3" if mass else "C2", markersize=7)
            marked.add(kind)
    axis.set_xlabel("distance from end 1 (m)")
    axis.set_ylabel("amplitude, single peak (mm)")
    axis.set_xlim(min(x), max(x))
    axis.set_ylim(0.0, 1.12 * max(envelope))
    title = f"{name}: along the span"
    if frequency is not None:
        title += f" at {frequency:.3g} Hz"
    axis.set_title(title)
    axis.legend(loc="lower right")
    axis.grid(True, alpha=0.3)
    return figure


def plot_span_profile(path, output, label=None):
    table = Table(path)
    save(profile_figure(table, label or os.path.splitext(os.path.basename(path))[0]), output)


def span_profile(result, output=None, *, label=None):
    """plot span-profile's figure of what stockbridge.span() returns (its 'profile'):
    the standing wave along the span at the governing frequency, attachments marked.
    Returns the matplotlib Figure; with `output` also saves it there."""
    profile = result.get("profile") if isinstance(result, dict) and "profile" in result else result
    if profile is None:
        raise PlotError("span-profile: no point of the span converged: no profile to draw")
    table = result_table(profile, "span-profile", "x_m", label or "span")
    return finish(profile_figure(table, label or "span", profile.get("frequency_hz")), output)


# ---------------------------------------------------------------- recorder

def recorder_years(value):
    """A life from a JSON summary: null (no damage) is unlimited."""
    return "unlimited" if value is None or not math.isfinite(value) else years(value) + " years"


def recorder_figure(table, summary=None, name="recorder"):
    """The recorded matrix (Yb against frequency, cycles as colour, log scales) with
    the predicted Yb(f) over it (and the calibrated, where the summary has one)."""
    low, high = table.required("yb_pp_mm_low"), table.required("yb_pp_mm_high")
    f_low, f_high = table.required("frequency_hz_low"), table.required("frequency_hz_high")
    cycles = table.required("cycles")
    figure, axis = plt.subplots(1, 1, figsize=FIGURE_SIZE, layout="constrained")
    shown = [i for i in range(len(cycles)) if cycles[i] > 0 and high[i] > 0]
    if not shown:
        raise PlotError(f"{name}: no bin with cycles to draw")
    norm = matplotlib.colors.LogNorm(vmin=min(cycles[i] for i in shown), vmax=max(max(cycles[i] for i in shown),
                                                                             1.0001 * min(cycles[i] for i in shown)))
    colours = plt.get_cmap("YlOrRd")
    for i in shown:
        bottom = low[i] if low[i] > 0 else 0.5 * high[i]  # a bin from Yb = 0: drawn from half its upper edge
        axis.add_patch(matplotlib.patches.Rectangle((f_low[i], bottom), f_high[i] - f_low[i], high[i] - bottom,
                                                    facecolor=colours(norm(cycles[i])), edgecolor="white",
                                                    linewidth=0.5))
    bar = figure.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=colours), ax=axis)
    bar.set_label("cycles recorded")
    ys = [low[i] if low[i] > 0 else 0.5 * high[i] for i in shown] + [high[i] for i in shown]
    xs = [f_low[i] for i in shown] + [f_high[i] for i in shown]
    title = name
    if summary is not None:
        for key, label, style in (("predicted", "predicted Yb(f), the span file", "-"),
                                  ("calibrated", "calibrated", "--")):
            part = summary.get(key)
            if key == "calibrated" and part is not None:
                part = part.get("predicted")
            if not part:
                continue
            f = numpy.asarray(part.get("frequency_hz", []), dtype=float)
            yb = numpy.asarray([numpy.nan if v is None else v for v in part.get("yb_pp_mm", [])], dtype=float)
            if len(f) and len(f) == len(yb):
                axis.plot(f, yb, style, color="#1f77b4" if key == "predicted" else "#2ca02c", linewidth=2,
                          marker="o", markersize=3, label=label)
                ys += [v for v in yb if math.isfinite(v) and v > 0]
        measured, predicted = summary.get("measured") or {}, summary.get("predicted") or {}
        title = f"{name}: measured life {recorder_years(measured.get('life_years'))}, predicted " \
                f"{recorder_years(predicted.get('life_years'))}"
        calibrated = summary.get("calibrated")
        if calibrated and calibrated.get("predicted"):
            title += f", calibrated {recorder_years(calibrated['predicted'].get('life_years'))}"
        if axis.get_legend_handles_labels()[0]:
            axis.legend(loc="upper right")
    axis.set_xscale("log")
    axis.set_yscale("log")
    axis.set_xlim(min(xs) / 1.05, max(xs) * 1.05)
    axis.set_ylim(min(ys) / 1.2, max(ys) * 1.2)
    axis.set_xlabel("frequency (Hz)")
    axis.set_ylabel("Yb, peak-to-peak at 89 mm (mm)")
    axis.set_title("\n".join(textwrap.wrap(title, 80)), fontsize="medium")
    return figure


RECORDER_SUMMARY_HINT = "expected the JSON summary that stockbridge recorder --json prints"


def plot_recorder(path, output, summary_path=None):
    summary = None if summary_path is None else read_json_summary(summary_path, RECORDER_SUMMARY_HINT)
    save(recorder_figure(Table(path), summary, os.path.splitext(os.path.basename(path))[0]), output)


def recorder(result, output=None, *, label=None):
    """plot recorder's figure of what stockbridge.recorder() returns: the recorded
    matrix (Yb against frequency, cycles as colour, log scales) with the predicted
    Yb(f) over it before and after calibration; the title gives the measured,
    predicted and calibrated lives. Returns the matplotlib Figure; with `output` (a
    path: .png, .pdf, .svg) also saves it there."""
    table = result_table(result, "recorder", "cycles", label or "recorder")
    return finish(recorder_figure(table, result, label or "recorder"), output)


# ---------------------------------------------------------------- fatigue tests

FATIGUE_SUMMARY_HINT = "expected the JSON summary that stockbridge fatigue-tests --json prints"


def read_fatigue_summary(path):
    """The summary stockbridge fatigue-tests --json printed (a dict with 'fit')."""
    summary = read_json_summary(path, FATIGUE_SUMMARY_HINT)
    if not isinstance(summary, dict) or not isinstance(summary.get("fit"), dict):
        raise PlotError(f"{path}: no 'fit': {FATIGUE_SUMMARY_HINT}")
    return summary


def safe_border_stress(branches, cycles):
    """The Safe Border Line's stress (MPa) at `cycles`, from the summary's branches."""
    for branch in branches:
        until = branch["until"]
        if until is None or cycles <= until:
            return branch["a"] * cycles ** branch["b"]
    return branches[-1]["a"] * cycles ** branches[-1]["b"]


def fatigue_figure(table, summary=None):
    """The S-N plot of a fatigue-tests table: failures as dots, runouts as
    right-pointing triangles (censored: they would have lasted longer), failures
    below the Safe Border Line ringed red; with the summary the censored Basquin fit,
    its design curve (mean - 2 s) and the Safe Border Line of each layer count."""
    stress = table.required("stress_ps_mpa")
    cycles = table.required("cycles")
    failed = [v == 1 for v in table.required("failed")]
    below = [v == 1 for v in table.column("below_sbl")] if "below_sbl" in table else [False] * len(stress)
    figure, axis = plt.subplots(figsize=FIGURE_SIZE, layout="constrained")
    pick = lambda values, keep: [v for v, k in zip(values, keep) if k]  # noqa: E731
    runout = [not f for f in failed]
    axis.plot(pick(cycles, failed), pick(stress, failed), "o", color="C0", markersize=5,
              label=f"failures ({sum(failed)})")
    axis.plot(pick(cycles, runout), pick(stress, runout), ">", color="C0", markerfacecolor="none", markersize=7,
              label=f"runouts ({sum(runout)}, censored)")
    if any(below):
        axis.plot(pick(cycles, below), pick(stress, below), "o", color="C3", markerfacecolor="none", markersize=10,
                  label=f"failures below the Safe Border Line ({sum(below)})")
    low, high = min(cycles), max(cycles)
    n_low, n_high = 10 ** math.floor(math.log10(low)), 10 ** math.ceil(math.log10(high))
    grid = [n_low * (n_high / n_low) ** (k / 60) for k in range(61)]
    title = f"{table.path}: {len(stress)} tests"
    if summary is not None:
        fit = summary["fit"]
        a, b, s = fit["a"], fit["b"], fit["scatter"]
        if b < 0:
            axis.plot(grid, [10 ** ((math.log10(n) - a) / b) for n in grid], "-", color="C1",
                      label=f"Basquin fit: log10 N = {a:.3f} {b:+.3f} log10 σ")
            axis.plot(grid, [10 ** ((math.log10(n) - fit["design_a"]) / b) for n in grid], "--", color="C1",
                      label=f"design curve: mean - 2 s (s = {s:.3f})")
        for k, line in enumerate(summary.get("safe_border_lines", [])):
            axis.plot(grid, [safe_border_stress(line["branches"], n) for n in grid], ":", color=f"C{2 + k}",
                      linewidth=1.6, label=line["name"])
        below_sbl = fit.get("below_sbl", {})
        title += (f", {fit['failures']} failures, {fit['runouts']} runouts; "
                  f"{below_sbl.get('count', 0)} of the failures below the Safe Border Line "
                  f"({100 * below_sbl.get('fraction', 0):.3g} %)")
    axis.set_xscale("log")
    log_scale(axis, "y")  # stresses over a decade or two: labelled at 1, 2 and 5 times the powers of ten
    axis.set_xlabel("cycles N")
    axis.set_ylabel("Poffenberger-Swart stress, zero-to-peak (MPa)")
    axis.grid(True, which="major", alpha=0.3)
    axis.legend(fontsize="small", loc="lower left")
    axis.set_title(textwrap.fill(title, TITLE_WIDTH, subsequent_indent="    "), fontsize="medium")
    return figure


def plot_fatigue_tests(path, output, summary=None):
    save(fatigue_figure(Table(path), read_fatigue_summary(summary) if summary else None), output)


def fatigue_tests(result, output=None, *, label=None):
    """plot fatigue-tests' figure of what stockbridge.fatigue_tests() returns: the tests
    on S-N axes (failures, runouts, those below the Safe Border Line), the fit, its
    design curve and the Safe Border Line of each layer count present; the title
    names the tests (`label`, default "fatigue_tests"). Returns the matplotlib
    Figure; with `output` (a path: .png, .pdf, .svg) also saves it there."""
    check_result(result, "fatigue_tests", "table", "fit")
    table = result_table(result["table"], "fatigue_tests", "stress_ps_mpa", label or "fatigue_tests")
    return finish(fatigue_figure(table, result), output)


# ---------------------------------------------------------------- span modes

SPAN_MODES_SHOWN = 4  # shapes drawn where --modes does not say which


class ModeShapes:
    """The shapes of a span's modes along it: the samples `x` (m from end 1), each
    mode's shape by its number, and the attachments as (name, x)."""

    def __init__(self, name, x, shapes, attachments):
        self.name, self.x, self.shapes, self.attachments = name, x, shapes, attachments

    @classmethod
    def from_csv(cls, path):
        """The shapes CSV of stockbridge span --modes --shapes: attachment, x_m, mode_1, ..."""
        table = Table(path)
        x = table.required("x_m")
        shapes = {}
        for column in table.header:
            match = re.fullmatch(r"mode_(\d+)", column)
            if match:
                shapes[int(match.group(1))] = table.required(column)
        if not shapes:
            raise PlotError(f"{path}: no column mode_1, mode_2, ...: expected the shapes CSV of stockbridge span "
                            "--modes --shapes")
        attachments = []
        if "attachment" in table:
            for names, position in zip(table.text("attachment"), x):
                attachments += [(name, position) for name in names.split(";") if name]
        return cls(path, x, shapes, attachments)

    @classmethod
    def from_result(cls, result, name):
        """What stockbridge.span_modes() returns: 'x_m', 'shapes' (modes x samples), the
        summary's attachments."""
        check_result(result, "span_modes", "x_m", "shapes", "mode", "summary")
        shapes = numpy.asarray(result["shapes"], dtype=float)
        if shapes.ndim != 2 or shapes.shape[1] != len(result["x_m"]):
            raise PlotError(f"{name}: no shapes: expected stockbridge.span_modes(..., shapes=True)")
        attachments = [(a["name"], a["position_m"]) for a in result["summary"].get("attachments", [])]
        return cls(name, list(result["x_m"]), {int(n): list(shapes[i]) for i, n in enumerate(result["mode"])},
                   attachments)


def selected_modes(available, wanted, name):
    """The mode numbers to draw: `wanted` (each must be there), or the first few."""
    if wanted is None:
        return sorted(available)[:SPAN_MODES_SHOWN]
    missing = [n for n in wanted if n not in available]
    if missing:
        raise PlotError(f"{name}: no mode {missing[0]}: expected one of 1 to {max(available)}")
    return list(wanted)


def attachment_colours(attachments):
    """A colour per attachment name, in the order they first appear."""
    names = list(dict.fromkeys(name for name, _ in attachments))
    return {name: f"C{1 + k % 9}" for k, name in enumerate(names)}


def draw_mode_shape(axis, shapes, number, frequency, colours):
    """One mode's shape along the span, each attachment a dotted line and a dot on the shape."""
    axis.plot(shapes.x, shapes.shapes[number], "-", color="C0", linewidth=1.2)
    axis.axhline(0.0, color="0.7", linewidth=0.6)
    for name, position in shapes.attachments:
        axis.axvline(position, color=colours[name], linestyle=":", linewidth=1.0)
        y = numpy.interp(position, shapes.x, shapes.shapes[number])
        axis.plot([position], [y], "o", color=colours[name], markersize=5)
    axis.set_ylim(-1.15, 1.15)
    axis.set_yticks([-1.0, 0.0, 1.0])
    axis.set_ylabel(f"mode {number}" + ("" if frequency is None else f"\n{frequency:.4g} Hz"), fontsize="small")


def span_modes_figure(modes, shapes=None, wanted=None):
    """The shapes of a few modes (`wanted`, default the first four) along the span with
    the attachments marked, over the ratio of every mode's frequency to the bare
    span's of the same number (what the attachments move them by)."""
    numbers = [int(n) for n in modes.required("mode")]
    frequency = dict(zip(numbers, modes.required("frequency_hz")))
    ratio = modes.required("bare_frequency_ratio")
    drawn = [] if shapes is None else selected_modes(shapes.shapes, wanted, shapes.name)
    figure, axes = plt.subplots(len(drawn) + 1, 1, figsize=FIGURE_SIZE, layout="constrained",
                                height_ratios=[1.0] * len(drawn) + [1.4], squeeze=False)
    axes = [row[0] for row in axes]
    if drawn:
        colours = attachment_colours(shapes.attachments)
        for axis, number in zip(axes, drawn):
            draw_mode_shape(axis, shapes, number, frequency.get(number), colours)
            axis.set_xlim(min(shapes.x), max(shapes.x))
        for axis in axes[:len(drawn) - 1]:
            axis.tick_params(labelbottom=False)
        axes[len(drawn) - 1].set_xlabel("x, from end 1 (m); each shape Y / max|Y|")
        handles = [matplotlib.lines.Line2D([], [], color=c, linestyle=":", marker="o", markersize=5)
                   for c in colours.values()]
        if handles:
            axes[0].legend(handles, list(colours), fontsize="small", loc="lower right", bbox_to_anchor=(1.0, 1.0),
                           ncol=min(len(handles), 4), frameon=False, borderaxespad=0.2)  # above the shapes
    bottom = axes[-1]
    bottom.plot(numbers, ratio, "o-", color="C0", markersize=3, linewidth=0.8)
    bottom.axhline(1.0, color="0.5", linewidth=0.8, linestyle="--")
    bottom.set_xlabel("mode number n")
    bottom.set_ylabel("f / (n c / 2L)")
    bottom.grid(True, alpha=0.3)
    title = f"{modes.path}: {len(numbers)} modes from {min(frequency.values()):.4g} to {max(frequency.values()):.4g} Hz"
    figure.suptitle(textwrap.fill(title, TITLE_WIDTH), fontsize="medium")
    return figure


def mode_numbers(text):
    """--modes 1,2,5: mode numbers from 1."""
    try:
        numbers = [int(item) for item in text.split(",")]
    except ValueError:
        numbers = []
    if not numbers or any(n < 1 for n in numbers):
        raise PlotError(f"--modes = '{text}': expected mode numbers from 1, comma-separated (1,2,5)")
    return numbers


def plot_span_modes(path, output, shapes_path=None, wanted=None):
    shapes = None if shapes_path is None else ModeShapes.from_csv(shapes_path)
    save(span_modes_figure(Table(path), shapes, wanted), output)


def span_modes(result, output=None, *, modes=None, label=None):
    """plot span-modes' figure of what stockbridge.span_modes() returns: the shapes of
    `modes` (mode numbers; default the first four) along the span with its
    attachments marked, over every mode's frequency relative to the bare span's; the
    title names the span (`label`, default "span_modes"). Returns the matplotlib
    Figure; with `output` (a path: .png, .pdf, .svg) also saves it there."""
    name = label or "span_modes"
    table = result_table(result, "span_modes", "mode", name)
    return finish(span_modes_figure(table, ModeShapes.from_result(result, name), modes), output)


# ---------------------------------------------------------------- the span in time

def simulate_figure(table, summary=None, name="simulate"):
    """The history of stockbridge simulate: the displacement at each probe over time;
    with its summary also the envelope per period and the amplitude along the span,
    each beside the balance's antinode amplitude, the dampers marked."""
    time = table.required("time_s")
    probes = [c for c in table.header if re.fullmatch(r"y_at_\d+mm_m", c)]
    if not probes:
        raise PlotError(f"{name}: no column y_at_<mm>mm_m: expected the history CSV of stockbridge simulate")
    panels = 3 if summary else 1
    figure, axes = plt.subplots(panels, 1, figsize=FIGURE_SIZE, layout="constrained", squeeze=False)
    axes = [row[0] for row in axes]
    for k, column in enumerate(probes):
        millimetres = int(re.fullmatch(r"y_at_(\d+)mm_m", column).group(1))
        axes[0].plot(time, [1e3 * y for y in table.required(column)], "-", color=f"C{k % 10}", linewidth=0.5,
                     label=f"{millimetres / 1e3:g} m")
    axes[0].set_xlabel("t (s)")
    axes[0].set_ylabel("y (mm)")
    axes[0].legend(fontsize="small", loc="lower right", bbox_to_anchor=(1.0, 1.0), ncol=min(len(probes), 6),
                   frameon=False, borderaxespad=0.2, title="probes, from end 1", title_fontsize="small")  # above
    axes[0].grid(True, alpha=0.3)
    title = f"{name}: {len(time)} rows, {time[-1]:.4g} s" if len(time) else f"{name}: no rows"
    if summary:
        title = simulate_summary_panels(axes[1], axes[2], summary, name)
    figure.suptitle(textwrap.fill(title, TITLE_WIDTH), fontsize="medium")
    return figure


def simulate_summary_panels(envelope_axis, along_axis, summary, name):
    """The envelope per period and the amplitude along the span, the balance's antinode
    amplitude dashed; returns the title."""
    for key in ("envelope_m", "x_m", "amplitude_m", "frequency_hz", "dt_s", "settled"):
        if key not in summary:
            raise PlotError(f"{name}: the summary has no '{key}': expected what stockbridge simulate --json printed")
    ebm = summary.get("ebm_antinode_amplitude_m")
    period_s = 1.0 / summary["frequency_hz"]
    envelope = summary["envelope_m"]
    envelope_axis.plot([period_s * (i + 1) for i in range(len(envelope))], [1e3 * y for y in envelope], "-",
                       color="C0", linewidth=1.0, label="simulation, mid-span")
    along_axis.plot(summary["x_m"], [1e3 * y for y in summary["amplitude_m"]], "-", color="C0", linewidth=0.4,
                    alpha=0.5, label="simulation, |y|, last period")
    if "antinode_along_m" in summary:  # the standing wave's envelope (|y| at the nodes samples it)
        along_axis.plot(summary["x_m"], [1e3 * y for y in summary["antinode_along_m"]], "-", color="C0",
                        linewidth=1.2, label="simulation, local antinode amplitude")
    for axis in (envelope_axis, along_axis):
        if ebm is not None:
            axis.axhline(1e3 * ebm, color="C3", linestyle="--", linewidth=1.0, label="energy balance")
        axis.grid(True, alpha=0.3)
        axis.legend(fontsize="small", loc="lower right")
    for damper in summary.get("dampers", []):
        along_axis.axvline(damper["position_m"], color="0.4", linestyle=":", linewidth=1.0)
    envelope_axis.set_xlabel("t (s)")
    envelope_axis.set_ylabel("Y (mm)")
    along_axis.set_xlabel("x, from end 1 (m); dampers dotted")
    along_axis.set_ylabel("amplitude (mm)")
    ratio = summary.get("antinode_amplitude_m_ratio")
    state = (f"settled, Y / balance's {ratio:.3f}" if summary["settled"] and ratio is not None
             else "settled" if summary["settled"] else "not settled")
    return f"{name}: {summary['frequency_hz']:.4g} Hz, {summary.get('simulated_s', 0.0):.4g} s simulated, {state}"


def plot_simulate(path, output, summary_path=None):
    summary = None if summary_path is None else read_json_summary(summary_path, "stockbridge simulate --json")
    save(simulate_figure(Table(path), summary, os.path.basename(path)), output)


def simulate(result, output=None, *, label=None):
    """plot simulate's figure of what stockbridge.simulate() returns: the displacement
    at each probe over time, the envelope per period and the amplitude along the span
    beside the balance's antinode amplitude. Returns the matplotlib Figure; with
    `output` (a path: .png, .pdf, .svg) also saves it there."""
    name = label or "simulate"
    table = result_table(result, "simulate", "time_s", name)
    check_result(result, "simulate", "summary")
    return finish(simulate_figure(table, result["summary"], name), output)


# ---------------------------------------------------------------- command line

class Parser(argparse.ArgumentParser):
    """Usage errors in one line, exit status 2."""

    def error(self, message):
        self.exit(2, f"{PROGRAM}: {message} (see {self.prog} --help)\n")


def parser():
    result = Parser(prog="python3 -m stockbridge.plot", description=__doc__.splitlines()[0])
    commands = result.add_subparsers(dest="command", required=True, parser_class=Parser)
    impedance = commands.add_parser("impedance", help="|Z| and phase (or Re and Im) over frequency, of one or more "
                                    "files")
    impedance.add_argument("csv", nargs="+", help="impedance CSV files, drawn on one figure")
    impedance.add_argument("-o", "--output", required=True)
    impedance.add_argument("--label", action="append", help="a file's name in the legend (once per file, in order)")
    impedance.add_argument("--re-im", action="store_true", help="plot Re Z and Im Z instead of |Z| and phase")
    impedance.add_argument("--linear", action="store_true", help="linear axes")
    impedance.add_argument("--power", action="store_true", help="add a panel: dissipated power Re Z V^2 / 2")
    span = commands.add_parser("span", help="amplitude and fymax stress over frequency, damped and undamped, of "
                               "one or more span CSVs, with their verdicts")
    span.add_argument("csv", nargs="+", help="span CSV files (stockbridge span -o), drawn on one figure")
    span.add_argument("-o", "--output", required=True)
    span.add_argument("--label", action="append", help="a file's name in the legend and title (once per file, in "
                      "order; default: the file's name without .csv)")
    span.add_argument("--summary", action="append", metavar="FILE.json",
                      help="the JSON summary stockbridge span --json printed for a file (once per file, in order): "
                      "the dampers' positions and the life in the title")
    profile = commands.add_parser("span-profile", help="the standing wave along a span at its governing frequency, "
                                  "masses and dampers marked (stockbridge span --profile)")
    profile.add_argument("csv", help="the profile CSV (stockbridge span --profile)")
    profile.add_argument("-o", "--output", required=True)
    profile.add_argument("--label", help="the span's name in the title (default: the file's name without .csv)")
    rec = commands.add_parser("recorder", help="a recorder's matrix (Yb against frequency, cycles as colour) from "
                              "the bins CSV of stockbridge recorder, with the predicted Yb(f)")
    rec.add_argument("csv", help="the bins CSV (stockbridge recorder -o)")
    rec.add_argument("-o", "--output", required=True)
    rec.add_argument("--summary", metavar="FILE.json", help="what stockbridge recorder --json printed: the "
                     "predicted and calibrated Yb(f) and the lives")
    fatigue = commands.add_parser("fatigue-tests", help="S-N plot of a fatigue-tests CSV: failures, runouts, the "
                                  "fit, its design curve and the Safe Border Line")
    fatigue.add_argument("csv", help="the CSV stockbridge fatigue-tests -o wrote")
    fatigue.add_argument("-o", "--output", required=True)
    fatigue.add_argument("--summary", metavar="FILE.json",
                         help="the JSON summary stockbridge fatigue-tests --json printed: the fit, its design curve "
                         "and the Safe Border Lines")
    modes = commands.add_parser("span-modes", help="a span's mode shapes with its attachments marked and its "
                                "frequencies against the bare span's (stockbridge span --modes)")
    modes.add_argument("csv", help="the modes CSV (stockbridge span --modes -o)")
    modes.add_argument("-o", "--output", required=True)
    modes.add_argument("--shapes", metavar="FILE.csv", help="the shapes CSV (stockbridge span --modes --shapes): "
                       "the shapes along the span")
    modes.add_argument("--modes", help="the modes whose shapes to draw, e.g. 1,2,5 (default: the first four)")
    sim = commands.add_parser("simulate", help="the span in time: displacements over time, the envelope and the "
                              "amplitude along the span beside the energy balance's (stockbridge simulate)")
    sim.add_argument("csv", help="the history CSV (stockbridge simulate -o)")
    sim.add_argument("-o", "--output", required=True)
    sim.add_argument("--summary", metavar="FILE.json", help="what stockbridge simulate --json printed: the envelope, "
                     "the amplitude along the span and the balance's")
    for name, text in (("loop", "hysteresis loops of a cycle, response or loop file"),
                       ("fit", "measured and fitted loops or impedance (identify ... --fitted)"),
                       ("design", "objective over each variable of a design CSV: feasible, infeasible, polished, "
                        "best"),
                       ("line", "stresses with and without dampers and the dampers per end, span by span, of a "
                        "schedule CSV (stockbridge line)")):
        command = commands.add_parser(name, help=text)
        command.add_argument("csv")
        command.add_argument("-o", "--output", required=True)
    return result


def run(args):
    if args.command == "impedance":
        if args.label and len(args.label) != len(args.csv):
            raise PlotError(f"{len(args.label)} --label for {len(args.csv)} files: expected one per file")
        plot_impedance(args.csv, args.output, args.label, args.re_im, args.linear, args.power)
    elif args.command == "loop":
        plot_loop(args.csv, args.output)
    elif args.command == "span":
        for option, values in (("--label", args.label), ("--summary", args.summary)):
            if values and len(values) != len(args.csv):
                raise PlotError(f"{len(values)} {option} for {len(args.csv)} span CSV files: expected one per file, "
                                "in their order")
        plot_span(args.csv, args.output, args.label, args.summary)
    elif args.command == "recorder":
        plot_recorder(args.csv, args.output, args.summary)
    elif args.command == "span-profile":
        plot_span_profile(args.csv, args.output, args.label)
    elif args.command == "design":
        plot_design(args.csv, args.output)
    elif args.command == "line":
        plot_line(args.csv, args.output)
    elif args.command == "fatigue-tests":
        plot_fatigue_tests(args.csv, args.output, args.summary)
    elif args.command == "simulate":
        plot_simulate(args.csv, args.output, args.summary)
    elif args.command == "span-modes":
        plot_span_modes(args.csv, args.output, args.shapes, None if args.modes is None else mode_numbers(args.modes))
    else:
        plot_fit(args.csv, args.output)


def main(argv=None):
    args = parser().parse_args(argv)
    matplotlib.use("Agg")  # files only; imported as a library, pyplot's backend stays the user's
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            run(args)
    except PlotError as error:
        print(f"{PROGRAM}: {error}", file=sys.stderr)
        return 2
    finally:
        for warning in caught:  # as the program prints them: one "warning:" line each
            print(f"warning: {warning.message}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
