// Conductors in span files: [conductor] type = "..." takes the catalogue's entry,
// keys beside it override the derived values, file = "..." reads a conductor file
// (relative to the span file, or to the working directory for span text), and the
// table `stockbridge conductors TYPE` prints gives the same conductor. Conductor
// files' errors name their file, line and key.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/requests/conductor_request.hpp"
#include "stockbridge/span/stranded_conductor.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::io {
namespace {

/// A span file around a [conductor] table, without dampers, judged by the Safe Border
/// Line (`fatigue`: the [fatigue] table's keys).
std::string span_with(const std::string& conductor_table, const std::string& fatigue = "cycles = 5e8\n") {
  return conductor_table +
         "\n[span]\nlength = 400\ntension_fraction = 0.15\n[wind]\nlaw = \"cigre\"\n[self_damping]\n"
         "law = \"noiseux-1991\"\n[fatigue]\n" + fatigue;
}

std::filesystem::path conductor_directory() {
  return std::filesystem::temp_directory_path() / ("stockbridge-conductor-file-" + std::to_string(::getpid()));
}

std::filesystem::path write_in_conductor_directory(const std::string& name, const std::string& contents) {
  return testing::write_temp_file(conductor_directory(), name, contents);
}

/// The InputError message of loading `text` as a span file.
std::string span_file_error(const std::string& text, const std::string& name = "span.toml") {
  const auto path = write_in_conductor_directory(name, text);
  try {
    load_span_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

/// The text of the catalogue's Drake file, as shipped.
std::string drake_file_text() {
  std::ifstream in(std::string(STOCKBRIDGE_SOURCE_DIR) + "/data/conductors/acsr_drake.toml");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void expect_same_conductor(const span::Conductor& a, const span::Conductor& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.mass_per_length, b.mass_per_length);
  EXPECT_EQ(a.diameter, b.diameter);
  EXPECT_EQ(a.rated_tensile_strength, b.rated_tensile_strength);
  EXPECT_EQ(a.ei_min, b.ei_min);
  EXPECT_EQ(a.ei_max, b.ei_max);
  EXPECT_EQ(a.outer_wire_diameter, b.outer_wire_diameter);
  EXPECT_EQ(a.outer_wire_modulus, b.outer_wire_modulus);
  EXPECT_EQ(a.aluminium_layers, b.aluminium_layers);
  EXPECT_EQ(a.outer_wire_material, b.outer_wire_material);
}

const span::Conductor& drake_derived() {
  static const span::Conductor drake = span::conductor_of(catalogue_conductor("ACSR Drake"));
  return drake;
}

TEST(SpanConductorType, TakesTheCatalogueEntry) {
  for (const char* type : {"ACSR Drake", "acsr-drake", "ACSR_DRAKE"}) {
    const SpanFile file = load_span_text(span_with(std::string("[conductor]\ntype = \"") + type + "\"\n"), "test");
    expect_same_conductor(file.span.conductor(), drake_derived());
    EXPECT_EQ(file.span.tension(), 0.15 * 138800.0);  // tension_fraction of the entry's RTS
  }
}

TEST(SpanConductorType, KeysBesideTypeOverrideTheEntrysValues) {
  const SpanFile file = load_span_text(
      span_with("[conductor]\ntype = \"ACSR Drake\"\nname = \"Drake, line 7\"\nei_min = 40\naluminium_layers = 1\n"), "test");
  const span::Conductor& c = file.span.conductor();
  EXPECT_EQ(c.name, "Drake, line 7");
  EXPECT_EQ(c.ei_min, 40.0);
  EXPECT_EQ(c.aluminium_layers, 1);
  EXPECT_EQ(c.ei_max, drake_derived().ei_max);  // the rest: the entry's
  EXPECT_EQ(c.diameter, drake_derived().diameter);
  EXPECT_EQ(c.outer_wire_modulus, drake_derived().outer_wire_modulus);
}

TEST(SpanConductorType, TheTableTheCatalogueCommandPrintsGivesTheSameConductor) {
  // Pasting `stockbridge conductors "ACSR Drake"`'s table: every number to the last bit
  // (an earth wire's span with its own endurance limit, the Safe Border Line not being
  // stated for its outer wires).
  for (const span::StrandedConductor& entry : conductor_catalogue()) {
    SCOPED_TRACE(entry.type);
    const std::string fatigue =
        span::conductor_of(entry).safe_border_line_applies() ? "cycles = 5e8\n" : "endurance_limit_mpa = 30\n";
    const SpanFile pasted = load_span_text(span_with(requests::conductor_table_toml(entry), fatigue), "test");
    expect_same_conductor(pasted.span.conductor(), span::conductor_of(entry));
  }
}

TEST(SpanConductorType, AnUnknownTypeIsOneLineWithTheKnownTypes) {
  const std::string message = span_file_error(span_with("[conductor]\ntype = \"ACSR Drak\"\n"));
  EXPECT_NE(message.find("span.toml:2: conductor.type = \"ACSR Drak\": expected a conductor of the catalogue: "
                         "AAAC 1055, AAAC 823, AAAC 900, AAAC ASTER570, AAC Arbutus, AAC Orchid, ACSR Bersfort, "
                         "ACSR Bersimis, ACSR Cardinal, ACSR Drake, ACSR Falcon, ACSR Ibis, ACSR Linnet, ACSR Tern, "
                         "Alumoweld 19 No. 9, Alumoweld 7 No. 8, EHS 3/8, GSW 19/3.25, OPGW 13.6, OPGW 9.6"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("or file = a conductor file"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(SpanConductorType, TypeAndFileTogetherUnknownKeysAndBadOverridesAreRefused) {
  EXPECT_NE(span_file_error(span_with("[conductor]\ntype = \"ACSR Drake\"\nfile = \"c.toml\"\n"))
                .find("span.toml:3: conductor.file: given beside conductor.type: expected one of type"),
            std::string::npos);
  EXPECT_NE(span_file_error(span_with("[conductor]\ntype = \"ACSR Drake\"\neimin = 40\n")).find("span.toml:3: unknown key 'conductor.eimin'"),
            std::string::npos);
  EXPECT_NE(span_file_error(span_with("[conductor]\ntype = \"ACSR Drake\"\nei_min = -1\n"))
                .find("span.toml:3: conductor.ei_min = -1: expected a finite value > 0 (N m^2)"),
            std::string::npos);
  EXPECT_NE(span_file_error(span_with("[conductor]\ntype = 7\n")).find("span.toml:2: conductor.type: the integer 7: expected a string"),
            std::string::npos);
}

TEST(SpanConductorFile, ReadsAUsersConductorFileRelativeToTheSpanFile) {
  // The catalogue's own Drake file, copied beside the span file under another type:
  // the same conductor, and the file is an input the command must not overwrite.
  std::string text = drake_file_text();
  text.replace(text.find("type = \"ACSR Drake\""), 19, "type = \"My Drake\"");
  const auto conductor = testing::write_temp_file(conductor_directory() / "conductors", "my_drake.toml", text);
  const auto path = write_in_conductor_directory("span_with_file.toml",
                                                 span_with("[conductor]\nfile = \"conductors/my_drake.toml\"\nei_max = 1200\n"));
  const SpanFile file = load_span_file(path);
  span::Conductor expected = drake_derived();
  expected.name = "My Drake";
  expected.ei_max = 1200.0;  // overridden
  expect_same_conductor(file.span.conductor(), expected);
  ASSERT_EQ(file.inputs.size(), 1u);
  EXPECT_EQ(std::filesystem::canonical(file.inputs[0]), std::filesystem::canonical(conductor));
  // read_conductor_file alone: the same entry.
  EXPECT_EQ(span::conductor_of(read_conductor_file(conductor)).ei_min, drake_derived().ei_min);
}

TEST(SpanConductorFile, AMissingFileSaysWhereItWasLookedFor) {
  const std::string message = span_file_error(span_with("[conductor]\nfile = \"nowhere.toml\"\n"));
  EXPECT_NE(message.find("span.toml:2: conductor.file: \"nowhere.toml\": expected an existing conductor file (looked for "),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("relative paths start at the file's folder"), std::string::npos) << message;
  // Span text (Python's span(text=...)) has no folder: the working directory.
  try {
    load_span_text(span_with("[conductor]\nfile = \"nowhere.toml\"\n"), "span(text=...)");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("span(text=...): conductor.file: \"nowhere.toml\": expected an existing "
                                         "conductor file (looked for " +
                                         (std::filesystem::current_path() / "nowhere.toml").string()),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("relative paths start at the working directory"), std::string::npos) << e.what();
  }
}

TEST(SpanConductorFile, ErrorsInTheConductorFileNameItsFileLineAndKey) {
  std::string text = drake_file_text();
  const std::string from = "lay_ratio = 12 ";
  text.replace(text.find(from), from.size(), "lay_ratio = 1  ");
  write_in_conductor_directory("bad_drake.toml", text);
  const std::string message = span_file_error(span_with("[conductor]\nfile = \"bad_drake.toml\"\n"), "span_bad.toml");
  int line = 1;
  for (std::size_t i = 0; i < text.find("lay_ratio = 1  "); ++i) line += text[i] == '\n';
  EXPECT_NE(message.find("bad_drake.toml:" + std::to_string(line) + ": conductor.layer[2].lay_ratio = 1: expected more than 2 pi R / D"),
            std::string::npos)
      << message;
}

TEST(ConductorFile, KeysAndTypesAreChecked) {
  auto error = [](const std::string& text) {
    const auto path = write_in_conductor_directory("c.toml", text);
    try {
      read_conductor_file(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no InputError)");
  };
  std::string text = drake_file_text();
  auto with = [&](const std::string& from, const std::string& to) {
    std::string changed = text;
    changed.replace(changed.find(from), from.size(), to);
    return changed;
  };
  EXPECT_NE(error(with("material = \"steel\"", "material = \"iron\"")).find("conductor.core.material = \"iron\": expected steel, aluminium, aluminium-alloy or aluminium-clad-steel"),
            std::string::npos);
  EXPECT_NE(error(with("lay_ratio = 21 ", "lay_ratio = 21\nlay_length = 0.2 ")).find("conductor.layer[0].lay_ratio: given beside conductor.layer[0].lay_length"),
            std::string::npos);
  EXPECT_NE(error(with("lay_ratio = 21 ", "# no lay ")).find("missing key 'lay_ratio' in [conductor.layer[0]]"), std::string::npos);
  EXPECT_NE(error(with("count = 6 ", "count = 6\ncolour = \"red\" ")).find("unknown key 'conductor.layer[0].colour'"),
            std::string::npos);
  EXPECT_NE(error(with("diameter = 0.02814", "diameter = 0.03")).find("conductor.diameter = 0.03: expected the stranding's outer diameter"),
            std::string::npos);
  EXPECT_NE(error("[conductor]\ntype = \"x\"\n").find("c.toml:1: missing key 'mass_per_length' in [conductor]"), std::string::npos);
}

}  // namespace
}  // namespace stockbridge::io
