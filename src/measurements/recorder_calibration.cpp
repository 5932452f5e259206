// A span parameter calibrated on a recorder's counts (recorder.hpp's analyse_record):
// Gauss-Newton with a Levenberg-Marquardt damping on the bands' mean ln Yb, each
// evaluation a balance on the span's tables; the parameters by their span-file keys,
// and the span file's text with the calibrated values.
#include "recorder_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::measurements {

namespace {

// Names here are unique among the library's files (unity batches).

constexpr double calibration_nan = std::numeric_limits<double>::quiet_NaN();

// ---- calibration ---------------------------------------------------------

bool recorder_log_key(const std::string& key) { return key != "wind.turbulence_intensity"; }

/// The bands of the fit: recorded cycles and a known mean (a prediction is checked per evaluation).
struct RecorderFit {
  const RecorderCounts& counts;
  const span::Span& span;
  const span::SpanTables& tables;
  const span::BalanceOptions& balance;
  const RecorderOptions& options;
  std::vector<std::size_t> bands;  // indices into the prediction's bands
  std::vector<double> target, weight;
  int balances = 0;

  span::Span span_at(const std::vector<double>& u) const {
    span::Span s = span;
    for (std::size_t i = 0; i < options.calibrate.size(); ++i) {
      const std::string& key = options.calibrate[i];
      s = with_parameter(s, key, recorder_log_key(key) ? std::exp(u[i]) : u[i]);
    }
    return s;
  }

  RecorderPrediction predict(const std::vector<double>& u) {
    const span::Span s = span_at(u);
    ++balances;
    const span::SpanBalance b = span::run_balance(s, tables, balance);
    return predict_record(counts, s, b, options.points_per_band, options.days);
  }

  /// The residuals (predicted - recorded mean ln Yb), none where a fit band is not known.
  std::optional<std::vector<double>> residuals(const std::vector<double>& u) {
    const RecorderPrediction p = predict(u);
    std::vector<double> r;
    for (std::size_t k = 0; k < bands.size(); ++k) {
      const RecorderBand& band = p.bands[bands[k]];
      if (!band.converged || !std::isfinite(band.predicted_mean_ln_yb)) return std::nullopt;
      r.push_back(band.predicted_mean_ln_yb - target[k]);
    }
    return r;
  }

  double cost(const std::vector<double>& r) const {
    double c = 0.0;
    for (std::size_t k = 0; k < r.size(); ++k) c += weight[k] * r[k] * r[k];
    return c;
  }
};

double recorder_clamp(const std::string& key, double u) {
  return key == "wind.turbulence_intensity" ? std::clamp(u, 0.0, 1.0) : u;
}

/// Solves the p x p (p <= 2) system A x = b; false where singular.
bool recorder_solve(const std::vector<std::vector<double>>& a, const std::vector<double>& b, std::vector<double>& x) {
  if (b.size() == 1) {
    if (!(std::abs(a[0][0]) > 0.0)) return false;
    x = {b[0] / a[0][0]};
    return true;
  }
  const double det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  if (!(std::abs(det) > 1e-300) || !std::isfinite(det)) return false;
  x = {(b[0] * a[1][1] - a[0][1] * b[1]) / det, (a[0][0] * b[1] - a[1][0] * b[0]) / det};
  return true;
}

}  // namespace

RecorderCalibration calibrate_record(const RecorderCounts& counts, const span::Span& span,
                                     const span::SpanTables& tables, const span::BalanceOptions& balance,
                                     const RecorderOptions& options, const RecorderPrediction& before) {
  RecorderFit fit{counts, span, tables, balance, options, {}, {}, {}, 0};
  for (std::size_t k = 0; k < before.bands.size(); ++k) {
    const RecorderBand& b = before.bands[k];
    if (b.recorded_cycles > 0.0 && std::isfinite(b.recorded_mean_ln_yb) && b.converged &&
        std::isfinite(b.predicted_mean_ln_yb)) {
      fit.bands.push_back(k);
      fit.target.push_back(b.recorded_mean_ln_yb);
      fit.weight.push_back(b.recorded_cycles);
    }
  }
  const std::size_t p = options.calibrate.size();
  RecorderCalibration c;
  std::vector<double> u(p);
  for (std::size_t i = 0; i < p; ++i) {
    const double v = parameter_of(span, options.calibrate[i]);
    c.values.push_back({options.calibrate[i], v, v, calibration_nan});
    u[i] = recorder_log_key(options.calibrate[i]) ? std::log(v) : v;
  }
  const std::size_t nb = fit.bands.size();
  double weight_sum = 0.0;
  for (const double w : fit.weight) weight_sum += w;
  if (nb == 0) {
    c.message = "no band with recorded cycles and a converged prediction: nothing to fit";
    c.residual_before = c.residual_after = calibration_nan;
    c.prediction = before;
    c.span = span;
    return c;
  }
  std::vector<double> r(nb);
  for (std::size_t k = 0; k < nb; ++k) r[k] = before.bands[fit.bands[k]].predicted_mean_ln_yb - fit.target[k];
  double cost = fit.cost(r);
  c.residual_before = std::sqrt(cost / weight_sum);

  // The Jacobian of the residuals by central differences (one-sided at a bound).
  const auto jacobian = [&](const std::vector<double>& at) -> std::optional<std::vector<std::vector<double>>> {
    std::vector<std::vector<double>> j(nb, std::vector<double>(p));
    for (std::size_t i = 0; i < p; ++i) {
      const std::string& key = options.calibrate[i];
      const double h = recorder_log_key(key) ? 1e-3 : std::max(1e-4, 1e-2 * at[i]);
      std::vector<double> up = at, down = at;
      up[i] = recorder_clamp(key, at[i] + h);
      down[i] = recorder_clamp(key, at[i] - h);
      const auto ru = fit.residuals(up);
      const auto rd = fit.residuals(down);
      if (!ru || !rd || !(up[i] > down[i])) return std::nullopt;
      for (std::size_t k = 0; k < nb; ++k) j[k][i] = ((*ru)[k] - (*rd)[k]) / (up[i] - down[i]);
    }
    return j;
  };
  const auto normal = [&](const std::vector<std::vector<double>>& j, const std::vector<double>& w) {
    std::vector<std::vector<double>> a(p, std::vector<double>(p, 0.0));
    for (std::size_t k = 0; k < nb; ++k) {
      for (std::size_t i = 0; i < p; ++i) {
        for (std::size_t m = 0; m < p; ++m) a[i][m] += w[k] * j[k][i] * j[k][m];
      }
    }
    return a;
  };

  double lambda = 1e-3;
  std::optional<std::vector<std::vector<double>>> j_at_u;
  for (c.iterations = 0; c.iterations < options.max_iterations; ++c.iterations) {
    j_at_u = jacobian(u);
    if (!j_at_u) {
      c.message = "the balance did not converge next to the parameters: no Jacobian";
      break;
    }
    const std::vector<std::vector<double>>& j = *j_at_u;
    const std::vector<std::vector<double>> a = normal(j, fit.weight);
    std::vector<double> g(p, 0.0);
    for (std::size_t k = 0; k < nb; ++k) {
      for (std::size_t i = 0; i < p; ++i) g[i] -= fit.weight[k] * j[k][i] * r[k];
    }
    bool accepted = false;
    double step = 0.0;
    while (lambda < 1e10) {
      std::vector<std::vector<double>> damped = a;
      for (std::size_t i = 0; i < p; ++i) damped[i][i] *= 1.0 + lambda;
      std::vector<double> delta;
      if (!recorder_solve(damped, g, delta)) {
        lambda *= 10.0;
        continue;
      }
      std::vector<double> trial = u;
      for (std::size_t i = 0; i < p; ++i) trial[i] = recorder_clamp(options.calibrate[i], u[i] + delta[i]);
      const auto rt = fit.residuals(trial);
      if (rt && fit.cost(*rt) <= cost) {
        step = 0.0;
        for (std::size_t i = 0; i < p; ++i) step = std::max(step, std::abs(trial[i] - u[i]));
        const double decrease = cost - fit.cost(*rt);
        u = trial;
        r = *rt;
        cost = fit.cost(r);
        lambda = std::max(lambda / 10.0, 1e-12);
        accepted = true;
        if (step < 1e-6 || decrease <= 1e-12 * std::max(cost, 1e-300)) c.converged = true;
        break;
      }
      lambda *= 10.0;
    }
    if (!accepted) {
      c.converged = true;  // no step lowers the cost: a minimum to the step's resolution
      break;
    }
    if (c.converged) {
      j_at_u.reset();
      break;
    }
  }
  if (!c.converged && c.message.empty()) c.message = fmt::format("{} iterations without convergence", c.iterations);
  if (c.converged) c.message = fmt::format("converged in {} iterations", c.iterations);
  // A value held at its bound is no fit: the record asks for more than the key can give.
  for (std::size_t i = 0; i < p; ++i) {
    if (options.calibrate[i] == "wind.turbulence_intensity" && (u[i] <= 0.0 || u[i] >= 1.0)) {
      c.converged = false;
      c.message = fmt::format("{} ran to its bound, {}: the record lies beyond what it can explain (the weighted RMS "
                              "of ln Yb is still {:.3g}); check the record's units and days, the dampers, or calibrate "
                              "another key",
                              options.calibrate[i], u[i], std::sqrt(cost / weight_sum));
    }
  }
  if (!j_at_u) j_at_u = jacobian(u);
  if (j_at_u && nb > p) {
    std::vector<double> w(nb);
    for (std::size_t k = 0; k < nb; ++k) w[k] = fit.weight[k] * static_cast<double>(nb) / weight_sum;
    double s2 = 0.0;
    for (std::size_t k = 0; k < nb; ++k) s2 += w[k] * r[k] * r[k];
    s2 /= static_cast<double>(nb - p);
    const std::vector<std::vector<double>> a = normal(*j_at_u, w);
    for (std::size_t i = 0; i < p; ++i) {
      std::vector<double> e(p, 0.0), col;
      e[i] = 1.0;
      if (!recorder_solve(a, e, col)) continue;
      const double se_u = std::sqrt(s2 * col[i]);
      const double value = recorder_log_key(options.calibrate[i]) ? std::exp(u[i]) : u[i];
      c.values[i].standard_error = recorder_log_key(options.calibrate[i]) ? value * se_u : se_u;
    }
  }
  for (std::size_t i = 0; i < p; ++i) {
    c.values[i].value = recorder_log_key(options.calibrate[i]) ? std::exp(u[i]) : u[i];
  }
  c.residual_after = std::sqrt(cost / weight_sum);
  c.span = fit.span_at(u);
  const span::SpanBalance b = span::run_balance(*c.span, tables, balance);
  ++fit.balances;
  c.prediction = predict_record(counts, *c.span, b, options.points_per_band, options.days);
  c.balances = fit.balances;
  return c;
}

namespace {

std::string recorder_value_text(double value) { return fmt::format("{:.10g}", value); }

}  // namespace

span::Span with_parameter(const span::Span& s, const std::string& key, double value) {
  span::WindModel wind = s.wind();
  span::SelfDampingModel sd = s.self_damping();
  if (key == "wind.turbulence_intensity") {
    if (wind.law != span::WindLaw::foti) {
      throw InvalidParameter(key, fmt::format(": the span's wind law is '{}'; only law = 'foti' has a turbulence "
                                              "intensity (wind.power_scale scales any law)",
                                              span::wind_law_name(wind.law)));
    }
    wind.turbulence_intensity = value;
    wind.turbulence_terrain.reset();
  } else if (key == "wind.power_scale") {
    wind.power_scale = value;
  } else if (key == "self_damping.k") {
    if (sd.law == span::SelfDampingLaw::foti) {
      throw InvalidParameter(key, ": the span's self-damping law is 'foti', which has no factor k; expected a power "
                                  "law (noiseux-1991, ..., power)");
    }
    sd.k = value;
  } else {
    throw InvalidParameter("calibrate", fmt::format(" = '{}': expected wind.turbulence_intensity, wind.power_scale or "
                                                    "self_damping.k",
                                                    printable(key)));
  }
  return within_field(key.substr(0, key.find('.')), [&] {
    return span::Span(s.conductor(), s.length(), s.tension(), std::move(wind), std::move(sd), s.dampers(), s.fatigue(),
                      s.terrain());
  });
}

double parameter_of(const span::Span& s, const std::string& key) {
  if (key == "wind.turbulence_intensity") return s.wind().turbulence_intensity;
  if (key == "wind.power_scale") return s.wind().power_scale;
  if (key == "self_damping.k") return s.self_damping().factor(s.conductor());
  throw InvalidParameter("calibrate", fmt::format(" = '{}': not a calibrated key", printable(key)));
}

std::string calibrated_span_text(const std::filesystem::path& source, const std::vector<CalibratedValue>& values) {
  const std::string file = source.string();
  std::ifstream in(source, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot be read", file));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::vector<std::string> lines;
  {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t nl = text.find('\n', start);
      if (nl == std::string::npos) {
        if (start < text.size()) lines.push_back(text.substr(start));
        break;
      }
      lines.push_back(text.substr(start, nl - start + 1));
      start = nl + 1;
    }
  }
  toml::table document;
  try {
    document = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: {}", file, e.source().begin.line, e.description()));
  }
  std::vector<std::string> appended;
  std::vector<std::pair<std::size_t, std::string>> inserts;  // after line (1-based), text
  for (const CalibratedValue& v : values) {
    const std::size_t dot = v.key.find('.');
    const std::string table_name = v.key.substr(0, dot);
    const std::string key = v.key.substr(dot + 1);
    const std::string value = recorder_value_text(v.value);
    const toml::table* table = document[table_name].as_table();
    if (!table) {
      appended.push_back(fmt::format("\n[{}]\n{} = {}  # calibrated on a vibration recorder's counts\n", table_name, key, value));
      continue;
    }
    if (table->is_inline()) {
      throw InputError(fmt::format("{}:{}: [{}] is an inline table: expected a [{}] table whose key {} can be set",
                                   file, table->source().begin.line, table_name, table_name, key));
    }
    if (const toml::node* node = table->get(key)) {
      const std::size_t line = node->source().begin.line;
      if (line == 0 || line > lines.size()) {
        throw InputError(fmt::format("{}: {}.{}: its line is not known; expected 'key = value' on one line", file,
                                     table_name, key));
      }
      std::string& l = lines[line - 1];
      const std::size_t eq = l.find('=');
      if (eq == std::string::npos) {
        throw InputError(fmt::format("{}:{}: {}.{}: expected 'key = value' on one line", file, line, table_name, key));
      }
      const bool crlf = l.ends_with("\r\n");
      const std::string rest = l.substr(eq + 1);
      const std::size_t hash = rest.find('#');
      std::string comment = hash == std::string::npos ? std::string() : "  " + rest.substr(hash);
      while (!comment.empty() && (comment.back() == '\n' || comment.back() == '\r')) comment.pop_back();
      l = l.substr(0, eq + 1) + " " + value + comment + (crlf ? "\r\n" : "\n");
    } else {
      inserts.emplace_back(table->source().begin.line,
                           fmt::format("{} = {}  # calibrated on a vibration recorder's counts\n", key, value));
    }
  }
  std::sort(inserts.begin(), inserts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [after, line] : inserts) {
    lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(std::min(after, lines.size())), line);
  }
  std::string out;
  for (const std::string& l : lines) out += l;
  if (!out.empty() && out.back() != '\n') out += '\n';
  for (const std::string& a : appended) out += a;
  return out;
}

}  // namespace stockbridge::measurements
