// The design study: damper numbers by their file paths, ties and the inertia's
// constant radius of gyration, validation, the space-filling sample, constraints,
// and the search against a dense scan of a one-variable problem.

#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/damper_numbers.hpp"
#include "stockbridge/design/search.hpp"
#include "stockbridge/requests/design_request.hpp"
#include "support/damper_fixtures.hpp"
#include "support/test_scale.hpp"
#include "unit/span/aster570.hpp"

namespace stockbridge::design {
namespace {

using damper::damper_number;
using damper::set_damper_number;

damper::DamperDescription two_arm_damper(int sections = 40) {
  damper::ArmDescription left = stockbridge::testing::sauter_arm(sections), right = left;
  left.name = "left";
  right.name = "right";
  return damper::DamperDescription{0.7, {left, right}};
}

DesignSpan aster_span(const damper::DamperDescription& d, double position = 1.0) {
  span::FatigueSpec fatigue;
  fatigue.cycles = 5e8;
  std::vector<span::SpanDamper> dampers{{damper::Damper(d), position, true, "damper", nullptr, std::nullopt}};
  return {span::Span(span::testing::aster570(), 400.0, span::testing::aster570_tension, span::WindModel{},
                     span::SelfDampingModel{}, std::move(dampers), fatigue),
          "aster", span::BalanceOptions{}};
}

DesignStudy study_of(std::vector<DesignVariable> variables, std::vector<DesignTie> ties = {},
                     DesignConstraints constraints = {}, int points = 6) {
  const damper::DamperDescription d = two_arm_damper(12);
  return DesignStudy(d, {aster_span(d)}, Objective::max_stress, std::move(variables), std::move(ties), constraints, points);
}

TEST(DamperNumbers, AreFoundByTheirFilePaths) {
  damper::DamperDescription d = two_arm_damper();
  EXPECT_EQ(damper_number(d, "clamp.mass"), 0.7);
  EXPECT_EQ(damper_number(d, "arm.left.mass"), d.arms[0].mass);
  EXPECT_EQ(damper_number(d, "arm[1].inertia"), d.arms[1].inertia);
  EXPECT_EQ(damper_number(d, "arm.right.cable.length"), d.arms[1].cable.length);
  set_damper_number(d, "arm.right.cable.length", 0.25);
  set_damper_number(d, "arm.left.cable.ei", 3.5);
  set_damper_number(d, "arm[0].cable.jenkin[0].h", 0.9);
  set_damper_number(d, "arm.left.offset", 0.04);
  EXPECT_EQ(d.arms[1].cable.length, 0.25);
  EXPECT_EQ(d.arms[0].cable.ei.at(0.1), 3.5);
  EXPECT_EQ(d.arms[0].cable.jenkin[0].h.at(0.1), 0.9);
  EXPECT_EQ(d.arms[0].offset, 0.04);
  EXPECT_EQ(d.arms[1].cable.ei.at(0.1), 2.8);  // the other arm untouched
}

TEST(DamperNumbers, APathThatNamesNothingIsRefusedWithWhatWasExpected) {
  const damper::DamperDescription d = two_arm_damper();
  const auto message = [&](const char* path) {
    try {
      damper_number(d, path);
    } catch (const InvalidParameter& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("arm.middle.mass").find("no arm is named 'middle' (the arms: left, right"), std::string::npos);
  EXPECT_NE(message("arm.left.weight").find("names no number of the damper"), std::string::npos);
  EXPECT_NE(message("arm[2].mass").find("the damper has 2 arm(s)"), std::string::npos);
  EXPECT_NE(message("arm.left.cable.jenkin[1].h").find("1 Jenkin element(s)"), std::string::npos);
  EXPECT_NE(message("clamp.inertia").find("names no number"), std::string::npos);
  damper::DamperDescription profiled = d;
  profiled.arms[0].cable.ei = cable::Profile::table({0.0, 0.1}, {2.0, 3.0}, "ei");
  EXPECT_THROW(damper_number(profiled, "arm.left.cable.ei"), InvalidParameter);
}

TEST(DesignStudy, TiesFollowTheirVariableAndTheInertiaKeepsTheRadiusOfGyration) {
  const DesignStudy study = study_of({{"arm.left.mass", 0.5, 3.0}, {"arm.left.cable.length", 0.1, 0.3}},
                                     {{"arm.right.mass", "arm.left.mass"}});
  const damper::DamperDescription base = study.base();
  const damper::DamperDescription d = study.damper_of({1.712, 0.2});
  EXPECT_EQ(d.arms[0].mass, 1.712);
  EXPECT_EQ(d.arms[1].mass, 1.712);
  EXPECT_EQ(d.arms[0].cable.length, 0.2);
  EXPECT_EQ(d.arms[1].cable.length, base.arms[1].cable.length);  // not tied
  // inertia / mass unchanged on both arms: the radius of gyration is kept
  EXPECT_DOUBLE_EQ(d.arms[0].inertia / d.arms[0].mass, base.arms[0].inertia / base.arms[0].mass);
  EXPECT_DOUBLE_EQ(d.arms[1].inertia / d.arms[1].mass, base.arms[1].inertia / base.arms[1].mass);
  // ... unless the inertia is varied itself
  const DesignStudy with_inertia = study_of({{"arm.left.mass", 0.5, 3.0}, {"arm.left.inertia", 1e-4, 1e-2}});
  EXPECT_EQ(with_inertia.damper_of({2.0, 3e-3}).arms[0].inertia, 3e-3);
  EXPECT_FALSE(study.position_of({1.0, 0.2}));
  EXPECT_EQ(study.base_values(), (std::vector<double>{base.arms[0].mass, base.arms[0].cable.length}));
}

TEST(DesignStudy, ACandidateIsRoundedToBuildWithinItsVariablesRanges) {
  const DesignStudy study = study_of({{"arm.left.mass", 0.5, 1.738}, {"arm.left.cable.length", 0.1004, 0.3},
                                      {"arm.left.cable.jenkin[0].h", 0.2, 2.0}});
  EXPECT_EQ(rounded_candidate(study, {1.2345678, 0.22426174413697125, 0.70049}, 3),
            (std::vector<double>{1.23, 0.224, 0.7}));
  EXPECT_EQ(rounded_candidate(study, {1.2345678, 0.22426174413697125, 0.70049}, 2),
            (std::vector<double>{1.2, 0.22, 0.7}));
  // The nearest 3-digit values 1.74 and 0.100 lie outside the ranges [.., 1.738] and
  // [0.1004, ..]: rounded toward the inside instead.
  EXPECT_EQ(rounded_candidate(study, {1.7379, 0.1004, 0.7}, 3)[0], 1.73);
  EXPECT_EQ(rounded_candidate(study, {1.7379, 0.1004, 0.7}, 3)[1], 0.101);
  // Many digits give the candidate back.
  const std::vector<double> x{1.2345678, 0.22426174413697125, 0.70049};
  const std::vector<double> r = rounded_candidate(study, x, 15);
  for (std::size_t d = 0; d < x.size(); ++d) EXPECT_NEAR(r[d], x[d], 1e-14 * x[d]);
  EXPECT_THROW(rounded_candidate(study, x, 0), InvalidParameter);
  EXPECT_THROW(rounded_candidate(study, x, 16), InvalidParameter);
}

TEST(DesignStudy, IsCheckedWhereTheFileSpellsIt) {
  const auto field_of = [](auto&& make) {
    try {
      make();
    } catch (const InvalidParameter& e) {
      return e.field();
    }
    return std::string("no error");
  };
  EXPECT_EQ(field_of([] { study_of({{"arm.left.mass", 3.0, 0.5}}); }), "variable[0].max");
  EXPECT_EQ(field_of([] { study_of({{"arm.left.mas", 0.5, 3.0}}); }), "variable[0].name");
  EXPECT_EQ(field_of([] { study_of({{"arm.left.mass", 0.5, 3.0}}, {{"arm.right.mass", "arm.left.cable.length"}}); }),
            "tie[0].equals");
  EXPECT_EQ(field_of([] { study_of({{"position", 0.5, 2.0}}, {{"arm.right.mass", "position"}}); }), "tie[0].equals");
  EXPECT_EQ(field_of([] { study_of({{"arm.left.mass", 0.5, 3.0}}, {{"arm.left.mass", "arm.left.mass"}}); }),
            "tie[0].name");
  EXPECT_EQ(field_of([] { study_of({{"arm.left.mass", 0.5, 3.0}}, {}, {-1.0, std::nullopt}); }),
            "constraints.total_mass_max");
  EXPECT_EQ(field_of([] { study_of({{"position", 0.5, 250.0}}); }), "variable[0].max");
  EXPECT_EQ(field_of([] { study_of({{"arm.left.mass", 0.5, 3.0}, {"arm.left.mass", 1.0, 2.0}}); }), "variable[1].name");
  EXPECT_EQ(field_of([] { study_of({}); }), "variable");  // no [[variable]]: the file's key
}

TEST(SpaceFillingSample, FillsTheBoxStratifiedAndFollowsTheSeed) {
  const std::vector<DesignVariable> box{{"a", 0.0, 1.0}, {"b", -2.0, 2.0}, {"c", 10.0, 20.0}};
  const auto points = space_filling_sample(box, 16, 7);
  ASSERT_EQ(points.size(), 16u);
  for (std::size_t d = 0; d < box.size(); ++d) {
    // A Sobol sequence's first 2^m points put one point in each of 2^m equal bins of
    // every coordinate; a digital shift keeps that.
    std::set<int> bins;
    for (const auto& p : points) {
      ASSERT_GT(p[d], box[d].min);
      ASSERT_LT(p[d], box[d].max);
      bins.insert(static_cast<int>(16.0 * (p[d] - box[d].min) / (box[d].max - box[d].min)));
    }
    EXPECT_EQ(bins.size(), 16u) << "coordinate " << d;
  }
  EXPECT_EQ(space_filling_sample(box, 16, 7), points);
  EXPECT_NE(space_filling_sample(box, 16, 8), points);
}

TEST(DesignEvaluation, ConstraintsMakeACandidateInfeasibleAndSaySo) {
  const DesignStudy heavy = study_of({{"arm.left.mass", 0.5, 3.0}}, {}, {1.0, std::nullopt});
  const Evaluation e = evaluate(heavy, heavy.base_values());
  ASSERT_TRUE(e.converged()) << e.failure;
  EXPECT_FALSE(e.feasible());
  EXPECT_TRUE(e.failure.empty()) << e.failure;
  EXPECT_NE(e.infeasibility.find("total mass 2.412 kg > total_mass_max 1 kg"), std::string::npos) << e.infeasibility;
  const DesignStudy stiff = study_of({{"arm.left.mass", 0.5, 3.0}}, {}, {std::nullopt, 1e-3});
  const Evaluation c = evaluate(stiff, stiff.base_values());
  EXPECT_FALSE(c.feasible());
  EXPECT_NE(c.infeasibility.find("messenger_curvature_max 0.001 1/m"), std::string::npos) << c.infeasibility;
  EXPECT_GT(c.messenger_curvature_max, 1e-3);
  const DesignStudy free = study_of({{"arm.left.mass", 0.5, 3.0}});
  const Evaluation f = evaluate(free, free.base_values());
  EXPECT_TRUE(f.feasible());
  EXPECT_EQ(f.termination, Termination::converged);
  EXPECT_EQ(f.objective, f.max_stress_ratio);
  EXPECT_NEAR(f.total_mass, 0.7 + 2 * 0.856, 1e-12);
}

// One variable, the dampers' position: the search (sample and polish) against a
// dense scan of the same objective; the tables are shared, only the balances differ.
TEST(DesignSearch, OneVariableMatchesADenseScan) {
  const DesignStudy study = study_of({{"position", 0.5, 2.0}});
  SearchOptions options;
  options.samples = stockbridge::testing::scaled(6, 2);
  options.polish = 1;
  options.polish_evaluations = stockbridge::testing::scaled(12, 4);
  ThreadRunner runner(2);
  const DesignResult result = run_search(study, options, runner);
  ASSERT_TRUE(result.best);
  const Evaluation& best = result.evaluations[*result.best].evaluation;
  EXPECT_TRUE(best.feasible());
  EXPECT_EQ(result.evaluations.front().stage, Stage::base);
  // The polish's outcome is kept: it ran within its budget and ended as NLopt said.
  ASSERT_EQ(result.polishes.size(), 1u);
  const SolverSummary& polish = result.polishes.front();
  EXPECT_TRUE(polish.termination == Termination::converged || polish.termination == Termination::max_iterations)
      << brief_report(polish);
  EXPECT_LE(polish.evaluations, options.polish_evaluations);
  EXPECT_GE(polish.evaluations, 1);
  // A candidate's evaluation is a function of its values: the best again, bit for bit.
  EXPECT_EQ(evaluate(study, best.x).objective, best.objective);
  // Threads change nothing.
  ThreadRunner one(1);
  const DesignResult again = run_search(study, options, one);
  ASSERT_EQ(again.evaluations.size(), result.evaluations.size());
  for (std::size_t i = 0; i < again.evaluations.size(); ++i) {
    EXPECT_EQ(again.evaluations[i].evaluation.x, result.evaluations[i].evaluation.x);
    EXPECT_EQ(again.evaluations[i].evaluation.objective, result.evaluations[i].evaluation.objective);
  }
  if (stockbridge::testing::short_tests()) return;  // too few evaluations to find the optimum, and no dense scan
  const int steps = 30;
  const double step = 1.5 / steps;
  double scan_best = std::numeric_limits<double>::infinity(), scan_at = 0.0;
  TableCache cache;
  for (int k = 0; k <= steps; ++k) {
    const Evaluation e = evaluate(study, {0.5 + k * step}, &cache);
    ASSERT_TRUE(e.converged()) << e.failure;
    if (e.objective < scan_best) scan_best = e.objective, scan_at = 0.5 + k * step;
  }
  EXPECT_LE(best.objective, scan_best * (1 + 1e-9)) << "scan's best at " << scan_at << " m";
  EXPECT_NEAR(best.x[0], scan_at, 2 * step);
}

}  // namespace
}  // namespace stockbridge::design

namespace stockbridge::design {
namespace {

// The position as a fraction of each span's shortest loop: the dampers move with the
// conductor and tension (two spans of different tension, different positions), and a
// candidate's figures are given span by span, the governing one the largest.
TEST(DesignStudy, APositionByTheLoopScalesWithEachSpanAndFiguresComeSpanBySpan) {
  const damper::DamperDescription d = two_arm_damper(12);
  DesignSpan slack = aster_span(d), taut = aster_span(d);
  taut.name = "taut";
  taut.span = span::Span(taut.span.conductor(), taut.span.length(), 1.6 * taut.span.tension(), taut.span.wind(),
                         taut.span.self_damping(), taut.span.dampers(), taut.span.fatigue());
  const DesignStudy study(d, {slack, taut}, Objective::max_stress, {{std::string(kPositionLoopFraction), 0.2, 1.5}}, {},
                          {}, 6);
  const double loop_slack = span::shortest_loop(slack.span), loop_taut = span::shortest_loop(taut.span);
  EXPECT_NEAR(loop_taut / loop_slack, std::sqrt(1.6), 1e-12);  // c = sqrt(T / m)
  EXPECT_NEAR(study.base_values()[0], 1.0 / loop_slack, 1e-12);  // the file's 1 m on the first span
  EXPECT_FALSE(study.position_of({0.6}));
  EXPECT_NEAR(*study.position_on(0, {0.6}), 0.6 * loop_slack, 1e-12);
  EXPECT_NEAR(*study.position_on(1, {0.6}), 0.6 * loop_taut, 1e-12);
  const Evaluation e = evaluate(study, {0.6});
  ASSERT_TRUE(e.converged()) << e.failure;
  ASSERT_EQ(e.spans.size(), 2u);
  const double largest = std::max(e.spans[0].max_stress_ratio, e.spans[1].max_stress_ratio);
  EXPECT_EQ(e.max_stress_ratio, largest);
  EXPECT_EQ(e.spans[e.span_at_max].max_stress_ratio, largest);
  for (const SpanFigures& f : e.spans) {
    EXPECT_GT(f.undamped_max_stress, 0.0);
    EXPECT_EQ(f.worse_than_undamped(), f.max_stress > f.undamped_max_stress);
  }
  // A fraction whose dampers would leave the span's half is refused at the variable.
  try {
    DesignStudy(d, {slack}, Objective::max_stress, {{std::string(kPositionLoopFraction), 0.2, 5.0}}, {}, {}, 6);
  } catch (const InvalidParameter& error) {
    ADD_FAILURE() << "a fraction of 5 loops (about 8 m) fits in 200 m: " << error.what();
  }
  EXPECT_THROW(DesignStudy(d, {slack}, Objective::max_stress, {{std::string(kPositionLoopFraction), 0.2, 6.0}}, {}, {}, 6),
               InvalidParameter);
}

}  // namespace
}  // namespace stockbridge::design

namespace stockbridge::design {
namespace {

/// The ASTER570 span with a 12.5 kg sphere at mid-span, and (where `beside`) the
/// file's damper 1.5 m on either side of it (positions along the span).
DesignSpan sphere_span(const damper::DamperDescription& d, bool beside) {
  const DesignSpan plain = aster_span(d);
  DesignSpan s = plain;
  s.name = beside ? "sphere" : "bare";
  std::vector<span::SpanDamper> dampers = plain.span.dampers();
  if (beside) {
    span::SpanDamper along = dampers.front();
    along.position = 0.0;
    along.along = {198.5, 201.5};
    dampers.push_back(along);
  }
  s.span = plain.span.with_masses({{"sphere", 12.5, {200.0}, 1.0}}).with_dampers(std::move(dampers));
  return s;
}

// A span file with a warning sphere and dampers beside it: the candidate replaces
// those too (at the file's positions along the span) and moves only the ends', the
// sphere stays; the figures differ from the plain span's, with the governing place
// named, and the dampers beside the sphere lower the largest stress.
TEST(DesignStudy, ASpanWithASphereKeepsItAndGetsTheCandidateBesideIt) {
  const damper::DamperDescription d = two_arm_damper(12);
  const std::vector<DesignVariable> position{{"position", 0.5, 2.0}};
  const DesignStudy with(d, {sphere_span(d, true)}, Objective::max_stress, position, {}, {}, 6);
  const DesignStudy plain(d, {aster_span(d)}, Objective::max_stress, position, {}, {}, 6);
  const DesignStudy bare(d, {sphere_span(d, false)}, Objective::max_stress, position, {}, {}, 6);
  EXPECT_EQ(with.base_values(), (std::vector<double>{1.0}));  // the first damper at the ends
  damper::DamperDescription heavier = d;
  set_damper_number(heavier, "clamp.mass", 1.1);
  const span::Span s = with.span_with(0, damper::Damper(heavier), 1.5);
  ASSERT_EQ(s.masses().size(), 1u);
  ASSERT_EQ(s.dampers().size(), 2u);
  EXPECT_EQ(s.dampers()[0].position, 1.5);
  EXPECT_EQ(s.dampers()[1].along, (std::vector<double>{198.5, 201.5}));
  for (const span::SpanDamper& damper : s.dampers()) EXPECT_EQ(damper.damper->clamp_mass(), 1.1);

  const Evaluation e = evaluate(with, {1.0}), p = evaluate(plain, {1.0}), b = evaluate(bare, {1.0});
  ASSERT_TRUE(e.converged()) << e.failure;
  ASSERT_TRUE(p.converged()) << p.failure;
  ASSERT_TRUE(b.converged()) << b.failure;
  EXPECT_NE(e.max_stress, p.max_stress);
  EXPECT_FALSE(e.place_at_max.empty());
  EXPECT_EQ(e.spans.at(0).governing_place, e.place_at_max);
  EXPECT_TRUE(p.place_at_max.starts_with("span clamp")) << p.place_at_max;
  // The dampers beside the sphere take energy the plain span's ends alone do not:
  // on 6 frequencies, 13.3 MPa against 26.1 (the plain span) and 28.9 (the sphere alone).
  EXPECT_LT(e.max_stress, 0.75 * p.max_stress);
  EXPECT_LT(e.max_stress, 0.75 * b.max_stress);
  EXPECT_FALSE(b.place_at_max.empty());
  // What a rank sends and --resume reads keeps the places.
  const Evaluation back = requests::parse_evaluation_record(requests::evaluation_record(e));
  EXPECT_EQ(back.place_at_max, e.place_at_max);
  EXPECT_EQ(back.spans.at(0).governing_place, e.spans.at(0).governing_place);
  // The position variable needs dampers at the ends to move.
  DesignSpan along_only = sphere_span(d, true);
  along_only.span = along_only.span.with_dampers({along_only.span.dampers().back()});
  try {
    DesignStudy(d, {along_only}, Objective::max_stress, position, {}, {}, 6);
    ADD_FAILURE() << "a position variable for a span without dampers at its ends";
  } catch (const InvalidParameter& error) {
    EXPECT_NE(std::string(error.what()).find("span sphere has no [[damper]] at its ends (position) to move"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace stockbridge::design
