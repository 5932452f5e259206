// The identification core (src/identification/fit_core.hpp, private): the L1 misfit
// on a hand-computed record, the parameter packing, and the NLopt search: it finds
// minima, keeps the best of several starts, keeps its best point when NLopt is
// stopped, and lets every other exception through with its type.

#include "identification/fit_core.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlopt.hpp>

#include "stockbridge/core/error.hpp"

namespace stockbridge::identification::fit_core {
namespace {

// Path 0, 1, 3, 2; residuals 0, 1, 0, 0: the intervals give error 0.5 + 1 + 0 and
// reference 0.5 + 3 + 1.5.
const std::vector<double> kPath{0.0, 1.0, 3.0, 2.0};
const std::vector<double> kMeasured{0.0, 1.0, 2.0, 1.0};
const std::vector<double> kModel{0.0, 2.0, 2.0, 1.0};

TEST(IdentificationCore, L1SumsFollowThePathByTheTrapezoidRule) {
  const L1Sums all = l1_sums(kPath, kMeasured, kModel, 0, 4);
  EXPECT_DOUBLE_EQ(all.error, 1.5);
  EXPECT_DOUBLE_EQ(all.reference, 5.0);
  const L1Sums from_second = l1_sums(kPath, kMeasured, kModel, 1, 4);  // the first interval left out
  EXPECT_DOUBLE_EQ(from_second.error, 1.0);
  EXPECT_DOUBLE_EQ(from_second.reference, 4.5);
  EXPECT_DOUBLE_EQ(l1_sums(kPath, kMeasured, kModel, 0, 2).reference, 0.5);  // `to` excluded
  EXPECT_DOUBLE_EQ(relative_l1_misfit(kPath, kMeasured, kModel, 0), 0.3);
}

TEST(IdentificationCore, AnUndeterminedModelOutputMakesTheMisfitInfinite) {
  std::vector<double> model = kModel;
  model[0] = std::numeric_limits<double>::quiet_NaN();  // before `from`: still counts
  EXPECT_EQ(relative_l1_misfit(kPath, kMeasured, model, 1), std::numeric_limits<double>::infinity());
}

TEST(IdentificationCore, CheckedReversalsNameTheRecordsQuantities) {
  const RecordNames names{"curvatures", "moments", "the curvature"};
  const std::vector<double> cycle{0.0, 1.0, 0.0, -1.0, 0.0, 1.0, 0.0};  // reversals at 1, 3, 5
  EXPECT_EQ(checked_reversals(cycle, cycle, names), (std::vector<std::size_t>{1, 3, 5}));
  try {
    checked_reversals(cycle, {1.0}, names);
    ADD_FAILURE() << "sizes that differ accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_STREQ(e.what(), "record: 7 curvatures but 1 moments");
  }
  EXPECT_THROW(checked_reversals({0.0, 1.0, 0.0, -1.0}, {0.0, 1.0, 0.0, -1.0}, names), InvalidParameter);
}

TEST(IdentificationCore, ElementsShareTheTotalsWithDistinctSlipCurvatures) {
  const section::MasingParameters p = spread_over_elements(2.0, 30.0, 1.2, 3);
  EXPECT_EQ(p.ei, 2.0);
  ASSERT_EQ(p.jenkin.size(), 3u);
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_DOUBLE_EQ(p.jenkin[j].c, 10.0);
    EXPECT_DOUBLE_EQ(p.jenkin[j].h, 0.2 * static_cast<double>(j + 1));  // 1 : 2 : 3 of 1.2
  }
  const section::MasingParameters sorted = sorted_by_slip_curvature({1.0, {{10.0, 2.0}, {10.0, 0.5}, {1.0, 1.0}}});
  EXPECT_EQ(sorted.jenkin[0].h, 0.5);  // h / c = 0.05, 0.2, 1
  EXPECT_EQ(sorted.jenkin[1].h, 2.0);
  EXPECT_EQ(sorted.jenkin[2].h, 1.0);
}

TEST(IdentificationCore, LogParametersRoundTripAndScaleTheOffset) {
  const LogParameters packing(2, 4.0);
  const section::MasingParameters p{2.8, {{60.0, 0.2}, {20.0, 0.7}}};
  const std::vector<double> x = packing.pack(p, -1.0);
  ASSERT_EQ(x.size(), 6u);
  EXPECT_DOUBLE_EQ(x[0], std::log(2.8));
  EXPECT_DOUBLE_EQ(x[5], -0.25);
  const section::MasingParameters back = packing.parameters(x);
  EXPECT_NEAR(back.ei, 2.8, 1e-14);
  ASSERT_EQ(back.jenkin.size(), 2u);
  EXPECT_NEAR(back.jenkin[0].c, 60.0, 1e-12);  // packed order kept
  EXPECT_NEAR(back.jenkin[1].h, 0.7, 1e-14);
  EXPECT_DOUBLE_EQ(packing.offset(x), -1.0);
}

/// (x0 - 1)^2 + (x1 + 2)^2: minimum 0 at (1, -2).
double bowl(const std::vector<double>& x) { return (x[0] - 1.0) * (x[0] - 1.0) + (x[1] + 2.0) * (x[1] + 2.0); }

SearchSettings settings(Optimizer optimizer = Optimizer::subplex) {
  SearchSettings s;
  s.optimizer = optimizer;
  s.tolerance = 1e-12;
  s.max_evaluations = 4000;
  s.initial_step = 0.5;
  return s;
}

TEST(IdentificationCore, BothOptimizersFindTheMinimum) {
  for (const Optimizer optimizer : {Optimizer::subplex, Optimizer::nelder_mead}) {
    Search search(bowl);
    const Minimum m = search.run({0.0, 0.0}, settings(optimizer));
    EXPECT_NEAR(m.x[0], 1.0, 1e-5);
    EXPECT_NEAR(m.x[1], -2.0, 1e-5);
    EXPECT_EQ(m.value, bowl(m.x));
    EXPECT_EQ(search.runs(), 1);
    EXPECT_GT(search.evaluations(), 10);
    EXPECT_EQ(m.termination, Termination::converged);
  }
}

// How a run ended is kept with its minimum: out of evaluations is not converged.
TEST(IdentificationCore, ARunOutOfEvaluationsSaysSo) {
  SearchSettings few = settings();
  few.max_evaluations = 5;
  const Minimum m = Search(bowl).run({0.0, 0.0}, few);
  EXPECT_EQ(m.termination, Termination::max_iterations);
  EXPECT_GT(m.value, 1e-3);  // far from the minimum at (1, -2)
}

TEST(IdentificationCore, TheBestOfSeveralStartsWinsAndRestartsNeverLoseIt) {
  // Two basins: x = -3 (value 0.5) and x = 1 (value 0); from -3.2 the search stays in the worse.
  Search search([](const std::vector<double>& x) {
    return std::min((x[0] + 3.0) * (x[0] + 3.0) + 0.5, 4.0 * (x[0] - 1.0) * (x[0] - 1.0));
  });
  SearchSettings s = settings();
  s.initial_step = 0.1;
  const Minimum worse = search.run({-3.2}, s);
  EXPECT_NEAR(worse.x[0], -3.0, 1e-5);
  const Minimum best = search.from_each({{-3.2}, {0.8}, {-2.9}}, s);
  EXPECT_NEAR(best.x[0], 1.0, 1e-5);
  EXPECT_LT(best.value, 1e-9);
  const Minimum again = search.restarted(best, 2, s);
  EXPECT_LE(again.value, best.value);
  EXPECT_EQ(search.runs(), 1 + 3 + 2);
}

TEST(IdentificationCore, PointsOutsideTheLimitsAndUndefinedValuesArePenalised) {
  int calls = 0;
  Search search([&](const std::vector<double>& x) {
    ++calls;
    return x[0] > 1.0 ? std::numeric_limits<double>::quiet_NaN() : x[0];
  });
  EXPECT_EQ(search.evaluate({Search::variable_limit + 1.0}), Search::penalty);
  EXPECT_EQ(search.evaluate({std::numeric_limits<double>::quiet_NaN()}), Search::penalty);
  EXPECT_EQ(calls, 0);  // the objective never sees them
  EXPECT_EQ(search.evaluate({2.0}), Search::penalty);
  EXPECT_EQ(search.evaluate({0.5}), 0.5);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(search.evaluations(), 4);
}

/// The bowl, throwing `E` at the `at`-th evaluation (once), and remembering the
/// lowest value it returned before.
template <class E>
struct FailingBowl {
  FailingBowl(int at_call, E thrown) : at(at_call), error(std::move(thrown)) {}
  int at;
  E error;
  int calls = 0;
  double lowest = std::numeric_limits<double>::infinity();
  std::vector<double> lowest_x;
  double operator()(const std::vector<double>& x) {
    if (++calls == at) throw error;
    const double value = bowl(x);
    if (value < lowest) {
      lowest = value;
      lowest_x = x;
    }
    return value;
  }
};

TEST(IdentificationCore, ALibraryErrorFromTheObjectivePropagatesWithItsTypeAndMessage) {
  for (const Optimizer optimizer : {Optimizer::subplex, Optimizer::nelder_mead}) {
    FailingBowl<NumericalError> objective{30, NumericalError("state determination diverged")};
    Search search(std::ref(objective));
    try {
      search.run({0.0, 0.0}, settings(optimizer));
      ADD_FAILURE() << "the objective's error was swallowed";
    } catch (const NumericalError& e) {
      EXPECT_STREQ(e.what(), "state determination diverged");
    }
    EXPECT_EQ(objective.calls, 30);  // the run stopped at the error
    EXPECT_EQ(search.runs(), 0);
  }
}

TEST(IdentificationCore, OutOfMemoryAndInvalidArgumentsPropagate) {
  FailingBowl<std::bad_alloc> out_of_memory{5, std::bad_alloc()};
  EXPECT_THROW(Search(std::ref(out_of_memory)).run({0.0, 0.0}, settings()), std::bad_alloc);
  FailingBowl<std::invalid_argument> invalid{5, std::invalid_argument("bad")};
  EXPECT_THROW(Search(std::ref(invalid)).run({0.0, 0.0}, settings()), std::invalid_argument);
  // NLopt's own complaint: a zero initial step.
  SearchSettings bad = settings();
  bad.initial_step = 0.0;
  EXPECT_THROW(Search(bowl).run({0.0, 0.0}, bad), std::invalid_argument);
}

TEST(IdentificationCore, AForcedStopEndsTheRunAtItsBestPoint) {
  for (const Optimizer optimizer : {Optimizer::subplex, Optimizer::nelder_mead}) {
    FailingBowl<nlopt::forced_stop> objective{40, nlopt::forced_stop()};
    Search search(std::ref(objective));
    const Minimum m = search.run({0.13, 0.37}, settings(optimizer));
    EXPECT_EQ(search.runs(), 1);
    EXPECT_GT(objective.lowest, 1e-6);  // stopped well before the minimum...
    EXPECT_LT(objective.lowest, bowl({0.13, 0.37}));
    EXPECT_EQ(m.value, objective.lowest);  // ...at the best point it had seen
    EXPECT_EQ(m.x, objective.lowest_x);
  }
}

}  // namespace
}  // namespace stockbridge::identification::fit_core
