// The span's natural frequencies with its attachments (span_modes.hpp): the bare
// string's harmonics; a mass at mid-span against tan(kL/2) = 2m/(Mk); a mass at a
// third against the two-segment determinant, solved here by a scan and bisection of
// its own; masses and a damper at its linear impedance against a finite-element
// model (linear string elements, lumped masses, the damper's arms from their beam
// formulas, Eigen's generalized eigensolver, Richardson-extrapolated); the shapes'
// ends, continuity and slope jumps; a zero mass and removed dampers change nothing;
// a damper's clamp-still modes left out; the options' and a sheet's refusals.

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "aster570.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/modes.hpp"
#include "stockbridge/span/span_modes.hpp"
#include "support/damper_fixtures.hpp"
#include "support/error_message.hpp"

namespace stockbridge::span {
namespace {

using testing::aster570;
using testing::aster570_tension;
using testing::expect_relative;
using stockbridge::testing::invalid_parameter_message;

constexpr double kModesPi = std::numbers::pi;
const double kMassPerLength = aster570().mass_per_length;
const double kWaveSpeed = std::sqrt(aster570_tension / kMassPerLength);

Span modes_span(double length, std::vector<SpanMass> masses, std::vector<SpanDamper> dampers = {}) {
  FatigueSpec fatigue;
  fatigue.cycles = 5e8;
  return Span(aster570(), length, aster570_tension, WindModel{}, SelfDampingModel{}, std::move(dampers), fatigue,
              std::nullopt, std::move(masses));
}

SpanModesOptions up_to(double max_frequency_hz, ModeDampers dampers = ModeDampers::removed) {
  SpanModesOptions options;
  options.max_frequency_hz = max_frequency_hz;
  options.dampers = dampers;
  return options;
}

std::vector<double> frequencies_of(const SpanModes& modes) {
  std::vector<double> f;
  for (const SpanMode& mode : modes.modes) f.push_back(mode.frequency_hz);
  return f;
}

/// The root of a continuous g between lo and hi where it changes sign, by bisection.
double bisect_sign_change(const std::function<double(double)>& g, double lo, double hi) {
  const bool rising = g(hi) > 0.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((g(mid) > 0.0) == rising ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

/// Every root of g in (0, k_max], by a scan of `per_pi` steps per pi / L and bisection.
std::vector<double> scanned_roots(const std::function<double(double)>& g, double k_max, double length, int per_pi) {
  std::vector<double> roots;
  const double step = kModesPi / length / per_pi;
  for (double a = 0.5 * step; a < k_max; a += step) {
    const double b = std::min(a + step, k_max);
    if (g(a) * g(b) < 0.0) roots.push_back(bisect_sign_change(g, a, b));
  }
  return roots;
}

TEST(SpanModes, WithoutAttachmentsTheyAreTheStringsHarmonics) {
  const double length = 400.0, fmax = 40.0;
  const SpanModes modes = span_modes(modes_span(length, {}), up_to(fmax));
  const int expected = static_cast<int>(std::floor(fmax * 2.0 * length / kWaveSpeed));
  ASSERT_EQ(static_cast<int>(modes.modes.size()), expected);
  EXPECT_EQ(span_modes_below(modes_span(length, {}), ModeDampers::removed, fmax), expected);
  for (const SpanMode& mode : modes.modes) {
    expect_relative(mode.frequency_hz, mode.number * kWaveSpeed / (2.0 * length), 1e-10);
    expect_relative(mode.wavelength_m, 2.0 * length / mode.number, 1e-10);
  }
  EXPECT_LT(modes.max_end_residual, 1e-10);
  EXPECT_EQ(modes.clamp_still_modes, 0);
}

TEST(SpanModes, AMassAtMidSpanMovesTheSymmetricModesOnlyAsTanKLOver2Is2mOverMk) {
  const double length = 400.0, mass = 20.0, m = kMassPerLength;
  const SpanModes modes = span_modes(modes_span(length, {{"sphere", mass, {0.5 * length}, 1.0}}), up_to(40.0));
  ASSERT_GT(modes.modes.size(), 200u);
  // The symmetric modes' closed form, pole-free: M k sin(kL/2) - 2 m cos(kL/2) = 0,
  // one root for each j in k L / 2 in (j pi, j pi + pi / 2).
  const auto symmetric = [&](double k) { return mass * k * std::sin(0.5 * k * length) - 2.0 * m * std::cos(0.5 * k * length); };
  for (const SpanMode& mode : modes.modes) {
    const double k = 2.0 * kModesPi / mode.wavelength_m;
    if (mode.number % 2 == 0) {  // antisymmetric: the bare string's, a node at the mass
      expect_relative(mode.frequency_hz, mode.number * kWaveSpeed / (2.0 * length), 1e-10);
      EXPECT_LT(std::abs(mode.attachment_deflection[0]), 1e-9) << mode.number;
      continue;
    }
    const int j = (mode.number - 1) / 2;
    const double expected_k = bisect_sign_change(symmetric, 2.0 * j * kModesPi / length, (2.0 * j + 1.0) * kModesPi / length);
    expect_relative(k, expected_k, 1e-10);
    const double ratio = 2.0 * m / (mass * k);
    EXPECT_NEAR(std::tan(0.5 * k * length), ratio, 1e-6 * ratio) << mode.number;
  }
}

TEST(SpanModes, AMassAtAThirdAgreesWithTheTwoSegmentDeterminant) {
  const double length = 300.0, a = 100.0, mass = 12.0, m = kMassPerLength, fmax = 30.0;
  const SpanModes modes = span_modes(modes_span(length, {{"marker", mass, {a}, 1.0}}), up_to(fmax));
  // Y(L) of the chain in closed form: sin(kL) - (k M / m) sin(k a) sin(k (L - a)).
  const auto end_deflection = [&](double k) {
    return std::sin(k * length) - k * mass / m * std::sin(k * a) * std::sin(k * (length - a));
  };
  // The scan's points, (i + 1/2) pi / (64 L), never fall on a root at k L = 3 pi j
  // (the mass on a node of the bare span's mode 3 j), simple roots like the rest.
  const std::vector<double> expected = scanned_roots(end_deflection, 2.0 * kModesPi * fmax / kWaveSpeed, length, 64);
  ASSERT_EQ(modes.modes.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    expect_relative(2.0 * kModesPi / modes.modes[i].wavelength_m, expected[i], 1e-10);
  }
}

/// The finite-element model of the span: linear string elements of length h = L / n,
/// lumped masses (m h at each node, a rigid mass at its node), and each damper's
/// arms as two degrees of freedom each relative to its clamp's node (MODEL.md
/// section 4: the arms' mass matrices and their uniform beams' tip stiffness, from
/// tests/support, nothing from the library). The natural frequencies below fmax, Hz.
struct FeDamper {
  double position = 0.0;
  damper::DamperDescription description;
  double ei = 0.0;  ///< every arm's uniform linear bending stiffness
};

std::vector<double> finite_element_frequencies(double length, int n, const std::vector<SpanMass>& masses,
                                               const std::vector<FeDamper>& dampers, double fmax) {
  const double h = length / n, t = aster570_tension;
  const auto node_at = [&](double x) {
    const double i = x / h;
    EXPECT_NEAR(i, std::round(i), 1e-9) << "an attachment between the mesh's nodes";
    return static_cast<Eigen::Index>(std::round(i)) - 1;  // the interior nodes 1..n-1 are dofs 0..n-2
  };
  Eigen::Index dofs = n - 1;
  for (const FeDamper& d : dampers) dofs += 2 * static_cast<Eigen::Index>(d.description.arms.size());
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(dofs, dofs), mass = Eigen::MatrixXd::Zero(dofs, dofs);
  for (Eigen::Index i = 0; i < n - 1; ++i) {
    stiffness(i, i) = 2.0 * t / h;
    if (i > 0) stiffness(i, i - 1) = stiffness(i - 1, i) = -t / h;
    mass(i, i) = kMassPerLength * h;
  }
  for (const SpanMass& m : masses) {
    for (const double x : m.positions) mass(node_at(x), node_at(x)) += m.mass;
  }
  Eigen::Index next = n - 1;
  for (const FeDamper& d : dampers) {
    const Eigen::Index clamp = node_at(d.position);
    mass(clamp, clamp) += d.description.clamp_mass;
    for (const damper::ArmDescription& arm : d.description.arms) {
      const Eigen::Vector2d coupling = -stockbridge::testing::arm_load_vector(arm);
      mass(clamp, clamp) += arm.mass;
      mass.block<2, 2>(next, next) = stockbridge::testing::arm_mass_matrix(arm);
      mass.block<2, 1>(next, clamp) = coupling;
      mass.block<1, 2>(clamp, next) = coupling.transpose();
      stiffness.block<2, 2>(next, next) = stockbridge::testing::beam_tip_stiffness(d.ei, arm.cable.length);
      next += 2;
    }
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness, mass, Eigen::EigenvaluesOnly);
  std::vector<double> f;
  for (Eigen::Index i = 0; i < dofs; ++i) {
    const double hz = std::sqrt(solver.eigenvalues()(i)) / (2.0 * kModesPi);
    if (hz < fmax) f.push_back(hz);
  }
  return f;
}

/// Richardson's extrapolation of the element model (its error a series in h^2) from
/// h = L / 400 and L / 800. What remains is the model's h^4 term: against the
/// library, at most 1.1e-8 below 40 Hz, 1e-7 below 60 Hz and 5.9e-7 below 75 Hz on
/// these 20 m spans, and 16 times less (6.9e-10, 6.2e-9, 3.7e-8) from L / 800 and
/// L / 1600, which take ten times as long: the library's frequencies are the limit.
std::vector<double> converged_frequencies(double length, const std::vector<SpanMass>& masses,
                                          const std::vector<FeDamper>& dampers, double fmax) {
  const std::vector<double> coarse = finite_element_frequencies(length, 400, masses, dampers, 1.2 * fmax);
  const std::vector<double> fine = finite_element_frequencies(length, 800, masses, dampers, 1.2 * fmax);
  std::vector<double> out;
  for (std::size_t i = 0; i < std::min(coarse.size(), fine.size()); ++i) {
    const double f = (4.0 * fine[i] - coarse[i]) / 3.0;
    if (f < fmax) out.push_back(f);
  }
  return out;
}

void expect_same_frequencies(const std::vector<double>& actual, const std::vector<double>& expected, double tolerance) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) expect_relative(actual[i], expected[i], tolerance);
}

TEST(SpanModes, TwoMassesAgreeWithTheFiniteElementModel) {
  const double length = 20.0, fmax = 40.0;
  const std::vector<SpanMass> masses{{"sphere", 15.0, {7.0}, 1.0}, {"marker", 6.0, {12.4}, 1.0}};
  const SpanModes modes = span_modes(modes_span(length, masses), up_to(fmax));
  EXPECT_GE(modes.modes.size(), 10u);
  expect_same_frequencies(frequencies_of(modes), converged_frequencies(length, masses, {}, fmax), 1e-6);
}

/// Sauter's arm and a shorter, lighter one: no two arms alike, so no clamp-still mode.
damper::DamperDescription unlike_arms() {
  damper::ArmDescription short_arm = stockbridge::testing::sauter_arm();
  short_arm.name = "short";
  short_arm.mass = 0.6;
  short_arm.inertia = 0.0011;
  short_arm.cable.length = 0.14;
  return {0.7, {stockbridge::testing::sauter_arm(), short_arm}};
}

SpanDamper modes_span_damper(const damper::DamperDescription& description, double position, bool both_ends) {
  return {damper::Damper(description), position, both_ends, "unlike", nullptr, std::nullopt};
}

TEST(SpanModes, ADamperAtItsLinearImpedanceAgreesWithTheFiniteElementModel) {
  const double length = 20.0, fmax = 60.0;
  const std::vector<SpanMass> masses{{"sphere", 15.0, {12.4}, 1.0}};
  // Sticking: Sauter's cable is ei 2.8 with one Jenkin element of c = 20, uniform: 22.8 N m^2.
  const SpanModes one_end = span_modes(modes_span(length, masses, {modes_span_damper(unlike_arms(), 1.0, false)}),
                                       up_to(fmax, ModeDampers::linear));
  EXPECT_EQ(one_end.clamp_still_modes, 0);
  expect_same_frequencies(frequencies_of(one_end),
                          converged_frequencies(length, masses, {{1.0, unlike_arms(), 22.8}}, fmax), 1e-6);
  const SpanModes both_ends = span_modes(modes_span(length, masses, {modes_span_damper(unlike_arms(), 1.0, true)}),
                                         up_to(fmax, ModeDampers::linear));
  expect_same_frequencies(frequencies_of(both_ends),
                          converged_frequencies(length, masses, {{1.0, unlike_arms(), 22.8}, {19.0, unlike_arms(), 22.8}}, fmax),
                          1e-6);
  EXPECT_LT(both_ends.max_end_residual, 1e-9);
}

TEST(SpanModes, ShapesVanishAtTheEndsAreContinuousAndJumpInSlopeByTheMass) {
  const double length = 100.0;
  const std::vector<SpanMass> masses{{"light", 10.0, {30.0}, 1.0}, {"heavy", 25.0, {71.3}, 1.0}};
  const SpanModes modes = span_modes(modes_span(length, masses), up_to(30.0));
  ASSERT_GT(modes.modes.size(), 30u);
  ASSERT_EQ(modes.attachments.size(), 2u);
  for (const SpanMode& mode : modes.modes) {
    ASSERT_EQ(mode.shape.size(), modes.x.size());
    const double k = 2.0 * kModesPi / mode.wavelength_m, w = 2.0 * kModesPi * mode.frequency_hz;
    EXPECT_EQ(mode.shape.front(), 0.0);
    EXPECT_LT(std::abs(mode.shape.back()), 1e-9) << mode.number;
    double largest = 0.0;
    for (const double y : mode.shape) largest = std::max(largest, std::abs(y));
    EXPECT_LE(largest, 1.0 + 1e-12);
    EXPECT_GT(largest, std::cos(kModesPi / 20.0) - 1e-9);  // 20 samples a wavelength at most
    for (std::size_t a = 0; a < modes.attachments.size(); ++a) {
      const std::size_t i = std::find(modes.x.begin(), modes.x.end(), modes.attachments[a].position) - modes.x.begin();
      ASSERT_LT(i + 2, modes.x.size());
      // Each side a sinusoid of wavenumber k through its two nearest samples, carried to
      // the attachment: (Y, Y') just before and just after it.
      const auto side = [&](std::size_t p, std::size_t q) {
        const double sp = modes.x[p] - modes.x[i], sq = modes.x[q] - modes.x[i];
        Eigen::Matrix2d basis;
        basis << std::cos(k * sp), std::sin(k * sp) / k, std::cos(k * sq), std::sin(k * sq) / k;
        return Eigen::Vector2d(basis.fullPivLu().solve(Eigen::Vector2d(mode.shape[p], mode.shape[q])));
      };
      const Eigen::Vector2d before = side(i - 2, i - 1), after = side(i + 1, i + 2);
      EXPECT_NEAR(before(0), mode.shape[i], 1e-9) << mode.number;
      EXPECT_NEAR(after(0), mode.shape[i], 1e-9) << mode.number;
      EXPECT_NEAR(mode.attachment_deflection[a], mode.shape[i], 1e-15);
      const double jump = -w * w * modes.attachments[a].mass * mode.shape[i] / aster570_tension;
      EXPECT_NEAR(after(1) - before(1), jump, 1e-8 * (k + std::abs(jump))) << mode.number;
    }
  }
}

TEST(SpanModes, AZeroMassIsNoMass) {
  const SpanModes bare = span_modes(modes_span(400.0, {}), up_to(40.0));
  const SpanModes zero = span_modes(modes_span(400.0, {{"none", 0.0, {137.0}, 1.0}}), up_to(40.0));
  expect_same_frequencies(frequencies_of(zero), frequencies_of(bare), 1e-12);
}

TEST(SpanModes, RemovedDampersAreNoDampers) {
  const std::vector<SpanMass> masses{{"sphere", 15.0, {180.0}, 1.0}};
  const Span damped = modes_span(400.0, masses, {modes_span_damper(unlike_arms(), 1.0, true)});
  const SpanModes removed = span_modes(damped, up_to(30.0, ModeDampers::removed));
  EXPECT_EQ(frequencies_of(removed), frequencies_of(span_modes(modes_span(400.0, masses), up_to(30.0))));
  EXPECT_EQ(removed.attachments.size(), 1u);
  const SpanModes linear = span_modes(damped, up_to(30.0, ModeDampers::linear));
  EXPECT_EQ(linear.attachments.size(), 3u);
  EXPECT_NE(frequencies_of(linear), frequencies_of(removed));
}

TEST(SpanModes, ADamperOfIdenticalArmsHasClampStillModesLeftOut) {
  const damper::ArmDescription arm = stockbridge::testing::sauter_arm();
  const damper::DamperDescription alike{0.7, {arm, arm}};
  const double fmax = 75.0;  // above both of the arm's clamp-held frequencies, 21.17 and 68.21 Hz
  const Span span = modes_span(20.0, {}, {modes_span_damper(alike, 1.0, true)});
  const SpanModes modes = span_modes(span, up_to(fmax, ModeDampers::linear));
  const damper::ArmModes held = damper::arm_modes(damper::Damper(alike).arms()[0], damper::CableLimit::stick);
  const int held_below = (held.frequencies_hz(0) < fmax) + (held.frequencies_hz(1) < fmax);
  ASSERT_EQ(held_below, 2);
  EXPECT_EQ(modes.clamp_still_modes, 2 * held_below);  // each damper's arms against each other, at each held frequency
  EXPECT_EQ(span_modes_below(span, ModeDampers::linear, fmax), static_cast<int>(modes.modes.size()) + 2 * held_below);
  EXPECT_LT(modes.max_end_residual, 1e-9);
  // The rest are the unlike-arms model's with both arms alike: the element model's,
  // less its clamp-still frequencies.
  std::vector<double> expected = converged_frequencies(20.0, {}, {{1.0, alike, 22.8}, {19.0, alike, 22.8}}, fmax);
  for (int i = 0; i < 2; ++i) {
    if (held.frequencies_hz(i) >= fmax) continue;
    for (int copy = 0; copy < 2; ++copy) {
      const auto nearest = std::min_element(expected.begin(), expected.end(), [&](double p, double q) {
        return std::abs(p - held.frequencies_hz(i)) < std::abs(q - held.frequencies_hz(i));
      });
      expect_relative(*nearest, held.frequencies_hz(i), 1e-6);
      expected.erase(nearest);
    }
  }
  expect_same_frequencies(frequencies_of(modes), expected, 1e-6);
}

TEST(SpanModes, RefusesBadOptionsAndASheetDamperAtItsLinearImpedance) {
  const Span span = modes_span(400.0, {});
  EXPECT_NE(invalid_parameter_message([&] { span_modes(span, up_to(0.0)); }).find("max_frequency_hz = 0"),
            std::string::npos);
  EXPECT_NE(invalid_parameter_message([&] { span_modes(span, up_to(5000.0)); }).find("at most 10000 modes"),
            std::string::npos);
  SpanModesOptions coarse = up_to(10.0);
  coarse.samples_per_wavelength = 2.0;
  EXPECT_NE(invalid_parameter_message([&] { span_modes(span, coarse); }).find("samples_per_wavelength = 2"),
            std::string::npos);
  EXPECT_NE(invalid_parameter_message([] { parse_mode_dampers("stick"); }).find("dampers = 'stick': expected removed"),
            std::string::npos);

  damper::ImpedanceMeasurement measurement;
  for (const double v : {0.05, 0.1}) {
    for (const double f : {10.0, 20.0, 40.0}) {
      measurement.points.push_back({damper::Excitation::from_velocity(f, v), {100.0, 50.0}});
    }
  }
  auto sheet = std::make_shared<const ImpedanceSheet>(measurement, "vendor.csv");
  const Span measured = modes_span(400.0, {}, {{std::nullopt, 1.0, true, "vendor", sheet, std::nullopt}});
  const std::string message = invalid_parameter_message([&] { span_modes(measured, up_to(10.0, ModeDampers::linear)); });
  EXPECT_NE(message.find("dampers = linear: damper[0] ('vendor') is known by its measured sheet only"), std::string::npos)
      << message;
  EXPECT_EQ(span_modes(measured, up_to(10.0, ModeDampers::removed)).modes.size(),
            span_modes(span, up_to(10.0)).modes.size());
}

}  // namespace
}  // namespace stockbridge::span
