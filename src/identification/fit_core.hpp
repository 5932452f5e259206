#pragma once
// What the local and the global identification share (private to the library):
// the relative L1 misfit along a measured path, the packing of Masing parameters
// and a constant output offset into the optimiser's variables, and the NLopt
// search from several starts.
//
// Both fits compare a model output y_model (moment, tip force or clamp moment, the
// offset already added) with the measured y along the prescribed path p (curvature,
// deflection or rotation), by the trapezoid rule over the samples:
//     error = sum |y_model - y| |dp|,  reference = sum |y| |dp|.

#include <cstddef>
#include <functional>
#include <cmath>
#include <limits>
#include <string_view>
#include <vector>

#include "stockbridge/identification/local_identification.hpp"
#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/cable/section_law_descriptor.hpp"
#include "stockbridge/section/bouc_wen_section.hpp"
#include "stockbridge/section/masing_law.hpp"

namespace stockbridge::identification::fit_core {

/// The misfit's two sums (see above).
struct L1Sums {
  double error = 0.0;
  double reference = 0.0;
  double relative() const { return error / reference; }
};

/// The sums over the intervals between samples `from` and `to` - 1 (to <= size of
/// every vector). A NaN model output inside them makes the error NaN.
L1Sums l1_sums(const std::vector<double>& path, const std::vector<double>& measured,
               const std::vector<double>& model, std::size_t from, std::size_t to);

/// error / reference from sample `from` to the end; +infinity if any model output
/// is NaN (a model state that could not be determined), wherever it lies.
double relative_l1_misfit(const std::vector<double>& path, const std::vector<double>& measured,
                          const std::vector<double>& model, std::size_t from);

/// The reversals of the path (reversals()), after checking that path and measured
/// have the same size and that there are at least three (a full cycle after the
/// first extreme); throws InvalidParameter otherwise. The names go into the
/// messages: "record: 5 <path_values> but 4 <measured_values>", "record: 2
/// reversals of <path>: ...".
struct RecordNames {
  std::string_view path_values;
  std::string_view measured_values;
  std::string_view path;
};
std::vector<std::size_t> checked_reversals(const std::vector<double>& path, const std::vector<double>& measured,
                                           const RecordNames& names);

/// ei and `elements` Jenkin elements sharing c_total equally and h_total in the
/// proportions 1 : 2 : ... : elements (distinct slip curvatures: a start where the
/// elements coincide would keep them together).
section::MasingParameters spread_over_elements(double ei, double c_total, double h_total, int elements);

/// The elements in order of their slip curvature h / c (as both fits report them).
section::MasingParameters sorted_by_slip_curvature(section::MasingParameters parameters);

/// The optimiser's variables: log ei, log c and log h of each element (so that the
/// parameters stay positive), then the constant offset in units of offset_scale
/// (> 0, the output's magnitude: every variable is of order one).
class LogParameters {
 public:
  LogParameters(int elements, double offset_scale);
  std::vector<double> pack(const section::MasingParameters& parameters, double offset) const;
  /// The elements in the packed order (the model's sums depend on it).
  section::MasingParameters parameters(const std::vector<double>& x) const;
  double offset(const std::vector<double>& x) const;

 private:
  int elements_;
  double offset_scale_;
};

/// A law of numbers' variables (SectionLawDescriptor::pack) and the offset, in units of `offset_scale`.
struct LawLogParameters {
  const cable::SectionLawDescriptor* law = nullptr;
  double offset_scale = 1.0;
  std::vector<double> pack(const std::vector<double>& values, double offset) const {
    std::vector<double> x = law->pack(values);
    x.push_back(offset / offset_scale);
    return x;
  }
  std::vector<double> parameters(const std::vector<double>& x) const {
    return law->unpack(std::vector<double>(x.begin(), x.end() - 1));
  }
  double offset(const std::vector<double>& x) const { return x.back() * offset_scale; }
};

/// One optimisation's settings (NLopt's derivative-free Subplex or Nelder-Mead).
struct SearchSettings {
  Optimizer optimizer = Optimizer::subplex;
  double tolerance = 1e-10;   ///< relative change of x at which a run stops
  int max_evaluations = 1000; ///< per run
  double initial_step = 0.1;  ///< in every variable
};

/// A point and the objective's value there.
struct Minimum {
  std::vector<double> x;
  double value = std::numeric_limits<double>::infinity();
  /// How the NLopt run that reached it ended: converged (the step or the change of
  /// the objective fell below the tolerance), max_iterations (its evaluations used
  /// up), no_progress (stopped by round-off), inner_failure (NLopt failed).
  Termination termination = Termination::not_run;
};

/// Minimises an objective of the packed variables with NLopt, counting evaluations
/// and runs. The objective is evaluated only where every variable is finite and
/// at most `variable_limit` in magnitude (beyond, exp overflows the model); there,
/// and where the objective is not finite, NLopt sees `penalty`.
///
/// Exceptions: NLopt's round-off limit and a forced stop (which the objective may
/// ask for by throwing nlopt::forced_stop) end a run with its best point. Any other
/// exception, from the objective (library errors, std::bad_alloc) or from NLopt
/// (std::invalid_argument, std::bad_alloc, its generic failure), propagates unchanged.
class Search {
 public:
  static constexpr double variable_limit = 60.0;
  static constexpr double penalty = 1e300;
  using Objective = std::function<double(const std::vector<double>& x)>;

  explicit Search(Objective objective);

  /// One NLopt run from x.
  Minimum run(std::vector<double> x, const SearchSettings& settings);
  /// A run from every start; the best point.
  Minimum from_each(const std::vector<std::vector<double>>& starts, const SearchSettings& settings);
  /// `times` further runs, each from the best point so far, which they replace
  /// when better (a restart escapes a simplex that collapsed on the way).
  Minimum restarted(Minimum best, int times, const SearchSettings& settings);

  /// The value NLopt sees at x (counted as an evaluation).
  double evaluate(const std::vector<double>& x);
  int evaluations() const { return evaluations_; }
  int runs() const { return runs_; }

 private:
  Objective objective_;
  int evaluations_ = 0;
  int runs_ = 0;
};

}  // namespace stockbridge::identification::fit_core
