#include "stockbridge/requests/response_request.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stockbridge/requests/plausibility.hpp"
#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::requests {

void validate(const ResponseRequest& request) {
  (void)excitation(request.frequency, request.velocity, request.displacement);
  (void)solver_options(request.solver);
}

ResponseResult run_response(const damper::Damper& damper, const ResponseRequest& request) {
  ResponseResult out;
  out.excitation = excitation(request.frequency, request.velocity, request.displacement);
  const damper::SolverOptions options = solver_options(request.solver);
  out.warnings = setting_warnings(unusual_excitation(request.frequency, request.velocity, request.displacement));
  out.state = damper::solve_steady_state(damper, out.excitation, options);
  Eigen::Index n = 0;
  std::vector<const damper::ArmSolution*> arms;
  for (const damper::ArmSolution& s : out.state.arms) {
    arms.push_back(&s);
    n = std::max(n, s.period.loads.cols());
  }
  out.time = damper::time_grid(out.excitation, static_cast<int>(n));
  // The last iterate's force too, where every arm has a period of n samples.
  const Eigen::RowVectorXd force = damper::shaker_force(damper, out.excitation, arms);
  out.shaker_force.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::quiet_NaN());
  if (force.size() == n) out.shaker_force.assign(force.data(), force.data() + force.size());
  return out;
}

std::vector<ResponseSample> response_samples(const ResponseResult& result) {
  std::vector<ResponseSample> samples;
  for (std::size_t j = 0; j < result.time.size(); ++j) samples.push_back({&result, j});
  return samples;
}

namespace {

using Sample = ResponseSample;
using ResponseQuantity = Quantity<Sample>;

/// A per-arm quantity of the arm's period at the sample (NaN where the arm's period is shorter).
template <class Read>
ResponseQuantity per_arm(std::string name, std::string unit, std::string meaning, Read read) {
  return {std::move(name), std::move(unit), std::move(meaning), ColumnKind::number,
          [read](const Sample& s, std::size_t k) {
            const damper::ArmPeriod& p = s.result->state.arms.at(k).period;
            const auto j = static_cast<Eigen::Index>(s.j);
            return j < p.loads.cols() ? read(p, j) : kNoValue;
          },
          {}};
}

}  // namespace

Table<Sample> response_table(const damper::Damper& damper) {
  const auto clamp = [](const Sample& s) {
    const damper::Excitation& e = s.result->excitation;
    return std::pair{e.angular_frequency() * s.result->time[s.j], e.displacement_amplitude};
  };
  std::vector<ResponseQuantity> q{
      {"time_s", "s", "t_j = j T / N of one steady period", ColumnKind::number,
       [](const Sample& s, std::size_t) { return s.result->time[s.j]; }, {}},
      {"clamp_displacement_m", "m", "the clamp's motion x_c = X sin(W t)", ColumnKind::number,
       [clamp](const Sample& s, std::size_t) {
         const auto [phase, x] = clamp(s);
         return x * std::sin(phase);
       },
       {}},
      {"clamp_velocity_m_s", "m/s", "its velocity W X cos(W t)", ColumnKind::number,
       [clamp](const Sample& s, std::size_t) {
         const auto [phase, x] = clamp(s);
         return s.result->excitation.angular_frequency() * x * std::cos(phase);
       },
       {}},
      {"shaker_force_n", "N", "the force the shaker applies, m_c x_c'' - sum F_k (empty unless every arm has a period)",
       ColumnKind::number, [](const Sample& s, std::size_t) { return s.result->shaker_force[s.j]; }, {}},
      per_arm("<arm>_x_m", "m", "the arm's tip deflection x relative to the clamp",
              [](const damper::ArmPeriod& p, Eigen::Index j) { return p.kinematics(0, j); }),
      per_arm("<arm>_phi_rad", "rad", "its tip rotation phi",
              [](const damper::ArmPeriod& p, Eigen::Index j) { return p.kinematics(1, j); }),
      per_arm("<arm>_force_n", "N", "the cable's tip force F",
              [](const damper::ArmPeriod& p, Eigen::Index j) { return p.loads(0, j); }),
      per_arm("<arm>_clamp_moment_n_m", "N m", "the cable's moment at the clamp T = Q + F l",
              [](const damper::ArmPeriod& p, Eigen::Index j) { return p.clamp_moment[static_cast<std::size_t>(j)]; }),
      per_arm("<arm>_tip_moment_n_m", "N m", "the cable's tip moment Q",
              [](const damper::ArmPeriod& p, Eigen::Index j) { return p.loads(1, j); }),
      per_arm("<arm>_clamp_curvature_per_m", "1/m", "the curvature at the integration point nearest the clamp",
              [](const damper::ArmPeriod& p, Eigen::Index j) { return p.clamp_curvature[static_cast<std::size_t>(j)]; }),
      per_arm("<arm>_clamp_section_moment_n_m", "N m", "the bending moment there, T - F s_0 (its hysteresis loop against the curvature)",
              [](const damper::ArmPeriod& p, Eigen::Index j) {
                return p.clamp_section_moment[static_cast<std::size_t>(j)];
              }),
      {"converged", "", "1 where the point converged, 0 where the rows hold the last iterate (the same in every row)",
       ColumnKind::flag, [](const Sample& s, std::size_t) { return s.result->state.point.converged() ? 1.0 : 0.0; },
       {}},
  };
  return Table<Sample>(std::move(q), {{"<arm>", arm_column_prefixes(damper)}});
}

io::JsonObject response_summary(const damper::Damper& damper, const ResponseResult& result) {
  return point_summary_table(damper).values(result.state.point).json_row(0).add("warnings",
                                                                               warning_messages(result.warnings));
}

}  // namespace stockbridge::requests
