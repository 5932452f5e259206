#include "input_files.hpp"

#include <fmt/format.h>

#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/span_file.hpp"

namespace stockbridge::cli {

damper::Damper read_damper_input(const std::string& path, const std::vector<CommandFile>& outputs) {
  require_outputs_apart(outputs, {{"the damper file", path}});
  io::DamperFile file = io::load_damper_file(path);
  std::vector<CommandFile> inputs;
  for (const auto& cable_file : file.cable_files) inputs.push_back({"a cable file the damper file references", cable_file.string()});
  require_outputs_apart(outputs, inputs);
  print_warnings(file.warnings);
  return std::move(file.damper);
}

span::Span read_span_input(const std::string& path, const std::vector<CommandFile>& outputs) {
  require_outputs_apart(outputs, {{"the span file", path}});
  io::SpanFile file = io::load_span_file(path);
  std::vector<CommandFile> inputs;
  for (const auto& input : file.inputs) inputs.push_back({"a file the span file references", input.string()});
  require_outputs_apart(outputs, inputs);
  print_warnings(file.warnings);
  return std::move(file.span);
}

cable::Cable read_cable_input(const std::string& path, const std::vector<CommandFile>& outputs) {
  require_outputs_apart(outputs, {{"the cable file", path}});
  io::CableFile file = io::load_cable_file(path);
  print_warnings(file.warnings);
  return std::move(file.cable);
}

void print_warnings(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) fmt::print(stderr, "warning: {}\n", line);
}

void warn_unusual_options(const std::vector<UnusualValue>& values) {
  for (UnusualValue u : values) {
    u.field = "--" + u.field;
    print_warnings({u.message()});
  }
}

}  // namespace stockbridge::cli
