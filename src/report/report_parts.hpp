#pragma once
// What several reports share: numbers as a reader wants them, a span's inputs
// restated, its curves, its verdict, and the caveats every life carries.

#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/report/html_page.hpp"
#include "stockbridge/report/svg_chart.hpp"
#include "stockbridge/requests/modes_request.hpp"
#include "stockbridge/requests/span_request.hpp"
#include "stockbridge/requests/sweep_request.hpp"
#include "stockbridge/requests/time_check.hpp"

namespace stockbridge::report::parts {

/// A number to `digits` significant digits ("-" where it is not finite).
std::string number(double value, int digits = 4);
/// Pa as "7.91 MPa".
std::string megapascal(double pascal);
/// A life in years, "unlimited (no damage)" when infinite.
std::string years(double life_years);

Tone verdict_tone(span::Verdict verdict);

/// The span's inputs restated with units: conductor, length, tension in its three
/// forms, the TB 273 judgement, wind, self-damping, dampers and positions, fatigue,
/// climate.
std::vector<Fact> span_inputs(const span::Span& span, span::DamperModel model);

/// The span's key figures: stresses, Yb and microstrain, damped and undamped; lives.
std::vector<Fact> span_key_figures(const span::SpanAnalysis& analysis);

/// The verdict's line: why it is safe, unsafe or unknown.
std::string span_verdict_reason(const span::SpanAnalysis& analysis);

/// The span's figures (stress with microstrain, amplitude, powers), `name` in the titles.
void span_figures(HtmlPage& page, const span::SpanAnalysis& analysis, std::string_view name);
/// The standing wave along the span at the governing frequency, the attachments marked
/// (a span with masses or dampers along it).
void span_profile_figure(HtmlPage& page, const span::SpanAnalysis& analysis, std::string_view name);
/// The span's natural mode nearest the governing frequency (span --modes), its shape
/// along the span with the attachments marked: a span with masses or dampers along
/// it, where the modes are no longer the bare string's sines.
void span_modes_figure(HtmlPage& page, const span::SpanAnalysis& analysis, std::string_view name);

/// The stress chart alone (the data sheet's per-span figure).
Chart span_stress_chart(const span::SpanAnalysis& analysis, std::string_view title);

/// What every life rests on; `life` adds the climate's caveats.
std::vector<std::string> span_caveats(bool life);

/// The points that did not converge, a line each (at most `shown`, then a count).
std::vector<std::string> span_failures(const span::SpanAnalysis& analysis, std::size_t shown = 12);

/// The damper's numbers: its total mass, the clamp's, each arm's mass, inertia,
/// offset and messenger.
std::vector<Fact> damper_facts(const damper::Damper& damper);

/// Per amplitude, the largest power the damper takes and its frequency, over the
/// converged points ("none converged" where there is none).
std::vector<Fact> largest_power_facts(const std::vector<damper::SweepRun>& runs, bool constant_displacement);

/// |Z| and phase, and the power, over frequency, a curve per amplitude.
void impedance_figures(HtmlPage& page, const damper::Damper& damper, const std::vector<damper::SweepRun>& runs,
                       bool constant_displacement, std::string_view name);
/// A table of the impedance at a few frequencies per amplitude (what a test sheet lists).
void impedance_table(HtmlPage& page, const damper::Damper& damper, const std::vector<damper::SweepRun>& runs,
                     bool constant_displacement);
/// The linear modes: each arm's (clamp held) and the damper's, stick and slip.
void modes_table(HtmlPage& page, const requests::ModesResult& modes);
/// The sweep's points that did not converge, a line each (at most `shown`, then a count).
std::vector<std::string> sweep_failures(const std::vector<damper::SweepRun>& runs, bool constant_displacement,
                                        std::size_t shown = 12);

/// The span report's section of `span --check-time`: a row per frequency, the
/// simulation's figures beside the balance's (nothing where there are no checks).
void time_checks_section(HtmlPage& page, const std::vector<requests::TimeCheck>& checks, bool poffenberger_swart);

/// "1.2, 2.4 m", the dampers' positions.
std::string positions_text(const span::Span& span);

}  // namespace stockbridge::report::parts
