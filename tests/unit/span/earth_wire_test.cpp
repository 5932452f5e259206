// Earth wires and OPGW (MODEL.md sections 11 and 15; docs/span.md, "Earth wires and
// OPGW"): the catalogue's galvanised steel, aluminium-clad steel and OPGW entries load
// with their data sheets' values and EI_min wire by wire (hand computations written
// out here); a span of outer wires other than aluminium is refused under the Safe
// Border Line, naming the key to give (fatigue.endurance_limit_mpa), and judged by
// that limit once given; aluminium conductors are judged as before.

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/span/analysis.hpp"
#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/span.hpp"
#include "stockbridge/span/stranded_conductor.hpp"
#include "support/error_message.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::span {
namespace {

/// What a catalogue entry must give: its data sheet's numbers, the stranding's label,
/// the outer wires, and EI_min by hand (written out below).
struct EarthWire {
  const char* type;
  const char* stranding;
  WireMaterial outer;
  int aluminium_layers;
  double mass_per_length;         // kg/m
  double diameter;                // m
  double rated_tensile_strength;  // N
  double outer_wire_diameter;     // m
  double outer_wire_modulus;      // Pa
  double ei_min;                  // N m^2, by hand
};

// EI_min = sum over the wires of E_w pi r_w^4 / 4 (MODEL.md sections 7 and 11), by hand:
//   EHS 3/8:     7 x 207e9 x pi (1.525e-3)^4 / 4 = 7 x 207e9 x 4.2479e-12 = 7 x 0.87931 = 6.1551
//   GSW 19/3.25: 19 x 207e9 x pi (1.625e-3)^4 / 4 = 19 x 207e9 x 5.4765e-12 = 19 x 1.1336 = 21.539
//   7 No. 8:     7 x 162e9 x pi (1.632e-3)^4 / 4 = 7 x 162e9 x 5.5715e-12 = 7 x 0.90258 = 6.3181
//   19 No. 9:    19 x 162e9 x pi (1.453e-3)^4 / 4 = 19 x 162e9 x 3.5007e-12 = 19 x 0.56711 = 10.775
//   OPGW 9.6:    the tube 79.9e9 x pi (1.6e-3)^4 / 4 = 79.9e9 x 5.1472e-12 = 0.41126,
//                6 ACS wires 6 x 162e9 x 5.1472e-12 = 5.0031: 5.4143
//   OPGW 13.6:   the ACS centre 162e9 x pi (1.4e-3)^4 / 4 = 162e9 x 3.0172e-12 = 0.48878,
//                the inner layer 6 x 150.2e9 x pi (1.35e-3)^4 / 4 = 6 x 150.2e9 x 2.6087e-12 = 2.3510,
//                12 alloy wires 12 x 68e9 x 2.6087e-12 = 2.1287: 4.9685
const EarthWire kEarthWires[] = {
    {"Alumoweld 19 No. 9", "19: aluminium-clad-steel 1+6+12 x 2.906 mm", WireMaterial::aluminium_clad_steel, 0, 0.843,
     0.01453, 152460.0, 0.002906, 162e9, 10.775},
    {"Alumoweld 7 No. 8", "7: aluminium-clad-steel 1+6 x 3.264 mm", WireMaterial::aluminium_clad_steel, 0, 0.390, 0.00979,
     70870.0, 0.003264, 162e9, 6.3181},
    {"EHS 3/8", "7: steel 1+6 x 3.05 mm", WireMaterial::steel, 0, 0.407, 0.00915, 68500.0, 0.00305, 207e9, 6.1551},
    {"GSW 19/3.25", "19: steel 1+6+12 x 3.25 mm", WireMaterial::steel, 0, 1.250, 0.01625, 186000.0, 0.00325, 207e9,
     21.539},
    {"OPGW 13.6", "12/7: aluminium-clad-steel 1 x 2.8 mm, aluminium-clad-steel 6 x 2.7 mm, aluminium-alloy 12 x 2.7 mm",
     WireMaterial::aluminium_alloy, 1, 0.440, 0.0136, 63600.0, 0.0027, 68e9, 4.9685},
    {"OPGW 9.6", "7: steel 1 x 3.2 mm, aluminium-clad-steel 6 x 3.2 mm", WireMaterial::aluminium_clad_steel, 0, 0.344,
     0.0096, 58200.0, 0.0032, 162e9, 5.4143},
};

TEST(EarthWireCatalogue, EveryEntryLoadsWithItsDataSheetsValues) {
  for (const EarthWire& expected : kEarthWires) {
    SCOPED_TRACE(expected.type);
    const StrandedConductor& entry = io::catalogue_conductor(expected.type);
    EXPECT_EQ(entry.type, expected.type);
    EXPECT_FALSE(entry.source.empty());
    EXPECT_EQ(stranding_label(entry), expected.stranding);
    const Conductor c = conductor_of(entry);
    EXPECT_NO_THROW(c.validate());
    EXPECT_EQ(c.mass_per_length, expected.mass_per_length);
    EXPECT_EQ(c.diameter, expected.diameter);
    EXPECT_EQ(c.rated_tensile_strength, expected.rated_tensile_strength);
    EXPECT_EQ(c.outer_wire_diameter, expected.outer_wire_diameter);
    EXPECT_EQ(c.outer_wire_modulus, expected.outer_wire_modulus);
    EXPECT_EQ(c.outer_wire_material, expected.outer);
    EXPECT_EQ(c.aluminium_layers, expected.aluminium_layers);
    EXPECT_EQ(c.safe_border_line_applies(), is_aluminium(expected.outer));
    // The data sheet's diameter is the stranding's, to 0.2 %.
    EXPECT_NEAR(stranding_diameter(entry) / c.diameter, 1.0, 2e-3);
  }
}

TEST(EarthWireCatalogue, EiMinIsTheSumOverTheWiresOfEachWiresOwnModulus) {
  for (const EarthWire& expected : kEarthWires) {
    SCOPED_TRACE(expected.type);
    const Conductor c = conductor_of(io::catalogue_conductor(expected.type));
    EXPECT_NEAR(c.ei_min / expected.ei_min, 1.0, 1e-4) << c.ei_min;
    // Seven-wire strands are 7 to 9 times stiffer without slip, the larger up to 90.
    EXPECT_GT(c.ei_max, 5.0 * c.ei_min);
    EXPECT_LT(c.ei_max, 90.0 * c.ei_min);
  }
}

TEST(EarthWireCatalogue, TheMassesComputedFromTheStrandingAgreeWithTheSheets) {
  // Wire by wire, each layer lengthened by its lay (sqrt(1 + (2 pi R / lambda)^2)), with
  // the densities 7780 kg/m^3 (galvanised steel, as the catalogue's ACSR cores) and
  // 6590 (20 % aluminium-clad steel): within 4 % of the sheets (zinc and lay differ).
  for (const char* type : {"EHS 3/8", "GSW 19/3.25", "Alumoweld 7 No. 8", "Alumoweld 19 No. 9"}) {
    SCOPED_TRACE(type);
    const StrandedConductor& c = io::catalogue_conductor(type);
    const double density = c.core.material == WireMaterial::steel ? 7780.0 : 6590.0;
    const auto area = [](double d) { return std::numbers::pi / 4.0 * d * d; };
    double mass = density * area(c.core.wire_diameter);
    const std::vector<double> radii = pitch_radii(c);
    for (std::size_t j = 0; j < c.layers.size(); ++j) {
      const double stretch = std::hypot(1.0, 2.0 * std::numbers::pi * radii[j] / lay_length(c, j));
      mass += density * c.layers[j].count * area(c.layers[j].wire_diameter) * stretch;
    }
    EXPECT_NEAR(mass / c.mass_per_length, 1.0, 0.04) << mass;
  }
}

TEST(WireMaterials, AluminiumCladSteelIsReadAndNamed) {
  EXPECT_EQ(parse_wire_material("aluminium-clad-steel"), WireMaterial::aluminium_clad_steel);
  EXPECT_EQ(parse_wire_material("aluminum-clad-steel"), WireMaterial::aluminium_clad_steel);
  EXPECT_EQ(wire_material_name(WireMaterial::aluminium_clad_steel), "aluminium-clad-steel");
  EXPECT_FALSE(is_aluminium(WireMaterial::aluminium_clad_steel));
  EXPECT_FALSE(is_aluminium(WireMaterial::steel));
  EXPECT_TRUE(is_aluminium(WireMaterial::aluminium_alloy));
  EXPECT_EQ(stockbridge::testing::invalid_parameter_message([] { parse_wire_material("copper"); }),
            "material = \"copper\": expected steel, aluminium, aluminium-alloy or aluminium-clad-steel");
}

TEST(WireMaterials, AConductorWithoutAluminiumLayersIsValidOnlyWithOtherOuterWires) {
  Conductor c = conductor_of(io::catalogue_conductor("EHS 3/8"));
  EXPECT_EQ(c.aluminium_layers, 0);
  EXPECT_NO_THROW(c.validate());
  c.outer_wire_material = WireMaterial::aluminium;  // aluminium outer wires pick the line by their layers
  EXPECT_EQ(stockbridge::testing::invalid_parameter_message([&] { c.validate(); }),
            "aluminium_layers = 0: expected an integer from 1 to 10");
}

// The Safe Border Line and the endurance limit.

constexpr double kFiveHundredMillion = 5e8;

/// A span of the catalogue's `type` at 20 % RTS, 300 m, no dampers, under `fatigue`.
Span earth_wire_span(const char* type, const FatigueSpec& fatigue) {
  const Conductor c = conductor_of(io::catalogue_conductor(type));
  return Span(c, 300.0, 0.2 * c.rated_tensile_strength, WindModel{}, SelfDampingModel{}, {}, fatigue);
}

FatigueSpec safe_border_line_at(double cycles) {
  FatigueSpec fatigue;
  fatigue.cycles = cycles;
  return fatigue;
}

TEST(EarthWireSpan, TheSafeBorderLineIsRefusedForSteelAndAluminiumCladSteelNamingTheKeyToGive) {
  for (const char* type : {"EHS 3/8", "GSW 19/3.25"}) {
    EXPECT_EQ(stockbridge::testing::invalid_parameter_message(
                  [&] { earth_wire_span(type, safe_border_line_at(kFiveHundredMillion)); }),
              "fatigue.endurance_limit_mpa: missing: the conductor's outer wires are steel, and the CIGRE Safe Border "
              "Line (criterion \"safe-border-line\") is stated for aluminium outer layers only: expected "
              "endurance_limit_mpa (the outer wires' endurance limit, MPa zero-to-peak) in place of cycles, or curve = "
              "an S-N curve of these wires")
        << type;
  }
  for (const char* type : {"Alumoweld 7 No. 8", "Alumoweld 19 No. 9", "OPGW 9.6"}) {
    EXPECT_NE(stockbridge::testing::invalid_parameter_message(
                  [&] { earth_wire_span(type, safe_border_line_at(kFiveHundredMillion)); })
                  .find("fatigue.endurance_limit_mpa: missing: the conductor's outer wires are aluminium-clad-steel, "),
              std::string::npos)
        << type;
  }
}

TEST(EarthWireSpan, AGivenEnduranceLimitIsTheOneTheVerdictUses) {
  FatigueSpec fatigue;
  fatigue.criterion = FatigueCriterion::stress;
  fatigue.endurance_limit = 30e6;
  const Span span = earth_wire_span("EHS 3/8", fatigue);
  EXPECT_EQ(span.endurance_limit(), 30e6);
  EXPECT_EQ(span.criterion_description(), "a given endurance limit");
  // No life without a curve: its N(sigma) would be the Safe Border Line's.
  fatigue.life = LifeModel{};
  fatigue.life->wind_weibull = {2.0, 4.0};
  fatigue.life->aeolian_fraction = 0.3;
  EXPECT_NE(stockbridge::testing::invalid_parameter_message([&] { earth_wire_span("EHS 3/8", fatigue); })
                .find("fatigue.curve: missing: the conductor's outer wires are steel, and the life's N(sigma) is the "
                      "CIGRE Safe Border Line's"),
            std::string::npos);
  EXPECT_NE(stockbridge::testing::invalid_parameter_message([&] { static_cast<void>(span.sn_curve()); })
                .find("fatigue.curve: missing: the conductor's outer wires are steel"),
            std::string::npos);
}

TEST(EarthWireSpan, AnSnCurveOfTheWiresTakesTheLinesPlace) {
  FatigueSpec fatigue = safe_border_line_at(kFiveHundredMillion);
  fatigue.curve = SnCurve::from_table({60.0, 30.0}, {1e5, 1e8}, "steel wires, test");
  const Span span = earth_wire_span("EHS 3/8", fatigue);
  EXPECT_EQ(span.endurance_limit(), fatigue.curve->endurance_limit(kFiveHundredMillion));
}

TEST(EarthWireSpan, AluminiumOuterWiresAreJudgedByTheSafeBorderLineAsBefore) {
  // OPGW 13.6's outer layer is aluminium alloy: the one-layer line, as an AAAC of one layer.
  const Span opgw = earth_wire_span("OPGW 13.6", safe_border_line_at(kFiveHundredMillion));
  EXPECT_EQ(opgw.endurance_limit(), safe_border_curve(1).endurance_limit(kFiveHundredMillion));
  const Span drake = earth_wire_span("ACSR Drake", safe_border_line_at(kFiveHundredMillion));
  EXPECT_EQ(drake.conductor().outer_wire_material, WireMaterial::aluminium);
  EXPECT_EQ(drake.endurance_limit(), safe_border_curve(2).endurance_limit(kFiveHundredMillion));
  EXPECT_EQ(drake.sn_curve().name(), "the CIGRE Safe Border Line (several aluminium layers)");
}

// The span file.

std::filesystem::path earth_wire_directory() {
  return std::filesystem::temp_directory_path() / ("stockbridge-earth-wire-" + std::to_string(::getpid()));
}

/// A span file of `conductor` (the [conductor] table's lines) with `fatigue` (the [fatigue] table's).
std::string earth_wire_span_text(const std::string& conductor, const std::string& fatigue) {
  return "[conductor]\n" + conductor + "\n[span]\nlength = 300\ntension_fraction = 0.2\n[wind]\nlaw = \"cigre\"\n"
         "[self_damping]\nlaw = \"noiseux-1991\"\n[fatigue]\n" + fatigue;
}

TEST(EarthWireSpanFile, TheSafeBorderLineIsRefusedAtTheFatigueTable) {
  const auto path = stockbridge::testing::write_temp_file(earth_wire_directory(), "ehs.toml",
                                             earth_wire_span_text("type = \"EHS 3/8\"\n", "cycles = 5e8\n"));
  try {
    io::load_span_file(path);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() + ":11: fatigue.endurance_limit_mpa: missing: the conductor's outer wires are steel, and the "
                              "CIGRE Safe Border Line (criterion \"safe-border-line\") is stated for aluminium outer "
                              "layers only: expected endurance_limit_mpa (the outer wires' endurance limit, MPa "
                              "zero-to-peak) in place of cycles, or curve = an S-N curve of these wires");
  }
}

TEST(EarthWireSpanFile, TheKeysOfASteelEarthWireReadBackAsTheCatalogues) {
  // The table `stockbridge conductors "EHS 3/8"` prints: outer_wire_material = "steel"
  // and aluminium_layers = 0 (refused for aluminium outer wires).
  const Conductor typed = conductor_of(io::catalogue_conductor("EHS 3/8"));
  const std::string keys = "mass_per_length = 0.407\ndiameter = 0.00915\nrated_tensile_strength = 68500\nei_min = 6.2\n"
                           "outer_wire_diameter = 0.00305\nouter_wire_modulus = 207e9\nouter_wire_material = \"steel\"\n";
  const io::SpanFile file = io::load_span_text(earth_wire_span_text(keys, "endurance_limit_mpa = 30\n"), "test");
  EXPECT_EQ(file.span.conductor().outer_wire_material, WireMaterial::steel);
  EXPECT_EQ(file.span.conductor().aluminium_layers, 0);
  EXPECT_EQ(file.span.conductor().outer_wire_modulus, typed.outer_wire_modulus);
  try {
    io::load_span_text(earth_wire_span_text(keys + "aluminium_layers = 0\n", "cycles = 5e8\n"), "test");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test: fatigue.endurance_limit_mpa: missing: the conductor's outer wires are steel"),
              std::string::npos)
        << e.what();
  }
  // Without outer_wire_material the keys are an aluminium conductor's, as before.
  try {
    io::load_span_text(earth_wire_span_text("type = \"EHS 3/8\"\nouter_wire_material = \"aluminum\"\n", "cycles = 5e8\n"),
                       "test");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("conductor.aluminium_layers = 0: expected an integer from 1 to 10"),
              std::string::npos)
        << e.what();
  }
}

TEST(EarthWireSpanFile, WithEnduranceLimitMpaItRunsAndTheVerdictIsAgainstThatLimit) {
  const auto verdict_at = [](double limit_mpa, double* judged) {
    const io::SpanFile file = io::load_span_text(
        earth_wire_span_text("type = \"EHS 3/8\"\n", "endurance_limit_mpa = " + std::to_string(limit_mpa) + "\n"), "test");
    EXPECT_EQ(file.span.fatigue().criterion, FatigueCriterion::stress);
    const SpanAnalysis a = analyse_span(file.span, {10.0, 20.0, 40.0}, AnalysisOptions{});
    EXPECT_NEAR(a.balance.summary.endurance_limit, limit_mpa * 1e6, 1e-6 * limit_mpa * 1e6);
    *judged = a.balance.summary.max_judged_stress;
    return a.balance.summary.verdict;
  };
  double judged = 0.0;
  verdict_at(30.0, &judged);
  ASSERT_GT(judged, 0.0);
  // A limit just above the largest judged stress: safe; just below: unsafe.
  double again = 0.0;
  EXPECT_EQ(verdict_at(1.05 * judged / 1e6, &again), Verdict::safe);
  EXPECT_EQ(again, judged);
  EXPECT_EQ(verdict_at(0.95 * judged / 1e6, &again), Verdict::unsafe);
}

}  // namespace
}  // namespace stockbridge::span
