#include "stockbridge/requests/time_check.hpp"

#include <cmath>
#include <functional>
#include <limits>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/parallel.hpp"

namespace stockbridge::requests {

namespace {

bool within_tolerance(double ratio) { return std::abs(ratio - 1.0) <= kTimeCheckTolerance; }

}  // namespace

const ComparedFigure& judged_stress(const SteadyComparison& f, bool poffenberger_swart) {
  return poffenberger_swart ? f.stress_poffenberger_swart_pa : f.stress_fymax_pa;
}

bool TimeCheck::compared() const {
  return std::isfinite(figures.antinode_amplitude_m.ratio) && std::isfinite(figures.stress_fymax_pa.ratio);
}

// The stresses and Y_b at one frequency are each proportional to the clamp's loop
// amplitude S: their ratios are S's, and the fymax stress's stands for all.
bool agrees(const SteadyComparison& figures) {
  return within_tolerance(figures.antinode_amplitude_m.ratio) && within_tolerance(figures.stress_fymax_pa.ratio);
}

bool TimeCheck::agrees() const { return compared() && requests::agrees(figures); }

void validate_check_frequencies(const std::vector<double>& frequencies) {
  if (frequencies.empty()) throw InvalidParameter("check_time: no frequency given, expected at least one (Hz)");
  for (std::size_t i = 0; i < frequencies.size(); ++i) {
    if (!(frequencies[i] > 0.0) || !std::isfinite(frequencies[i])) {
      throw_invalid(fmt::format("check_time[{}]", i), frequencies[i], "a frequency, Hz, > 0");
    }
  }
}

std::vector<TimeCheck> check_span_in_time(const io::SpanFile& file, const std::vector<double>& frequencies, int threads,
                                          const std::atomic<bool>* stop) {
  validate_check_frequencies(frequencies);
  span::check_in_time(file.span);
  std::vector<TimeCheck> checks(frequencies.size());
  for (std::size_t i = 0; i < frequencies.size(); ++i) checks[i].asked_frequency_hz = frequencies[i];
  parallel_for(frequencies.size(), threads, [&](std::size_t i) {
    TimeCheck& check = checks[i];
    SimulateRequest request;
    request.frequency_hz = frequencies[i];
    try {
      check.result.emplace(run_simulate(file, request, {}, {}, stop));
      check.figures = steady_comparison(file.span, *check.result);
    } catch (const NumericalError& e) {
      check.failure = e.what();
    }
  });
  return checks;
}

io::SpanFile span_file_as_balanced(const io::SpanFile& file, const CheckedSpanRequest& request,
                                   const SpanResult& result) {
  io::SpanFile out = file;
  out.span = result.analysis.span;
  out.balance = analysis_options(file.balance, request).balance;
  return out;
}

Table<TimeCheck> time_check_table(bool poffenberger_swart) {
  const std::string stress = poffenberger_swart ? "stress_ps_mpa" : "stress_fymax_mpa";
  const std::string stress_meaning =
      poffenberger_swart ? "the Poffenberger-Swart stress from Y_b (the criterion's)" : "the fymax stress at clamp 1";
  std::vector<Quantity<TimeCheck>> q;
  q.push_back({"asked_frequency_hz", "Hz", "the frequency asked", ColumnKind::number,
               [](const TimeCheck& c, std::size_t) { return c.asked_frequency_hz; }, {}});
  q.push_back(masked_quantity<TimeCheck>(
      "frequency_hz", "Hz", "the frequency simulated and balanced: the span's natural mode nearest the one asked",
      [](const TimeCheck& c) { return c.result.has_value(); },
      [](const TimeCheck& c, std::size_t) { return c.result->history.frequency_hz; }));
  q.push_back({"settled", "", "whether the run settled (its figures are steady)", ColumnKind::flag,
               [](const TimeCheck& c, std::size_t) { return c.result && c.result->history.settled ? 1.0 : 0.0; }, {}});
  q.push_back(masked_quantity<TimeCheck>(
      "simulated_s", "s", "the time simulated", [](const TimeCheck& c) { return c.result.has_value(); },
      [](const TimeCheck& c, std::size_t) { return c.result->history.time_s; }));
  const auto add = [&q](const std::string& name, const std::string& unit, const std::string& meaning, double scale,
                        std::function<const ComparedFigure&(const SteadyComparison&)> figure) {
    q.push_back({name + (unit.empty() ? "" : "_" + unit), unit == "mpa" ? "MPa" : unit, meaning + ", in time",
                 ColumnKind::number,
                 [figure, scale](const TimeCheck& c, std::size_t) { return scale * figure(c.figures).simulated; }, {}});
    q.push_back({"ebm_" + name + (unit.empty() ? "" : "_" + unit), unit == "mpa" ? "MPa" : unit,
                 meaning + ", by the energy balance", ColumnKind::number,
                 [figure, scale](const TimeCheck& c, std::size_t) { return scale * figure(c.figures).balanced; }, {}});
    q.push_back({name + "_ratio", "", meaning + ": the simulation's over the balance's", ColumnKind::number,
                 [figure](const TimeCheck& c, std::size_t) { return figure(c.figures).ratio; }, {}});
  };
  add("antinode_amplitude", "m", "the antinode amplitude at mid-span", 1.0,
      [](const SteadyComparison& f) -> const ComparedFigure& { return f.antinode_amplitude_m; });
  add(stress.substr(0, stress.size() - 4), "mpa", stress_meaning, 1e-6,
      [poffenberger_swart](const SteadyComparison& f) -> const ComparedFigure& {
        return judged_stress(f, poffenberger_swart);
      });
  add("bending_amplitude", "m", "Y_b, peak-to-peak at x_b from clamp 1", 1.0,
      [](const SteadyComparison& f) -> const ComparedFigure& { return f.bending_amplitude_m; });
  q.push_back({"agrees", "",
               "the antinode amplitude and the stress each within 10 % of the balance's (empty: nothing compared)",
               ColumnKind::flag,
               [](const TimeCheck& c, std::size_t) {
                 return c.compared() ? (c.agrees() ? 1.0 : 0.0) : std::numeric_limits<double>::quiet_NaN();
               },
               {}});
  return Table<TimeCheck>(std::move(q));
}

std::vector<io::JsonObject> time_check_rows(const std::vector<TimeCheck>& checks, bool poffenberger_swart) {
  const TableValues values = time_check_table(poffenberger_swart).values(checks);
  std::vector<io::JsonObject> rows;
  for (std::size_t r = 0; r < values.rows; ++r) rows.push_back(values.json_row(r));
  return rows;
}

std::vector<std::string> time_check_warnings(const std::vector<TimeCheck>& checks, bool poffenberger_swart) {
  std::vector<std::string> out;
  for (const TimeCheck& c : checks) {
    const std::string at = fmt::format("check in time at {:.6g} Hz", c.asked_frequency_hz);
    if (!c.result) {
      out.push_back(fmt::format("{}: no run ({})", at, c.failure));
    } else if (!c.result->history.settled) {
      out.push_back(fmt::format("{}: the run did not settle in {} s ([time] duration longer); nothing compared", at,
                                format_value(c.result->settings.duration_s)));
    } else if (!c.compared()) {
      out.push_back(fmt::format("{}: the balance at {:.6g} Hz did not converge; nothing compared", at,
                                c.result->history.frequency_hz));
    } else if (!c.agrees()) {
      out.push_back(fmt::format(
          "{} ({:.6g} Hz simulated): the simulation's antinode amplitude is {:.3f} and its {} {:.3f} of the balance's, "
          "more than {:.0f} % apart: the balance's assumptions do not hold here (docs/time-domain.md)",
          at, c.result->history.frequency_hz, c.figures.antinode_amplitude_m.ratio,
          poffenberger_swart ? "Poffenberger-Swart stress" : "fymax stress",
          judged_stress(c.figures, poffenberger_swart).ratio, 100.0 * kTimeCheckTolerance));
    }
  }
  return out;
}

}  // namespace stockbridge::requests
