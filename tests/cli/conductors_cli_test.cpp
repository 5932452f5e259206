// `stockbridge conductors`: the catalogue as text and JSON, one entry as the
// [conductor] table a span file takes (run through `stockbridge span` against
// type = "..."), the strand command on a strand of two materials, and exit 2 with
// one line naming file, line, key and value for a bad type or conductor file. Earth
// wires: listed with their outer wires, and a steel earth wire's span under the Safe
// Border Line refused (exit 2, one line naming endurance_limit_mpa, nothing written)
// until its file gives endurance_limit_mpa.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/json_number.hpp"

namespace stockbridge::testing {
namespace {

/// A span file of `conductor_table`, no dampers, three frequencies, judged by the Safe
/// Border Line (`fatigue`: the [fatigue] table's keys).
std::string conductors_span(const std::string& conductor_table, const std::string& fatigue = "cycles = 5e8\n") {
  return conductor_table +
         "\n[span]\nlength = 300\ntension_fraction = 0.2\n[wind]\nlaw = \"cigre\"\n[self_damping]\n"
         "law = \"noiseux-1991\"\n[fatigue]\n" + fatigue;
}

TEST(ConductorsCli, ListsTheCatalogue) {
  const auto dir = scratch_directory("conductors-list");
  const CliResult r = run_cli("conductors", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  for (const char* type : {"ACSR Drake", "ACSR Cardinal", "ACSR Linnet", "ACSR Falcon", "AAAC ASTER570", "AAC Arbutus",
                           "ACSR Tern", "ACSR Ibis", "ACSR Bersimis", "ACSR Bersfort", "AAC Orchid", "AAAC 823",
                           "AAAC 900", "AAAC 1055", "EHS 3/8", "GSW 19/3.25", "Alumoweld 7 No. 8", "Alumoweld 19 No. 9",
                           "OPGW 9.6", "OPGW 13.6"}) {
    EXPECT_NE(r.out.find(type), std::string::npos) << type;
  }
  // Drake's row: stranding, D 28.14 mm, m 1.628 kg/m, RTS 138.8 kN, EI_min 44.25 N m^2,
  // aluminium outer wires.
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(ACSR Drake +26/7: steel 1\+6 x 3\.45 mm, aluminium 10\+16 x 4\.44 mm +28\.14 +1\.628 +138\.8 +44\.25 +1501 +aluminium\n)")))
      << r.out;
  // The EHS strand's: D 9.15 mm, m 0.407 kg/m, RTS 68.5 kN, EI_min 6.16 N m^2, steel outer wires.
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(EHS 3/8 +7: steel 1\+6 x 3\.05 mm +9\.15 +0\.407 +68\.5 +6\.16 +[0-9]+ +steel\n)")))
      << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(Alumoweld 7 No\. 8 .* aluminium-clad-steel\n)"))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(OPGW 13\.6 .* aluminium-alloy\n)"))) << r.out;
}

TEST(ConductorsCli, ListsTheCatalogueAsJson) {
  const auto dir = scratch_directory("conductors-json");
  const CliResult r = run_cli("conductors --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.starts_with("{\"conductors\": [{\"type\": \"AAAC 1055\"")) << r.out;
  EXPECT_EQ(lines_of(r.out).size(), 1u);
}

TEST(ConductorsCli, OneEntryAsJson) {
  const auto dir = scratch_directory("conductors-one-json");
  const CliResult r = run_cli("conductors acsr-drake --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"type\": \"ACSR Drake\""), std::string::npos) << r.out;
  EXPECT_NEAR(json_number(r.out, "ei_min_n_m2"), 44.25, 0.005);  // MODEL.md section 11
  EXPECT_EQ(json_number(r.out, "aluminium_layers"), 2.0);
  EXPECT_EQ(json_number(r.out, "outer_wire_diameter_m"), 0.00444);
}

TEST(ConductorsCli, TheTablePrintedRunsAsTheSpanOfTheType) {
  // The [conductor] table of `stockbridge conductors "ACSR Drake"`, pasted into a span
  // file, gives the span CSV of type = "ACSR Drake" byte for byte.
  const auto dir = scratch_directory("conductors-paste");
  const CliResult table = run_cli("conductors \"ACSR Drake\"", dir);
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_TRUE(table.out.starts_with("# ACSR Drake, 26/7: steel 1+6 x 3.45 mm, aluminium 10+16 x 4.44 mm\n")) << table.out;
  EXPECT_NE(table.out.find("\n[conductor]\nname = \"ACSR Drake\"\n"), std::string::npos) << table.out;
  std::ofstream(dir / "pasted.toml") << conductors_span(table.out);
  std::ofstream(dir / "typed.toml") << conductors_span("[conductor]\ntype = \"ACSR Drake\"\n");
  const CliResult pasted = run_cli("span pasted.toml --frequencies 10,20,30 --quiet -o pasted.csv", dir);
  const CliResult typed = run_cli("span typed.toml --frequencies 10,20,30 --quiet -o typed.csv", dir);
  ASSERT_EQ(pasted.exit_code, 0) << pasted.err;
  ASSERT_EQ(typed.exit_code, 0) << typed.err;
  EXPECT_EQ(read_text(dir / "pasted.csv"), read_text(dir / "typed.csv"));
  EXPECT_FALSE(read_text(dir / "typed.csv").empty());
}

TEST(ConductorsCli, AnEarthWiresTableNamesItsOuterWiresAndRunsWithItsEnduranceLimit) {
  const auto dir = scratch_directory("conductors-paste-earth-wire");
  const CliResult table = run_cli("conductors \"EHS 3/8\"", dir);
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("\nouter_wire_material = \"steel\" "), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("\naluminium_layers = 0 "), std::string::npos) << table.out;
  std::ofstream(dir / "pasted.toml") << conductors_span(table.out, "endurance_limit_mpa = 30\n");
  std::ofstream(dir / "typed.toml") << conductors_span("[conductor]\ntype = \"EHS 3/8\"\n", "endurance_limit_mpa = 30\n");
  const CliResult pasted = run_cli("span pasted.toml --frequencies 10,20,30 --quiet -o pasted.csv", dir);
  const CliResult typed = run_cli("span typed.toml --frequencies 10,20,30 --quiet --json -o typed.csv", dir);
  ASSERT_EQ(pasted.exit_code, 0) << pasted.err;
  ASSERT_EQ(typed.exit_code, 0) << typed.err;
  EXPECT_EQ(read_text(dir / "pasted.csv"), read_text(dir / "typed.csv"));
  // The verdict is against the given 30 MPa.
  EXPECT_NE(typed.out.find("\"criterion\": \"stress\""), std::string::npos) << typed.out;
  EXPECT_EQ(json_number(typed.out, "endurance_limit_mpa"), 30.0);
  const CliResult json = run_cli("conductors \"EHS 3/8\" --json", dir);
  EXPECT_NE(json.out.find("\"outer_wire_material\": \"steel\""), std::string::npos) << json.out;
  EXPECT_EQ(json_number(json.out, "aluminium_layers"), 0.0);
}

TEST(ConductorsCli, ASteelEarthWireUnderTheSafeBorderLineIsExitTwoOneLineNamingEnduranceLimitMpa) {
  const auto dir = scratch_directory("conductors-earth-wire-sbl");
  std::ofstream(dir / "ehs.toml") << conductors_span("[conductor]\ntype = \"EHS 3/8\"\n");
  const CliResult r = run_cli("span ehs.toml --frequencies 10,20,30 -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_EQ(r.err, "stockbridge: ehs.toml:11: fatigue.endurance_limit_mpa: missing: the conductor's outer wires are "
                   "steel, and the CIGRE Safe Border Line (criterion \"safe-border-line\") is stated for aluminium outer "
                   "layers only: expected endurance_limit_mpa (the outer wires' endurance limit, MPa zero-to-peak) in "
                   "place of cycles, or curve = an S-N curve of these wires\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
  // An aluminium-clad steel OPGW alike; an OPGW of aluminium-alloy outer wires runs.
  std::ofstream(dir / "opgw.toml") << conductors_span("[conductor]\ntype = \"OPGW 9.6\"\n");
  const CliResult acs = run_cli("span opgw.toml --frequencies 10,20,30 -o opgw.csv", dir);
  EXPECT_EQ(acs.exit_code, 2);
  EXPECT_EQ(acs.stderr_lines(), 1) << acs.err;
  EXPECT_NE(acs.err.find("fatigue.endurance_limit_mpa: missing: the conductor's outer wires are aluminium-clad-steel"),
            std::string::npos)
      << acs.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "opgw.csv"));
  std::ofstream(dir / "alloy.toml") << conductors_span("[conductor]\ntype = \"OPGW 13.6\"\n");
  const CliResult alloy = run_cli("span alloy.toml --frequencies 10,20,30 --quiet -o alloy.csv", dir);
  EXPECT_EQ(alloy.exit_code, 0) << alloy.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "alloy.csv"));
}

TEST(ConductorsCli, AnUnknownTypeIsExitTwoAndOneLine) {
  const auto dir = scratch_directory("conductors-unknown");
  const CliResult r = run_cli("conductors \"ACSR Drak\"", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_TRUE(r.err.starts_with("stockbridge: type = \"ACSR Drak\": expected a conductor of the catalogue: AAAC 1055, "))
      << r.err;
}

TEST(ConductorsCli, ASpanFilesBadTypeOrConductorFileIsExitTwoNamingFileLineAndKey) {
  const auto dir = scratch_directory("conductors-span-bad");
  std::ofstream(dir / "typo.toml") << conductors_span("[conductor]\ntype = \"ACSR Drak\"\n");
  CliResult r = run_cli("span typo.toml -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_TRUE(r.err.starts_with("stockbridge: typo.toml:2: conductor.type = \"ACSR Drak\": expected a conductor of the "
                                "catalogue: "))
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));

  std::ofstream(dir / "missing.toml") << conductors_span("[conductor]\nfile = \"mine.toml\"\n");
  r = run_cli("span missing.toml -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_TRUE(r.err.starts_with("stockbridge: missing.toml:2: conductor.file: \"mine.toml\": expected an existing "
                                "conductor file (looked for "))
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));

  // A conductor file with an aluminium layer of more wires than fit.
  std::ofstream(dir / "mine.toml") << "[conductor]\ntype = \"Mine\"\nmass_per_length = 0.5\ndiameter = 0.015\n"
                                      "rated_tensile_strength = 50000\n[conductor.core]\nmaterial = \"steel\"\n"
                                      "youngs_modulus = 207e9\nwire_diameter = 0.003\n[[conductor.layer]]\n"
                                      "material = \"aluminium\"\nyoungs_modulus = 68.9e9\ncount = 9\n"
                                      "wire_diameter = 0.006\nlay_ratio = 12\n";
  r = run_cli("span missing.toml -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_EQ(r.err, "stockbridge: mine.toml:13: conductor.layer[0].count = 9: expected at most 4 wires of 0.006 m side by "
                   "side around the layer beneath (pitch radius 0.0045 m)\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
}

TEST(ConductorsCli, TheStrandCommandShowsEachMaterialsModulus) {
  const auto dir = scratch_directory("conductors-strand-drake");
  const CliResult r =
      run_cli(std::string("strand '") + STOCKBRIDGE_SOURCE_DIR + "/examples/strand_acsr_drake.toml'", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("strand: 33 wires (core + 3 layers), E = 207000000000 Pa (core), 207000000000, 68900000000, "
                       "68900000000 Pa (layers, from the inside out)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("ei_min = 44.25"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace stockbridge::testing
