#include "stockbridge/identification/impedance_identification.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "fit_core.hpp"
#include "impedance_fit_statistics.hpp"
#include "impedance_fit_variables.hpp"
#include "least_squares.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/core/parallel.hpp"
#include "stockbridge/damper/damper_numbers.hpp"

namespace stockbridge::identification {

namespace {

using namespace impedance_fit;

/// Each point's solution (a tracker's checkpoint, one path per distinct arm), and
/// which arms were distinct: a fitted mass or length can make arms alike or apart,
/// and a checkpoint warm-starts only a damper with the same distinct arms.
struct Checkpoints {
  std::vector<damper::DamperTracker::Checkpoint> points;
  std::vector<std::size_t> distinct;
};

/// The model at every measured point. Each curve is solved from `warm` where given
/// (per point, the solution there for nearby parameters: a Newton step or two,
/// where following the curve from its first frequency takes substeps near every
/// resonance), else, or where a point fails from it, along the curve in frequency
/// order. `solutions` (if given) receives each point's solution, to warm-start the
/// next parameters (empty where it did not converge).
std::vector<damper::ImpedancePoint> solve_points(const damper::Damper& damper, const ImpedanceMeasurement& m,
                                                 const damper::SolverOptions& solver, const Checkpoints* warm,
                                                 Checkpoints* solutions) {
  std::vector<damper::ImpedancePoint> points(m.points.size());
  if (solutions) *solutions = {std::vector<damper::DamperTracker::Checkpoint>(m.points.size()), damper.distinct()};
  auto keep = [&](damper::DamperTracker& tracker, std::size_t i) {
    if (solutions && points[i].converged()) solutions->points[i] = tracker.checkpoint();
  };
  for (const std::vector<std::size_t>& curve : measured_curves(m)) {
    damper::DamperTracker tracker(damper, solver, m.held);
    bool warm_started = warm && warm->points.size() == m.points.size() && warm->distinct == damper.distinct() &&
                        std::all_of(curve.begin(), curve.end(), [&](std::size_t i) { return !warm->points[i].empty(); });
    for (std::size_t k = 0; k < curve.size() && warm_started; ++k) {
      tracker.restore(warm->points[curve[k]]);
      points[curve[k]] = tracker.solve(m.points[curve[k]].excitation);
      warm_started = points[curve[k]].converged();
      keep(tracker, curve[k]);
    }
    if (warm_started) continue;
    damper::DamperTracker along(damper, solver, m.held);
    for (const std::size_t i : curve) {
      points[i] = along.solve(m.points[i].excitation);
      keep(along, i);
    }
  }
  return points;
}

/// The model at one point of the variables: the residuals, where it converged, and
/// its solutions (to warm-start nearby points).
struct Evaluation {
  Eigen::VectorXd x;
  Eigen::VectorXd residuals;
  std::vector<bool> converged;
  Checkpoints solutions;
};

/// The relative complex residuals of the model's Z against the measured one (Z = 0
/// where the model did not converge).
class ImpedanceProblem : public least_squares::Problem {
 public:
  /// The model's cables have at most `max_sections` sections.
  ImpedanceProblem(const FitVariables& variables, const ImpedanceMeasurement& measurement,
                   const ImpedanceIdentificationOptions& options, int max_sections = cable::max_sections)
      : variables_(variables), measurement_(measurement), options_(options), max_sections_(max_sections) {}

  int variables() const override { return variables_.size(); }
  int residual_count() const override { return 2 * static_cast<int>(measurement_.points.size()); }

  /// Levenberg-Marquardt's points are warm-started from the best so far (its
  /// current iterate), the Jacobian's columns from the point they differentiate at
  /// (on `threads` threads: the columns are independent model runs).
  Eigen::VectorXd residuals(const Eigen::VectorXd& x) override { return evaluated(x).residuals; }
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x) override {
    const Evaluation at = evaluated(x);
    Eigen::MatrixXd jacobian(residual_count(), variables());
    std::vector<int> columns(static_cast<std::size_t>(variables()));
    std::iota(columns.begin(), columns.end(), 0);
    if (variables_.fits_clamp_mass()) {
      jacobian.col(variables_.clamp_mass_index()) = clamp_mass_column(at);
      columns.pop_back();
    }
    run_in_parallel(columns.size(), [&](std::size_t k) {
      Eigen::VectorXd shifted = x;
      shifted(columns[k]) += kDifferenceStep;
      jacobian.col(columns[k]) = (evaluate(shifted, &at).residuals - at.residuals) / kDifferenceStep;
    });
    return jacobian;
  }

  /// The Jacobian columns, at x, of numbers of the damper the variables keep fixed:
  /// dr/dq for each number's variable q as `free` would fit it (DamperNumber), by the
  /// same forward differences as jacobian()'s (on `threads` threads), then where
  /// `clamp_mass` the clamp mass's (analytic, per the damper's mass).
  Eigen::MatrixXd fixed_number_columns(const Eigen::VectorXd& x, const std::vector<DamperNumber>& numbers, bool clamp_mass) {
    const Evaluation at = evaluated(x);
    Eigen::MatrixXd columns(residual_count(), static_cast<Eigen::Index>(numbers.size()) + (clamp_mass ? 1 : 0));
    run_in_parallel(numbers.size(), [&](std::size_t k) {
      const Change change{numbers[k].path, numbers[k].value(kDifferenceStep)};
      columns.col(static_cast<Eigen::Index>(k)) = (evaluate(x, &at, &change).residuals - at.residuals) / kDifferenceStep;
    });
    if (clamp_mass) columns.col(columns.cols() - 1) = clamp_mass_column(at);
    return columns;
  }

  /// The model's points (with the clamp mass) at x; converged() false where it did not converge.
  std::vector<damper::ImpedancePoint> points(const Eigen::VectorXd& x) const {
    const damper::DamperDescription description =
        variables_.damper(x, std::max(0.0, variables_.clamp_mass(x)), max_sections_);
    const Evaluation* warm = best_recent();
    return solve_points(damper::Damper(description), measurement_, options_.solver, warm ? &warm->solutions : nullptr,
                        nullptr);
  }

  int evaluations() const { return evaluations_.load(); }

 private:
  /// A number of the damper set apart from the variables' (a fixed number's column).
  struct Change {
    std::string path;
    double value = 0.0;
  };

  /// The model with the clamp mass left out (it is added as i W m_c, which may then
  /// be negative), with `change` made to the damper if given.
  Evaluation evaluate(const Eigen::VectorXd& x, const Evaluation* warm, const Change* change = nullptr) {
    ++evaluations_;
    const std::size_t n = measurement_.points.size();
    Evaluation e{x, Eigen::VectorXd(2 * n), std::vector<bool>(n, false), {}};
    std::vector<damper::ImpedancePoint> arms;
    if (x.cwiseAbs().maxCoeff() <= fit_core::Search::variable_limit) {
      try {
        damper::DamperDescription description = variables_.damper(x, 0.0, max_sections_);
        if (change) damper::set_damper_number(description, change->path, change->value);
        arms = solve_points(damper::Damper(description), measurement_, options_.solver,
                            warm ? &warm->solutions : nullptr, &e.solutions);
      } catch (const InvalidParameter&) {
        arms.clear();  // parameters the model does not accept (overflowed)
      }
    }
    if (arms.empty()) {
      e.residuals.setConstant(kRejected);
      return e;
    }
    const double clamp_mass = variables_.clamp_mass(x);
    for (std::size_t i = 0; i < n; ++i) {
      const MeasuredImpedance& m = measurement_.points[i];
      std::complex<double> z = 0.0;
      if (arms[i].converged()) {
        z = arms[i].impedance + std::complex<double>(0.0, m.excitation.angular_frequency() * clamp_mass);
        e.converged[i] = true;
      }
      const std::complex<double> r = (z - m.impedance) / std::abs(m.impedance);
      e.residuals(2 * i) = r.real();
      e.residuals(2 * i + 1) = r.imag();
    }
    return e;
  }

  /// dr/dx of the clamp-mass variable: i W (mass scale) / |Z| where the model converged.
  Eigen::VectorXd clamp_mass_column(const Evaluation& at) const {
    Eigen::VectorXd column = Eigen::VectorXd::Zero(residual_count());
    for (std::size_t i = 0; i < measurement_.points.size(); ++i) {
      const MeasuredImpedance& m = measurement_.points[i];
      if (at.converged[i]) {
        column(2 * i + 1) = m.excitation.angular_frequency() * variables_.mass_scale() / std::abs(m.impedance);
      }
    }
    return column;
  }

  /// The evaluation at x: Levenberg-Marquardt asks for the Jacobian at its best point,
  /// which need not be the last one evaluated, so the last few are kept.
  Evaluation evaluated(const Eigen::VectorXd& x) {
    for (const Evaluation& e : recent_) {
      if (e.x == x) return e;
    }
    Evaluation e = evaluate(x, best_recent());
    if (recent_.size() == 4) recent_.erase(recent_.begin());
    recent_.push_back(e);
    return e;
  }

  /// The kept evaluation with the smallest residuals (none at first).
  const Evaluation* best_recent() const {
    const Evaluation* best = nullptr;
    for (const Evaluation& e : recent_) {
      if (!best || e.residuals.squaredNorm() < best->residuals.squaredNorm()) best = &e;
    }
    return best;
  }

  template <class Task>
  void run_in_parallel(std::size_t count, Task task) const {
    parallel_for(count, options_.threads, task);
  }

  const FitVariables& variables_;
  const ImpedanceMeasurement& measurement_;
  const ImpedanceIdentificationOptions& options_;
  int max_sections_;
  std::vector<Evaluation> recent_;
  std::atomic<int> evaluations_{0};
};

}  // namespace

std::vector<std::size_t> cable_types(const damper::DamperDescription& d) {
  std::vector<std::size_t> type(d.arms.size());
  std::vector<std::size_t> first_of_type;
  for (std::size_t k = 0; k < d.arms.size(); ++k) {
    const cable::CableDescription& c = d.arms[k].cable;
    auto same = [&](std::size_t f) {
      const cable::CableDescription& first = d.arms[f].cable;
      return first.law == c.law && first.ei == c.ei && first.jenkin == c.jenkin && first.numbers == c.numbers;
    };
    const auto found = std::find_if(first_of_type.begin(), first_of_type.end(), same);
    type[k] = static_cast<std::size_t>(found - first_of_type.begin());
    if (found == first_of_type.end()) first_of_type.push_back(k);
  }
  return type;
}

void ImpedanceIdentificationOptions::validate() const {
  require_in_range("elements", elements, 1, 6);
  require_in_range("max_jacobians", max_jacobians, 1, 10000);
  require_in_range("threads", threads, 1, 1024);
  if (!(std::isfinite(rms_limit) && rms_limit > 0.0)) {
    throw_invalid("rms_limit", rms_limit, "a finite fraction > 0 (0.1 for 10 %)");
  }
  if (scatter && !(std::isfinite(*scatter) && *scatter > 0.0 && *scatter < 1.0)) {
    throw_invalid("scatter", *scatter, "a fraction of |Z| > 0 and < 1 (0.01 for 1 %)");
  }
  solver.validate();
}

std::vector<damper::ImpedancePoint> model_impedance(const damper::Damper& damper, const ImpedanceMeasurement& m,
                                                    const damper::SolverOptions& solver) {
  return solve_points(damper, m, solver, nullptr, nullptr);
}

ImpedanceIdentification identify_impedance(const damper::DamperDescription& start, const ImpedanceMeasurement& measurement,
                                           const ImpedanceIdentificationOptions& options) {
  options.validate();
  measurement.validate();
  (void)damper::Damper(start);  // validates the start, naming its fields
  const FitVariables variables(start, options);
  if (2 * measurement.points.size() < static_cast<std::size_t>(variables.size())) {
    throw InvalidParameter("measurement", fmt::format(": {} points for {} parameters: expected at least {}",
                                       measurement.points.size(), variables.size(), (variables.size() + 1) / 2));
  }
  ImpedanceIdentificationOptions converged = options;
  for (damper::HarmonicBalanceOptions* o : {&converged.solver.harmonic_balance, &converged.solver.collocation}) {
    o->tolerance = std::min(o->tolerance, kModelTolerance);
    o->periodicity_tolerance = std::min(o->periodicity_tolerance, kModelTolerance);
  }
  ImpedanceProblem coarse(variables, measurement, converged, kExploreSections);
  ImpedanceProblem problem(variables, measurement, converged);

  // Each start explored briefly on coarse cables, the best polished to convergence.
  // The first start's run is kept whatever its misfit, so that a misfit that is not
  // finite at every start (no run better than another) still polishes a start rather
  // than an empty point.
  least_squares::Run best;
  int starts = 0;
  for (const Eigen::VectorXd& x : variables.starts()) {
    least_squares::Run run = least_squares::levenberg_marquardt(coarse, x, std::min(kExploreJacobians, options.max_jacobians));
    ++starts;
    if (starts == 1 || run.sum_of_squares < best.sum_of_squares) best = std::move(run);
    if (std::sqrt(best.sum_of_squares / measurement.points.size()) < kReproducedError) break;
  }
  best = least_squares::levenberg_marquardt(problem, best.x, options.max_jacobians);

  const Eigen::VectorXd x = variables.sorted(best.x);
  const double sum_of_squares = problem.residuals(x).squaredNorm();
  // The damper's exact scalings (FitVariables::scalings) are null directions of the
  // Jacobian, which its forward differences would blur into a small but finite
  // singular value: they are projected out, so that the statistics see them exactly.
  Eigen::MatrixXd jacobian = problem.jacobian(x);
  const std::vector<Eigen::VectorXd> scalings = variables.scalings(x);
  for (const Eigen::VectorXd& g : scalings) jacobian -= (jacobian * g) * g.transpose();  // disjoint supports: orthogonal
  // The standard errors at the stated scatter per real residual (s / sqrt(2)), or at
  // the residuals' own where larger (a lack of fit inflates them).
  const double scatter = options.scatter.value_or(default_scatter);
  const double component_scatter = scatter / std::sqrt(2.0);
  const least_squares::Statistics statistics =
      least_squares::statistics(jacobian, sum_of_squares, kStatedScatter, component_scatter);

  ImpedanceIdentification result;
  result.cable_type = variables.type_of_arm();
  result.law = variables.law();
  result.cables = variables.cables(x);
  result.law_cables = variables.law_cables(x);
  result.clamp_mass = variables.clamp_mass(x);
  result.damper = variables.damper(x, std::max(0.0, result.clamp_mass));
  result.misfit = sum_of_squares;
  result.rms_relative_error = std::sqrt(sum_of_squares / static_cast<double>(measurement.points.size()));
  result.rms_limit = options.rms_limit;
  result.poor_fit = result.rms_relative_error > options.rms_limit;
  result.parameters = estimates(variables, x, statistics);
  result.lack_of_fit = lack_of_fit(statistics, sum_of_squares, result.rms_relative_error, scatter, !options.scatter.has_value(),
                                   static_cast<int>(jacobian.rows()));
  result.correlation = statistics.correlation;
  result.stick_stiffness = stick_stiffnesses(variables, x, statistics);
  result.fitted = problem.points(x);
  result.not_converged = static_cast<int>(
      std::count_if(result.fitted.begin(), result.fitted.end(), [](const damper::ImpedancePoint& p) { return !p.converged(); }));
  result.notes = determination_notes(result.parameters, statistics, result.stick_stiffness, result.fitted);
  if (!scalings.empty()) {
    result.notes.push_back(fmt::format(
        "a damper scaled by any s (cable lengths and offsets times s, inertias times s^2, {}) has the same impedance: "
        "the data do not determine its size; fix one arm's inertia, cable length or (nonzero) offset at the drawing's "
        "value (leave it out of free)",
        variables.numbered() ? scaling_words(*variables.law()) : "ei and c times s^3, h times s"));
  }
  if (result.lack_of_fit.significant) {
    const Eigen::VectorXd residuals = problem.residuals(x);
    const std::vector<DamperNumber> fixed = fixed_numbers(start, variables.numbers());
    const bool clamp_mass = !variables.fits_clamp_mass();
    const Eigen::MatrixXd columns = problem.fixed_number_columns(x, fixed, clamp_mass);
    std::vector<least_squares::ExtraVariable> steps;
    for (Eigen::Index k = 0; k < columns.cols(); ++k) {
      least_squares::ExtraVariable step = least_squares::extra_variable(jacobian, residuals, columns.col(k));
      FixedNumberSuspect suspect;
      if (k < static_cast<Eigen::Index>(fixed.size())) {
        const DamperNumber& n = fixed[static_cast<std::size_t>(k)];
        suspect = {n.path, n.unit, n.start, 0.0, n.value(step.step)};
      } else {
        suspect = {"clamp.mass", "kg", start.clamp_mass, 0.0, start.clamp_mass + variables.mass_scale() * step.step};
      }
      suspect.misfit_reduction = sum_of_squares > 0.0 ? std::min(1.0, step.reduction / sum_of_squares) : 0.0;
      result.lack_of_fit.suspects.push_back(suspect);
      steps.push_back(std::move(step));
    }
    std::vector<std::size_t> order(steps.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return result.lack_of_fit.suspects[a].misfit_reduction > result.lack_of_fit.suspects[b].misfit_reduction;
    });
    std::vector<FixedNumberSuspect> ranked;
    std::vector<least_squares::ExtraVariable> ranked_steps;
    for (const std::size_t k : order) {
      ranked.push_back(result.lack_of_fit.suspects[k]);
      ranked_steps.push_back(steps[k]);
    }
    result.lack_of_fit.suspects = std::move(ranked);
    result.lack_of_fit.notes =
        confounding_notes(variables, x, statistics, result.lack_of_fit.suspects, ranked_steps, result.parameters);
  }
  result.fit = best.summary;
  if (!best.summary.converged()) {
    result.notes.push_back(fmt::format("the fit stopped short of its tolerance after {} iterations ({}): the estimates are "
                                       "the best point reached",
                                       best.jacobians, termination_name(best.summary.termination)));
  }
  result.model_evaluations = coarse.evaluations() + problem.evaluations() + 1;
  result.starts = starts;
  return result;
}

}  // namespace stockbridge::identification
