"""stockbridge: Stockbridge damper impedance from a distributed Masing cable model.

The numerics live in the C++ library; this package binds it (``stockbridge._core``,
built by the CMake project) and adds plots (``python3 -m stockbridge.plot`` of the CSV
files; ``stockbridge.plot.span(result, "span.png")``, ``line`` and ``impedance`` of what
span, line and impedance return, after ``import stockbridge.plot``).

    import stockbridge as sb
    damper = sb.load_damper("examples/sauter2003.toml")
    z = sb.impedance(damper, [10.0, 20.0], velocity=[0.2, 0.05])
    s = sb.span("examples/aster570_400m.toml", points=50)
    modes = sb.span_modes("examples/aster570_400m.toml", fmax=10)   # natural frequencies, shapes
    sim = sb.simulate("examples/aster570_400m.toml", frequency=20)  # the span in time beside the balance
    drake = sb.conductor("ACSR Drake")   # the catalogue's [conductor] values, EI_min 44.25 N m^2
    d = sb.design("examples/design_aster570.toml", samples=16, threads=2)
    schedule = sb.line("examples/line_short.toml", threads=2)["schedule"]
    fit = sb.identify_impedance(sb.load_damper("examples/damper_to_identify.toml"),
                                "examples/measured_impedance.csv")
"""

import json

import numpy

from . import _toml


class UnusualValueWarning(UserWarning):
    """A value outside the typical ranges of Stockbridge dampers and their tests
    (docs/file-formats.md): accepted, but most often a unit mistake. The CLI prints
    the same text as a "warning:" line."""


try:
    from ._core import __version__  # noqa: F401  (the library's, as stockbridge --version)
    from ._core import (Cable, Damper, Error, InputError, InvalidParameter, NumericalError,  # noqa: F401
                        UnusualValueError, conductor,
                        conductors, cycle, identify_global, identify_local, impedance, load_cable, load_conductor,
                        load_damper, load_strand, loop, modes, response, strand_bounds)
    from ._core import (_cable_from_toml, _damper_from_toml, _defaults, _design, _identify_impedance, _line,  # noqa: F401
                        _fatigue_tests, _identify_self_damping, _recorder, _span)
    from ._core import _simulate, _span_modes  # noqa: F401
except ImportError:  # the plots work from the source tree without the compiled module
    _defaults = {}  # the library's defaults come with it


def _from_values(build, text, source, allow_unusual=False):
    """The library's reader on text made from Python values: its errors name the
    values, not a file, so they are InvalidParameter (a ValueError); a value a unit
    slip explains stays an UnusualValueError (allow_unusual=True takes it)."""
    try:
        return build(text, source, allow_unusual)
    except UnusualValueError:
        raise
    except InputError as error:
        raise InvalidParameter(str(error)) from None


def _pair(element):
    c, h = element  # a (c, h) pair; more or fewer values is an error, not silently dropped
    return c, h


def make_cable(length, sections=40, ei=None, jenkin=(), law=None, allow_unusual=False, **keys):
    """A cable with the keys of a cable file's [cable] table: length (m), sections,
    and the section law's numbers. The Masing law (the default): ei (N m^2),
    jenkin = [(c, h), ...] or [{"c": ..., "h": ..., "k0": ...}, ...] (N m^2, N m),
    optionally lever_arm_cap. Another law (law="bouc-wen", ...): its numbers by key,
    as its cable files name them and Cable's properties give them (Bouc-Wen: ei_min,
    ei_max (N m^2) and chi0 (1/m)). Optionally mirror_length; any value may be a profile
    {"s": [...], "value": [...]}. Checked exactly as a cable file is (a misspelt or
    missing key, a key of the other law, a bad value: InvalidParameter naming it; a
    value a unit slip explains, a length of 187.5 for 0.1875 m: UnusualValueError,
    unless `allow_unusual`)."""
    elements = [e if isinstance(e, dict) else dict(zip(("c", "h"), _pair(e))) for e in jenkin]
    entries = {"length": length, "sections": sections, **keys}
    if law is not None:
        entries = {"law": law, **entries}
    if elements or law in (None, "masing"):
        entries["jenkin"] = elements
    if ei is not None:
        entries["ei"] = ei
    return _from_values(_cable_from_toml, _toml.table("cable", entries), "make_cable", allow_unusual)


def make_damper(clamp_mass, arms, allow_unusual=False):
    """A damper from arms given as dicts {name, mass, inertia, offset, cable} (kg,
    kg m^2, m; cable a Cable or a dict of a cable table's keys), and optionally
    length (m): the arm's cable length, cutting the Cable (identified once, on any
    length) to it. Checked exactly as a damper file is (a misspelt or missing key, a
    bad value: InvalidParameter naming it; a value a unit slip explains, a mass of
    856 for 0.856 kg: UnusualValueError, unless `allow_unusual`)."""
    text = _toml.table("clamp", {"mass": clamp_mass})
    for arm in arms:
        arm = dict(arm)
        cable = arm.pop("cable", None)
        if "length" in arm:
            length = arm.pop("length")
            if not hasattr(cable, "with_length"):
                raise InvalidParameter(f"length = {length!r}: goes with cable = a Cable (in a dict of cable keys, "
                                       "give the cable's own 'length')")
            cable = cable.with_length(length)
        text += "[[arm]]\n" + "".join(f"{_toml.key(k)} = {_toml.value(v)}\n" for k, v in arm.items())
        if cable is not None:
            text += _toml.table("arm.cable", cable)
    return _from_values(_damper_from_toml, text, "make_damper", allow_unusual)


_TENSION_FORMS = ("tension", "tension_fraction", "catenary_parameter")


def _span_spec(file, text, spec, base):
    """The span description as tomllib's dict and the folder its relative paths start at."""
    import copy
    import os
    import tomllib
    given = [name for name, v in (("file", file), ("text", text), ("spec", spec)) if v is not None]
    if len(given) != 1:
        raise InvalidParameter("give one of file (a span file's path), text (its contents) and spec (a dict of its "
                               f"tables), not {' and '.join(given) or 'none'}")
    if file is not None:
        with open(file, "rb") as handle:
            try:
                return tomllib.load(handle), os.path.dirname(os.path.abspath(file))
            except tomllib.TOMLDecodeError as e:
                raise InputError(f"{file}: TOML syntax error: {e}") from None
    if text is not None:
        try:
            return tomllib.loads(text), base
        except tomllib.TOMLDecodeError as e:
            raise InputError(f"span(text=...): TOML syntax error: {e}") from None
    return copy.deepcopy(dict(spec)), base


def _mass_entries(masses):
    """[[mass]] tables of `masses`: dicts as a span file's (name, mass, positions,
    stress_factor), or (mass, positions) and (mass, positions, name) tuples."""
    entries = []
    for k, m in enumerate(masses):
        if isinstance(m, dict):
            entries.append(dict(m))
            continue
        if not isinstance(m, (tuple, list)) or len(m) not in (2, 3):
            raise InvalidParameter(f"masses[{k}] = {m!r}: expected a dict (name, mass, positions, stress_factor) or "
                                   "(mass kg, [positions m from end 1]) with an optional name third")
        entry = {"mass": float(m[0]), "positions": [float(x) for x in m[1]]}
        if len(m) == 3:
            entry["name"] = str(m[2])
        entries.append(entry)
    return entries


def _override(spec, damper, positions, ends, tension, tension_fraction, catenary_parameter, length, conductor_type,
              masses=None):
    """The span description with the overrides applied, each as the span file would say it."""
    forms = {name: v for name, v in zip(_TENSION_FORMS, (tension, tension_fraction, catenary_parameter)) if v is not None}
    if len(forms) > 1:
        raise InvalidParameter(f"give one of tension, tension_fraction and catenary_parameter, not {' and '.join(forms)}")
    section = spec.setdefault("span", {})
    if forms:
        for name in _TENSION_FORMS:
            section.pop(name, None)
        section.update(forms)
    if length is not None:
        section["length"] = length
    if conductor_type is not None:
        spec["conductor"] = {"type": conductor_type}
    dampers = spec.get("damper", [])
    if damper is not None:
        path = str(damper)
        which = "impedance" if path.lower().endswith(".csv") else "file"
        template = {"file": path} if which == "file" else {"impedance": path}
        dampers = [dict({k: v for k, v in d.items() if k not in ("file", "impedance")}, **template) for d in dampers]
        if not dampers and positions is None:
            raise InvalidParameter("damper: the span has no [[damper]] to replace: give positions too")
        if not dampers:
            dampers = [template]
    if positions is not None:
        if not dampers:
            raise InvalidParameter("positions: the span has no [[damper]] to place: give damper too")
        model = {k: v for k, v in dampers[0].items() if k not in ("position", "positions")}
        dampers = [dict(model, position=float(a)) for a in positions]
    if ends is not None:
        dampers = [dict(d, ends=ends) for d in dampers]
    if dampers:
        spec["damper"] = dampers
    if masses is not None:
        spec.pop("mass", None)
        if masses:
            spec["mass"] = _mass_entries(masses)
    return spec


def span(file=None, frequencies=None, points=_defaults.get("span_points"), no_dampers=False, damper_model=None,
         optimize_position=None, threads=_defaults.get("span_threads"), text=None, spec=None, base=None,
         damper=None, positions=None, ends=None, tension=None, tension_fraction=None, catenary_parameter=None,
         length=None, conductor_type=None, spacing_min=_defaults.get("span_spacing_min"),
         objective=_defaults.get("span_objective"), report=None, allow_unusual=False, masses=None,
         no_attachments=False, check_time=()):
    """The energy balance of a span over the wind band, as ``stockbridge span``.

    The span: a span file's path (`file`; its relative paths start at its folder), its
    contents (`text`) or its tables as a dict (`spec`, as tomllib reads a span file);
    the relative paths of `text` and `spec` start at `base` (default: the working
    directory; a missing file's message names the folder). Overrides, each as the
    span file would say it, without editing text: `damper` (a damper file, or a
    measured sheet's CSV, for every [[damper]]), `positions` (m from the clamp: one
    damper per position, the first [[damper]]'s kind), `ends` ("both" or "one"),
    one of `tension` (N), `tension_fraction` and `catenary_parameter` (H/w, m),
    `length` (m), `conductor_type` (the catalogue's, replacing [conductor]),
    `masses` (replacing the file's [[mass]] entries: dicts as a span file's, or
    (mass kg, [positions m from end 1]) tuples; [] for the span without them: "with
    and without warning spheres").
    `frequencies` (Hz, increasing) or `points` log-spaced over the band;
    `no_dampers`; `no_attachments` (without the masses and the dampers along the
    span, as --no-attachments); `damper_model` "travelling" or "weak" (None: the span file's
    [balance] damper_model, travelling by default); `optimize_position` = (amin,
    amax) in m to search every damper's position first (each its own, at least
    `spacing_min` m apart, minimising `objective`: "max_stress" or "life"; the
    positions found in the summary's positions_m); `threads` for the dampers'
    impedance tables; `report` a path: also write the HTML report there (as ``span
    --report``: self-contained, printable on A4). A value a unit slip explains (a
    tension of 30.3 for kN) and a tension no span hangs at are refused
    (UnusualValueError) unless `allow_unusual` (as --allow-unusual: a warning).

    Returns a dict: one array per column of the span CSV, by the CSV's names (stresses
    in MPa; NaN where a point did not converge), 'converged' and 'several_states'
    (bool arrays), 'termination', 'messages' and 'notes' (per point), 'dampers' (the
    <name> of the per-damper columns), 'columns' (the CSV's order), 'profile' (the
    standing wave along the span at the governing frequency, as ``span --profile``
    writes it: arrays x_m, displacement_m, envelope_m, attachment, and frequency_hz;
    None where no point converged) and 'summary': the --json summary's keys (None
    where the JSON has null; a life is None where a point is missing,
    life_missing_points says how many). `check_time` (Hz, as ``span --check-time``):
    the span also simulated in time at each frequency, the summary's 'check_time' a
    dict per frequency (the simulation's figures, the balance's and their ratios,
    'agrees'), a warning where they part by more than 10 %."""
    overrides = (damper, positions, ends, tension, tension_fraction, catenary_parameter, length, conductor_type, masses)
    if spec is None and all(v is None for v in overrides):
        out = _span(file=None if file is None else str(file), text=text, base=None if base is None else str(base),
                    frequencies=frequencies, points=points, no_dampers=no_dampers, no_attachments=no_attachments,
                    damper_model=damper_model,
                    optimize_position=None if optimize_position is None else tuple(optimize_position),
                    spacing_min=spacing_min, objective=objective, threads=threads,
                    check_time=[float(f) for f in check_time], report=report is not None, allow_unusual=allow_unusual)
    else:
        described, folder = _span_spec(file, text, spec, None if base is None else str(base))
        described = _override(described, *overrides)
        out = _span(text=_toml.document(described), base=folder, frequencies=frequencies, points=points,
                    no_dampers=no_dampers, no_attachments=no_attachments, damper_model=damper_model,
                    optimize_position=None if optimize_position is None else tuple(optimize_position),
                    spacing_min=spacing_min, objective=objective, threads=threads,
                    check_time=[float(f) for f in check_time], report=report is not None, allow_unusual=allow_unusual)
    out["summary"] = json.loads(out.pop("summary_json"))
    _write_report(report, out)
    return out


def recorder(span, counts, days, calibrate=(), allow_unusual=False, points_per_band=3):
    """A vibration recorder's counts against a span, as ``stockbridge recorder``.

    `span` a span file's path (with [fatigue] wind_weibull and aeolian_fraction),
    `counts` the recorder's CSV (the neutral form, one row per bin, or the matrix
    form: docs/measurements.md), `days` the record's length. `calibrate`: keys to fit
    on the record ("wind.turbulence_intensity", "wind.power_scale",
    "self_damping.k"; one, or one of the wind's with self_damping.k).
    `points_per_band` balance frequencies per frequency band of the record. A Yb a
    unit slip explains (m or um for mm) is refused (UnusualValueError) unless
    `allow_unusual`.

    Returns a dict: the --json summary's keys ('measured', 'predicted' with its
    'bands', 'calibrated' or None, 'failed_points', 'seconds_per_balance'), one array
    per column of the bins CSV by its names (yb_pp_mm_low, ..., stress_ps_mpa,
    microstrain_pp, cycles_to_failure, damage), and 'columns' (the CSV's order)."""
    if isinstance(calibrate, str):
        calibrate = [calibrate]
    out = _recorder(str(span), str(counts), float(days), list(calibrate), int(points_per_band), bool(allow_unusual))
    out.update(json.loads(out.pop("summary_json")))
    return out


def _write_report(path, out):
    """Writes the HTML report a function made (`out`'s 'report_html') to `path`, if given."""
    html = out.pop("report_html", None)
    if path is not None:
        with open(path, "w", encoding="utf-8") as f:
            f.write(html)


def line(file=None, text=None, base=None, threads=1, report=None, allow_unusual=False):
    """The damper schedule of a line, as ``stockbridge line``: for every span the
    fewest dampers per end, of which type and where, that make it safe.

    The line: a line file's path (`file`; its relative paths start at its folder) or
    its contents (`text`, whose relative paths start at `base`, default the working
    directory), one of the two. `threads` spans computed at once, sharing the
    dampers' impedance tables (the same schedule for any number). Minutes for a real
    line; Ctrl-C stops it (KeyboardInterrupt), nothing returned. `report` a path:
    also write the HTML report there (as ``line --report``). A value a unit slip
    explains is refused (UnusualValueError) unless `allow_unusual`.

    Returns a dict: 'schedule', one array per column of the schedule CSV by its names,
    one value per span in the line's order (id, conductor, undamped_verdict,
    damper_type, positions_m, verdict, warnings and governing_place lists of str;
    dampers_per_end, sphere_dampers, converged_points, points and search_balances
    int; converged and terrain_hw_within bool; the rest float, NaN where the CSV's cell is empty: a
    stress or life of a balance that did not converge throughout); 'bill', the bill
    of materials CSV's columns (damper_type, dampers, spans, mass_kg); 'summary', the
    --json summary's keys (spans, spans_safe, spans_unsafe, spans_unknown, bill,
    governing_span, ...; None where the JSON has null; without the command's ranks,
    threads and seconds); 'warnings', the line file's values outside the typical
    ranges (each also an UnusualValueWarning; a span's own warnings are in its
    schedule row). A line file the reader refuses raises InputError naming the file
    (or ``line(text=...)``), line and key; a span whose scheduling fails is a row
    with verdict unknown and the reason in its warnings, as in the command's CSV."""
    out = _line(file=None if file is None else str(file), text=text, base=None if base is None else str(base),
                threads=threads, report=report is not None, allow_unusual=allow_unusual)
    out["summary"] = json.loads(out.pop("summary_json"))
    _write_report(report, out)
    return out


def fatigue_tests(file, conductor=None, allow_unusual=False, report=None, curve=None):
    """A conductor's fatigue tests, as ``stockbridge fatigue-tests``: a fatigue-test
    CSV (`file`: test, conductor, tension_n, yb_pp_mm, cycles, failed; its conductor
    files relative to it), the rows of `conductor` alone where given (a catalogue
    type or the file's name). Each test's Poffenberger-Swart stress and its place
    against the Safe Border Line; Basquin's curve log10 N = a + b log10 sigma_MPa with
    normal scatter s in log10 N, the runouts right-censored, by maximum likelihood.
    A value a unit slip explains (a tension in kN, a Yb in m) is refused
    (UnusualValueError) unless `allow_unusual`. `report` a path: also write the HTML
    report there (as ``--report``); `curve` a path: write the design curve (mean - 2 s)
    as an S-N curve file there (as ``--curve``).

    Returns a dict: the --json summary's keys ('file', 'conductor', 'tests', 'fit'
    with a, b, scatter, their standard errors, failures, runouts, log_likelihood,
    design_a, design_b and below_sbl {count, fraction, tests}; 'safe_border_lines'),
    'table', the output CSV's columns as arrays by name (test and conductor lists of
    str; failed and below_sbl bool; the rest float), 'curve_toml' (the S-N curve
    file's text, None where the slope is not negative) and 'warnings'. Fewer than 3
    failures at 2 stresses raise InputError naming the file."""
    out = _fatigue_tests(file=str(file), conductor=conductor, allow_unusual=allow_unusual, report=report is not None)
    summary = json.loads(out.pop("summary_json"))
    summary.update(out)
    _write_report(report, summary)
    if curve is not None:
        if summary["curve_toml"] is None:
            raise InvalidParameter("curve: the fit's slope b = %g is not negative: the tests give no S-N curve"
                                   % summary["fit"]["b"])
        with open(curve, "w", encoding="utf-8") as handle:
            handle.write(summary["curve_toml"])
    return summary


def design(file, samples=None, polish=None, threads=_defaults.get("design_threads"),
           round_digits=_defaults.get("design_round_digits"), allow_unusual=False):
    """The search for the best damper of a design study, as ``stockbridge design``: a
    design file's path (`file`; its damper and span files relative to it);
    `samples` space-filling candidates and `polish` local polishes instead of the
    file's; `threads` candidates evaluated at once; the best design is also rounded
    to `round_digits` significant digits (what is built) and evaluated again.

    Returns a dict: one array per column of the design CSV, by the CSV's names (one
    value per candidate in the CSV's order: the base, the samples, the polishes;
    'run' int, 'converged', 'feasible' and each span's '<span>_worse_than_undamped'
    bool, the rest float, NaN where not computed), 'stage' (array of str: base,
    sample or polish), 'governing_span' (array of str: the span of the largest
    stress ratio, empty unless converged), 'governing_place' (array of str: where on
    that span the largest stress lies, "span clamp 1", "sphere at 200 m"), 'columns' (the CSV's
    order), 'variables' (the variables' names, their columns), 'summary' (the --json
    summary's keys, None where the JSON has null; 'rounded' the rounded design's
    figures) and 'best_damper': the text of the --best damper file (the rounded
    design where it stays feasible), None when no candidate is feasible. A value a
    unit slip explains is refused (UnusualValueError) unless `allow_unusual`."""
    out = _design(file=str(file), samples=samples, polish=polish, threads=threads, round_digits=round_digits,
                  allow_unusual=allow_unusual)
    for name in ("stage", "governing_span", "governing_place"):
        if name in out:
            out[name] = numpy.array(out[name], dtype=str)
    out["summary"] = json.loads(out.pop("summary_json"))
    return out


def identify_impedance(damper, input=None, *, frequency=None, velocity=None, displacement=None, z=None,
                       elements=_defaults.get("fit_elements"), fit_clamp_mass=_defaults.get("fit_clamp_mass"),
                       free=(), rms_limit=_defaults.get("fit_rms_limit"), threads=_defaults.get("fit_threads"),
                       scatter=None, allow_unusual=False):
    """The cable parameters (and with `fit_clamp_mass` the clamp mass) of a damper
    from its measured impedance, as ``stockbridge identify impedance``: `damper` a
    Damper (load_damper, make_damper) whose masses, inertias, offsets and cable
    lengths are known, its cables' values the starting values; the measurement a
    CSV's path (`input`, the command's columns) or arrays of one value per point:
    `frequency` (Hz), `velocity` (m/s) or `displacement` (m), and complex `z` (N s/m).
    `elements` Jenkin elements per cable (a cable of law "bouc-wen" fits ei_min,
    ei_max and chi0 instead); `free` numbers of the damper fitted too, by
    path ("arm.long.mass", "arm.short.cable.length", "clamp.mass", as --free);
    `rms_limit` the RMS relative error of Z above which the fit is poor (warned of,
    'poor_fit' True); `scatter` the measurement's relative scatter of Z (0.01 for
    1 %; None: 1 %, assumed), against which 'lack_of_fit' tests the residuals (a
    significant lack of fit is warned of with the fixed numbers of the damper that may
    be wrong, and inflates the standard errors); `threads` model runs at once. A
    sheet's value outside what a shaker test gives is refused (UnusualValueError)
    unless `allow_unusual`.

    Returns a dict: the --json summary's keys (ei, jenkin or law, ei_min, ei_max,
    chi0; misfit, rms_relative_error,
    poor_fit, lack_of_fit, parameters with standard errors, geometry, correlation, undetermined,
    notes, ...), 'fitted' (the --fitted CSV's columns as arrays: the measured and the
    model's Z at each point), 'cable' (a Cable: the identified cable at the first arm's
    length, for make_damper), 'cable_files' (each cable type's cable file text),
    'damper' (the damper with the identified parameters and numbers) and
    'damper_file' (its damper file text, as --fitted-damper writes it)."""
    def values(array):
        return None if array is None else list(numpy.ravel(numpy.asarray(array)))
    out = _identify_impedance(damper, input=None if input is None else str(input), frequency=values(frequency),
                              velocity=values(velocity), displacement=values(displacement),
                              z=None if z is None else [complex(v) for v in numpy.ravel(numpy.asarray(z))],
                              elements=elements, fit_clamp_mass=fit_clamp_mass,
                              free=[free] if isinstance(free, str) else list(free), rms_limit=rms_limit,
                              threads=threads, scatter=None if scatter is None else float(scatter),
                              allow_unusual=allow_unusual)
    summary = json.loads(out.pop("summary_json"))
    summary.update(out)
    return summary


def identify_self_damping(file=None, tension=None, frequency=None, amplitude=None, power=None, n=None,
                          allow_unusual=False):
    """The power law P = k Y^l f^m / (T/1000)^n (W/m) of a conductor's self-damping
    fitted to its tests, as ``stockbridge identify self-damping``: a test CSV's path
    (`file`: tension_n, frequency_hz, amplitude_m, power_w_per_m) or arrays of one
    value per test: `tension` (N), `frequency` (Hz), `amplitude` (m, antinode, single
    peak) and `power` (W/m). Least squares on the logs. `n` fixes the tension
    exponent (needed when every test is at one tension: InvalidParameter naming n
    otherwise). A value a unit slip explains (a tension in kN, an amplitude in mm, a
    power in mW/m) is refused (UnusualValueError) unless `allow_unusual`.

    Returns a dict: the --json summary's keys (k, ln_k, l, m, n as {"value",
    "standard_error"}, n_given, points, residual_rms_ln_p, r_squared, tensions_n,
    notes, ...) and 'table', the [self_damping] table (law "power") a span file
    takes as it is, as -o writes it."""
    def values(array):
        return None if array is None else [float(v) for v in numpy.ravel(numpy.asarray(array, dtype=float))]
    return _identify_self_damping(file=None if file is None else str(file), tension=values(tension),
                                  frequency=values(frequency), amplitude=values(amplitude), power=values(power),
                                  n=None if n is None else float(n), allow_unusual=allow_unusual)


def span_modes(file=None, fmax=None, dampers="linear", shapes=True, text=None, base=None, allow_unusual=False):
    """The span's natural frequencies with its masses and dampers, as ``stockbridge
    span --modes``: the conductor a taut string pinned at its clamps, each [[mass]] a
    point mass, each damper at its linear impedance (`dampers` "linear": every
    element sticking) or left out ("removed"; a damper known only by its measured
    sheet has no linear impedance: InvalidParameter naming dampers). The modes below
    `fmax` (Hz; None: the top of the span's wind band). The span: a span file's path
    (`file`) or its contents (`text`, relative paths from `base`).

    Returns a dict: one array per column of the modes CSV, by its names ('mode',
    'frequency_hz', 'wavelength_m', 'bare_frequency_ratio', 'end_residual',
    '<attachment>_deflection'), 'columns' (the CSV's order), 'x_m' (the samples along
    the span, m from end 1: uniform and each attachment's position), 'shapes' (modes
    x samples: Y over the largest |Y|, Y'(0) > 0; no columns without `shapes`),
    'attachment_deflection' (modes x attachments) and 'summary', the --json
    summary's keys (frequencies_hz, attachments [{name, column, kind, position_m,
    mass_kg}], clamp_still_modes, ...)."""
    out = _span_modes(file=None if file is None else str(file), text=text, base=None if base is None else str(base),
                      fmax=None if fmax is None else float(fmax), dampers=dampers, shapes=shapes,
                      allow_unusual=allow_unusual)
    out["summary"] = json.loads(out.pop("summary_json"))
    return out


def simulate(file=None, frequency=None, duration=None, ends=None, elements_per_wavelength=None, steps_per_period=None,
             wind="ebm", probes=(), start_amplitude=None, every=1, text=None, base=None, report=None, allow_unusual=False):
    """The span in time under the energy balance's own wind, with its dampers each by
    its own nonlinear model, beside the balance at the same frequency, as ``stockbridge
    simulate`` (docs/time-domain.md): the span's natural mode nearest `frequency` (Hz)
    is the drive, started at `start_amplitude` (m; None: the balance's amplitude) and
    stepped until it settles or `duration` (s) is simulated; `ends` "clamped" or
    "pinned"; the mesh and step by `elements_per_wavelength` and `steps_per_period`
    (each None: the span file's, [span] ends and [time], else 60 s, clamped, 30, 160);
    `wind` "ebm" (the balance's own: the check) or "wake" (a wake oscillator per
    element with the span file's [wake], shedding at `frequency`);
    the displacement given at `probes` (m from end 1; empty: clamp 1's Y_b point, each
    damper, mid-span), a row every `every` steps. The span: a span file's path
    (`file`) or its contents (`text`, relative paths from `base`). `report` a path:
    the HTML report `simulate --report` writes is written there too.

    Returns a dict: one array per column of the history CSV, by its names ('time_s',
    'y_at_<mm>mm_m', 'damper_<i>_force_n', 'damper_<i>_velocity_m_s'), 'columns'
    (the CSV's order) and 'summary', the --json summary's keys (settled,
    antinode_amplitude_m beside ebm_antinode_amplitude_m and their ratio, the dampers'
    power, velocity and force harmonics, envelope_m, x_m, amplitude_m, ...; a
    figure None unless the run settled)."""
    if frequency is None:
        raise InvalidParameter("frequency: expected the drive's frequency, Hz")
    out = _simulate(file=None if file is None else str(file), text=text, base=None if base is None else str(base),
                    frequency=float(frequency), duration=None if duration is None else float(duration), ends=ends,
                    elements_per_wavelength=None if elements_per_wavelength is None else int(elements_per_wavelength),
                    steps_per_period=None if steps_per_period is None else int(steps_per_period), wind=wind,
                    probes=[float(x) for x in probes],
                    start_amplitude=None if start_amplitude is None else float(start_amplitude), every=int(every),
                    report=report is not None, allow_unusual=allow_unusual)
    _write_report(report, out)
    out["summary"] = json.loads(out.pop("summary_json"))
    return out
