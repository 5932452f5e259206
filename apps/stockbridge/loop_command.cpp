// stockbridge loop: drive one cable section of any section law (the Masing law exact
// or regularised, Bouc-Wen, ...) with a sinusoidal curvature and write its
// moment-curvature loop. The options are the laws' numbers (section_law_descriptor.hpp).

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "option_parsing.hpp"
#include "stockbridge/cable/section_law_descriptor.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/requests/section_loop.hpp"

namespace stockbridge::cli {

namespace {

struct LoopOptions {
  /// Each law's numbers by key (and the extras of its variants: the regularised law's exponent).
  std::vector<std::pair<std::string, std::optional<double>>> numbers;
  std::vector<std::string> jenkin;
  section::SinusoidalDrive drive;
  std::string law{requests::default_loop_law};
  std::string output;
};

/// The loop of the law asked for, each law given its own numbers only.
section::LoopRecord loop_of(const LoopOptions& options) {
  cable::LoopNumbers given{options.law, {}, {}};
  for (const auto& [key, value] : options.numbers) {
    if (value) given.numbers.emplace_back(key, *value);
  }
  for (std::size_t j = 0; j < options.jenkin.size(); ++j) {
    const section::Jenkin e = parse_jenkin_pair(options.jenkin[j], fmt::format("--jenkin #{}", j + 1));
    given.jenkin.emplace_back(e.c, e.h);
  }
  return requests::section_loop(given, options.drive, requests::command_line_spelling());
}

int run_loop_command(const LoopOptions& options) {
  const section::LoopRecord record = loop_of(options);

  io::write_file_atomically(options.output, requests::loop_table().values(requests::loop_samples(record)).csv());
  fmt::print(stderr, "loop: {} law, {} cycles x {} points: dissipated energy in the last cycle {} J/m\n",
             options.law, options.drive.cycles, options.drive.points, record.last_cycle_dissipation());
  return kSuccess;
}

}  // namespace

void add_loop_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<LoopOptions>();
  CLI::App* sub = app.add_subcommand(
      "loop", "Drive one cable section with kappa = A sin(2 pi k / points) and write its moment-curvature loop");
  // Every law's numbers, each key once (the first law's words; "ei" is the Masing and Iwan laws').
  for (const cable::SectionLawDescriptor* law : cable::section_laws()) {
    std::vector<cable::LawNumber> keys(law->numbers().begin(), law->numbers().end());
    for (const cable::LawNumber& extra : law->loop_extras()) keys.push_back(extra);
    for (const cable::LawNumber& n : keys) {
      const std::string key(n.key);
      if (std::any_of(options->numbers.begin(), options->numbers.end(), [&](const auto& e) { return e.first == key; })) {
        continue;
      }
      options->numbers.emplace_back(key, std::nullopt);
    }
  }
  for (auto& [key, value] : options->numbers) {
    std::string help;
    for (const cable::SectionLawDescriptor* law : cable::section_laws()) {
      std::vector<cable::LawNumber> keys(law->numbers().begin(), law->numbers().end());
      for (const cable::LawNumber& extra : law->loop_extras()) keys.push_back(extra);
      for (const cable::LawNumber& n : keys) {
        if (n.key != key) continue;
        help += fmt::format("{}{}: {}{}", help.empty() ? "" : "; ", law->title(), n.description,
                            n.unit.empty() ? "" : fmt::format(", {}", n.unit));
      }
    }
    sub->add_option(requests::command_line_spelling().key(key), value, help);
  }
  sub->add_option("--jenkin", options->jenkin, "Masing: a Jenkin element as c:h (N m^2 : N m); repeat for more");
  sub->add_option("--amplitude", options->drive.amplitude, "Curvature amplitude A, 1/m")->required();
  sub->add_option("--cycles", options->drive.cycles, "Number of cycles")->capture_default_str();
  sub->add_option("--points", options->drive.points, "Samples per cycle")->capture_default_str();
  std::string laws;
  for (const cable::SectionLawDescriptor* law : cable::section_laws()) {
    std::vector<std::string> keys;
    for (const cable::LawNumber& n : law->numbers()) keys.push_back(requests::command_line_spelling().key(n.key));
    if (law->jenkin_elements()) keys.push_back("--jenkin");
    std::string variants;
    for (std::string_view v : law->loop_variants()) variants += fmt::format(", {}", v);
    laws += fmt::format("{}{}{} ({})", laws.empty() ? "" : "; ", law->name(), variants, cable::joined_with_and(keys));
  }
  sub->add_option("--law", options->law,
                  "Section law: " + laws + " (exact is masing; regularised its rate law (3.15) with --exponent)")
      ->check(CLI::IsMember(requests::loop_law_names()))
      ->capture_default_str();
  sub->add_option("-o,--output", options->output, "Output CSV file")->required();
  sub->callback([options, &invocation] { invocation.set_exit_code(run_loop_command(*options)); });
}

}  // namespace stockbridge::cli
