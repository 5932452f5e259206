#include "stockbridge/requests/cycle_request.hpp"

#include <limits>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"

namespace stockbridge::requests {

cable::ExperimentDrive experiment_drive(const CycleRequest& request) {
  cable::ExperimentDrive drive;
  drive.experiment = cable::parse_experiment(request.experiment);
  drive.amplitude = request.amplitude;
  drive.cycles = request.cycles;
  drive.points = request.points;
  drive.validate();
  return drive;
}

namespace {

/// The cantilever is a small-deflection model: a tip deflection beyond 0.3 of the
/// length, or a rotation beyond 0.5 rad, is most often an amplitude in mm or degrees.
std::vector<Warning> drive_warnings(const cable::ExperimentDrive& drive, double length) {
  std::vector<Warning> out;
  if (drive.experiment == cable::Experiment::a && !typical::tip_deflection_ratio.contains(drive.amplitude / length)) {
    out.push_back({fmt::format("amplitude = {}: more than {} of the cable's length {} m, beyond the small deflections "
                               "the model assumes (a unit mistake? the amplitude of experiment (a) is in m)",
                               format_value(drive.amplitude), typical::tip_deflection_ratio.max, format_value(length)),
                   true});
  }
  if (drive.experiment == cable::Experiment::b && !typical::tip_rotation.contains(drive.amplitude)) {
    out.push_back({fmt::format("amplitude = {}: outside the typical 0 to {} rad of a tip rotation (a unit mistake? "
                               "the amplitude of experiment (b) is in rad)",
                               format_value(drive.amplitude), typical::tip_rotation.max),
                   true});
  }
  return out;
}

}  // namespace

CycleResult run_cycle(const cable::Cable& cable, const CycleRequest& request) {
  CycleResult out;
  out.drive = experiment_drive(request);
  out.warnings = drive_warnings(out.drive, cable.length());
  cable::Cantilever cantilever{cable};
  out.record = cable::run_experiment(cantilever, out.drive);
  return out;
}

std::vector<CycleSample> cycle_samples(const CycleResult& result) {
  std::vector<CycleSample> rows;
  for (std::size_t k = 0; k < result.record.samples.size(); ++k) rows.push_back({&result.record.samples[k], k});
  return rows;
}

namespace {

using CycleQuantity = Quantity<CycleSample>;

/// A number of a converged sample (NaN otherwise).
CycleQuantity solved(std::string name, std::string unit, std::string meaning,
                      double cable::ExperimentSample::*field) {
  return masked_quantity<CycleSample>(
      std::move(name), std::move(unit), std::move(meaning),
      [](const CycleSample& s) { return s.sample->solve.converged(); },
      [field](const CycleSample& s, std::size_t) { return s.sample->*field; });
}

}  // namespace

Table<CycleSample> cycle_table() {
  using S = cable::ExperimentSample;
  return Table<CycleSample>({
      {"step", "", "the sample k = 0 .. cycles x points", ColumnKind::count,
       [](const CycleSample& s, std::size_t) { return static_cast<double>(s.step); }, {}},
      solved("x_m", "m", "the tip deflection relative to the clamp (prescribed in (a), 0 in (b))", &S::deflection),
      solved("phi_rad", "rad", "the tip rotation (prescribed in (b))", &S::rotation),
      solved("force_n", "N", "the tip force F", &S::tip_force),
      solved("clamp_moment_n_m", "N m", "the moment at the clamp T = Q + F l", &S::clamp_moment),
      solved("tip_moment_n_m", "N m", "the tip moment Q (0 in (a))", &S::tip_moment),
      solved("dissipated_energy_j", "J", "what the sliders dissipated since the virgin state", &S::dissipated),
      {"newton_iterations", "", "of the sample's state determination", ColumnKind::count,
       [](const CycleSample& s, std::size_t) { return static_cast<double>(s.sample->solve.newton_iterations); }, {}},
      {"residual_rad", "rad", "the state determination's final residual", ColumnKind::number,
       [](const CycleSample& s, std::size_t) { return s.sample->solve.residual; }, {}},
      {"converged", "", "1 where the state determination converged, else 0", ColumnKind::flag,
       [](const CycleSample& s, std::size_t) { return s.sample->solve.converged() ? 1.0 : 0.0; }, {}},
  });
}

io::JsonObject cycle_summary(const CycleRequest& request, const CycleResult& result) {
  const cable::ExperimentSummary& s = result.record.summary;
  io::JsonObject json;
  json.add("experiment", request.experiment)
      .add("amplitude", request.amplitude)
      .add("cycles", request.cycles)
      .add("points", request.points)
      .add("last_cycle_dissipation_sliders_j", s.slider_dissipation)
      .add("last_cycle_dissipation_loop_j", s.loop_work)
      .add("last_cycle_measured_loop_area_j", s.measured_loop_area)
      .add("force_n", io::JsonObject().add("min", s.min_tip_force).add("max", s.max_tip_force))
      .add("clamp_moment_n_m", io::JsonObject().add("min", s.min_clamp_moment).add("max", s.max_clamp_moment))
      .add("x_m", io::JsonObject().add("min", s.min_deflection).add("max", s.max_deflection))
      .add("phi_rad", io::JsonObject().add("min", s.min_rotation).add("max", s.max_rotation))
      .add("newton_iterations", io::JsonObject().add("max", s.max_iterations).add("mean", s.mean_iterations))
      .add("failed_points", s.failed_samples)
      .add("warnings", warning_messages(result.warnings));
  return json;
}

}  // namespace stockbridge::requests
