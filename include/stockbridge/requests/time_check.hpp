#pragma once
// `stockbridge span --check-time F[,F...]` (docs/time-domain.md): the span in time
// at a few frequencies beside the energy balance, each run's steady figures over the
// balance's, and where the two part by more than a tenth, a warning: there the
// balance's own assumptions (one standing wave, the travelling-wave picture at the
// ends, the dampers' first harmonic) do not carry the answer.

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/requests/output_table.hpp"
#include "stockbridge/requests/simulate_request.hpp"
#include "stockbridge/requests/span_request.hpp"

namespace stockbridge::requests {

/// How far apart the simulation and the balance may be before a check warns:
/// |ratio - 1| above this, for the antinode amplitude or the judged stress.
inline constexpr double kTimeCheckTolerance = 0.10;

/// Whether the antinode amplitude and the stresses in time are each within
/// kTimeCheckTolerance of the balance's (false where a ratio is missing).
bool agrees(const SteadyComparison& figures);

/// The stress the span's criterion judges: the Poffenberger-Swart stress from Y_b
/// (`poffenberger_swart`: the criterion judges the bending strain), else the fymax stress.
const ComparedFigure& judged_stress(const SteadyComparison& figures, bool poffenberger_swart);

/// One frequency checked in time.
struct TimeCheck {
  double asked_frequency_hz = 0.0;
  /// The run, where every step converged.
  std::optional<SimulateResult> result;
  /// Why there is no run (a step that did not converge, the balance that gives the
  /// start did not): empty where there is one.
  std::string failure;
  /// The steady figures beside the balance's (all NaN without a settled run).
  SteadyComparison figures;

  /// Settled, and the balance converged: the ratios are numbers.
  bool compared() const;
  /// Compared and every judged ratio within kTimeCheckTolerance of 1.
  bool agrees() const;
};

/// InvalidParameter naming "check_time[i]" where a frequency is not > 0 (or none is given).
void validate_check_frequencies(const std::vector<double>& frequencies);

/// The span file's span in time at each frequency (run_simulate with the file's time
/// settings, no history kept), on up to `threads` threads; `stop` ends the runs
/// under way early (their checks are then not settled). A run that fails keeps its
/// reason. InvalidParameter as validate_check_frequencies, and as check_in_time
/// where the span cannot be stepped in time.
std::vector<TimeCheck> check_span_in_time(const io::SpanFile& file, const std::vector<double>& frequencies,
                                          int threads, const std::atomic<bool>* stop = nullptr);

/// The span file as the span command balanced it: its span as analysed (positions
/// searched, dampers or attachments left out as asked) and the balance options the
/// request made of the file's, so that a check compares with the command's own balance.
io::SpanFile span_file_as_balanced(const io::SpanFile& file, const CheckedSpanRequest& request,
                                   const SpanResult& result);

/// A check's figures as the CSV (--check-time-output) and the JSON's "check_time"
/// list give them: asked_frequency_hz, frequency_hz, settled, simulated_s, the
/// antinode amplitude, the judged stress (`poffenberger_swart`: the span's criterion
/// judges the bending strain at Y_b, else the fymax stress) and Y_b, each as the
/// simulation's, the balance's (ebm_) and their ratio, and agrees.
Table<TimeCheck> time_check_table(bool poffenberger_swart);

/// The checks as the span command's JSON gives them ("check_time"): a row of
/// time_check_table each.
std::vector<io::JsonObject> time_check_rows(const std::vector<TimeCheck>& checks, bool poffenberger_swart);

/// A warning line for each check that does not agree or has no figures, naming the
/// frequency and, where they part, by how much.
std::vector<std::string> time_check_warnings(const std::vector<TimeCheck>& checks, bool poffenberger_swart);

}  // namespace stockbridge::requests
