// Strands of several materials and the conductor catalogue (MODEL.md sections 7 and
// 11): ACSR Drake's bounds against hand computations written out here, a strand of
// one material unchanged to the last bit, the catalogue's derived numbers (ASTER570
// against examples/aster570_400m.toml), the forgiving match of a type, and the
// stranding's checks.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/io/strand_file.hpp"
#include "stockbridge/span/stranded_conductor.hpp"
#include "stockbridge/strand/strand_bounds.hpp"
#include "support/error_message.hpp"

namespace stockbridge::span {
namespace {

constexpr double kPiConductor = std::numbers::pi;
constexpr double kSteel = 207e9;       // Pa, MODEL.md section 11
constexpr double kAluminium = 68.9e9;  // Pa

/// pi r^4 / 4 of a wire of diameter d.
double wire_i(double d) { return kPiConductor * std::pow(d / 2.0, 4) / 4.0; }

/// One layer's no-slip term of MODEL.md section 7, N / 2 pi r^2 (r^2 / 2 + R^2) cos^3 alpha,
/// tan alpha = 2 pi R / lambda (m^4; times E).
double no_slip_term(int count, double d, double pitch_radius, double lay) {
  const double r = d / 2.0;
  const double tan_alpha = 2.0 * kPiConductor * pitch_radius / lay;
  return count / 2.0 * kPiConductor * r * r * (r * r / 2.0 + pitch_radius * pitch_radius) *
         std::pow(1.0 + tan_alpha * tan_alpha, -1.5);
}

void expect_relative_to(double actual, double expected, double tolerance) {
  EXPECT_LE(std::abs(actual - expected), tolerance * std::abs(expected)) << "actual " << actual << ", expected " << expected;
}

// ACSR Drake by hand (MODEL.md section 11): steel 1 + 6 wires of 3.45 mm at 207 GPa,
// aluminium 10 + 16 wires of 4.44 mm at 68.9 GPa.
//   steel:     7 x 207e9 x pi (1.725e-3)^4 / 4 = 7 x 207e9 x 6.9545e-12 = 10.077 N m^2
//   aluminium: 26 x 68.9e9 x pi (2.22e-3)^4 / 4 = 26 x 68.9e9 x 1.9077e-11 = 34.174 N m^2
//   EI_min = 44.25 N m^2
const double kDrakeEiMin = 7.0 * kSteel * wire_i(3.45e-3) + 26.0 * kAluminium * wire_i(4.44e-3);

// Pitch radii of touching layers: 1.725 + 1.725 = 3.45 mm; 3.45 + 1.725 + 2.22 = 7.395 mm;
// 7.395 + 2.22 + 2.22 = 11.835 mm.
constexpr double kDrakeR1 = 3.45e-3, kDrakeR2 = 7.395e-3, kDrakeR3 = 11.835e-3;

/// EI_max of Drake with the lay lengths lambda_1..3 (m), MODEL.md section 7 wire by wire:
/// E_steel (pi r_c^4 / 4 + steel layer term) + E_aluminium (both aluminium layer terms).
double drake_ei_max(double lay1, double lay2, double lay3) {
  return kSteel * (wire_i(3.45e-3) + no_slip_term(6, 3.45e-3, kDrakeR1, lay1)) +
         kAluminium * (no_slip_term(10, 4.44e-3, kDrakeR2, lay2) + no_slip_term(16, 4.44e-3, kDrakeR3, lay3));
}

TEST(SeveralMaterials, DrakeMinimumIsTheHandSumAndModelMdsFigure) {
  EXPECT_NEAR(kDrakeEiMin, 44.25, 0.005);  // MODEL.md section 11
  const strand::Strand drake = io::read_strand_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/strand_acsr_drake.toml");
  expect_relative_to(strand::strand_bounds(drake).ei_min, kDrakeEiMin, 1e-12);
}

TEST(SeveralMaterials, DrakeMaximumIsTheHandSumWithTheExamplesLayLengths) {
  // examples/strand_acsr_drake.toml: lay lengths 217, 250 and 337 mm (lay ratios 21, 13, 12).
  const strand::Strand drake = io::read_strand_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/strand_acsr_drake.toml");
  const double hand = drake_ei_max(0.217, 0.250, 0.337);
  expect_relative_to(strand::strand_bounds(drake).ei_max, hand, 1e-12);
  EXPECT_NEAR(hand, 1500.5, 0.5);
}

TEST(SeveralMaterials, EachLayersModulusCountsForItsOwnWiresOnly) {
  // Halving one layer's modulus removes half of that layer's terms, nothing else.
  strand::Strand strand{0.001, 210e9, {{6, 0.001, 0.002, 0.06}, {12, 0.001, 0.004, 0.1}}};
  const strand::StrandBounds all_steel = strand::strand_bounds(strand);
  strand.layers[1].youngs_modulus = 105e9;
  const strand::StrandBounds halved = strand::strand_bounds(strand);
  expect_relative_to(all_steel.ei_min - halved.ei_min, 0.5 * 12.0 * 210e9 * wire_i(0.002), 1e-9);
  expect_relative_to(all_steel.ei_max - halved.ei_max, 0.5 * 210e9 * no_slip_term(12, 0.002, 0.004, 0.1), 1e-9);
  strand.layers[1].youngs_modulus.reset();
  strand.core_youngs_modulus = 70e9;  // the core's own: only pi r_c^4 / 4 changes
  expect_relative_to(all_steel.ei_min - strand::strand_bounds(strand).ei_min, 140e9 * wire_i(0.002), 1e-9);
}

TEST(SeveralMaterials, OneMaterialGivenPerLayerIsBitForBitTheStrandsModulus) {
  // Existing strand files keep their results to the last bit: a modulus given equal to
  // the strand's, or none, weighs each term by exactly 1.
  strand::Strand plain{0.001, 210e9, {{6, 0.001, 0.002, 0.06}, {12, 0.001, 0.004, 0.1}}};
  strand::Strand explicit_moduli = plain;
  explicit_moduli.core_youngs_modulus = 210e9;
  for (strand::StrandLayer& layer : explicit_moduli.layers) layer.youngs_modulus = 210e9;
  EXPECT_EQ(strand::strand_bounds(plain).ei_min, strand::strand_bounds(explicit_moduli).ei_min);
  EXPECT_EQ(strand::strand_bounds(plain).ei_max, strand::strand_bounds(explicit_moduli).ei_max);
  EXPECT_TRUE(strand::single_modulus(explicit_moduli));
  // The 19-wire example's printed figures (docs/strand.md), unchanged.
  EXPECT_EQ(format_value(strand::strand_bounds(plain).ei_min), "3.133738671955819");
  EXPECT_EQ(format_value(strand::strand_bounds(plain).ei_max), "68.09624780759316");
}

TEST(SeveralMaterials, AModulusOfItsOwnMustBePositive) {
  strand::Strand strand{0.001, 210e9, {{6, 0.001, 0.002, 0.06}}};
  strand.layers[0].youngs_modulus = -1.0;
  EXPECT_EQ(stockbridge::testing::invalid_parameter_message([&] { strand::validate(strand); }),
            "layer[0].youngs_modulus = -1: expected a finite value > 0 (Pa)");
  strand.layers[0].youngs_modulus.reset();
  strand.core_youngs_modulus = 0.0;
  EXPECT_EQ(stockbridge::testing::invalid_parameter_message([&] { strand::validate(strand); }),
            "core_youngs_modulus = 0: expected a finite value > 0 (Pa)");
}

// The catalogue.

TEST(ConductorCatalogue, DrakeIsModelMdsDrake) {
  const StrandedConductor& drake = io::catalogue_conductor("ACSR Drake");
  const Conductor c = conductor_of(drake);
  expect_relative_to(c.ei_min, kDrakeEiMin, 1e-12);
  // The catalogue gives lay ratios (21, 13, 12): lambda_j = k_j (2 R_j + d_j), the layers'
  // outer diameters 10.35, 19.23 and 28.11 mm.
  expect_relative_to(c.ei_max, drake_ei_max(21 * 10.35e-3, 13 * 19.23e-3, 12 * 28.11e-3), 1e-12);
  EXPECT_EQ(c.name, "ACSR Drake");
  EXPECT_EQ(c.outer_wire_diameter, 0.00444);
  EXPECT_EQ(c.outer_wire_modulus, kAluminium);
  EXPECT_EQ(c.aluminium_layers, 2);
  EXPECT_EQ(c.mass_per_length, 1.628);
  EXPECT_EQ(c.diameter, 0.02814);
  EXPECT_EQ(c.rated_tensile_strength, 138800.0);
  EXPECT_EQ(stranding_label(drake), "26/7: steel 1+6 x 3.45 mm, aluminium 10+16 x 4.44 mm");
}

TEST(ConductorCatalogue, Aster570ReproducesTheExamplesStiffnesses) {
  // examples/aster570_400m.toml: ei_min 28.28, ei_max 2155 N m^2; 61 wires of 3.45 mm, 68 GPa.
  const StrandedConductor& aster = io::catalogue_conductor("AAAC ASTER570");
  const Conductor c = conductor_of(aster);
  // EI_min of MODEL.md section 7: 61 E pi r^4 / 4 = 28.85 N m^2, 2.0 % above the
  // example's 28.28 ...
  expect_relative_to(c.ei_min, 61.0 * 68e9 * wire_i(3.45e-3), 1e-12);
  expect_relative_to(c.ei_min, 28.28, 0.021);
  // ... which is each wire's E I projected on the strand's axis, sum N_j E I cos alpha_j
  // (the core's alpha = 0; lay ratio 13 for every layer; pitch radii 3.45, 6.9, 10.35
  // and 13.8 mm, outer diameters 10.35, 17.25, 24.15 and 31.05 mm): 28.28 to 0.01 %.
  double projected = wire_i(3.45e-3);
  const int counts[] = {6, 12, 18, 24};
  for (int j = 0; j < 4; ++j) {
    const double pitch = 3.45e-3 * (j + 1);
    const double tan_alpha = 2.0 * kPiConductor * pitch / (13.0 * (2.0 * pitch + 3.45e-3));
    projected += counts[j] * wire_i(3.45e-3) / std::sqrt(1.0 + tan_alpha * tan_alpha);
  }
  expect_relative_to(68e9 * projected, 28.28, 2e-4);
  // EI_max with the lay ratio 13 (the middle of EN 50182's 10 to 16): 2154 against 2155.
  expect_relative_to(c.ei_max, 2155.0, 1e-3);
  EXPECT_EQ(c.aluminium_layers, 4);
  EXPECT_EQ(c.outer_wire_diameter, 0.00345);
  EXPECT_EQ(c.outer_wire_modulus, 68e9);
  EXPECT_EQ(c.mass_per_length, 1.571);
  EXPECT_EQ(c.diameter, 0.03105);
  EXPECT_EQ(c.rated_tensile_strength, 185300.0);
  EXPECT_EQ(stranding_label(aster), "61: aluminium-alloy 1+6+12+18+24 x 3.45 mm");
}

TEST(ConductorCatalogue, EveryEntryHasItsStrandingsDerivedNumbers) {
  struct Expected {
    const char* type;
    const char* stranding;
    int aluminium_layers;
    double ei_min;  // N m^2, EI_min by hand: sum over the wires of E pi d^4 / 64
  };
  constexpr double kAlloy = 68e9;  // Pa, almelec as ASTER570
  const Expected expected[] = {
      {"AAAC 1055", "61: aluminium-alloy 1+6+12+18+24 x 3.34 mm", 4, 61 * kAlloy * wire_i(3.34e-3)},
      {"AAAC 823", "37: aluminium-alloy 1+6+12+18 x 3.79 mm", 3, 37 * kAlloy * wire_i(3.79e-3)},
      {"AAAC 900", "37: aluminium-alloy 1+6+12+18 x 3.96 mm", 3, 37 * kAlloy * wire_i(3.96e-3)},
      {"AAAC ASTER570", "61: aluminium-alloy 1+6+12+18+24 x 3.45 mm", 4, 61 * 68e9 * wire_i(3.45e-3)},
      {"AAC Arbutus", "37: aluminium 1+6+12+18 x 3.724 mm", 3, 37 * kAluminium * wire_i(3.724e-3)},
      {"AAC Orchid", "37: aluminium 1+6+12+18 x 3.33 mm", 3, 37 * kAluminium * wire_i(3.33e-3)},
      {"ACSR Bersfort", "48/7: steel 1+6 x 3.32 mm, aluminium 10+16+22 x 4.27 mm", 3,
       7 * kSteel * wire_i(3.32e-3) + 48 * kAluminium * wire_i(4.27e-3)},
      {"ACSR Bersimis", "42/7: steel 1+6 x 2.54 mm, aluminium 8+14+20 x 4.572 mm", 3,
       7 * kSteel * wire_i(2.54e-3) + 42 * kAluminium * wire_i(4.572e-3)},
      {"ACSR Cardinal", "54/7: steel 1+6 x 3.376 mm, aluminium 12+18+24 x 3.376 mm", 3,
       7 * kSteel * wire_i(3.376e-3) + 54 * kAluminium * wire_i(3.376e-3)},
      {"ACSR Drake", "26/7: steel 1+6 x 3.45 mm, aluminium 10+16 x 4.44 mm", 2, kDrakeEiMin},
      {"ACSR Falcon", "54/19: steel 1+6+12 x 2.616 mm, aluminium 12+18+24 x 4.359 mm", 3,
       19 * kSteel * wire_i(2.616e-3) + 54 * kAluminium * wire_i(4.359e-3)},
      {"ACSR Ibis", "26/7: steel 1+6 x 2.441 mm, aluminium 10+16 x 3.139 mm", 2,
       7 * kSteel * wire_i(2.441e-3) + 26 * kAluminium * wire_i(3.139e-3)},
      {"ACSR Linnet", "26/7: steel 1+6 x 2.245 mm, aluminium 10+16 x 2.888 mm", 2,
       7 * kSteel * wire_i(2.245e-3) + 26 * kAluminium * wire_i(2.888e-3)},
      {"ACSR Tern", "45/7: steel 1+6 x 2.25 mm, aluminium 9+15+21 x 3.38 mm", 3,
       7 * kSteel * wire_i(2.25e-3) + 45 * kAluminium * wire_i(3.38e-3)},
  };
  for (const Expected& e : expected) {
    SCOPED_TRACE(e.type);
    const StrandedConductor& entry = io::catalogue_conductor(e.type);
    EXPECT_EQ(entry.type, e.type);
    EXPECT_EQ(stranding_label(entry), e.stranding);
    EXPECT_FALSE(entry.source.empty());
    const Conductor c = conductor_of(entry);
    c.validate();
    EXPECT_EQ(c.aluminium_layers, e.aluminium_layers);
    EXPECT_TRUE(c.safe_border_line_applies());
    expect_relative_to(c.ei_min, e.ei_min, 1e-12);
    // No slip is 15 to 90 times stiffer than free wires for these strandings.
    EXPECT_GT(c.ei_max, 15.0 * c.ei_min);
    EXPECT_LT(c.ei_max, 90.0 * c.ei_min);
    // The data sheet's diameter is the stranding's, to 0.2 %.
    expect_relative_to(stranding_diameter(entry), c.diameter, 2e-3);
  }
}

TEST(ConductorCatalogue, HoldsThePhaseConductorsAndTheEarthWires) {
  // The phase conductors above; the earth wires and OPGW in earth_wire_test.cpp.
  std::vector<std::string> types;
  for (const StrandedConductor& entry : io::conductor_catalogue()) types.push_back(entry.type);
  EXPECT_EQ(types, (std::vector<std::string>{"AAAC 1055", "AAAC 823", "AAAC 900", "AAAC ASTER570", "AAC Arbutus",
                                             "AAC Orchid", "ACSR Bersfort", "ACSR Bersimis", "ACSR Cardinal",
                                             "ACSR Drake", "ACSR Falcon", "ACSR Ibis", "ACSR Linnet", "ACSR Tern",
                                             "Alumoweld 19 No. 9", "Alumoweld 7 No. 8", "EHS 3/8", "GSW 19/3.25",
                                             "OPGW 13.6", "OPGW 9.6"}));
}

// The conductors of RTE's fatigue test data set (dohl): each data sheet's diameter
// and mass against its stranding, computed here wire by wire (densities 2703 kg/m^3
// for aluminium and its alloy, 7780 for steel; each layer's wires lengthened by its
// lay, sqrt(1 + (2 pi R_j / lambda_j)^2)): the diameter within 1 %, the mass within 2 %.
TEST(ConductorCatalogue, TheFatigueDataSetsConductorsDiameterAndMassAreTheirStrandings) {
  const auto density = [](WireMaterial material) { return material == WireMaterial::steel ? 7780.0 : 2703.0; };
  for (const char* type : {"ACSR Tern", "ACSR Ibis", "ACSR Bersimis", "ACSR Bersfort", "AAC Orchid", "AAAC 823",
                           "AAAC 900", "AAAC 1055"}) {
    SCOPED_TRACE(type);
    const StrandedConductor& c = io::catalogue_conductor(type);
    EXPECT_EQ(c.type, type);
    double diameter = c.core.wire_diameter, mass = density(c.core.material) * kPiConductor / 4.0 *
                                                   c.core.wire_diameter * c.core.wire_diameter;
    for (std::size_t j = 0; j < c.layers.size(); ++j) {
      const ConductorLayer& layer = c.layers[j];
      const double pitch_radius = diameter / 2.0 + layer.wire_diameter / 2.0;
      diameter += 2.0 * layer.wire_diameter;
      const double lay = layer.lay_ratio * diameter;
      EXPECT_NEAR(lay, lay_length(c, j), 1e-12);
      const double stretch = std::hypot(1.0, 2.0 * kPiConductor * pitch_radius / lay);
      mass += density(layer.material) * layer.count * kPiConductor / 4.0 * layer.wire_diameter * layer.wire_diameter *
              stretch;
    }
    EXPECT_NEAR(diameter / c.diameter, 1.0, 0.01);
    EXPECT_NEAR(mass / c.mass_per_length, 1.0, 0.02);
    // The rated tensile strength is 150 to 420 MPa of the cross-section (aluminium
    // about 160, almelec 325, ACSR between): a value off by a unit would not be.
    double area = 0.0;
    for (const ConductorLayer& layer : c.layers) area += layer.count * kPiConductor / 4.0 * layer.wire_diameter * layer.wire_diameter;
    area += kPiConductor / 4.0 * c.core.wire_diameter * c.core.wire_diameter;
    EXPECT_GT(c.rated_tensile_strength / area, 150e6);
    EXPECT_LT(c.rated_tensile_strength / area, 420e6);
  }
}

TEST(ConductorCatalogue, TypesMatchWhateverTheCaseSpacesAndHyphens) {
  for (const char* query : {"ACSR Drake", "acsr drake", "ACSR-Drake", "acsr_drake", " ACSR  DRAKE ", "Drake", "drake"}) {
    EXPECT_EQ(io::catalogue_conductor(query).type, "ACSR Drake") << query;
  }
  EXPECT_EQ(io::catalogue_conductor("aster570").type, "AAAC ASTER570");
  EXPECT_FALSE(io::conductor_type_matches("", "ACSR Drake"));
  EXPECT_FALSE(io::conductor_type_matches("ACSR", "ACSR Drake"));
}

TEST(ConductorCatalogue, AnUnknownTypeListsTheKnownOnes) {
  EXPECT_EQ(stockbridge::testing::invalid_parameter_message([] { io::catalogue_conductor("ACSR Drak"); }),
            "type = \"ACSR Drak\": expected a conductor of the catalogue: AAAC 1055, AAAC 823, AAAC 900, AAAC ASTER570, "
            "AAC Arbutus, AAC Orchid, ACSR Bersfort, ACSR Bersimis, ACSR Cardinal, ACSR Drake, ACSR Falcon, ACSR Ibis, "
            "ACSR Linnet, ACSR Tern, Alumoweld 19 No. 9, Alumoweld 7 No. 8, EHS 3/8, GSW 19/3.25, OPGW 13.6, OPGW 9.6 "
            "(case, spaces and hyphens aside; stockbridge conductors lists them)");
}

// The stranding's checks.

StrandedConductor two_layer_test_conductor() {
  StrandedConductor c;
  c.type = "test";
  c.mass_per_length = 0.5;
  c.diameter = 0.015;
  c.rated_tensile_strength = 50e3;
  c.core = {WireMaterial::steel, 207e9, 1, 0.003, 0.0, 0.0};
  c.layers = {{WireMaterial::aluminium, 68.9e9, 6, 0.003, 0.0, 12.0}, {WireMaterial::aluminium, 68.9e9, 12, 0.003, 0.2, 0.0}};
  return c;
}

TEST(StrandedConductorChecks, AGoodStrandingPasses) {
  const StrandedConductor c = two_layer_test_conductor();
  EXPECT_NO_THROW(c.validate());
  ASSERT_EQ(pitch_radii(c).size(), 2u);
  EXPECT_DOUBLE_EQ(pitch_radii(c)[0], 0.003);  // r_c + r_1
  EXPECT_DOUBLE_EQ(pitch_radii(c)[1], 0.006);  // R_1 + r_1 + r_2
  EXPECT_DOUBLE_EQ(lay_length(c, 0), 12.0 * 0.009);  // lay ratio x (2 R + d)
  EXPECT_EQ(lay_length(c, 1), 0.2);
  EXPECT_EQ(stranding_label(c), "18/1: steel 1 x 3 mm, aluminium 6+12 x 3 mm");
}

TEST(StrandedConductorChecks, EachBadStrandingIsNamedByItsKey) {
  auto message = [](auto change) {
    StrandedConductor c = two_layer_test_conductor();
    change(c);
    return stockbridge::testing::invalid_parameter_message([&] { c.validate(); });
  };
  EXPECT_EQ(message([](StrandedConductor& c) { c.diameter = 0.02; }),
            "diameter = 0.02: expected the stranding's outer diameter, 0.015 m, within 2 % (the wires' count or "
            "diameter wrong?)");
  EXPECT_EQ(message([](StrandedConductor& c) { c.layers[0].count = 8; }),
            "layer[0].count = 8: expected at most 6 wires of 0.003 m side by side around the layer beneath (pitch "
            "radius 0.003 m)");
  EXPECT_NE(message([](StrandedConductor& c) { c.layers[0].lay_ratio = 2.0; }).find("layer[0].lay_ratio = 2: expected more than 2 pi R / D"),
            std::string::npos);
  EXPECT_NE(message([](StrandedConductor& c) { c.layers[1].lay_length = 0.03; }).find("layer[1].lay_length = 0.03: expected more than 2 pi R"),
            std::string::npos);
  EXPECT_EQ(message([](StrandedConductor& c) { c.layers[1].lay_ratio = 10.0; }),
            "layer[1].lay_length = 0.2 with lay_ratio = 10: expected one of the two (the other 0)");
  EXPECT_EQ(message([](StrandedConductor& c) {
              for (int j = 0; j < 9; ++j) c.layers.push_back({WireMaterial::aluminium, 68.9e9, 12, 0.003, 0.0, 12.0});
              c.diameter = stranding_diameter(c);
            }),
            "layer: 11 layers of aluminium or aluminium-alloy wires: expected at most 10 (the Safe Border Line is chosen "
            "by their number)");
  EXPECT_EQ(message([](StrandedConductor& c) { c.layers[1].youngs_modulus = 0.0; }),
            "layer[1].youngs_modulus = 0: expected a finite value > 0 (Pa)");
  EXPECT_EQ(message([](StrandedConductor& c) { c.layers.clear(); }),
            "layer: none: expected the layers of wires around the core, from the inside out");
  EXPECT_EQ(stockbridge::testing::invalid_parameter_message([] { parse_wire_material("copper"); }),
            "material = \"copper\": expected steel, aluminium, aluminium-alloy or aluminium-clad-steel");
}

TEST(StrandedConductorChecks, AStrandOfSteelAloneIsAnEarthWireWithoutAluminiumLayers) {
  // An earth wire: no aluminium layer, its outer wires steel (MODEL.md section 15).
  StrandedConductor c = two_layer_test_conductor();
  for (ConductorLayer& layer : c.layers) layer.material = WireMaterial::steel, layer.youngs_modulus = 207e9;
  EXPECT_NO_THROW(c.validate());
  const Conductor derived = conductor_of(c);
  EXPECT_EQ(derived.aluminium_layers, 0);
  EXPECT_EQ(derived.outer_wire_material, WireMaterial::steel);
  EXPECT_FALSE(derived.safe_border_line_applies());
  EXPECT_EQ(stranding_label(c), "19: steel 1+6+12 x 3 mm");
  // EI_min wire by wire: 19 x 207e9 x pi (1.5e-3)^4 / 4.
  expect_relative_to(derived.ei_min, 19.0 * kSteel * wire_i(3e-3), 1e-12);
}

}  // namespace
}  // namespace stockbridge::span
