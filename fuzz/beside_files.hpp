#pragma once
// Files the fuzzed inputs may name, written once into the fuzzer's folder
// (fuzz_support.hpp's folder()): a damper file, a measured sheet, a conductor file,
// a spans CSV, a span file, each small and valid.

#include <string_view>

#include "fuzz_support.hpp"

namespace stockbridge::fuzz {

/// The example damper of one arm, 8 sections (quick to solve).
inline constexpr std::string_view kDamperFile =
    "[clamp]\nmass = 0.7\n[[arm]]\nname = \"a\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n"
    "[arm.cable]\nlength = 0.1875\nsections = 8\nei = 2.8\njenkin = [ { c = 20.0, h = 0.7 } ]\n";
/// A measured sheet of two curves.
inline constexpr std::string_view kSheetFile =
    "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n5,0.05,1,80\n20,0.05,5,200\n60,0.05,10,400\n"
    "5,0.2,10,70\n20,0.2,50,150\n60,0.2,40,300\n";
/// ACSR Drake as a conductor file (data/conductors/acsr_drake.toml, another type name).
inline constexpr std::string_view kConductorFile =
    "[conductor]\ntype = \"Mine\"\nmass_per_length = 1.628\ndiameter = 0.02814\nrated_tensile_strength = 138800\n"
    "[conductor.core]\nmaterial = \"steel\"\nyoungs_modulus = 207e9\nwire_diameter = 0.00345\n"
    "[[conductor.layer]]\nmaterial = \"steel\"\nyoungs_modulus = 207e9\ncount = 6\nwire_diameter = 0.00345\n"
    "lay_ratio = 21\n"
    "[[conductor.layer]]\nmaterial = \"aluminium\"\nyoungs_modulus = 68.9e9\ncount = 10\nwire_diameter = 0.00444\n"
    "lay_ratio = 13\n"
    "[[conductor.layer]]\nmaterial = \"aluminium\"\nyoungs_modulus = 68.9e9\ncount = 16\nwire_diameter = 0.00444\n"
    "lay_ratio = 12\n";
/// A line's spans: each tension form, a catalogue conductor and the conductor file.
inline constexpr std::string_view kSpansFile =
    "id,length_m,tension_fraction,catenary_parameter_m,conductor,terrain\n"
    "T01-T02,173,0.164,,,1\nT02-T03,196,,1560,,2\nT03-T04,300,0.2,,ACSR Drake,2\nT04-T05,280,0.18,,c.toml,\n";
/// A span of ACSR Drake with the damper file at 1 m, and a climate (for a life).
inline constexpr std::string_view kSpanFile =
    "[conductor]\ntype = \"ACSR Drake\"\n[span]\nlength = 300\ntension_fraction = 0.2\n"
    "[wind]\nlaw = \"cigre\"\n[self_damping]\nlaw = \"noiseux-1991\"\n"
    "[fatigue]\ncycles = 5e8\nwind_weibull = { shape = 2.0, scale = 4.0 }\naeolian_fraction = 0.3\n"
    "[[damper]]\nfile = \"d.toml\"\nposition = 1.0\n";

/// Writes d.toml, sheet.csv, c.toml, and unless the input is the spans CSV itself,
/// spans.csv, and span.toml, once; true when written.
inline bool write_beside_files(bool spans_csv = true) {
  bool written = !as_file(kDamperFile, "d.toml").empty() && !as_file(kSheetFile, "sheet.csv").empty() &&
                 !as_file(kConductorFile, "c.toml").empty() && !as_file(kSpanFile, "span.toml").empty();
  if (spans_csv) written = written && !as_file(kSpansFile, "spans.csv").empty();
  return written;
}

}  // namespace stockbridge::fuzz
