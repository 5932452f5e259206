#pragma once
// The reports an engineer attaches: one self-contained HTML page per run of
// `span`, `impedance`, `line` and `design`, and a damper's data sheet. Each restates
// its inputs with units, gives the verdict and the key figures first, then the
// figures, the assumptions (what a life means) and every warning of the run. A
// number that rests on a point that did not converge is never shown as a result:
// the page says how many points are missing instead.

#include <string>
#include <vector>

#include "stockbridge/damper/damper.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/design/search.hpp"
#include "stockbridge/io/line_file.hpp"
#include "stockbridge/line/schedule.hpp"
#include "stockbridge/measurements/recorder.hpp"
#include "stockbridge/report/html_page.hpp"
#include "stockbridge/requests/line_request.hpp"
#include "stockbridge/requests/modes_request.hpp"
#include "stockbridge/requests/span_request.hpp"
#include "stockbridge/requests/time_check.hpp"

namespace stockbridge::report {

/// What the front end knows of the run: when, the exact command, its warnings.
struct ReportContext {
  std::string generated_at;           ///< "2026-11-26 12:30 UTC"
  std::string command;                ///< the command line as typed; empty from Python
  std::vector<std::string> warnings;  ///< every warning the run printed
};

/// `stockbridge span`: the span's inputs (conductor, length, tension as N, % RTS and
/// H/w, wind, self-damping, dampers and positions, fatigue and climate), the verdict,
/// the amplitude, stress (with microstrain) and power curves with and without the
/// dampers against the endurance limit, the life and its caveats; with `checks`
/// (span --check-time), the simulation in time beside the balance at each frequency.
std::string span_report(const requests::SpanResult& result, const ReportContext& context,
                        const std::vector<requests::TimeCheck>& checks = {});

/// `stockbridge simulate`: whether the span in time agrees with the balance at the
/// frequency (within 10 %), the run's settings, its steady figures beside the
/// balance's, the dampers' powers, velocities and force harmonics, the envelope per
/// period and the amplitude along the span.
std::string simulate_report(const span::Span& span, span::DamperModel model, const requests::SimulateResult& result,
                            const ReportContext& context);

/// `stockbridge recorder`: the verdict (the measured damage per year and life
/// against the predicted), the recorded matrix as a picture (Yb against frequency,
/// cycles as colour) with the predicted Yb(f) over it before and after calibration,
/// the bands side by side, the calibration, and the damage table of the bins.
struct RecorderReportInput {
  const measurements::RecorderResult* result = nullptr;
  const span::Span* span = nullptr;
  std::string counts;  ///< the counts file as named
};
std::string recorder_report(const RecorderReportInput& input, const ReportContext& context);

/// A damper's impedance sweep (`stockbridge impedance`): the damper's numbers, |Z|,
/// phase and power at each amplitude, and its linear modes.
struct ImpedanceReportInput {
  std::string damper_name;  ///< the damper file's stem
  const damper::Damper* damper = nullptr;
  const std::vector<damper::SweepRun>* runs = nullptr;
  bool constant_displacement = false;  ///< the runs' amplitudes are X (m), else V (m/s)
  const requests::ModesResult* modes = nullptr;
};
std::string impedance_report(const ImpedanceReportInput& input, const ReportContext& context);

/// A line's damper schedule (`stockbridge line`): the rules, the verdicts, the
/// schedule table, the stress ratio (margin) per span, the bill of materials.
std::string line_report(const io::LineFile& file, const requests::LineSchedule& schedule,
                        const ReportContext& context);

/// A design search (`stockbridge design`): the study, the best design (the optimum
/// and the design rounded to build, each with its figures), the objective against
/// each variable, and the best design's stress curves on each span.
struct DesignReportInput {
  std::string design_name;  ///< the design file's stem
  const design::DesignStudy* study = nullptr;
  const design::DesignResult* result = nullptr;
  /// The best design rounded to a manufacturing precision and evaluated again (none
  /// where nothing is feasible), and its variables' values.
  const design::Evaluation* rounded = nullptr;
  int round_digits = 3;
  /// The design to build (rounded where feasible, else the optimum) balanced on each
  /// of the study's spans, in order (empty where nothing is feasible).
  std::vector<requests::SpanResult> best_spans;
};
std::string design_report(const DesignReportInput& input, const ReportContext& context);

/// A damper's data sheet (`stockbridge datasheet`): its numbers, the impedance and
/// power at the velocities damper standards test, its linear modes, and on each span
/// the damped and undamped stress curves and life.
struct DatasheetInput {
  std::string damper_name;
  const damper::Damper* damper = nullptr;
  const std::vector<damper::SweepRun>* runs = nullptr;
  const requests::ModesResult* modes = nullptr;
  std::vector<std::string> span_names;          ///< the span files' stems
  std::vector<requests::SpanResult> spans;      ///< the damper on each span
};
std::string datasheet(const DatasheetInput& input, const ReportContext& context);

}  // namespace stockbridge::report
