#!/usr/bin/env python3
"""Writes the hostile-input corpus (tests/bad_inputs/cases, tests/bad_inputs/accepted).

Each case is a folder: `args` (the command line after `stockbridge`, where INPUT
stands for the case's input file), `expect` (text the one error line must contain)
and the input file; a case whose input comes with other files (a line file's damper
file and spans CSV, a design file's damper and span files) has them too, and
`named`: the file the error line must name. Run once; the folders are committed.
"""
import os
import shutil

HERE = os.path.dirname(os.path.abspath(__file__))
CABLE = "[cable]\nlength = 0.3\nsections = 8\nei = 2.8\njenkin = [ { c = 20.0, h = 0.7 } ]\n"
ARM = ("[[arm]]\nname = \"a\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n"
       "[arm.cable]\nlength = 0.1875\nsections = 8\nei = 2.8\njenkin = [ { c = 20.0, h = 0.7 } ]\n")
DAMPER = "[clamp]\nmass = 0.7\n" + ARM
STRAND = "[strand]\ncore_radius = 0.001\n[[strand.layer]]\ncount = 6\nwire_radius = 0.001\npitch_radius = 0.002\nlay_length = 0.06\n"
MK = "curvature_per_m,moment_n_m\n" + "".join(f"{0.08 * s:.6f},{0.5 * s:.6f}\n" for s in
                                             [0, 0.5, 1, 0.5, 0, -0.5, -1, -0.5, 0, 0.5, 1, 0.5, 0, -0.5, -1])
CYCLE_A = "x_m,force_n\n" + "".join(f"{0.03 * s:.6f},{10 * s:.6f}\n" for s in
                                    [0, 0.5, 1, 0.5, 0, -0.5, -1, -0.5, 0, 0.5, 1, 0.5, 0, -0.5, -1])
SPAN = ("[conductor]\nname = \"ASTER570\"\nmass_per_length = 1.571\ndiameter = 0.03105\nrated_tensile_strength = 185300\n"
        "ei_min = 28.28\nouter_wire_diameter = 0.00345\nouter_wire_modulus = 68e9\naluminium_layers = 4\n"
        "[span]\nlength = 400\ntension_fraction = 0.15\n[wind]\nlaw = \"cigre\"\nspeed_min = 1.0\nspeed_max = 7.0\n"
        "[self_damping]\nlaw = \"noiseux-1991\"\n[fatigue]\ncycles = 5e8\n")
SPAN_CLIMATE = SPAN + "wind_weibull = { shape = 2.0, scale = 4.0 }\naeolian_fraction = 0.3\n"
RECORDER_CMD = "recorder span.toml INPUT --days 30 -o out.csv"
RECORDER_HEAD = "yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n"
RECORDER_FILES = {"span.toml": SPAN_CLIMATE}
SPAN_DAMPER = "[[damper]]\nfile = \"nope.toml\"\nposition = 1.0\nends = \"both\"\n"

CYCLE_CMD = "cycle INPUT --experiment a --amplitude 0.01 --cycles 1 --points 8 -o out.csv"
IMPEDANCE_CMD = "impedance INPUT --velocity 0.1 --frequencies 10 -o out.csv"
STRAND_CMD = "strand INPUT"
LOCAL_CMD = "identify local --input INPUT -o out.toml"
GLOBAL_CMD = "identify global --experiment a --length 0.3 --input INPUT -o out.toml"
SPAN_CMD = "span INPUT --frequencies 10,20 -o out.csv"
DESIGN_CMD = "design INPUT -o out.csv --best best.toml"
DESIGN = ("damper = \"nope.toml\"\nspans = [\"span.toml\"]\n"
          "[[variable]]\nname = \"arm.a.mass\"\nmin = 0.5\nmax = 1.5\n")
IMPEDANCE_FIT_CMD = "identify impedance --damper nope.toml --input INPUT -o out.toml"
MEASURED_Z = "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.05,5.1,80.2\n20,0.05,12.5,150.3\n"
LOOP_CMD = "loop --ei 2.8 --jenkin 20:0.7 --amplitude 0.05 -o out.csv"
# Issue 49's mutations: a sheet of two curves, each value checked where it is read.
SHEET = ("frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.05,5.1,80.2\n20,0.05,12.5,150.3\n30,0.05,20.1,210.7\n"
         "10,0.2,15.2,70.4\n20,0.2,40.8,130.9\n30,0.2,60.3,190.2\n")
SHEET_POLAR = ("frequency_hz,velocity_m_s,abs_z_n_s_m,phase_deg\n10,0.05,80.4,86.4\n20,0.05,150.8,85.2\n30,0.05,211.7,84.5\n"
               "10,0.2,72.0,77.8\n20,0.2,137.1,72.7\n30,0.2,199.5,72.4\n")
LINE = ("[conductor]\ntype = \"AAAC ASTER570\"\n[wind]\nlaw = \"cigre\"\n[self_damping]\nlaw = \"noiseux-1991\"\n"
        "[fatigue]\ncycles = 5e8\n[dampers]\ntypes = [ { name = \"sb1\", file = \"damper.toml\" } ]\nposition_max = 6.0\n")
LINE_SPANS = "[[span]]\nid = \"T01-T02\"\nlength = 300\ntension_fraction = 0.18\n[[span]]\nid = \"T02-T03\"\nlength = 350\ntension = 28000\n"
LINE_CSV = "spans = \"spans.csv\"\n" + LINE
SPANS_CSV = "id,length_m,tension_fraction,catenary_parameter_m,terrain\nT01-T02,300,0.18,,1\nT02-T03,350,,1600,2\n"
LINE_CMD = "line line.toml -o schedule.csv"
FATIGUE_CMD = "fatigue-tests INPUT -o out.csv"
FATIGUE_TESTS = ("test,conductor,tension_n,yb_pp_mm,cycles,failed\n"
                 "d1,ACSR Drake,35000,0.8272,3412811,true\n"
                 "d2,ACSR Drake,35000,0.6,14130145,true\n"
                 "d3,ACSR Drake,35000,1.34,8518680,true\n"
                 "d4,ACSR Drake,35000,0.529,20917000,true\n"
                 "d5,ACSR Drake,35000,0.8,102063666,false\n")
SPAN_WITH_DAMPER = SPAN + "[[damper]]\nfile = \"damper.toml\"\nposition = 1.0\n"
DESIGN_OK = ("damper = \"damper.toml\"\nspans = [\"span.toml\"]\n"
             "[[variable]]\nname = \"arm.a.mass\"\nmin = 0.5\nmax = 1.5\n"
             "[[tie]]\nname = \"arm.a.inertia\"\nequals = \"arm.a.mass\"\n")
DESIGN_FILES = {"damper.toml": DAMPER, "span.toml": SPAN_WITH_DAMPER}

# Self-damping tests (identify self-damping): three tensions, two frequencies, two amplitudes.
SD_CMD = "identify self-damping INPUT -o out.toml"
SD_HEADER = "tension_n,frequency_hz,amplitude_m,power_w_per_m\n"
SD = SD_HEADER + "".join(f"{t},{f},{y},{0.02 * (y / 0.002) ** 2.4 * (f / 20) ** 5.5 / (t / 28000) ** 2.5:.5g}\n"
                         for t in (20000, 28000, 35000) for f in (20, 30) for y in (0.001, 0.002))
SD_ROW = "28000,20,0.002,0.02\n"

cases = {
    # cable files
    "cable_syntax": (CYCLE_CMD, "cable.toml", "[cable\nlength = 0.3\n", "syntax error"),
    "cable_empty": (CYCLE_CMD, "cable.toml", "", "'cable'"),
    "cable_missing_length": (CYCLE_CMD, "cable.toml", CABLE.replace("length = 0.3\n", ""), "'length'"),
    "cable_missing_ei": (CYCLE_CMD, "cable.toml", CABLE.replace("ei = 2.8\n", ""), "'ei'"),
    "cable_unknown_key": (CYCLE_CMD, "cable.toml", CABLE + "colour = 1\n", "cable.colour"),
    "cable_unknown_table": (CYCLE_CMD, "cable.toml", CABLE + "[extra]\n", "'extra'"),
    "cable_length_string": (CYCLE_CMD, "cable.toml", CABLE.replace("length = 0.3", 'length = "0.3"'), "cable.length"),
    "cable_length_negative": (CYCLE_CMD, "cable.toml", CABLE.replace("length = 0.3", "length = -0.3"), "cable.length = -0.3"),
    "cable_length_zero": (CYCLE_CMD, "cable.toml", CABLE.replace("length = 0.3", "length = 0"), "cable.length = 0"),
    "cable_length_nan": (CYCLE_CMD, "cable.toml", CABLE.replace("length = 0.3", "length = nan"), "cable.length = nan"),
    "cable_length_inf": (CYCLE_CMD, "cable.toml", CABLE.replace("length = 0.3", "length = inf"), "cable.length = inf"),
    "cable_sections_zero": (CYCLE_CMD, "cable.toml", CABLE.replace("sections = 8", "sections = 0"), "cable.sections"),
    # A fuzzing finding: one Gauss point ties the tip's deflection to its rotation, so (b) had no solution.
    "cable_sections_one": ("cycle INPUT --experiment b --amplitude 0.1 -o out.csv", "cable.toml",
                           CABLE.replace("sections = 8", "sections = 1"), "cable.sections"),
    # Fuzzing finding: an absurd magnitude was accepted and overflowed the cable's flexibility.
    "cable_length_1e307": (CYCLE_CMD, "cable.toml", CABLE.replace("length = 0.3", "length = 0.11e308"),
                           "cable.length = 1.1e+307: expected a value from 1e-12 to 1e+12"),
    "damper_arm_mass_1e20": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace("mass = 0.856", "mass = 1e20"), "arm[0].mass = 1e+20"),
    "cable_sections_huge": (CYCLE_CMD, "cable.toml", CABLE.replace("sections = 8", "sections = 1000000000"), "cable.sections"),
    "cable_sections_float": (CYCLE_CMD, "cable.toml", CABLE.replace("sections = 8", "sections = 8.5"), "cable.sections"),
    "cable_ei_negative": (CYCLE_CMD, "cable.toml", CABLE.replace("ei = 2.8", "ei = -2.8"), "cable.ei = -2.8"),
    "cable_ei_huge": (CYCLE_CMD, "cable.toml", CABLE.replace("ei = 2.8", "ei = 1e400"), "1e400"),
    "cable_c_zero": (CYCLE_CMD, "cable.toml", CABLE.replace("c = 20.0", "c = 0"), "jenkin[0].c = 0"),
    "cable_h_negative": (CYCLE_CMD, "cable.toml", CABLE.replace("h = 0.7", "h = -0.7"), "jenkin[0].h = -0.7"),
    "cable_jenkin_not_table": (CYCLE_CMD, "cable.toml", CABLE.replace("[ { c = 20.0, h = 0.7 } ]", "[ 20.0 ]"), "jenkin[0]"),
    "cable_jenkin_unknown": (CYCLE_CMD, "cable.toml", CABLE.replace("h = 0.7 }", "h = 0.7, k = 1 }"), "jenkin[0].k"),
    "cable_k0_negative": (CYCLE_CMD, "cable.toml", CABLE.replace("h = 0.7 }", "h = 0.7, k0 = -1 }"), "k0 = -1"),
    "cable_profile_unsorted": (CYCLE_CMD, "cable.toml", CABLE.replace("ei = 2.8", "ei = { s = [0, 0.2, 0.1], value = [1, 2, 3] }"), "ei.s[2]"),
    "cable_profile_lengths": (CYCLE_CMD, "cable.toml", CABLE.replace("ei = 2.8", "ei = { s = [0, 0.2], value = [1] }"), "cable.ei"),
    "cable_profile_negative": (CYCLE_CMD, "cable.toml", CABLE.replace("ei = 2.8", "ei = { s = [0, 0.2], value = [1, -2] }"), "ei.value[1] = -2"),
    "cable_mirror_too_short": (CYCLE_CMD, "cable.toml", CABLE + "mirror_length = 0.1\n", "mirror_length"),
    "cable_lever_zero": (CYCLE_CMD, "cable.toml", CABLE + "lever_arm_cap = 0\n", "lever_arm_cap = 0"),
    # damper files
    "damper_syntax": (IMPEDANCE_CMD, "damper.toml", "[clamp\nmass = 0.7\n", "syntax error"),
    "damper_empty": (IMPEDANCE_CMD, "damper.toml", "", "'clamp'"),
    "damper_no_arm": (IMPEDANCE_CMD, "damper.toml", "[clamp]\nmass = 0.7\n", "'arm'"),
    "damper_clamp_negative": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace("mass = 0.7", "mass = -0.7"), "clamp.mass = -0.7"),
    "damper_arm_mass_zero": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace("mass = 0.856", "mass = 0"), "arm[0].mass = 0"),
    "damper_inertia_nan": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace("inertia = 0.001814", "inertia = nan"), "arm[0].inertia = nan"),
    "damper_offset_beyond_arm": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace("offset = 0.0325", "offset = 0.3"), "arm[0].offset = 0.3"),
    "damper_offset_in_mm": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace("offset = 0.0325", "offset = 32.5"), "arm[0].offset = 32.5"),
    "damper_unknown_arm_key": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace("name = \"a\"", "name = \"a\"\ncolour = 1"), "arm[0].colour"),
    "damper_missing_cable": (IMPEDANCE_CMD, "damper.toml", "[clamp]\nmass = 0.7\n[[arm]]\nmass = 1\ninertia = 0.001\noffset = 0.01\n", "'cable'"),
    "damper_bad_cable": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace("ei = 2.8", "ei = -2.8"), "arm[0].cable.ei = -2.8"),
    "damper_arm_not_array": (IMPEDANCE_CMD, "damper.toml", "[clamp]\nmass = 0.7\n[arm]\nmass = 1\n", "arm"),
    # A reused cable file (issue 13): it must exist; the damper file itself is not one.
    "damper_cable_file_missing": (IMPEDANCE_CMD, "damper.toml", DAMPER.split("[arm.cable]")[0] + '[arm.cable]\nfile = "nope.toml"\n',
                                  'arm[0].cable.file: "nope.toml": expected an existing cable file'),
    "damper_cable_file_not_a_cable": (IMPEDANCE_CMD, "damper.toml",
                                      DAMPER.split("[arm.cable]")[0] + '[arm.cable]\nfile = "damper.toml"\n', "'cable'"),
    "damper_modes_mass_zero": ("modes INPUT --json", "damper.toml", DAMPER.replace("mass = 0.856", "mass = 0"), "arm[0].mass = 0"),
    "damper_cable_file_not_a_string": (IMPEDANCE_CMD, "damper.toml", DAMPER.split("[arm.cable]")[0] + "[arm.cable]\nfile = 3\n",
                                       "arm[0].cable.file"),
    # span files (issue 14)
    "span_syntax": (SPAN_CMD, "span.toml", "[conductor\n", "syntax error"),
    "span_empty": (SPAN_CMD, "span.toml", "", "'conductor'"),
    "span_missing_diameter": (SPAN_CMD, "span.toml", SPAN.replace("diameter = 0.03105\n", ""), "missing key 'diameter' in [conductor]"),
    "span_diameter_negative": (SPAN_CMD, "span.toml", SPAN.replace("diameter = 0.03105", "diameter = -1"), "conductor.diameter = -1"),
    "span_diameter_in_mm": (SPAN_CMD, "span.toml", SPAN.replace("outer_wire_diameter = 0.00345", "outer_wire_diameter = 3.45"),
                            "conductor.outer_wire_diameter = 3.45"),
    "span_layers_zero": (SPAN_CMD, "span.toml", SPAN.replace("aluminium_layers = 4", "aluminium_layers = 0"), "conductor.aluminium_layers: 0: expected an integer from 1 to 10"),
    "span_layers_float": (SPAN_CMD, "span.toml", SPAN.replace("aluminium_layers = 4", "aluminium_layers = 4.5"), "conductor.aluminium_layers"),
    "span_length_1e307": (SPAN_CMD, "span.toml", SPAN.replace("length = 400", "length = 1e307"), "span.length = 1e+307"),
    "span_both_tensions": (SPAN_CMD, "span.toml", SPAN.replace("tension_fraction = 0.15", "tension_fraction = 0.15\ntension = 30000"),
                           "span.tension_fraction: given beside span.tension"),
    "span_no_tension": (SPAN_CMD, "span.toml", SPAN.replace("tension_fraction = 0.15\n", ""), "missing key 'tension' in [span]"),
    "span_conductor_type_unknown": (SPAN_CMD, "span.toml", SPAN.replace('name = "ASTER570"', 'type = "ACSR Drak"'),
                                    'conductor.type = "ACSR Drak": expected a conductor of the catalogue'),
    "span_conductor_file_missing": (SPAN_CMD, "span.toml", SPAN.replace('name = "ASTER570"', 'file = "mine.toml"'),
                                    'conductor.file: "mine.toml": expected an existing conductor file'),
    "span_conductor_type_and_file": (SPAN_CMD, "span.toml", SPAN.replace('name = "ASTER570"', 'type = "ACSR Drake"\nfile = "x.toml"'),
                                     "conductor.file: given beside conductor.type"),
    "span_fraction_above_one": (SPAN_CMD, "span.toml", SPAN.replace("tension_fraction = 0.15", "tension_fraction = 1.5"),
                                "span.tension_fraction = 1.5"),
    "span_tension_above_rts": (SPAN_CMD, "span.toml", SPAN.replace("tension_fraction = 0.15", "tension = 2e5"), "span.tension = 200000"),
    "span_wind_law_unknown": (SPAN_CMD, "span.toml", SPAN.replace('law = "cigre"', 'law = "cigr"'), "wind.law = 'cigr'"),
    "span_wind_law_number": (SPAN_CMD, "span.toml", SPAN.replace('law = "cigre"', "law = 1"), "wind.law: the integer 1"),
    "span_speed_max_below_min": (SPAN_CMD, "span.toml", SPAN.replace("speed_max = 7.0", "speed_max = 0.5"), "wind.speed_max = 0.5"),
    "span_turbulence_without_foti": (SPAN_CMD, "span.toml", SPAN.replace("speed_max = 7.0", "speed_max = 7.0\nturbulence_intensity = 0.1"),
                                     "wind.turbulence_intensity = 0.1"),
    "span_table_missing_csv": (SPAN_CMD, "span.toml", SPAN.replace('law = "cigre"', 'law = "table"\ntable = "fnc.csv"'),
                               'wind.table: "fnc.csv": expected an existing CSV file'),
    "span_table_law_without_table": (SPAN_CMD, "span.toml", SPAN.replace('law = "cigre"', 'law = "table"'), "missing key 'table' in [wind]"),
    "span_self_damping_unknown": (SPAN_CMD, "span.toml", SPAN.replace('law = "noiseux-1991"', 'law = "noiseux"'), "self_damping.law = 'noiseux'"),
    "span_claren_diana_without_n": (SPAN_CMD, "span.toml", SPAN.replace('law = "noiseux-1991"', 'law = "claren-diana-1969"'),
                                    "self_damping.n"),
    "span_foti_without_ei_max": (SPAN_CMD, "span.toml", SPAN.replace('law = "noiseux-1991"', 'law = "foti"\nlimit_curvature = 0.02'),
                                 "ei_max"),
    "span_damper_file_missing": (SPAN_CMD, "span.toml", SPAN + SPAN_DAMPER, 'damper[0].file: "nope.toml": expected an existing damper file'),
    "span_damper_file_is_the_span_file": (SPAN_CMD, "span.toml", SPAN + SPAN_DAMPER.replace("nope.toml", "span.toml"), "'clamp'"),
    "span_damper_ends_unknown": (SPAN_CMD, "span.toml", SPAN + SPAN_DAMPER.replace('"both"', '"three"'), "damper[0].ends"),
    "span_damper_not_array": (SPAN_CMD, "span.toml", SPAN + "[damper]\nposition = 1\n", "damper"),
    "span_unknown_key": (SPAN_CMD, "span.toml", SPAN.replace("speed_max = 7.0", "speed_max = 7.0\ncolour = 1"), "wind.colour"),
    "span_unknown_table": (SPAN_CMD, "span.toml", SPAN + "[extra]\n", "'extra'"),
    "span_cycles_negative": (SPAN_CMD, "span.toml", SPAN.replace("cycles = 5e8", "cycles = -5"), "fatigue.cycles = -5"),
    "span_weibull_without_fraction": (SPAN_CMD, "span.toml", SPAN + "wind_weibull = { shape = 2.0, scale = 4.0 }\n",
                                      "missing key 'aeolian_fraction' in [fatigue]"),
    "span_weibull_shape_negative": (SPAN_CMD, "span.toml",
                                    SPAN + "wind_weibull = { shape = -2.0, scale = 4.0 }\naeolian_fraction = 0.3\n",
                                    "fatigue.wind_weibull.shape = -2"),
    # measured impedance (issue 16): the measured file is read first, so the missing
    # damper file is never reached
    "measured_z_no_amplitude": (IMPEDANCE_FIT_CMD, "z.csv", MEASURED_Z.replace("velocity_m_s", "speed"),
                                "missing column 'velocity_m_s' (or 'displacement_m')"),
    "measured_z_no_impedance": (IMPEDANCE_FIT_CMD, "z.csv", MEASURED_Z.replace("re_z_n_s_m", "real"),
                                "missing column 're_z_n_s_m' (or 'abs_z_n_s_m')"),
    "measured_z_polar_no_phase": (IMPEDANCE_FIT_CMD, "z.csv", MEASURED_Z.replace("re_z_n_s_m,im_z_n_s_m", "abs_z_n_s_m,angle"),
                                  "missing column 'phase_deg'"),
    "measured_z_frequency_negative": (IMPEDANCE_FIT_CMD, "z.csv", MEASURED_Z.replace("\n20,", "\n-20,"),
                                      "z.csv:3: column 'frequency_hz' = -20: expected > 0"),
    "measured_z_velocity_zero": (IMPEDANCE_FIT_CMD, "z.csv", MEASURED_Z.replace("10,0.05", "10,0"),
                                 "z.csv:2: column 'velocity_m_s' = 0: expected > 0"),
    "measured_z_displacement_negative": (IMPEDANCE_FIT_CMD, "z.csv",
                                         MEASURED_Z.replace("velocity_m_s", "displacement_m").replace("20,0.05", "20,-0.001"),
                                         "z.csv:3: column 'displacement_m' = -0.001: expected > 0"),
    "measured_z_nan": (IMPEDANCE_FIT_CMD, "z.csv", MEASURED_Z.replace("12.5", "nan"),
                       "z.csv:3: column 're_z_n_s_m' = nan: expected a finite number"),
    "measured_z_zero": (IMPEDANCE_FIT_CMD, "z.csv", MEASURED_Z.replace("5.1,80.2", "0,0"), "expected a nonzero impedance"),
    "measured_z_abs_zero": (IMPEDANCE_FIT_CMD, "z.csv",
                            MEASURED_Z.replace("re_z_n_s_m,im_z_n_s_m", "abs_z_n_s_m,phase_deg").replace("5.1,80.2", "0,80"),
                            "z.csv:2: column 'abs_z_n_s_m' = 0: expected > 0"),
    "measured_z_one_row": (IMPEDANCE_FIT_CMD, "z.csv", MEASURED_Z.rsplit("20,", 1)[0], "1 data rows: expected at least 2"),
    "measured_z_semicolons": (IMPEDANCE_FIT_CMD, "z.csv", MEASURED_Z.replace(",", ";"), "separated by ';'"),
    # design files (issue 15): the faults a design file shows alone (its variables and
    # ties need the damper it names: tests/cli/design_cli_test.cpp)
    "design_syntax": (DESIGN_CMD, "design.toml", "damper = \n", "design.toml:1"),
    "design_empty": (DESIGN_CMD, "design.toml", "", "damper"),
    "design_damper_missing": (DESIGN_CMD, "design.toml", DESIGN, 'damper: "nope.toml": expected an existing damper file'),
    "design_damper_number": (DESIGN_CMD, "design.toml", DESIGN.replace('"nope.toml"', "3"), "damper"),
    "design_damper_is_itself": (DESIGN_CMD, "design.toml", DESIGN.replace("nope.toml", "design.toml"), "'clamp'"),
    "span_name_line_break": (SPAN_CMD, "span.toml", SPAN.replace('name = "ASTER570"', 'name = "A\\nB"'), "conductor.name"),
    # strand files
    # Fuzzing findings: a name with a line break (it goes into messages and files), and
    # wires wider than their pitch radius (ei_min came out above ei_max).
    "damper_name_line_break": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace('name = "a"', 'name = "a\\nb"'), "arm[0].name"),
    "strand_wires_overlap_core": (STRAND_CMD, "strand.toml", STRAND.replace("wire_radius = 0.001", "wire_radius = 0.005"),
                                  "strand.layer[0].pitch_radius = 0.002: expected at least 0.006"),
    "strand_lay_angle_steep": (STRAND_CMD, "strand.toml", STRAND.replace("lay_length = 0.06", "lay_length = 0.01"),
                               "strand.layer[0].lay_length = 0.01: expected more than 2 pi"),
    "strand_syntax": (STRAND_CMD, "strand.toml", "[strand\n", "syntax error"),
    "strand_empty": (STRAND_CMD, "strand.toml", "", "strand"),
    "strand_missing_core": (STRAND_CMD, "strand.toml", STRAND.replace("core_radius = 0.001\n", ""), "core_radius"),
    "strand_core_negative": (STRAND_CMD, "strand.toml", STRAND.replace("core_radius = 0.001", "core_radius = -0.001"), "core_radius"),
    "strand_count_zero": (STRAND_CMD, "strand.toml", STRAND.replace("count = 6", "count = 0"), "count"),
    "strand_lay_zero": (STRAND_CMD, "strand.toml", STRAND.replace("lay_length = 0.06", "lay_length = 0"), "lay_length"),
    "strand_unknown_key": (STRAND_CMD, "strand.toml", STRAND + "twist = 1\n", "twist"),
    "strand_wrong_type": (STRAND_CMD, "strand.toml", STRAND.replace("count = 6", 'count = "six"'), "count"),
    # moment-curvature records
    "mk_empty": (LOCAL_CMD, "mk.csv", "", "empty file"),
    "mk_header_only": (LOCAL_CMD, "mk.csv", "curvature_per_m,moment_n_m\n", "0 data rows"),
    "mk_missing_column": (LOCAL_CMD, "mk.csv", "curvature_per_m,torque\n0,0\n", "'moment_n_m'"),
    "mk_duplicate_column": (LOCAL_CMD, "mk.csv", "curvature_per_m,moment_n_m,moment_n_m\n0,0,0\n", "appears twice"),
    "mk_non_numeric": (LOCAL_CMD, "mk.csv", MK.replace("0.500000\n", "half\n", 1), "'half'"),
    "mk_nan": (LOCAL_CMD, "mk.csv", MK.replace("0.500000\n", "nan\n", 1), "finite"),
    "mk_inf": (LOCAL_CMD, "mk.csv", MK.replace("0.500000\n", "inf\n", 1), "finite"),
    "mk_semicolons": (LOCAL_CMD, "mk.csv", MK.replace(",", ";"), "separated by ';'"),
    "mk_short_row": (LOCAL_CMD, "mk.csv", MK + "0.1\n", "1 cells"),
    "mk_less_than_a_cycle": (LOCAL_CMD, "mk.csv", "curvature_per_m,moment_n_m\n0,0\n0.01,0.2\n0.02,0.4\n0.03,0.5\n0.02,0.3\n0.01,0.1\n0,-0.1\n-0.01,-0.3\n", "reversals"),
    # cycle records
    "cycle_missing_force": (GLOBAL_CMD, "cycle.csv", "x_m,torque\n0,0\n", "'force_n'"),
    "cycle_wrong_experiment_columns": ("identify global --experiment b --length 0.3 --input INPUT -o out.toml", "cycle.csv", CYCLE_A, "'phi_rad'"),
    "cycle_non_numeric": (GLOBAL_CMD, "cycle.csv", CYCLE_A.replace("5.000000\n", "5.0abc\n", 1), "'5.0abc'"),
    "cycle_too_short": (GLOBAL_CMD, "cycle.csv", "x_m,force_n\n0,0\n0.01,1\n", "data rows"),
    # Issue 49, hostile input end to end: each mutation of a valid file named by its
    # file, line (row) and column (key), refused before anything is computed.
    "measured_z_velocity_one_row_curve": (IMPEDANCE_FIT_CMD, "z.csv", SHEET.replace("20,0.2,", "20, 1 ,"),
                                          "z.csv:6: column 'velocity_m_s' = 1: the only row at this amplitude"),
    "measured_z_decimal_comma": (IMPEDANCE_FIT_CMD, "z.csv", SHEET.replace("12.5", "12,5"), "z.csv:3: 5 cells: expected 4, as the header has (a decimal comma?"),
    "measured_z_frequency_1e-300": (IMPEDANCE_FIT_CMD, "z.csv", SHEET.replace("\n20,0.05", "\n1e-300,0.05"),
                                    "z.csv:3: column 'frequency_hz' = 1e-300: expected a value from 1e-12 to 1e+12"),
    "measured_z_abs_1e-310": (IMPEDANCE_FIT_CMD, "z.csv", SHEET_POLAR.replace("150.8", "1e-310"),
                              "z.csv:3: column 'abs_z_n_s_m' = 1e-310: expected a value from 1e-12 to 1e+12"),
    "measured_z_columns_swapped": (IMPEDANCE_FIT_CMD, "z.csv", SHEET.replace("frequency_hz,velocity_m_s", "velocity_m_s,frequency_hz"),
                                   "z.csv:2: column 'frequency_hz' = 0.05: outside the typical 0.5 to 500 Hz"),
    "measured_z_phase_1e300": (IMPEDANCE_FIT_CMD, "z.csv", SHEET_POLAR.replace("85.2", "1e300"),
                               "z.csv:3: column 'phase_deg' = 1e+300: expected a phase in degrees"),
    "span_sheet_frequency_bad": ("span span.toml --frequencies 10,20 -o out.csv", "sheet.csv", SHEET.replace("\n20,0.2,", "\n-20,0.2,"),
                                 "sheet.csv:6: column 'frequency_hz' = -20: expected > 0",
                                 {"span.toml": SPAN + "[[damper]]\nimpedance = \"sheet.csv\"\nposition = 1.0\n"}),
    "span_tension_kn": (SPAN_CMD, "span.toml", SPAN.replace("tension_fraction = 0.15", "tension = 30.3"), "span.tension = 30.3: outside the typical 1000 to 500000 N of the conductor tension (in kN?"),
    "span_rts_kn": (SPAN_CMD, "span.toml", SPAN.replace("rated_tensile_strength = 185300", "rated_tensile_strength = 140.1"),
                    "conductor.rated_tensile_strength = 140.1: outside the typical 5000 to 1.5e+06 N of the conductor rated "
                    "tensile strength (in kN?"),
    "span_damper_position_mm": (SPAN_CMD, "span.toml", SPAN_WITH_DAMPER.replace("position = 1.0", "position = 1200"),
                                "damper[0].position = 1200: outside the typical 0.1 to 10 m of the damper position from the span "
                                "clamp (in mm?", {"damper.toml": DAMPER}),
    "span_conductor_type_deleted": (SPAN_CMD, "span.toml", SPAN.split("[span]")[0].split("\n")[0] + "\n[span]" + SPAN.split("[span]")[1],
                                    "in [conductor]: expected type = a conductor of the catalogue"),
    "line_spans_csv_row_short": (LINE_CMD, "spans.csv", SPANS_CSV.replace("T02-T03,350,,1600,2", "T02-T03,350,,1600"),
                                 "spans.csv:3: 4 cells: expected 5, as the header has", {"line.toml": LINE_CSV, "damper.toml": DAMPER}),
    "line_spans_csv_tension_kn": (LINE_CMD, "spans.csv", "id,length_m,tension_n\nT01-T02,300,30.3\n", "spans.csv:2: span \"T01-T02\": tension_n = 30.3: outside the typical 1000 to 500000 N",
                                  {"line.toml": LINE_CSV, "damper.toml": DAMPER}),
    "line_position_max_2147483648": (LINE_CMD, "line.toml", LINE.replace("position_max = 6.0", "position_max = 2147483648") + LINE_SPANS,
                                     "dampers.position_max = 2147483648: expected less than half of every span", {"damper.toml": DAMPER}),
    "line_type_name_empty": (LINE_CMD, "line.toml", LINE.replace('name = "sb1"', 'name = ""') + LINE_SPANS, "dampers.types[0].name: empty",
                             {"damper.toml": DAMPER}),
    "line_span_id_empty": (LINE_CMD, "line.toml", LINE + LINE_SPANS.replace('id = "T02-T03"', 'id = ""'), "span[1].id: empty",
                           {"damper.toml": DAMPER}),
    "line_spans_empty_array": (LINE_CMD, "line.toml", "spans = []\n" + LINE, "expected the path of a spans CSV file",
                               {"damper.toml": DAMPER}),
    "line_spans_csv_masses_text": (LINE_CMD, "spans.csv", "id,length_m,tension_fraction,masses\nT01-T02,300,0.15,12.5@100;12.5\n",
                                   "spans.csv:2: column 'masses' = '12.5@100;12.5': '12.5' is not a mass at a position",
                                   {"line.toml": LINE_CSV, "damper.toml": DAMPER}),
    "line_spans_csv_mass_beyond_span": (LINE_CMD, "spans.csv", "id,length_m,tension_fraction,masses\nT01-T02,300,0.15,12.5@300\n",
                                        "spans.csv:2: span \"T01-T02\": column 'masses' = '12.5@300': a position = 300",
                                        {"line.toml": LINE_CSV, "damper.toml": DAMPER}),
    "line_span_mass_in_grams": (LINE_CMD, "line.toml", LINE + LINE_SPANS + "[[span.mass]]\nmass = 12500\npositions = [150]\n",
                                "span \"T02-T03\": mass[0].mass = 12500: outside the typical 0.5 to 50 kg", {"damper.toml": DAMPER}),
    "line_sphere_dampers_crossing": (LINE_CMD, "line.toml", LINE.replace("position_max = 6.0", "position_max = 6.0\nsphere_distance_max = 30")
                                     + LINE_SPANS + "[[span.mass]]\nmass = 12.5\npositions = [120, 170]\n",
                                     "dampers.sphere_distance_max = 30: on span \"T02-T03\", the dampers beside the masses at 120 "
                                     "and 170 m would come within spacing_min of each other", {"damper.toml": DAMPER}),
    "line_diameter_mm": (LINE_CMD, "line.toml", LINE.replace('type = "AAAC ASTER570"', 'type = "AAAC ASTER570"\ndiameter = 28.14')
                         + LINE_SPANS, "conductor.diameter = 28.14: outside the typical 0.004 to 0.08 m of the conductor diameter (in mm?", {"damper.toml": DAMPER}),
    "design_tie_repeated": (DESIGN_CMD, "design.toml", DESIGN_OK + "[[tie]]\nname = \"arm.a.inertia\"\nequals = \"arm.a.mass\"\n",
                            "already tie[0]", DESIGN_FILES),
    "design_variable_max_inf": (DESIGN_CMD, "design.toml", DESIGN_OK.replace("max = 1.5", "max = inf"), "variable[0].max = inf: expected a finite bound",
                                DESIGN_FILES),
    "design_objective_10kb": (DESIGN_CMD, "design.toml", DESIGN_OK.replace("spans =", "objective = \"" + "x" * 10000 + "\"\nspans ="),
                              "...': expected max_stress or life", DESIGN_FILES),
    "design_variable_name_bad_utf8": (DESIGN_CMD, "design.toml", DESIGN_OK.replace("arm.a.mass\"\nmin", "arm.a.\udcffmass\"\nmin"),
                                      "line 4 reads 'name = \"arm.a.\\xffmass\"'", DESIGN_FILES),
    "option_line_output_missing_folder": ("line line.toml -o missing/schedule.csv", "line.toml", LINE + LINE_SPANS,
                                          "-o missing/schedule.csv: the folder missing does not exist", {"damper.toml": DAMPER}),
    # options
    "option_loop_ei_negative": ("loop --ei -2.8 --amplitude 0.05 -o out.csv", None, None, "ei = -2.8"),
    "option_loop_jenkin_format": ("loop --ei 2.8 --jenkin 20/0.7 --amplitude 0.05 -o out.csv", None, None, "c:h"),
    "option_loop_cycles_zero": ("loop --ei 2.8 --amplitude 0.05 --cycles 0 -o out.csv", None, None, "cycles = 0"),
    "option_loop_points_huge": ("loop --ei 2.8 --amplitude 0.05 --cycles 1000 --points 1000000 -o out.csv", None, None, "samples"),
    "option_cycle_experiment": ("cycle INPUT --experiment c --amplitude 0.01 -o out.csv", "cable.toml", CABLE, "c"),
    "option_cycle_amplitude_nan": ("cycle INPUT --experiment a --amplitude nan -o out.csv", "cable.toml", CABLE, "amplitude = nan"),
    "option_impedance_no_amplitude": ("impedance INPUT --frequencies 10 -o out.csv", "damper.toml", DAMPER, "--velocity"),
    "option_impedance_fmin_zero": ("impedance INPUT --velocity 0.1 --fmin 0 -o out.csv", "damper.toml", DAMPER, "fmin = 0"),
    "option_impedance_method": ("impedance INPUT --velocity 0.1 --method newton -o out.csv", "damper.toml", DAMPER, "newton"),
    "option_impedance_harmonics": ("impedance INPUT --velocity 0.1 --harmonics 1000 -o out.csv", "damper.toml", DAMPER, "harmonics = 1000"),
    "option_impedance_samples": ("impedance INPUT --velocity 0.1 --samples 5 -o out.csv", "damper.toml", DAMPER, "samples = 5"),
    "option_impedance_threads": ("impedance INPUT --velocity 0.1 --threads -1 -o out.csv", "damper.toml", DAMPER, "threads"),
    "option_impedance_energy": ("impedance INPUT --velocity 0.1 --energy-tolerance 0 -o out.csv", "damper.toml", DAMPER, "energy_tolerance = 0"),
    "option_response_velocity": ("response INPUT --frequency 20 --velocity -0.2 -o out.csv", "damper.toml", DAMPER, "velocity"),
    "option_identify_elements": ("identify local --input INPUT --elements 9 -o out.toml", "mk.csv", MK, "elements = 9"),
    "option_global_length": ("identify global --experiment a --length 0 --input INPUT -o out.toml", "cycle.csv", CYCLE_A, "length = 0"),
    "option_span_frequencies_decreasing": ("span INPUT --frequencies 20,10 -o out.csv", "span.toml", SPAN, "frequencies[1] = 10"),
    "option_span_points_one": ("span INPUT --points 1 -o out.csv", "span.toml", SPAN, "points = 1"),
    "option_span_damper_model": ("span INPUT --damper-model linear -o out.csv", "span.toml", SPAN, "linear"),
    "option_impedance_fit_elements": ("identify impedance --damper nope.toml --input INPUT --elements 9 -o out.toml", "z.csv",
                                      MEASURED_Z, "elements = 9"),
    "option_impedance_fit_threads": ("identify impedance --damper nope.toml --input INPUT --threads 0 -o out.toml", "z.csv",
                                     MEASURED_Z, "threads = 0"),
    "option_impedance_fit_scatter": ("identify impedance --damper nope.toml --input INPUT --scatter 1 -o out.toml", "z.csv",
                                     MEASURED_Z, "scatter = 1: expected a fraction"),
    "option_design_samples_zero": ("design INPUT --samples 0 -o out.csv --best best.toml", "design.toml", DESIGN, "samples = 0"),
    "option_design_threads_zero": ("design INPUT --threads 0 -o out.csv --best best.toml", "design.toml", DESIGN, "threads = 0"),
    "option_design_polish_negative": ("design INPUT --polish -1 -o out.csv --best best.toml", "design.toml", DESIGN, "polish = -1"),
    "option_design_best_is_input": ("design INPUT -o out.csv --best design.toml", "design.toml", DESIGN, "--best"),
    "option_span_position_reversed": ("span INPUT --optimize-position 3:0.5 -o out.csv", "span.toml", SPAN,
                                      "optimize_position = 3:0.5"),
    "option_span_position_malformed": ("span INPUT --optimize-position 2 -o out.csv", "span.toml", SPAN, "AMIN:AMAX"),
    "option_span_position_without_dampers": ("span INPUT --optimize-position 0.5:3 -o out.csv", "span.toml", SPAN,
                                             "no [[damper]] to place"),
    "option_span_threads": ("span INPUT --threads 0 -o out.csv", "span.toml", SPAN, "threads = 0"),
    "option_unknown": ("loop --ei 2.8 --amplitude 0.05 --colour red -o out.csv", None, None, "colour"),
    "option_missing_file": ("cycle missing.toml --experiment a --amplitude 0.01 -o out.csv", None, None, "missing.toml"),
    "option_output_is_directory": ("loop --ei 2.8 --amplitude 0.05 -o .", None, None, "directory"),
    # What a new user hit (issue 13): misspelt words named with the closest valid one,
    # empty or malformed lists, a setting the chosen method does not use.
    "option_misspelt_command": ("impedence INPUT --velocity 0.1 -o out.csv", "damper.toml", DAMPER,
                                "unknown command 'impedence' for 'stockbridge': did you mean 'impedance'?"),
    "option_misspelt_subcommand": ("identify globl --input INPUT -o out.toml", "cycle.csv", CYCLE_A, "did you mean 'global'?"),
    "option_misspelt_flag": ("response INPUT --frequncy 20 --velocity 0.2 -o out.csv", "damper.toml", DAMPER,
                             "unknown option '--frequncy' for 'stockbridge response': did you mean '--frequency'?"),
    "option_impedance_frequencies_empty": ('impedance INPUT --velocity 0.1 --frequencies "" -o out.csv', "damper.toml", DAMPER,
                                           "--frequencies = '': expected a comma-separated list of numbers"),
    "option_impedance_velocity_malformed": ("impedance INPUT --velocity 0.1,,0.2 --frequencies 10 -o out.csv", "damper.toml",
                                            DAMPER, "item 2 ('') is not a number"),
    # Fatigue tests (docs/measurements.md): every bad cell named by file, line and column.
    "fatigue_tests_tension_kn": (FATIGUE_CMD, "tests.csv", FATIGUE_TESTS.replace("35000,0.6,", "35,0.6,"),
                                 "tests.csv:3: column tension_n = 35: outside the typical"),
    "fatigue_tests_yb_in_m": (FATIGUE_CMD, "tests.csv", FATIGUE_TESTS.replace(",1.34,", ",0.00134,"),
                              "tests.csv:4: column yb_pp_mm = 0.00134"),
    "fatigue_tests_failed_word": (FATIGUE_CMD, "tests.csv", FATIGUE_TESTS.replace("3412811,true", "3412811,broken"),
                                  "tests.csv:2: column 'failed' = 'broken'"),
    "fatigue_tests_cycles_negative": (FATIGUE_CMD, "tests.csv", FATIGUE_TESTS.replace("14130145", "-14130145"),
                                      "tests.csv:3: column 'cycles' = -14130145: expected a number > 0"),
    "fatigue_tests_unknown_conductor": (FATIGUE_CMD, "tests.csv", FATIGUE_TESTS.replace("ACSR Drake", "ACSR Dreak", 1),
                                        "tests.csv:2: column 'conductor'"),
    "fatigue_tests_missing_column": (FATIGUE_CMD, "tests.csv", FATIGUE_TESTS.replace("yb_pp_mm", "yb_mm"),
                                     "missing column 'yb_pp_mm'"),
    "fatigue_tests_runouts_only": (FATIGUE_CMD, "tests.csv", FATIGUE_TESTS.replace(",true", ",false"),
                                   "0 failure(s) at 0 stress(es)"),
    "option_impedance_unused_setting": ("impedance INPUT --velocity 0.1 --frequencies 10 --steps 64 -o out.csv", "damper.toml",
                                        DAMPER, "steps = 64: not used by this method"),
    # vibration recorders (issue 50)
    "recorder_inverted_yb": (RECORDER_CMD, "counts.csv", RECORDER_HEAD + "0.1,0.2,10,15,5\n0.4,0.3,10,15,5\n",
                             "counts.csv:3: yb_pp_mm_low, yb_pp_mm_high = 0.4 to 0.3 mm", RECORDER_FILES),
    "recorder_overlapping_bins": (RECORDER_CMD, "counts.csv", RECORDER_HEAD + "0.1,0.3,10,15,5\n0.2,0.4,12,14,5\n",
                                  "counts.csv:3: the bin Yb 0.2 to 0.4 mm, 12 to 14 Hz overlaps the bin of line 2",
                                  RECORDER_FILES),
    "recorder_negative_count": (RECORDER_CMD, "counts.csv", RECORDER_HEAD + "0.1,0.2,10,15,-3\n",
                                "counts.csv:2: cycles = -3: a negative count", RECORDER_FILES),
    "recorder_count_not_a_number": (RECORDER_CMD, "counts.csv", RECORDER_HEAD + "0.1,0.2,10,15,lots\n",
                                    "counts.csv:2", RECORDER_FILES),
    "recorder_outside_wind_band": (RECORDER_CMD, "counts.csv", RECORDER_HEAD + "0.1,0.2,50,60,5\n",
                                   "counts.csv:2: frequency bin 50 to 60 Hz: outside the span's wind band", RECORDER_FILES),
    "recorder_yb_in_metres": (RECORDER_CMD, "counts.csv", RECORDER_HEAD + "0.0001,0.0002,10,15,5\n",
                              "counts.csv:2: yb_pp_mm_low = 0.0001", RECORDER_FILES),
    "recorder_yb_in_micrometres": (RECORDER_CMD, "counts.csv", RECORDER_HEAD + "100,200,10,15,5\n",
                                   "counts.csv:2: yb_pp_mm_low = 100", RECORDER_FILES),
    "recorder_matrix_cell": (RECORDER_CMD, "counts.csv", "yb_pp_mm,10-15 hz,15-20 hz\n0.1-0.2,4,x\n",
                             "counts.csv:2, column '15-20 hz': 'x'", RECORDER_FILES),
    "recorder_matrix_header": (RECORDER_CMD, "counts.csv", "yb_pp_mm,10 to 15\n0.1-0.2,4\n",
                               "counts.csv: header, column 2 '10 to 15'", RECORDER_FILES),
    "recorder_no_cycles": (RECORDER_CMD, "counts.csv", RECORDER_HEAD + "0.1,0.2,10,15,0\n",
                           "counts.csv: no cycles counted", RECORDER_FILES),
    # self-damping tests: bad cells, unit slips, designs that leave an exponent open
    "sd_tension_kn": (SD_CMD, "sd.csv", SD + "28,20,0.002,0.02\n", "column 'tension_n' = 28: outside"),
    "sd_amplitude_mm": (SD_CMD, "sd.csv", SD + "28000,20,2,0.02\n", "column 'amplitude_m' = 2: outside"),
    "sd_power_mw": (SD_CMD, "sd.csv", SD + "28000,20,0.002,120\n", "column 'power_w_per_m' = 120: outside"),
    "sd_power_negative": (SD_CMD, "sd.csv", SD + "28000,20,0.002,-0.02\n", "column 'power_w_per_m' = -0.02: expected > 0"),
    "sd_cell_text": (SD_CMD, "sd.csv", SD + "28000,20,abc,0.02\n", "amplitude_m"),
    "sd_missing_column": (SD_CMD, "sd.csv", SD.replace(",power_w_per_m", ""), "power_w_per_m"),
    "sd_one_frequency": (SD_CMD, "sd.csv", SD_HEADER + "".join(r.replace(",30,", ",20,") + "\n" for r in SD.split("\n")[1:] if r),
                         "m is not determined"),
    "sd_one_tension": (SD_CMD, "sd.csv", SD_HEADER + SD_ROW + "28000,30,0.002,0.09\n28000,20,0.001,0.004\n28000,30,0.001,0.02\n",
                       "--n: not determined"),
    "sd_too_few": (SD_CMD, "sd.csv", SD_HEADER + SD_ROW + "35000,30,0.002,0.09\n20000,20,0.001,0.004\n", "points = 3"),
}

accepted = {
    "cable_crlf": (CYCLE_CMD, "cable.toml", CABLE.replace("\n", "\r\n")),
    "damper_crlf": (IMPEDANCE_CMD, "damper.toml", DAMPER.replace("\n", "\r\n")),
    "mk_bom_crlf": (LOCAL_CMD, "mk.csv", "\ufeff" + MK.replace("\n", "\r\n")),
    "cycle_bom_crlf": (GLOBAL_CMD.replace("-o out.toml", "--method four-step -o out.toml"), "cycle.csv",
                       "\ufeff" + open(os.path.join(HERE, "..", "..", "examples", "cycle_measured_a.csv")).read().replace("\n", "\r\n")),
    "span_crlf": (SPAN_CMD, "span.toml", SPAN.replace("\n", "\r\n")),
    "sd_bom_crlf": (SD_CMD, "sd.csv", "\ufeff" + SD.replace("\n", "\r\n")),
    "fatigue_tests_bom_crlf": (FATIGUE_CMD, "tests.csv", "\ufeff" + FATIGUE_TESTS.replace("\n", "\r\n")),
    "velocity_list_with_spaces": ('impedance INPUT --velocity "0.1, 0.05" --frequencies "10, 20" -o out.csv', "damper.toml", DAMPER),
}

for folder in ("cases", "accepted"):
    shutil.rmtree(os.path.join(HERE, folder), ignore_errors=True)
for name, (args, file_name, contents, expect, *others) in cases.items():
    d = os.path.join(HERE, "cases", name)
    os.makedirs(d)
    if file_name:
        args = args.replace("INPUT", file_name)
        with open(os.path.join(d, file_name), "w", newline="", encoding="utf-8", errors="surrogateescape") as f:
            f.write(contents)
    # Files beside the input (a line's damper file, a design's span file): the one
    # error line must name the input (`named`), not them.
    for other, text in (others[0] if others else {}).items():
        with open(os.path.join(d, other), "w", newline="") as f:
            f.write(text)
    if others and file_name:
        with open(os.path.join(d, "named"), "w") as f:
            f.write(file_name + "\n")
    with open(os.path.join(d, "args"), "w") as f:
        f.write(args + "\n")
    with open(os.path.join(d, "expect"), "w") as f:
        f.write(expect + "\n")
for name, (args, file_name, contents) in accepted.items():
    d = os.path.join(HERE, "accepted", name)
    os.makedirs(d)
    with open(os.path.join(d, file_name), "w", newline="", encoding="utf-8") as f:
        f.write(contents)
    with open(os.path.join(d, "args"), "w") as f:
        f.write(args.replace("INPUT", file_name) + "\n")
print(len(cases), "bad cases,", len(accepted), "accepted cases")
