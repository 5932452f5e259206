#include "stockbridge/requests/self_damping_request.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::requests {

namespace {

io::JsonObject sdr_estimate(const measurements::Estimate& e) {
  io::JsonObject o;
  o.add("value", e.value);
  o.add("standard_error", e.standard_error);  // NaN (given, not fitted) is written as null
  return o;
}

/// "2.44 +- 0.03", or "2.7 (given)".
std::string sdr_text(const measurements::Estimate& e) {
  if (std::isnan(e.standard_error)) return fmt::format("{:.4g} (given)", e.value);
  return fmt::format("{:.4g} +- {:.2g}", e.value, e.standard_error);
}

}  // namespace

io::JsonObject self_damping_summary(const measurements::SelfDampingFit& fit, const std::vector<std::string>& warnings) {
  io::JsonObject o;
  o.add("law", "power");
  o.add("k", sdr_estimate(fit.k));
  o.add("ln_k", sdr_estimate(fit.ln_k));
  o.add("l", sdr_estimate(fit.l));
  o.add("m", sdr_estimate(fit.m));
  o.add("n", sdr_estimate(fit.n));
  o.add("n_given", fit.n_given);
  o.add("points", static_cast<long long>(fit.points));
  o.add("parameters", static_cast<long long>(fit.parameters));
  o.add("degrees_of_freedom", static_cast<long long>(fit.points - fit.parameters));
  o.add("residual_rms_ln_p", fit.residual_rms);
  o.add("residual_standard_error_ln_p", fit.residual_standard_error);
  o.add("r_squared", fit.r_squared);
  o.add("tensions_n", fit.tensions);
  o.add("frequencies_hz", fit.frequencies);
  o.add("amplitudes_m", fit.amplitudes);
  o.add("notes", fit.notes);
  o.add("warnings", warnings);
  return o;
}

std::string self_damping_table(const measurements::SelfDampingFit& fit, std::string_view source) {
  std::string text = fmt::format(
      "# Self-damping fitted by stockbridge identify self-damping to {} tests of {}\n"
      "# ({} tension{}): P = k Y^l f^m / (T/1000)^n, W/m (Y antinode amplitude in m,\n"
      "# single peak; f in Hz; T in N). Residual RMS in ln P {:.3g}, r^2 {:.6g}.\n"
      "# Standard errors: k {:.4g} (ln k {:.3g}), l {:.3g}, m {:.3g}, n {}.\n",
      fit.points, printable(source, 200), fit.tensions.size(), fit.tensions.size() == 1 ? "" : "s", fit.residual_rms,
      fit.r_squared, fit.k.standard_error, fit.ln_k.standard_error, fit.l.standard_error, fit.m.standard_error,
      fit.n_given ? std::string("none (given)") : fmt::format("{:.3g}", fit.n.standard_error));
  for (const std::string& note : fit.notes) text += fmt::format("# Note: {}.\n", note);
  text += "# The tested conductor's own law: k holds no diameter or mass factor.\n";
  text += fmt::format("[self_damping]\nlaw = \"power\"\nk = {}\nl = {}\nm = {}\nn = {}\n", fit.k.value, fit.l.value,
                      fit.m.value, fit.n.value);
  return text;
}

std::string self_damping_summary_line(const measurements::SelfDampingFit& fit) {
  return fmt::format("identify self-damping: k = {}, l = {}, m = {}, n = {}; {} tests at {} tension{}, residual RMS "
                     "in ln P {:.3g}, r^2 {:.4f}",
                     sdr_text(fit.k), sdr_text(fit.l), sdr_text(fit.m), sdr_text(fit.n), fit.points,
                     fit.tensions.size(), fit.tensions.size() == 1 ? "" : "s", fit.residual_rms, fit.r_squared);
}

}  // namespace stockbridge::requests
