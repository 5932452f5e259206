#include "input_files.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/span_file.hpp"

namespace stockbridge::cli {

namespace {

/// The outputs apart from the files a description references, each named by `role`.
void require_apart_from_references(const std::vector<CommandFile>& outputs, const std::string& role,
                                   const std::vector<std::filesystem::path>& references) {
  std::vector<CommandFile> inputs;
  for (const auto& reference : references) inputs.push_back({role, reference.string()});
  require_outputs_apart(outputs, inputs);
}

}  // namespace

void add_allow_unusual_flag(CLI::App& command, bool& allow_unusual) {
  command.add_flag("--allow-unusual", allow_unusual,
                   "Take a value outside its typical range that a unit slip explains (a tension of 30.3: kN?) as given, "
                   "with a warning, instead of refusing it");
}

damper::Damper read_damper_input(Invocation& invocation, const std::string& path,
                                 const std::vector<CommandFile>& outputs, SlipPolicy policy) {
  require_outputs_apart(outputs, {{"the damper file", path}});
  io::DamperFile file = io::load_damper_file(path, policy);
  require_apart_from_references(outputs, "a cable file the damper file references", file.cable_files);
  print_warnings(invocation, file.warnings);
  return std::move(file.damper);
}

io::SpanFile read_span_input(Invocation& invocation, const std::string& path,
                             const std::vector<CommandFile>& outputs, SlipPolicy policy) {
  require_outputs_apart(outputs, {{"the span file", path}});
  io::SpanFile file = io::load_span_file(path, policy);
  require_apart_from_references(outputs, "a file the span file references", file.inputs);
  print_warnings(invocation, file.warnings);
  return file;
}

io::DesignFile read_design_input(Invocation& invocation, const std::string& path,
                                 const std::vector<CommandFile>& outputs, SlipPolicy policy) {
  require_outputs_apart(outputs, {{"the design file", path}});
  io::DesignFile file = io::load_design_file(path, policy);
  require_apart_from_references(outputs, "a file the design file reads", file.inputs);
  print_warnings(invocation, file.warnings);
  return file;
}

cable::Cable read_cable_input(Invocation& invocation, const std::string& path,
                              const std::vector<CommandFile>& outputs, SlipPolicy policy) {
  require_outputs_apart(outputs, {{"the cable file", path}});
  io::CableFile file = io::load_cable_file(path, policy);
  print_warnings(invocation, file.warnings);
  return std::move(file.cable);
}

void print_warnings(Invocation& invocation, const std::vector<std::string>& lines) {
  for (const std::string& line : lines) invocation.warn(line);
}

void print_warnings(Invocation& invocation, const std::vector<Warning>& warnings) {
  for (const Warning& w : warnings) {
    if (!w.setting) {
      print_warnings(invocation, {w.message});
      continue;
    }
    // The setting's name (up to the first space) as its flag: max_iterations -> --max-iterations.
    std::string line = "--" + w.message;
    for (std::size_t i = 2; i < line.size() && line[i] != ' '; ++i) {
      if (line[i] == '_') line[i] = '-';
    }
    print_warnings(invocation, {line});
  }
}

namespace {

/// The values judged (typical_ranges.hpp), each named as its option ("--velocity").
std::vector<std::string> judged_options(const std::vector<UnusualValue>& values, SlipPolicy policy) {
  std::vector<std::string> lines;
  for (UnusualValue u : values) {
    u.field = "--" + u.field;
    judge_unusual(u, "", policy, lines);
  }
  return lines;
}

}  // namespace

void warn_unusual_options(Invocation& invocation, const std::vector<UnusualValue>& values, SlipPolicy policy) {
  print_warnings(invocation, judged_options(values, policy));
}

void refuse_slipped_options(const std::vector<UnusualValue>& values, SlipPolicy policy) {
  (void)judged_options(values, policy);
}

}  // namespace stockbridge::cli
