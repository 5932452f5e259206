// stockbridge span SPAN.toml --modes: the span's natural frequencies with its masses
// and dampers (span/span_modes.hpp): the modes CSV (-o), the shapes CSV (--shapes),
// the summary on stdout (or --json).

#include "span_modes_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/requests/span_modes_request.hpp"

namespace stockbridge::cli {

namespace {

// Helper names here are unique among the program's files (unity batches).

/// The modes listed on stdout; the rest are in the CSV.
constexpr std::size_t kModesListed = 12;

/// The span command's options that --modes cannot take.
constexpr const char* kBalanceOnlyOptions[] = {"--frequencies", "--points",      "--no-dampers", "--damper-model",
                                               "--optimize-position", "--spacing-min", "--objective", "--threads",
                                               "--report", "--profile", "--no-attachments", "--check-time",
                                               "--check-time-output"};

/// "sphere (mass, 20 kg) at 133.3, 266.7 m": each attachment's positions under its name.
std::vector<std::string> modes_attachment_lines(const span::SpanModes& modes) {
  std::vector<std::string> names;
  std::map<std::string, std::string> positions;
  std::map<std::string, std::string> what;
  for (const span::ModeAttachment& a : modes.attachments) {
    const std::string key = fmt::format("{} ({}, {:.4g} kg)", a.name, span::attachment_kind_name(a.kind), a.mass);
    if (!positions.contains(key)) names.push_back(key);
    std::string& at = positions[key];
    at += fmt::format("{}{:.6g}", at.empty() ? "" : ", ", a.position);
  }
  std::vector<std::string> lines;
  for (const std::string& key : names) lines.push_back(fmt::format("{} at {} m", key, positions[key]));
  return lines;
}

std::string modes_dampers_text(const span::Span& span, span::ModeDampers dampers) {
  if (span.dampers().empty()) return "none";
  return dampers == span::ModeDampers::removed ? "removed (--dampers removed)"
                                               : "at their linear impedance, every element sticking";
}

void print_span_modes_report(const span::Span& span, const requests::SpanModesResult& result, const std::string& output) {
  const span::SpanModes& m = result.modes;
  fmt::print("span modes: {}{} m at {:.6g} N, c = {:.4g} m/s; the bare span's f_n = n x {:.4g} Hz\n",
             span.conductor().name.empty() ? "" : span.conductor().name + ", ", format_value(span.length()),
             span.tension(), m.wave_speed, m.wave_speed / (2.0 * m.length));
  fmt::print("dampers: {}\n", modes_dampers_text(span, m.dampers));
  const std::vector<std::string> attachments = modes_attachment_lines(m);
  if (attachments.empty()) fmt::print("attachments: none\n");
  for (const std::string& line : attachments) fmt::print("attachment {}\n", line);
  fmt::print("{} modes below {:.4g} Hz{}\n", m.modes.size(), m.max_frequency_hz,
             result.fmax_from_wind_band ? " (the top of the wind band; --fmax sets another)" : "");
  if (!m.modes.empty()) fmt::print("  {:>4}  {:>12}  {:>10}\n", "mode", "frequency Hz", "f / bare");
  for (std::size_t i = 0; i < std::min(m.modes.size(), kModesListed); ++i) {
    const span::SpanMode& mode = m.modes[i];
    fmt::print("  {:>4}  {:>12.6g}  {:>10.6f}\n", mode.number, mode.frequency_hz,
               mode.frequency_hz * 2.0 * m.length / (mode.number * m.wave_speed));
  }
  if (m.modes.size() > kModesListed) fmt::print("  ... and {} more in {}\n", m.modes.size() - kModesListed, output);
  if (m.clamp_still_modes > 0) {
    fmt::print("left out: {} frequencies at which a damper's identical arms swing against each other and its clamp, "
               "and so the conductor, stands still\n",
               m.clamp_still_modes);
  }
}

}  // namespace

void add_span_modes_options(CLI::App& span, SpanModesFlags& flags) {
  CLI::Option* modes = span.add_flag(
      "--modes", flags.modes,
      "Instead of the balance: the span's natural frequencies with its masses and dampers, -o the modes CSV");
  for (const char* name : kBalanceOnlyOptions) modes->excludes(span.get_option(name));
  span.add_option("--fmax", flags.fmax, "With --modes: the modes below this frequency, Hz (default: the wind band's top)")
      ->needs(modes);
  span.add_option("--dampers", flags.dampers,
                  "With --modes: removed, or linear (each damper at its linear impedance, every element sticking)")
      ->capture_default_str()
      ->needs(modes);
  span.add_option("--shapes", flags.shapes,
                  "With --modes: also write the shapes CSV (attachment, x_m, mode_1, mode_2, ...)")
      ->needs(modes);
}

int run_span_modes_command(const SpanModesFlags& flags, const SpanModesCommon& common, Invocation& invocation) {
  requests::SpanModesRequest request;
  request.fmax = flags.fmax;
  request.dampers = flags.dampers;
  request.shapes = flags.shapes.has_value();
  requests::validate(request);
  const io::SpanFile file = read_span_input(
      invocation, common.span_file, {{"-o", common.output}, {"--shapes", flags.shapes.value_or("")}}, slip_policy(common.allow_unusual));
  const auto start = std::chrono::steady_clock::now();
  const requests::SpanModesResult result = requests::run_span_modes(file.span, request);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string modes_csv = requests::span_modes_table(result).values(result.modes.modes).csv();
  const std::string shapes_csv =
      flags.shapes ? requests::span_mode_shapes_table(result).values(requests::shape_samples(result)).csv() : "";
  io::write_file_atomically(common.output, modes_csv);
  if (flags.shapes) io::write_file_atomically(*flags.shapes, shapes_csv);
  if (common.json) {
    fmt::print("{}\n", requests::span_modes_summary(result).add("seconds", seconds).str());
  } else if (!common.quiet) {
    print_span_modes_report(file.span, result, common.output);
  }
  if (!common.quiet) fmt::print(stderr, "span modes: {} modes in {:.2f} s\n", result.modes.modes.size(), seconds);
  return kSuccess;
}

}  // namespace stockbridge::cli
