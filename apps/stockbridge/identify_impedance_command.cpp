// stockbridge identify impedance: the cable parameters (and optionally numbers of
// the damper itself, --free) of a damper from its measured impedance curves.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/measured_impedance_file.hpp"
#include "stockbridge/requests/impedance_fit_request.hpp"

namespace stockbridge::cli {

namespace {

struct ImpedanceFitOptions {
  std::string damper_file;
  std::string input;
  requests::ImpedanceFitRequest request;
  std::string output;
  std::string fitted;
  std::string fitted_damper;
  bool json = false;
  bool allow_unusual = false;
};

/// Where the cable file of each cable type goes: -o for the first; for the others
/// -o's name with the type's first arm's name appended ("cable.toml" -> "cable_right.toml").
std::vector<std::string> cable_outputs(const std::string& output, const identification::ImpedanceIdentification& fit,
                                       const damper::Damper& damper) {
  std::vector<std::string> paths;
  if (output.empty()) return paths;
  const std::filesystem::path path(output);
  for (std::size_t t = 0; t < fit.types(); ++t) {
    if (t == 0) {
      paths.push_back(output);
      continue;
    }
    const std::size_t arm = static_cast<std::size_t>(
        std::find(fit.cable_type.begin(), fit.cable_type.end(), t) - fit.cable_type.begin());
    std::filesystem::path other = path;
    other.replace_filename(fmt::format("{}_{}{}", path.stem().string(), damper.arm_name(arm), path.extension().string()));
    paths.push_back(other.string());
  }
  return paths;
}

int run_impedance_fit(const ImpedanceFitOptions& options, Invocation& invocation) {
  const identification::ImpedanceIdentificationOptions fit_options = requests::fit_options(options.request);
  const std::vector<CommandFile> outputs{
      {"-o", options.output}, {"--fitted", options.fitted}, {"--fitted-damper", options.fitted_damper}};
  require_outputs_apart(outputs, {{"the --input measurement", options.input}, {"the --damper file", options.damper_file}});
  const io::MeasuredImpedanceFile measured = io::load_measured_impedance(options.input, slip_policy(options.allow_unusual));
  const identification::ImpedanceMeasurement& measurement = measured.measurement;
  const damper::Damper damper =
      read_damper_input(invocation, options.damper_file, outputs, slip_policy(options.allow_unusual));
  print_warnings(invocation, measured.warnings);
  identification::ImpedanceIdentification fit;
  try {
    fit = identification::identify_impedance(damper.description(), measurement, fit_options);
  } catch (const InvalidParameter& e) {
    // The library names the measurement "measurement" and --free "free", anything else is the damper's.
    const std::string_view what = e.what(), measurement_prefix = "measurement: ";
    if (e.field() == "free") throw InputError("--free" + e.detail());
    if (e.field() == "elements") throw InputError(fmt::format("--elements{} (in {})", e.detail(), options.damper_file));
    throw InputError(what.starts_with(measurement_prefix)
                         ? fmt::format("{}: {}", options.input, what.substr(measurement_prefix.size()))
                         : fmt::format("{}: {}", options.damper_file, what));
  }
  print_warnings(invocation, requests::fit_warnings(fit, options.input));
  const std::vector<std::string> cables = cable_outputs(options.output, fit, damper);
  for (std::size_t t = 0; t < cables.size(); ++t) {
    io::write_file_atomically(cables[t], requests::fitted_cable_file(fit, t, options.input));
  }
  if (!options.fitted.empty()) {
    io::write_file_atomically(options.fitted, requests::fitted_table().values(requests::fitted_points(measurement, fit)).csv());
  }
  if (!options.fitted_damper.empty()) {
    io::write_file_atomically(options.fitted_damper, requests::fitted_damper_file(fit, options.input));
  }
  if (options.json) fmt::print("{}\n", requests::fit_summary(measurement, fit, damper, options.input, measured.warnings).str());
  fmt::print(stderr, "{}\n", requests::fit_summary_line(measurement, fit));
  if (cables.size() > 1) fmt::print(stderr, "cable files: {}\n", fmt::join(cables, ", "));
  if (fit.not_converged > 0) {
    fmt::print(stderr, "error: the fitted model did not converge at {} of {} measured points (converged = 0 in "
               "--fitted; they count as misfit 1 each)\n",
               fit.not_converged, measurement.points.size());
    return kNotConverged;
  }
  // A poor fit's warning line (fit_warnings) says the RMS error and the limit; a
  // significant lack of fit's, the error against the scatter and the suspects.
  return fit.poor_fit || fit.lack_of_fit.significant ? kNotConverged : kSuccess;
}

}  // namespace

void add_identify_impedance_command(CLI::App& identify, Invocation& invocation) {
  auto options = std::make_shared<ImpedanceFitOptions>();
  CLI::App* sub = identify.add_subcommand(
      "impedance", "Cable parameters (and chosen numbers of the damper) from its measured impedance (frequency_hz, "
                   "velocity_m_s, re_z_n_s_m, im_z_n_s_m)");
  sub->add_option("--damper", options->damper_file,
                  "Damper file: masses, inertias, offsets, cable lengths; its cables' values start the fit")
      ->required();
  sub->add_option("--input", options->input,
                  "Measured impedance (CSV: frequency_hz, velocity_m_s or displacement_m, re_z_n_s_m and im_z_n_s_m "
                  "or abs_z_n_s_m and phase_deg; several amplitudes)")
      ->required();
  sub->add_option("--elements", options->request.elements, "Jenkin elements per cable (a Masing cable; a Bouc-Wen one fits ei_min, ei_max and chi0)")->capture_default_str();
  sub->add_flag("--fit-clamp-mass", options->request.fit_clamp_mass, "Also fit the clamp mass (Im Z only; as --free clamp.mass)");
  sub->add_option("--free", options->request.free,
                  "Numbers of the damper fitted too, by path: clamp.mass, arm.<name>.mass, .inertia, .offset, "
                  ".cable.length (comma-separated; the damper file's values start them)")
      ->delimiter(',');
  sub->add_option("--rms-limit", options->request.rms_limit,
                  "RMS relative error of Z above which the fit is poor (warned of, exit status 3)")
      ->capture_default_str();
  sub->add_option("--scatter", options->request.scatter,
                  "The measurement's relative scatter of Z (0.01 for 1 %; default 0.01, assumed): a fit whose RMS error "
                  "exceeds it significantly (chi-square, 99 %) is a lack of fit (warned of with the fixed numbers that "
                  "may be wrong, exit status 3)");
  sub->add_option("--threads", options->request.threads, "Model runs at once")->capture_default_str();
  sub->add_option("-o,--output", options->output,
                  "Write the identified cable as a cable file (TOML; the length of the first arm) that damper files "
                  "reference");
  sub->add_option("--fitted", options->fitted, "Write measured and model Z at the measured points (CSV, for plotting)");
  sub->add_option("--fitted-damper", options->fitted_damper,
                  "Write the fitted damper as a damper file (TOML: the fitted cables and --free numbers written out)");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_flag("--json", options->json,
                "Print {\"ei\": ..., \"jenkin\": [{\"c\": ..., \"h\": ...}], \"misfit\": ..., \"parameters\": ...} on "
                "stdout");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_impedance_fit(*options, invocation)); });
}

}  // namespace stockbridge::cli
