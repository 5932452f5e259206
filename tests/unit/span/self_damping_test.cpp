// Self-damping: the named exponent sets, a power law on hand-computed numbers,
// exponents published as ranges (the user's value, checked), Foti & Martinelli's
// closed form against a quadrature of its local dissipation law along the wave,
// and validation messages.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "stockbridge/core/error.hpp"
#include "stockbridge/span/self_damping.hpp"

namespace stockbridge::span {
namespace {

using stockbridge::testing::invalid_parameter_message;
using testing::aster570;
using testing::aster570_tension;
using testing::expect_relative;

SelfDampingModel self_damping_model_of(SelfDampingLaw law) {
  SelfDampingModel model;
  model.law = law;
  return model;
}

TEST(SelfDamping, NamedExponentSets) {
  struct Case {
    const char* name;
    double l, m, n;
  };
  for (const Case& c : {Case{"noiseux-1991", 2.44, 5.63, 2.76}, Case{"kraus-hagedorn-1991", 2.47, 5.38, 2.80},
                        Case{"seppa-1971", 2.5, 5.75, 2.8}, Case{"moecks-schmidt-1989", 2.45, 5.38, 2.4},
                        Case{"polimi-2000", 2.43, 5.5, 2.0}}) {
    const SelfDampingModel model = self_damping_model_of(parse_self_damping_law(c.name));
    ASSERT_NO_THROW(model.validate()) << c.name;
    EXPECT_EQ(self_damping_law_name(model.law), c.name);
    const PowerLawExponents e = model.exponents();
    EXPECT_EQ(e.l, c.l) << c.name;
    EXPECT_EQ(e.m, c.m) << c.name;
    EXPECT_EQ(e.n, c.n) << c.name;
  }
  EXPECT_FALSE(published_exponents(SelfDampingLaw::power).has_value());
  EXPECT_EQ(invalid_parameter_message([] { parse_self_damping_law("rawlins"); }),
            "law = 'rawlins': expected one of noiseux-1991, kraus-hagedorn-1991, seppa-1971, moecks-schmidt-1989, "
            "claren-diana-1969, tompkins-1956, polimi-2000, power, foti");
}

TEST(SelfDamping, NoiseuxOnHandNumbers) {
  // ASTER570, Lilien's k = 1.819851, Y = 10 mm, f = 20 Hz, T = 27.795 kN, L = 400 m:
  // 400 * 1.819851 * 0.01^2.44 * 20^5.63 / 27.795^2.76 = 20.96750 W
  const SelfDampingModel noiseux = self_damping_model_of(SelfDampingLaw::noiseux_1991);
  expect_relative(noiseux.power(0.01, 20.0, aster570(), aster570_tension, 400.0), 20.96750, 1e-6);
  SelfDampingModel given_k = noiseux;
  given_k.k = 2.0 * lilien_k(aster570());  // a k of one's own replaces Lilien's
  expect_relative(given_k.power(0.01, 20.0, aster570(), aster570_tension, 400.0), 2.0 * 20.96750, 1e-6);
}

TEST(SelfDamping, RangesPublishedByTheSourceTakeTheUsersValue) {
  SelfDampingModel claren = self_damping_model_of(SelfDampingLaw::claren_diana_1969);  // n: 1.5 to 3
  EXPECT_EQ(invalid_parameter_message([&] { claren.validate(); }),
            "n: law = 'claren-diana-1969' gives n only as a range, 1.5 to 3: give the value to use");
  claren.n = 3.5;
  EXPECT_EQ(invalid_parameter_message([&] { claren.validate(); }),
            "n = 3.5: expected a value from 1.5 to 3 (the range of law = 'claren-diana-1969')");
  claren.n = 2.0;
  ASSERT_NO_THROW(claren.validate());
  const PowerLawExponents e = claren.exponents();
  EXPECT_EQ(e.l, 2.0);
  EXPECT_EQ(e.m, 4.0);
  EXPECT_EQ(e.n, 2.0);
  claren.l = 2.2;  // l is the source's own
  EXPECT_EQ(invalid_parameter_message([&] { claren.validate(); }),
            "l = 2.2: not used by law = 'claren-diana-1969' (it fixes l = 2; law = 'power' takes your own)");

  SelfDampingModel tompkins = self_damping_model_of(SelfDampingLaw::tompkins_1956);  // l 2.3-2.6, m 5-6, n 1.9
  tompkins.l = 2.5;
  EXPECT_EQ(invalid_parameter_message([&] { tompkins.validate(); }),
            "m: law = 'tompkins-1956' gives m only as a range, 5 to 6: give the value to use");
  tompkins.m = 5.5;
  ASSERT_NO_THROW(tompkins.validate());
  EXPECT_EQ(tompkins.exponents().n, 1.9);
}

TEST(SelfDamping, PowerLawTakesTheUsersExponents) {
  SelfDampingModel power = self_damping_model_of(SelfDampingLaw::power);
  power.l = 2.0;
  power.m = 4.0;
  EXPECT_EQ(invalid_parameter_message([&] { power.validate(); }), "n: missing: law = 'power' needs l, m and n");
  power.n = 2.0;
  power.k = 0.5;
  ASSERT_NO_THROW(power.validate());
  // 10 m * 0.5 * 0.02^2 * 10^4 / 30^2 = 10 * 0.5 * 4e-4 * 1e4 / 900 = 0.0222222 W
  expect_relative(power.power(0.02, 10.0, aster570(), 30000.0, 10.0), 0.02 / 0.9, 1e-12);
  power.l = -1.0;
  EXPECT_EQ(invalid_parameter_message([&] { power.validate(); }), "l = -1: expected a finite value > 0");
}

/// Foti & Martinelli's local law: dissipated energy per cycle and length at curvature amplitude chi.
double foti_local_energy(double ei_max, double chi0, double chi) {
  return chi <= chi0 ? ei_max * chi * chi * chi / (2.0 * chi0) : ei_max * chi * chi / 2.0;
}

/// f times the local law's average over a quarter wave (composite Simpson, `n` even).
double foti_by_quadrature(double amplitude, double frequency, double chi0, int n = 20000) {
  const Conductor c = aster570();
  const double k = wavenumber(c, aster570_tension, frequency);
  const double quarter = std::numbers::pi / (2.0 * k);
  const double h = quarter / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += weight * foti_local_energy(c.ei_max, chi0, k * k * amplitude * std::sin(k * i * h));
  }
  return frequency * sum * h / 3.0 / quarter;
}

TEST(SelfDamping, FotiClosedFormIsTheWaveAverageOfItsLocalLaw) {
  const Conductor c = aster570();
  const double chi0 = 0.0211;  // 1/m
  // micro-slip only (chi_m = k^2 Y = 0.0059 < chi0), mixed, mostly gross slip
  for (const auto& [y, f] : {std::pair{0.0265, 10.0}, std::pair{0.010, 40.0}, std::pair{0.100, 40.0}}) {
    expect_relative(foti_self_damping(c, aster570_tension, chi0, y, f), foti_by_quadrature(y, f, chi0), 1e-7);
  }
}

TEST(SelfDamping, FotiIsContinuousWhereGrossSlipStarts) {
  const Conductor c = aster570();
  const double chi0 = 0.0211;
  const double k = wavenumber(c, aster570_tension, 30.0);
  const double onset = chi0 / (k * k);  // chi_m = chi0
  const double below = foti_self_damping(c, aster570_tension, chi0, onset * (1 - 1e-9), 30.0);
  const double above = foti_self_damping(c, aster570_tension, chi0, onset * (1 + 1e-9), 30.0);
  expect_relative(above, below, 1e-7);
  // micro-slip everywhere below the onset: (2/pi)(1/3) f EI_max chi_m^3 / chi0, exactly
  const double chi_m = 0.5 * chi0;
  expect_relative(foti_self_damping(c, aster570_tension, chi0, chi_m / (k * k), 30.0),
                  2.0 / (3.0 * std::numbers::pi) * 30.0 * c.ei_max * std::pow(chi_m, 3) / chi0, 1e-12);
}

TEST(SelfDamping, FotiNeedsTheLimitCurvatureAndEiMax) {
  SelfDampingModel foti = self_damping_model_of(SelfDampingLaw::foti);
  EXPECT_EQ(invalid_parameter_message([&] { foti.validate(); }), "limit_curvature: missing: law = 'foti' needs it (1/m)");
  foti.limit_curvature = 0.0211;
  Conductor c = aster570();
  ASSERT_NO_THROW(foti.validate_with(c));
  expect_relative(foti.power(0.0265, 10.0, c, aster570_tension, 400.0),
                  400.0 * foti_self_damping(c, aster570_tension, 0.0211, 0.0265, 10.0), 1e-15);
  c.ei_max = 0.0;
  EXPECT_EQ(invalid_parameter_message([&] { foti.validate_with(c); }),
            "conductor.ei_max: not given: self_damping law = 'foti' needs it (N m^2)");
  foti.k = 1.8;
  EXPECT_EQ(invalid_parameter_message([&] { foti.validate(); }),
            "k = 1.8: not used by law = 'foti' (a power-law factor)");
  SelfDampingModel noiseux = self_damping_model_of(SelfDampingLaw::noiseux_1991);
  noiseux.limit_curvature = 0.02;
  EXPECT_EQ(invalid_parameter_message([&] { noiseux.validate(); }),
            "limit_curvature = 0.02: not used by law = 'noiseux-1991' (only law = 'foti' uses it)");
}

}  // namespace
}  // namespace stockbridge::span
