#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "report_parts.hpp"
#include "stockbridge/report/reports.hpp"

namespace stockbridge::report {

namespace {

/// The mass, the largest power at each amplitude, the damper's modes, the points converged.
std::vector<Fact> sweep_key_figures(const ImpedanceReportInput& in, const requests::SweepTally& tally) {
  std::vector<Fact> out{{"total mass", parts::number(in.damper->total_mass(), 4) + " kg"}};
  for (Fact& f : parts::largest_power_facts(*in.runs, in.constant_displacement)) out.push_back(std::move(f));
  if (in.modes) {
    std::string stick, slip;
    for (const requests::ModeRow& r : requests::mode_rows(*in.modes)) {
      if (r.arm != "damper") continue;
      std::string& list = r.limit == damper::CableLimit::stick ? stick : slip;
      list += (list.empty() ? "" : ", ") + parts::number(r.frequency_hz, 3);
    }
    out.emplace_back("damper modes, stick (Hz)", stick.empty() ? "-" : stick);
    out.emplace_back("damper modes, slip (Hz)", slip.empty() ? "-" : slip);
  }
  out.emplace_back("points converged", fmt::format("{} of {}", tally.converged, tally.points));
  return out;
}

}  // namespace

std::string impedance_report(const ImpedanceReportInput& in, const ReportContext& context) {
  HtmlPage page({"Damper impedance: " + in.damper_name, context.generated_at, context.command});
  const requests::SweepTally tally = requests::tally(*in.runs);
  const int points = tally.points, converged = tally.converged;
  const double f0 = in.runs->front().points.front().frequency_hz, f1 = in.runs->front().points.back().frequency_hz;
  page.verdict(converged == points ? "computed" : "incomplete",
               fmt::format(" {} of {} points converged, {} amplitude{} from {} to {} Hz.", converged, points,
                           in.runs->size(), in.runs->size() == 1 ? "" : "s", parts::number(f0, 3), parts::number(f1, 3)),
               converged == points ? Tone::good : Tone::unknown);
  page.key_figures(sweep_key_figures(in, tally));
  page.section("The damper");
  page.facts(parts::damper_facts(*in.damper));
  page.section("Impedance");
  parts::impedance_figures(page, *in.damper, *in.runs, in.constant_displacement, in.damper_name);
  parts::impedance_table(page, *in.damper, *in.runs, in.constant_displacement);
  if (in.modes) {
    page.section("Linear modes");
    page.paragraph("The natural frequencies with every Jenkin element sticking (the messenger at EI_max) and every one "
                   "slipping (EI_min): the damper's resonances lie between the two, moving toward the slip ones as "
                   "the amplitude grows.");
    parts::modes_table(page, *in.modes);
  }
  page.section("Assumptions");
  page.list({"The clamp moves harmonically at the amplitude held over the sweep (the IEC 61897 / IEEE 664 shaker test); "
             "Z = F / V is the fundamental harmonic of the clamp force over the clamp velocity.",
             "The messenger is a quasi-static cantilever of Masing cross-sections (an elastic beam and Jenkin elements); "
             "the masses are rigid bodies."});
  page.section("Warnings");
  std::vector<std::string> warnings = context.warnings;
  for (const std::string& f : parts::sweep_failures(*in.runs, in.constant_displacement)) warnings.push_back(f);
  page.list(warnings, true);
  return page.html();
}

}  // namespace stockbridge::report
