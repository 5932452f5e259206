// Span files: the issue's form read as written; every required key missing named
// with its table; bad values reported at their own line with the field's path;
// tension given exactly once; the wind table's CSV and the damper files found
// relative to the span file from any working directory; unknown keys rejected.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/span_file.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::io {
namespace {

const std::string kDamper =
    "[clamp]\nmass = 0.7\n[[arm]]\nname = \"a\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n"
    "[arm.cable]\nlength = 0.1875\nsections = 8\nei = 2.8\njenkin = [ { c = 20.0, h = 0.7 } ]\n";

/// The issue's form, with a damper file in a sub-folder.
const std::string kSpan = R"([conductor]
name = "ASTER570"
mass_per_length = 1.571
diameter = 0.03105
rated_tensile_strength = 185300
ei_min = 28.28
ei_max = 2155
outer_wire_diameter = 0.00345
outer_wire_modulus = 68e9
aluminium_layers = 4

[span]
length = 400
tension_fraction = 0.15

[wind]
law = "cigre"
strouhal = 0.185
speed_min = 1.0
speed_max = 7.0

[self_damping]
law = "noiseux-1991"

[[damper]]
file = "dampers/stockbridge.toml"
position = 1.0
ends = "both"

[fatigue]
cycles = 5e8
wind_weibull = { shape = 2.0, scale = 4.0 }
aeolian_fraction = 0.3
)";

std::filesystem::path span_directory() {
  return std::filesystem::temp_directory_path() / ("stockbridge-span-file-" + std::to_string(::getpid()));
}

std::filesystem::path write_span(const std::string& contents, const std::string& name = "span.toml") {
  const auto dir = span_directory();
  testing::write_temp_file(dir / "dampers", "stockbridge.toml", kDamper);
  return testing::write_temp_file(dir, name, contents);
}

/// `text` with the first occurrence of `from` replaced by `to` (which must be there).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The 1-based line of the first line of `text` starting with `start`.
int line_of(const std::string& text, const std::string& start) {
  int line = 1;
  for (std::size_t at = 0; at < text.size(); ++line) {
    if (text.compare(at, start.size(), start) == 0) return line;
    const std::size_t next = text.find('\n', at);
    if (next == std::string::npos) break;
    at = next + 1;
  }
  ADD_FAILURE() << "no line starting with " << start;
  return 0;
}

/// ":<line>: ", as messages locate a key.
std::string at_line(int line) {
  std::string text = ":";
  text += std::to_string(line);
  text += ": ";
  return text;
}

/// The error's message after the file's path ("" + ":<line>: ..."), or "accepted".
std::string span_error_of(const std::string& contents) {
  const auto path = write_span(contents, "bad.toml");
  try {
    load_span_file(path);
  } catch (const InputError& e) {
    const std::string what = e.what();
    return what.rfind(path.string(), 0) == 0 ? what.substr(path.string().size()) : what;
  }
  return "accepted";
}

TEST(SpanFile, ReadsTheIssuesFormAsWritten) {
  const auto path = write_span(kSpan);
  const SpanFile file = load_span_file(path);
  const span::Span& s = file.span;
  EXPECT_EQ(s.conductor().name, "ASTER570");
  EXPECT_DOUBLE_EQ(s.conductor().mass_per_length, 1.571);
  EXPECT_DOUBLE_EQ(s.conductor().diameter, 0.03105);
  EXPECT_DOUBLE_EQ(s.conductor().rated_tensile_strength, 185300.0);
  EXPECT_DOUBLE_EQ(s.conductor().ei_min, 28.28);
  EXPECT_DOUBLE_EQ(s.conductor().ei_max, 2155.0);
  EXPECT_DOUBLE_EQ(s.conductor().outer_wire_diameter, 0.00345);
  EXPECT_DOUBLE_EQ(s.conductor().outer_wire_modulus, 68e9);
  EXPECT_EQ(s.conductor().aluminium_layers, 4);
  EXPECT_DOUBLE_EQ(s.length(), 400.0);
  EXPECT_NEAR(s.tension(), 0.15 * 185300.0, 1e-9);
  EXPECT_EQ(s.wind().law, span::WindLaw::cigre);
  EXPECT_DOUBLE_EQ(s.wind().strouhal, 0.185);
  EXPECT_DOUBLE_EQ(s.wind().speed_min, 1.0);
  EXPECT_DOUBLE_EQ(s.wind().speed_max, 7.0);
  EXPECT_EQ(s.self_damping().law, span::SelfDampingLaw::noiseux_1991);
  EXPECT_FALSE(s.self_damping().k.has_value());
  ASSERT_EQ(s.dampers().size(), 1u);
  EXPECT_EQ(s.dampers()[0].name, "stockbridge");
  EXPECT_DOUBLE_EQ(s.dampers()[0].position, 1.0);
  EXPECT_TRUE(s.dampers()[0].both_ends);
  EXPECT_DOUBLE_EQ(s.dampers()[0].damper->clamp_mass(), 0.7);
  ASSERT_TRUE(s.fatigue().cycles.has_value());
  EXPECT_DOUBLE_EQ(*s.fatigue().cycles, 5e8);
  EXPECT_FALSE(s.fatigue().endurance_limit.has_value());
  ASSERT_TRUE(s.fatigue().life.has_value());
  EXPECT_DOUBLE_EQ(s.fatigue().life->wind_weibull.shape, 2.0);
  EXPECT_DOUBLE_EQ(s.fatigue().life->wind_weibull.scale, 4.0);
  EXPECT_DOUBLE_EQ(s.fatigue().life->aeolian_fraction, 0.3);
  ASSERT_EQ(file.inputs.size(), 1u);
  EXPECT_EQ(file.inputs[0], span_directory() / "dampers/stockbridge.toml");
  EXPECT_TRUE(file.warnings.empty());
}

TEST(SpanFile, TheShippedExampleReads) {
  const SpanFile file = load_span_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/aster570_400m.toml");
  ASSERT_EQ(file.span.dampers().size(), 1u);
  EXPECT_EQ(file.span.dampers()[0].name, "sauter2003");
  EXPECT_TRUE(file.warnings.empty());
}

TEST(SpanFile, OptionalKeysTakeTheModelsDefaults) {
  std::string text = replaced(kSpan, "strouhal = 0.185\nspeed_min = 1.0\nspeed_max = 7.0\n", "");
  text = replaced(text, "ends = \"both\"\n", "");
  text = replaced(text, "ei_max = 2155\n", "");
  text = replaced(text, "wind_weibull = { shape = 2.0, scale = 4.0 }\naeolian_fraction = 0.3\n", "");
  const SpanFile file = load_span_file(write_span(text));
  const span::WindModel defaults;
  EXPECT_EQ(file.span.wind().strouhal, defaults.strouhal);
  EXPECT_EQ(file.span.wind().speed_min, defaults.speed_min);
  EXPECT_EQ(file.span.wind().speed_max, defaults.speed_max);
  EXPECT_TRUE(file.span.dampers()[0].both_ends);
  EXPECT_EQ(file.span.conductor().ei_max, 0.0);
  EXPECT_FALSE(file.span.fatigue().life.has_value());
  // No dampers at all, and a tension in N; one damper at one end.
  std::string bare = replaced(kSpan, "[[damper]]\nfile = \"dampers/stockbridge.toml\"\nposition = 1.0\nends = \"both\"\n", "");
  bare = replaced(bare, "tension_fraction = 0.15", "tension = 30000");
  const SpanFile no_dampers = load_span_file(write_span(bare));
  EXPECT_TRUE(no_dampers.span.dampers().empty());
  EXPECT_TRUE(no_dampers.inputs.empty());
  EXPECT_DOUBLE_EQ(no_dampers.span.tension(), 30000.0);
  EXPECT_FALSE(load_span_file(write_span(replaced(kSpan, "ends = \"both\"", "ends = \"one\""))).span.dampers()[0].both_ends);
}

struct MissingKey {
  std::string line;   ///< the line removed
  std::string table;  ///< the table it belonged to (whose header line the message names)
  std::string key;
};

class SpanFileMissingKey : public ::testing::TestWithParam<MissingKey> {};

TEST_P(SpanFileMissingKey, IsNamedWithItsTable) {
  const MissingKey& m = GetParam();
  const std::string text = replaced(kSpan, m.line + "\n", "");
  const std::string error = span_error_of(text);
  const std::string where = m.table == "damper" ? "[[damper]]" : "[" + m.table + "]";
  const std::string expected = at_line(line_of(text, where)) + "missing key '" + m.key + "' in [" +
                               (m.table == "damper" ? "damper[0]" : m.table) + "]";
  EXPECT_EQ(error.rfind(expected, 0), 0u) << error << "\nexpected: " << expected;
}

INSTANTIATE_TEST_SUITE_P(
    EveryRequiredKey, SpanFileMissingKey,
    ::testing::Values(MissingKey{"mass_per_length = 1.571", "conductor", "mass_per_length"},
                      MissingKey{"diameter = 0.03105", "conductor", "diameter"},
                      MissingKey{"rated_tensile_strength = 185300", "conductor", "rated_tensile_strength"},
                      MissingKey{"ei_min = 28.28", "conductor", "ei_min"},
                      MissingKey{"outer_wire_diameter = 0.00345", "conductor", "outer_wire_diameter"},
                      MissingKey{"outer_wire_modulus = 68e9", "conductor", "outer_wire_modulus"},
                      MissingKey{"aluminium_layers = 4", "conductor", "aluminium_layers"},
                      MissingKey{"length = 400", "span", "length"},
                      MissingKey{"tension_fraction = 0.15", "span", "tension"},
                      MissingKey{"law = \"cigre\"", "wind", "law"},
                      MissingKey{"law = \"noiseux-1991\"", "self_damping", "law"},
                      MissingKey{"file = \"dampers/stockbridge.toml\"", "damper", "file"},
                      MissingKey{"position = 1.0", "damper", "position"},
                      MissingKey{"aeolian_fraction = 0.3", "fatigue", "aeolian_fraction"}));

// Issue 49: a [conductor] table whose `type` line was deleted (its overrides left)
// was refused as "missing key 'mass_per_length' ...: expected a number", which does
// not say that a type or a file would do.
TEST(SpanFile, AConductorWithoutTypeOrFileNamesThemAsAlternatives) {
  const std::string conductor = kSpan.substr(0, kSpan.find("[span]"));
  const std::string text = replaced(kSpan, conductor, "[conductor]\ndiameter = 0.02814\n\n");
  EXPECT_EQ(span_error_of(text),
            ":1: missing key 'mass_per_length' in [conductor]: expected type = a conductor of the catalogue (e.g. "
            "\"ACSR Drake\"), file = a conductor file, or every one of mass_per_length, diameter, "
            "rated_tensile_strength, ei_min, outer_wire_diameter, outer_wire_modulus and aluminium_layers");
  EXPECT_EQ(span_error_of(replaced(kSpan, conductor, "[conductor]\ntype = \"ACSR Drake\"\ndiameter = 0.02814\n\n")),
            "accepted");
}

TEST(SpanFile, AMissingTableIsNamed) {
  for (const std::string table : {"conductor", "span", "wind", "self_damping", "fatigue"}) {
    std::string text = replaced(kSpan, "[" + table + "]", "[" + table + "_]");
    EXPECT_NE(span_error_of(text).find("unknown key '" + table + "_'"), std::string::npos) << span_error_of(text);
  }
  const std::string no_fatigue = kSpan.substr(0, kSpan.find("[fatigue]"));
  EXPECT_NE(span_error_of(no_fatigue).find("missing key 'fatigue' in the top level"), std::string::npos)
      << span_error_of(no_fatigue);
}

/// The span file `text` is refused with `message` at the line that starts with `key_line`.
void expect_error_at(const std::string& text, const std::string& key_line, const std::string& message) {
  const std::string expected = at_line(line_of(text, key_line)) + message;
  const std::string error = span_error_of(text);
  EXPECT_EQ(error.rfind(expected, 0), 0u) << error << "\nexpected the start: " << expected;
}

/// A bad value is reported at its own line, named by its full path: the line of
/// `to` (of its last line where it holds several, unless `first` says otherwise).
void expect_at_line(const std::string& from, const std::string& to, const std::string& message, bool first = false) {
  expect_error_at(replaced(kSpan, from, to), first ? to.substr(0, to.find('\n')) : to.substr(to.rfind('\n') + 1), message);
}

TEST(SpanFile, BadValuesAreReportedAtTheirLine) {
  expect_at_line("diameter = 0.03105", "diameter = -1", "conductor.diameter = -1: expected a finite value > 0 (m)");
  expect_at_line("ei_min = 28.28", "ei_min = 0", "conductor.ei_min = 0: expected a finite value > 0");
  expect_at_line("aluminium_layers = 4", "aluminium_layers = 11", "conductor.aluminium_layers: 11: expected an integer from 1 to 10");
  expect_at_line("aluminium_layers = 4", "aluminium_layers = 4.5", "conductor.aluminium_layers: the number 4.5: expected an integer from 1 to 10");
  expect_at_line("length = 400", "length = -400", "span.length = -400");
  expect_at_line("tension_fraction = 0.15", "tension_fraction = 1.5",
                 "span.tension_fraction = 1.5: expected a fraction of the rated tensile strength > 0 and < 1");
  expect_at_line("law = \"cigre\"", "law = \"cigr\"", "wind.law = 'cigr': expected cigre, foti");
  expect_at_line("law = \"cigre\"", "law = 3", "wind.law: the integer 3: expected a string");
  expect_at_line("speed_max = 7.0", "speed_max = 0.5", "wind.speed_max = 0.5: expected more than speed_min = 1 m/s");
  expect_at_line("strouhal = 0.185", "strouhal = 1.85", "wind.strouhal = 1.85");
  expect_at_line("law = \"noiseux-1991\"", "law = \"noiseux\"", "self_damping.law = 'noiseux': expected one of");
  expect_at_line("law = \"noiseux-1991\"", "law = \"noiseux-1991\"\nk = -1", "self_damping.k = -1");
  expect_at_line("law = \"noiseux-1991\"", "law = \"noiseux-1991\"\nn = 2.5", "self_damping.n");
  expect_at_line("law = \"noiseux-1991\"", "law = \"foti\"\nlimit_curvature = -0.02", "self_damping.limit_curvature = -0.02");
  expect_at_line("position = 1.0", "position = -1", "damper[0].position = -1");
  expect_at_line("ends = \"both\"", "ends = \"three\"", "damper[0].ends: \"three\": expected \"both\"");
  expect_at_line("cycles = 5e8", "cycles = -5", "fatigue.cycles = -5");
  expect_at_line("aeolian_fraction = 0.3", "aeolian_fraction = 1.3", "fatigue.aeolian_fraction = 1.3");
  expect_at_line("wind_weibull = { shape = 2.0, scale = 4.0 }", "wind_weibull = { shape = -2.0, scale = 4.0 }",
                 "fatigue.wind_weibull.shape = -2");
  expect_at_line("wind_weibull = { shape = 2.0, scale = 4.0 }", "wind_weibull = { shape = 2.0, scale = 4.0, k = 1 }",
                 "unknown key 'fatigue.wind_weibull.k'");
}

// The optional [balance] table: every key read into span::BalanceOptions, every key
// left out at its default, bad values at their line.
TEST(SpanFile, TheBalanceTableSetsTheBalanceOptions) {
  const span::BalanceOptions defaults;
  const SpanFile plain = load_span_file(write_span(kSpan));
  EXPECT_EQ(plain.balance.polish_tolerance, defaults.polish_tolerance);
  EXPECT_EQ(plain.balance.table.velocities, defaults.table.velocities);
  const SpanFile file = load_span_file(write_span(kSpan + R"(
[balance]
damper_model = "weak"
polish = false
polish_tolerance = 1e-7
max_polish_evaluations = 80
amplitude_min_over_diameter = 1e-5
amplitude_max_over_diameter = 2

[balance.table]
velocities = 13
velocity_min = 0.002
velocity_max = 2.0
column_ratio = 1.25
)"));
  const span::BalanceOptions& b = file.balance;
  EXPECT_EQ(b.damper_model, span::DamperModel::weak);
  EXPECT_FALSE(b.polish);
  EXPECT_EQ(b.polish_tolerance, 1e-7);
  EXPECT_EQ(b.max_polish_evaluations, 80);
  EXPECT_EQ(b.amplitude_min_over_diameter, 1e-5);
  EXPECT_EQ(b.amplitude_max_over_diameter, 2.0);
  EXPECT_EQ(b.table.velocities, 13);
  EXPECT_EQ(b.table.velocity_min, 0.002);
  EXPECT_EQ(b.table.velocity_max, 2.0);
  EXPECT_EQ(b.table.column_ratio, 1.25);
  EXPECT_EQ(b.fixed_point.tolerance, defaults.fixed_point.tolerance);  // not a file key
  const std::string balance = "\n[balance]\npolish_tolerance = 1e-6\n[balance.table]\nvelocities = 9\n";
  const auto bad = [&](const std::string& from, const std::string& to, const std::string& message) {
    expect_error_at(kSpan + replaced(balance, from, to), to, message);
  };
  bad("polish_tolerance = 1e-6", "polish_tolerance = -1", "balance.polish_tolerance = -1: expected a finite value > 0");
  bad("polish_tolerance = 1e-6", "damper_model = \"strong\"",
      "balance.damper_model = 'strong': expected travelling or weak");
  bad("polish_tolerance = 1e-6", "polish = 1", "balance.polish: the integer 1: expected true or false");
  bad("velocities = 9", "velocities = 1", "balance.table.velocities: 1: expected an integer from 2 to 1000");
  bad("velocities = 9", "column_ratio = 0.5", "balance.table.column_ratio = 0.5: expected a factor from 1 to 10");
  bad("polish_tolerance = 1e-6", "polish_tolerence = 1e-6", "unknown key 'balance.polish_tolerence'");
}

TEST(SpanFile, TensionIsGivenExactlyOnce) {
  expect_at_line("tension_fraction = 0.15", "tension_fraction = 0.15\ntension = 30000",
                 "span.tension_fraction: given beside span.tension: expected one of", true);
  EXPECT_NE(span_error_of(replaced(kSpan, "tension_fraction = 0.15", "tension = 185300")).find("span.tension = 185300"),
            std::string::npos);
  expect_at_line("tension_fraction = 0.15", "tension = -1", "span.tension = -1");
}

// H/w as utilities give it: T = (H/w) m g; one of the three forms only; the terrain
// category 1..4 and x_b of Yb read where given.
TEST(SpanFile, TensionAsTheCatenaryParameterAndTheTerrain) {
  const SpanFile file = load_span_file(write_span(replaced(
      replaced(kSpan, "tension_fraction = 0.15", "catenary_parameter = 1800\nterrain = 2"), "cycles = 5e8",
      "cycles = 5e8\nyb_distance = 0.1")));
  EXPECT_DOUBLE_EQ(file.span.tension(), 1800.0 * 1.571 * 9.80665);
  EXPECT_EQ(file.span.terrain(), 2);
  EXPECT_EQ(file.span.fatigue().yb_distance, 0.1);
  EXPECT_TRUE(file.warnings.empty());
  EXPECT_FALSE(load_span_file(write_span(kSpan)).span.terrain().has_value());
  EXPECT_EQ(load_span_file(write_span(kSpan)).span.fatigue().yb_distance, 0.089);
  expect_at_line("tension_fraction = 0.15", "tension_fraction = 0.15\ncatenary_parameter = 1800",
                 "span.catenary_parameter: given beside span.tension_fraction: expected one of tension (N), "
                 "tension_fraction and catenary_parameter (H/w, m)");
  expect_at_line("tension_fraction = 0.15", "catenary_parameter = -5", "span.catenary_parameter = -5: expected a finite value > 0 (m)");
  expect_at_line("tension_fraction = 0.15", "catenary_parameter = 20000",
                 "span.catenary_parameter = 20000: expected less than the rated tensile strength per weight, 12027.6 m "
                 "(T = (H/w) m g = 308125 N)");
  expect_at_line("length = 400", "length = 400\nterrain = 5", "span.terrain: 5: expected an integer from 1 to 4");
  expect_at_line("cycles = 5e8", "cycles = 5e8\nyb_distance = 0", "fatigue.yb_distance = 0: expected a finite value > 0");
  EXPECT_NE(span_error_of(replaced(kSpan, "tension_fraction = 0.15", "")).find(
                "missing key 'tension' in [span]: expected one of tension (N), tension_fraction (of the rated tensile "
                "strength) and catenary_parameter (H/w, m)"),
            std::string::npos);
}

// The unit slips of a first use, each refused at its line naming the key and the
// unit it likely is (nothing computed from it), and accepted with a warning where
// the study says so (SlipPolicy::warn: --allow-unusual, allow_unusual=True).
TEST(SpanFile, UnitSlipsAreRefusedAtTheirLineNamingTheLikelyUnit) {
  const auto expect_slip = [&](const std::string& from, const std::string& to, const std::string& message,
                               bool possible = true) {
    const std::string text = replaced(kSpan, from, to);
    const auto path = write_span(text, "slip.toml");
    try {
      load_span_file(path);
      ADD_FAILURE() << to << ": accepted";
    } catch (const UnusualValueError& e) {
      EXPECT_EQ(std::string(e.what()), path.string() + at_line(line_of(text, to)) + message);
    }
    if (!possible) {  // no span has it: refused however unusual the study
      EXPECT_THROW(load_span_file(path, SlipPolicy::warn), InputError) << to;
      return;
    }
    const SpanFile accepted = load_span_file(path, SlipPolicy::warn);
    ASSERT_FALSE(accepted.warnings.empty()) << to;
    EXPECT_EQ(accepted.warnings.front(), path.string() + at_line(line_of(text, to)) + message);
  };
  expect_slip("rated_tensile_strength = 185300", "rated_tensile_strength = 185.3",
              "conductor.rated_tensile_strength = 185.3: outside the typical 5000 to 1.5e+06 N of the conductor "
              "rated tensile strength (in kN? 185.3 kN = 185300 N)");
  expect_slip("outer_wire_modulus = 68e9", "outer_wire_modulus = 68.9",
              "conductor.outer_wire_modulus = 68.9: outside the typical 4e+10 to 2.2e+11 Pa of the outer wire "
              "Young's modulus (in GPa? 68.9 GPa = 6.89e+10 Pa)");
  expect_slip("mass_per_length = 1.571", "mass_per_length = 1571",
              "conductor.mass_per_length = 1571: outside the typical 0.03 to 8 kg/m of the conductor mass per length "
              "(in g/m? 1571 g/m = 1.571 kg/m)");
  expect_slip("diameter = 0.03105", "diameter = 31.05",
              "conductor.diameter = 31.05: outside the typical 0.004 to 0.08 m of the conductor diameter (in mm? "
              "31.05 mm = 0.03105 m)");
  expect_slip("tension_fraction = 0.15", "tension = 28.02",
              "span.tension = 28.02: outside the typical 1000 to 500000 N of the conductor tension (in kN? 28.02 kN = "
              "28020 N)");
  expect_slip("tension_fraction = 0.15", "tension_fraction = 15",
              "span.tension_fraction = 15: outside the typical 0.03 to 0.4 of the tension as a fraction of the rated "
              "tensile strength (a percentage? 15 % = 0.15)",
              false);
  expect_slip("length = 400", "length = 0.4",
              "span.length = 0.4: outside the typical 20 to 3000 m of the span length (in km? 0.4 km = 400 m)", false);
  expect_slip("position = 1.0", "position = 1200",
              "damper[0].position = 1200: outside the typical 0.1 to 10 m of the damper position from the span clamp "
              "(in mm? 1200 mm = 1.2 m)",
              false);
  expect_slip("aeolian_fraction = 0.3", "aeolian_fraction = 30",
              "fatigue.aeolian_fraction = 30: outside the typical 0.01 to 1 of the share of the year with aeolian "
              "vibration (a percentage? 30 % = 0.3)",
              false);
}

// A value outside its range that no slip explains is a warning, and the run goes on.
TEST(SpanFile, AnUnusualValueNoSlipExplainsWarnsAtItsLine) {
  const auto warning_of = [](const std::string& from, const std::string& to) {
    const SpanFile file = load_span_file(write_span(replaced(kSpan, from, to)));
    EXPECT_EQ(file.warnings.size(), 1u) << to;
    return file.warnings.empty() ? std::string() : file.warnings.front();
  };
  EXPECT_NE(warning_of("cycles = 5e8", "cycles = 500").find("fatigue.cycles = 500: outside the typical 1e+06 to 1e+10 "
                                                            "of the cycles of the endurance limit (a unit mistake?)"),
            std::string::npos);
  EXPECT_NE(warning_of("aeolian_fraction = 0.3", "aeolian_fraction = 0.003").find("fatigue.aeolian_fraction = 0.003"),
            std::string::npos);
}

// A tension at which no span hangs (a sag over a tenth of the span, H/w outside 100
// to 5000 m) is refused at the tension's key, whichever form gave it; a tension
// beyond the rated strength always.
TEST(SpanFile, ATensionNoSpanHangsAtIsRefusedAtItsKey) {
  const auto error_of = [](const std::string& to, SlipPolicy policy = SlipPolicy::refuse) {
    const auto path = write_span(replaced(kSpan, "tension_fraction = 0.15", to), "sag.toml");
    try {
      const SpanFile file = load_span_file(path, policy);
      return file.warnings.empty() ? std::string("accepted") : "warning " + file.warnings.back();
    } catch (const InputError& e) {
      return std::string(e.what()).substr(path.string().size());
    }
  };
  // 2000 N: H/w = 130 m, a sag of 154 m on 400 m.
  EXPECT_EQ(error_of("tension = 2000"), ":14: span.tension = 2000: H/w = 129.8 m and a sag of 154 m (38.5 % of the 400 "
                                        "m span): expected H/w from 100 to 5000 m and a sag within 10 % of the span, as "
                                        "spans hang");
  EXPECT_EQ(error_of("catenary_parameter = 6000").find(":14: span.catenary_parameter = 6000: H/w = 6000 m"), 0u);
  EXPECT_EQ(error_of("tension_fraction = 0.01").find(":14: span.tension_fraction = 0.01: H/w = 120.3 m"), 0u)
      << error_of("tension_fraction = 0.01");
  EXPECT_EQ(error_of("tension = 2000", SlipPolicy::warn).find("warning "), 0u);
  EXPECT_NE(error_of("tension = 200000", SlipPolicy::warn).find("span.tension = 200000: expected less than the rated "
                                                                "tensile strength"),
            std::string::npos);
}

// A range error names the key at fault: ei_min in N mm^2 (not ei_max, which is
// right); a span too short for its dampers (not the damper's position, which is usual).
TEST(SpanFile, RangeErrorsNameTheKeyAtFault) {
  expect_at_line("ei_min = 28.28", "ei_min = 37500",
                 "conductor.ei_min = 37500: expected at most ei_max = 2155 N m^2 (the free wires' stiffness, typically "
                 "0.5 to 2000 N m^2)");
  expect_at_line("ei_max = 2155", "ei_max = 20", "conductor.ei_max = 20: expected 0 (not given) or at least ei_min");
  expect_error_at(replaced(replaced(kSpan, "length = 400", "length = 16"), "position = 1.0", "position = 9"), "length = 16",
                  "span.length = 16: expected more than twice damper[0].position = 9 m: the span is too short for its "
                  "dampers");
  expect_at_line("position = 1.0", "position = 300", "damper[0].position = 300: outside the typical 0.1 to 10 m");
}

// A damper known by its measured sheet: `impedance = "sheet.csv"` beside the span
// file instead of `file`; one of the two; a sheet of one curve refused at its key.
TEST(SpanFile, ADamperFromAMeasuredSheet) {
  const auto dir = span_directory();
  testing::write_temp_file(dir, "sheet.csv",
                           "frequency_hz,velocity_m_s,abs_z_n_s_m,phase_deg\n10,0.05,100,80\n20,0.05,150,70\n"
                           "10,0.1,110,75\n20,0.1,160,60\n");
  const std::string damper = "[[damper]]\nfile = \"dampers/stockbridge.toml\"\n";
  const SpanFile file = load_span_file(write_span(replaced(kSpan, damper, "[[damper]]\nimpedance = \"sheet.csv\"\n")));
  ASSERT_EQ(file.span.dampers().size(), 1u);
  const span::SpanDamper& d = file.span.dampers()[0];
  EXPECT_TRUE(d.measured());
  EXPECT_FALSE(d.damper.has_value());
  EXPECT_EQ(d.name, "sheet");
  EXPECT_EQ(d.sheet->curves(), 2);
  EXPECT_DOUBLE_EQ(d.sheet->frequency_range().lo, 10.0);
  EXPECT_EQ(file.inputs.back(), dir / "sheet.csv");
  expect_at_line("file = \"dampers/stockbridge.toml\"", "file = \"dampers/stockbridge.toml\"\nimpedance = \"sheet.csv\"",
                 "damper[0].impedance: given beside file: expected a damper file or a measured sheet, one of the two");
  testing::write_temp_file(dir, "one.csv", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.05,1,100\n20,0.05,2,150\n");
  expect_at_line("file = \"dampers/stockbridge.toml\"", "impedance = \"one.csv\"",
                 "damper[0].impedance: \"one.csv\": 1 curve(s) of two or more frequencies: expected at least two "
                 "amplitudes measured");
  expect_at_line("file = \"dampers/stockbridge.toml\"", "impedance = \"none.csv\"",
                 "damper[0].impedance: \"none.csv\": expected an existing measured impedance CSV file");
}

TEST(SpanFile, AWindTableIsReadFromItsCsvBesideTheSpanFile) {
  const auto dir = span_directory();
  testing::write_temp_file(dir / "wind", "fnc.csv", "y_over_d,fnc\n0,0\n0.1,1.2\n0.5,8\n1.0,-1\n");
  const std::string text = replaced(kSpan, "law = \"cigre\"", "law = \"table\"\ntable = \"wind/fnc.csv\"");
  const SpanFile file = load_span_file(write_span(text));
  EXPECT_EQ(file.span.wind().law, span::WindLaw::table);
  ASSERT_EQ(file.span.wind().table.size(), 4u);
  EXPECT_DOUBLE_EQ(file.span.wind().table[1].y_over_d, 0.1);
  EXPECT_DOUBLE_EQ(file.span.wind().table[1].fnc, 1.2);
  EXPECT_NE(std::find(file.inputs.begin(), file.inputs.end(), dir / "wind/fnc.csv"), file.inputs.end());
  // Missing, without the key, beside another law, a bad cell, a bad point.
  expect_at_line("law = \"cigre\"", "law = \"table\"\ntable = \"nope.csv\"", "wind.table: \"nope.csv\": expected an existing CSV file");
  EXPECT_NE(span_error_of(replaced(kSpan, "law = \"cigre\"", "law = \"table\"")).find("missing key 'table' in [wind]"),
            std::string::npos);
  expect_at_line("law = \"cigre\"", "law = \"cigre\"\ntable = \"wind/fnc.csv\"", "wind.table: \"wind/fnc.csv\": only law = \"table\"");
  testing::write_temp_file(dir / "wind", "bad.csv", "y_over_d,fnc\n0,0\n0.1,abc\n");
  EXPECT_NE(span_error_of(replaced(kSpan, "law = \"cigre\"", "law = \"table\"\ntable = \"wind/bad.csv\"")).find("bad.csv:3"),
            std::string::npos);
  testing::write_temp_file(dir / "wind", "unsorted.csv", "y_over_d,fnc\n0.2,1\n0.1,2\n");
  const std::string unsorted = replaced(kSpan, "law = \"cigre\"", "law = \"table\"\ntable = \"wind/unsorted.csv\"");
  // A bad point is named where it is written: the table's file, row and column.
  EXPECT_EQ(span_error_of(unsorted),
            (dir / "wind/unsorted.csv").string() + ":3: column 'y_over_d' = 0.1: expected more than the row before's 0.2 "
                                                   "(increasing)");
  testing::write_temp_file(dir / "wind", "negative.csv", "y_over_d,fnc\n-0.1,1\n0.1,2\n");
  EXPECT_EQ(span_error_of(replaced(kSpan, "law = \"cigre\"", "law = \"table\"\ntable = \"wind/negative.csv\"")),
            (dir / "wind/negative.csv").string() +
                ":2: column 'y_over_d' = -0.1: expected an amplitude over the diameter from 0 to 10");
}

// [fatigue] criterion: named, or told by the one limit given; the microstrain
// criterion's limit as a zero-to-peak stress, E_a eps / 2 (150 microstrain, the
// IEEE's, by default); a limit in MPa the same as in Pa.
TEST(SpanFile, TheFatigueCriterionIsNamedOrToldByItsLimit) {
  const auto fatigue_of = [](const std::string& keys) {
    return load_span_file(write_span(replaced(kSpan, "cycles = 5e8", keys))).span;
  };
  const span::Span microstrain = fatigue_of("criterion = \"microstrain\"");
  EXPECT_EQ(microstrain.fatigue().criterion, span::FatigueCriterion::microstrain);
  EXPECT_FALSE(microstrain.fatigue().limit_pp_microstrain.has_value());
  EXPECT_DOUBLE_EQ(microstrain.endurance_limit(), 0.5e-6 * 150.0 * 68e9);  // 5.1 MPa
  EXPECT_TRUE(microstrain.judges_poffenberger_swart());
  EXPECT_EQ(microstrain.criterion_description(), "150 microstrain peak-to-peak (the IEEE committee's limit)");
  const span::Span given = fatigue_of("criterion = \"microstrain\"\nlimit_pp_microstrain = 200");
  EXPECT_DOUBLE_EQ(given.endurance_limit(), 0.5e-6 * 200.0 * 68e9);
  EXPECT_EQ(given.criterion_description(), "200 microstrain peak-to-peak (given)");
  // The criterion told by the key given.
  const span::Span told = fatigue_of("limit_pp_microstrain = 200");
  EXPECT_EQ(told.fatigue().criterion, span::FatigueCriterion::microstrain);
  EXPECT_EQ(told.endurance_limit(), given.endurance_limit());
  const span::Span in_mpa = fatigue_of("endurance_limit_mpa = 8.5");
  const span::Span in_pa = fatigue_of("endurance_limit = 8.5e6");
  EXPECT_EQ(in_mpa.fatigue().criterion, span::FatigueCriterion::stress);
  EXPECT_EQ(in_pa.fatigue().criterion, span::FatigueCriterion::stress);
  EXPECT_EQ(in_mpa.endurance_limit(), 8.5e6);
  EXPECT_EQ(in_pa.endurance_limit(), in_mpa.endurance_limit());
  EXPECT_FALSE(in_mpa.judges_poffenberger_swart());
  EXPECT_EQ(in_mpa.criterion_description(), "a given endurance limit");
  EXPECT_EQ(fatigue_of("criterion = \"stress\"\nendurance_limit_mpa = 8.5").endurance_limit(), 8.5e6);
  const span::Span sbl = load_span_file(write_span(kSpan)).span;
  EXPECT_EQ(sbl.fatigue().criterion, span::FatigueCriterion::safe_border_line);
  EXPECT_EQ(sbl.criterion_description(), "the CIGRE Safe Border Line at 5e+08 cycles");
  EXPECT_EQ(fatigue_of("criterion = \"safe-border-line\"\ncycles = 5e8").endurance_limit(), sbl.endurance_limit());
}

// A limit of another criterion, or the same limit twice, is refused at its line
// naming the key as written.
TEST(SpanFile, ALimitTheCriterionDoesNotUseIsRefusedNamingIt) {
  const auto refused = [](const std::string& keys, const std::string& at, const std::string& message) {
    expect_error_at(replaced(kSpan, "cycles = 5e8", keys), at, message);
  };
  refused("endurance_limit = 8.5e6\nendurance_limit_mpa = 8.5", "endurance_limit_mpa",
          "fatigue.endurance_limit_mpa: given beside endurance_limit (Pa): expected one of the two");
  refused("criterion = \"microstrain\"\ncycles = 5e8", "cycles",
          "fatigue.cycles: given beside criterion = \"microstrain\", which does not use it");
  refused("criterion = \"microstrain\"\nendurance_limit = 8.5e6", "endurance_limit",
          "fatigue.endurance_limit: given beside criterion = \"microstrain\", which does not use it");
  refused("criterion = \"stress\"\nendurance_limit_mpa = 8.5\nlimit_pp_microstrain = 150", "limit_pp_microstrain",
          "fatigue.limit_pp_microstrain: given beside criterion = \"stress\", which does not use it");
  refused("criterion = \"safe-border-line\"\ncycles = 5e8\nlimit_pp_microstrain = 150", "limit_pp_microstrain",
          "fatigue.limit_pp_microstrain: given beside criterion = \"safe-border-line\", which does not use it");
  // A stress limit told by its key leaves the cycles beside it unused.
  refused("cycles = 5e8\nendurance_limit_mpa = 8.5", "cycles",
          "fatigue.cycles: given beside criterion = \"stress\", which does not use it");
  refused("criterion = \"stress\"", "[fatigue]",
          "fatigue.endurance_limit: missing: criterion \"stress\" takes endurance_limit_mpa (or endurance_limit in Pa)");
  refused("criterion = \"ieee\"", "criterion",
          "fatigue.criterion = 'ieee': expected safe-border-line, microstrain or stress");
  refused("criterion = \"microstrain\"\nlimit_pp_microstrain = -150", "limit_pp_microstrain",
          "fatigue.limit_pp_microstrain = -150");
  EXPECT_NE(span_error_of(replaced(kSpan, "cycles = 5e8\n", "")).find(
                "missing key 'cycles' in [fatigue]: expected cycles (the Safe Border Line at that many cycles), "
                "endurance_limit_mpa (a given endurance limit), limit_pp_microstrain, or criterion ="),
            std::string::npos)
      << span_error_of(replaced(kSpan, "cycles = 5e8\n", ""));
}

// A limit of the stress criterion given in MPa beside the microstrain criterion is
// named as written (endurance_limit_mpa), not as the model holds it.
TEST(SpanFile, ALimitInMpaTheCriterionDoesNotUseIsNamedAsWritten) {
  expect_error_at(replaced(kSpan, "cycles = 5e8", "criterion = \"microstrain\"\nendurance_limit_mpa = 8.5"),
                  "endurance_limit_mpa",
                  "fatigue.endurance_limit_mpa: given beside criterion = \"microstrain\", which does not use it");
}

// [span] wind_law_by_terrain: the cigre law becomes foti with the terrain's assumed
// intensity; refused without a terrain; a foti law's own intensity kept.
TEST(SpanFile, TheWindLawByTerrain) {
  const span::Span by_terrain = load_span_file(write_span(replaced(
      kSpan, "tension_fraction = 0.15", "tension_fraction = 0.15\nterrain = 4\nwind_law_by_terrain = true"))).span;
  EXPECT_EQ(by_terrain.wind().law, span::WindLaw::foti);
  EXPECT_DOUBLE_EQ(by_terrain.wind().turbulence_intensity, 1.0 / std::log(10.0 / 0.3));
  EXPECT_EQ(by_terrain.wind().turbulence_terrain, 4);
  // A terrain alone leaves CIGRE's laminar wind.
  const span::Span terrain_only =
      load_span_file(write_span(replaced(kSpan, "tension_fraction = 0.15", "tension_fraction = 0.15\nterrain = 4"))).span;
  EXPECT_EQ(terrain_only.wind().law, span::WindLaw::cigre);
  EXPECT_EQ(terrain_only.wind().turbulence_intensity, 0.0);
  // foti with its own intensity keeps it; foti without one takes the terrain's.
  const std::string foti = replaced(replaced(kSpan, "law = \"cigre\"", "law = \"foti\"\nturbulence_intensity = 0.05"),
                                    "tension_fraction = 0.15", "tension_fraction = 0.15\nterrain = 4");
  const span::Span own = load_span_file(write_span(foti)).span;
  EXPECT_EQ(own.wind().turbulence_intensity, 0.05);
  EXPECT_FALSE(own.wind().turbulence_terrain.has_value());
  const span::Span taken =
      load_span_file(write_span(replaced(foti, "\nturbulence_intensity = 0.05", ""))).span;
  EXPECT_DOUBLE_EQ(taken.wind().turbulence_intensity, 1.0 / std::log(10.0 / 0.3));
  expect_at_line("tension_fraction = 0.15", "tension_fraction = 0.15\nwind_law_by_terrain = true",
                 "span.wind_law_by_terrain: the span gives no terrain (1 to 4) to take the wind's turbulence from");
  expect_at_line("tension_fraction = 0.15", "tension_fraction = 0.15\nwind_law_by_terrain = 1",
                 "span.wind_law_by_terrain: the integer 1: expected true or false");
}

TEST(SpanFile, DamperFilesAreFoundRelativeToTheSpanFileFromAnotherFolder) {
  const auto path = write_span(kSpan);
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  const SpanFile file = load_span_file(path);
  std::filesystem::current_path(cwd);
  ASSERT_EQ(file.span.dampers().size(), 1u);
  const std::string missing = replaced(kSpan, "dampers/stockbridge.toml", "dampers/none.toml");
  const std::string error = span_error_of(missing);
  EXPECT_EQ(error.rfind(at_line(line_of(missing, "file =")) +
                            "damper[0].file: \"dampers/none.toml\": expected an existing damper file",
                        0),
            0u)
      << error;
  // An error inside the damper file is located there.
  testing::write_temp_file(span_directory() / "dampers", "broken.toml", replaced(kDamper, "mass = 0.856", "mass = -1"));
  const std::string broken = span_error_of(replaced(kSpan, "dampers/stockbridge.toml", "dampers/broken.toml"));
  EXPECT_NE(broken.find("broken.toml:5: arm[0].mass = -1"), std::string::npos) << broken;
}

TEST(SpanFile, UnknownKeysAreRejected) {
  expect_at_line("strouhal = 0.185", "colour = 1", "unknown key 'wind.colour'");
  expect_at_line("ei_min = 28.28", "ei_min = 28.28\nei = 28.28", "unknown key 'conductor.ei'");
  expect_at_line("position = 1.0", "position = 1.0\nname = \"x\"", "unknown key 'damper[0].name'");
  EXPECT_NE(span_error_of(kSpan + "[extra]\n").find("unknown key 'extra'"), std::string::npos);
}

TEST(SpanFile, TextIsCheckedAlikeAndNamedWithoutLines) {
  std::string text = replaced(kSpan, "[[damper]]\nfile = \"dampers/stockbridge.toml\"\nposition = 1.0\nends = \"both\"\n", "");
  EXPECT_EQ(load_span_text(text, "span()").span.length(), 400.0);
  try {
    load_span_text(replaced(text, "diameter = 0.03105", "diameter = -1"), "span()");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "span(): conductor.diameter = -1: expected a finite value > 0 (m)");
  }
}

}  // namespace
}  // namespace stockbridge::io
