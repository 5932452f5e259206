// stockbridge conductors: the catalogue of conductors a span file's
// [conductor] type = "..." selects (data/conductors, compiled into the library).

#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/requests/conductor_request.hpp"

namespace stockbridge::cli {

namespace {

struct ConductorsOptions {
  std::optional<std::string> type;
  bool json = false;
};

int run_conductors_command(const ConductorsOptions& options) {
  if (options.type) {
    const span::StrandedConductor& conductor = io::catalogue_conductor(*options.type);
    fmt::print("{}", options.json ? requests::conductor_summary(conductor).str() + "\n"
                                  : requests::conductor_table_toml(conductor));
    return kSuccess;
  }
  const auto& catalogue = io::conductor_catalogue();
  fmt::print("{}", options.json ? requests::conductors_summary(catalogue).str() + "\n"
                                : requests::conductor_list_text(catalogue));
  return kSuccess;
}

}  // namespace

void add_conductors_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<ConductorsOptions>();
  CLI::App* sub = app.add_subcommand(
      "conductors", "The catalogue of conductors a span file's [conductor] type = \"...\" selects (docs/span.md)");
  sub->add_option("type", options->type,
                  "One conductor (e.g. \"ACSR Drake\"; case, spaces and hyphens aside): print its [conductor] table "
                  "for a span file");
  sub->add_flag("--json", options->json, "Print JSON instead of text (one object; the list as {\"conductors\": [...]})");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_conductors_command(*options)); });
}

}  // namespace stockbridge::cli
