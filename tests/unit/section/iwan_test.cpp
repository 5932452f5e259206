// Segalman's four-parameter Iwan model (MODEL.md section 17) against its closed
// forms: the backbone, K_T at zero, M_S at phi_max, the Masing branches and the
// reversal memory, the dissipation per steady cycle, and the limits chi -> 0 and
// beta -> 0 (a uniform density of Jenkin elements).

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/cable/section_law_descriptor.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/section/iwan_section.hpp"
#include "stockbridge/section/masing_section.hpp"
#include "stockbridge/section/sinusoidal_drive.hpp"

namespace stockbridge::section {
namespace {

const IwanParameters kIwanNumbers{2.8, 0.7, 20.0, -0.5, 0.2};

/// MODEL.md 17 written out anew: phi_max, R, S and the backbone.
struct IwanClosedForm {
  double phi_max, r, s, chi, ms;
  explicit IwanClosedForm(const IwanParameters& p) : chi(p.exponent), ms(p.slip_moment) {
    const double c = p.beta + (chi + 1) / (chi + 2);
    phi_max = p.slip_moment * (1 + p.beta) / (p.tangent_stiffness * c);
    r = p.slip_moment * (chi + 1) / (std::pow(phi_max, chi + 2) * c);
    s = p.slip_moment * p.beta / (phi_max * c);
  }
  double backbone(double u) const {
    if (u >= phi_max) return ms;
    return r * std::pow(u, chi + 2) / (chi + 2) + r * u * (std::pow(phi_max, chi + 1) - std::pow(u, chi + 1)) / (chi + 1) +
           s * u;
  }
  double cycle_dissipation(double a) const { return 4 * r * std::pow(a, chi + 3) / ((chi + 2) * (chi + 3)); }
};

double iwan_moment_at(IwanSection& section, double kappa) {
  section.set_trial_curvature(kappa);
  section.commit();
  return section.moment();
}

TEST(Iwan, TheVirginCurveIsTheBackboneWithItsTangentAtZeroAndItsSlipMoment) {
  const IwanClosedForm f(kIwanNumbers);
  IwanSection section(kIwanNumbers);
  EXPECT_NEAR(section.tangent(), kIwanNumbers.ei + kIwanNumbers.tangent_stiffness, 1e-9 * kIwanNumbers.tangent_stiffness);  // K_T at zero
  for (int k = 1; k <= 40; ++k) {
    const double kappa = 1.5 * f.phi_max * k / 40.0;
    const double m = iwan_moment_at(section, kappa);
    EXPECT_NEAR(m, kIwanNumbers.ei * kappa + f.backbone(kappa), 1e-9 * std::abs(m)) << kappa;
  }
  IwanSection fresh(kIwanNumbers);
  const double at_phi_max = iwan_moment_at(fresh, f.phi_max);
  EXPECT_NEAR(at_phi_max - kIwanNumbers.ei * f.phi_max, kIwanNumbers.slip_moment, 1e-9 * kIwanNumbers.slip_moment);  // M_S at phi_max
  EXPECT_NEAR(fresh.tangent(), kIwanNumbers.ei, 1e-9 * kIwanNumbers.ei);
  // The tangent is B'(u) = R (phi_max^(chi+1) - u^(chi+1)) / (chi + 1) + S.
  IwanSection half(kIwanNumbers);
  iwan_moment_at(half, 0.5 * f.phi_max);
  const double u = 0.5 * f.phi_max;
  EXPECT_NEAR(half.tangent() - kIwanNumbers.ei,
              f.r * (std::pow(f.phi_max, f.chi + 1) - std::pow(u, f.chi + 1)) / (f.chi + 1) + f.s, 1e-9 * kIwanNumbers.ei);
}

TEST(Iwan, BranchesAreMasingsWithTheReversalMemory) {
  const IwanClosedForm f(kIwanNumbers);
  const double a = 0.8 * f.phi_max, b = 0.3 * f.phi_max;
  IwanSection section(kIwanNumbers);
  const double ma = iwan_moment_at(section, a) - kIwanNumbers.ei * a;
  // After the reversal at a: M_iwan - M_a = -2 B((a - kappa) / 2).
  for (const double kappa : {0.6 * f.phi_max, b}) {
    const double m = iwan_moment_at(section, kappa) - kIwanNumbers.ei * kappa;
    EXPECT_NEAR(m, ma - 2 * f.backbone(0.5 * (a - kappa)), 1e-9 * kIwanNumbers.slip_moment) << kappa;
  }
  // Back up from b: on the branch from b until a, then on the virgin curve again.
  const double mb = ma - 2 * f.backbone(0.5 * (a - b));
  const double up = 0.6 * f.phi_max;
  EXPECT_NEAR(iwan_moment_at(section, up) - kIwanNumbers.ei * up, mb + 2 * f.backbone(0.5 * (up - b)), 1e-9 * kIwanNumbers.slip_moment);
  const double beyond = 0.95 * f.phi_max;
  EXPECT_NEAR(iwan_moment_at(section, beyond) - kIwanNumbers.ei * beyond, f.backbone(beyond), 1e-9 * kIwanNumbers.slip_moment);
  // Down past -a from a reversal on the virgin curve: the virgin curve's negative side.
  const double down = -0.97 * f.phi_max;
  EXPECT_NEAR(iwan_moment_at(section, down) - kIwanNumbers.ei * down, -f.backbone(0.97 * f.phi_max), 1e-9 * kIwanNumbers.slip_moment);
}

TEST(Iwan, ASteadyCycleDissipatesTheIwanClosedForm) {
  for (const IwanParameters& p : {kIwanNumbers, IwanParameters{2.8, 0.7, 20.0, -0.2, 0.0}, IwanParameters{5.0, 1.2, 60.0, 0.0, 1.0}}) {
    const IwanClosedForm f(p);
    for (const double fraction : {0.2, 0.6, 0.95}) {
      IwanSection section(p);
      const double a = fraction * f.phi_max;
      const LoopRecord record = run_loop(section, SinusoidalDrive{a, 3, 400});
      const double expected = f.cycle_dissipation(a);
      EXPECT_NEAR(record.last_cycle_dissipation(), expected, 1e-9 * expected) << p.exponent << " " << fraction;
    }
  }
}

TEST(Iwan, WithChiAndBetaToZeroItIsAUniformDensityOfJenkinElements) {
  const IwanParameters uniform{2.8, 0.7, 20.0, 0.0, 0.0};
  const IwanClosedForm f(uniform);
  // rho = R on (0, phi_max): B(u) = R phi_max u - R u^2 / 2.
  IwanSection section(uniform);
  for (int k = 1; k <= 10; ++k) {
    const double u = f.phi_max * k / 10.0;
    const double m = iwan_moment_at(section, u) - uniform.ei * u;
    EXPECT_NEAR(m, f.r * f.phi_max * u - 0.5 * f.r * u * u, 1e-9 * uniform.slip_moment) << u;
  }
  // The limits are continuous: chi and beta of 1e-8 move the backbone by about as much.
  IwanSection near(IwanParameters{2.8, 0.7, 20.0, -1e-8, 1e-8});
  IwanSection at(uniform);
  for (int k = 1; k <= 10; ++k) {
    const double u = 1.2 * f.phi_max * k / 10.0;
    EXPECT_NEAR(iwan_moment_at(near, u), iwan_moment_at(at, u), 1e-7 * uniform.slip_moment) << u;
  }
  // And a uniform density of 2000 Jenkin elements (stiffness R phi_max / n each,
  // slipping at (j + 1/2) phi_max / n) follows it within 1e-6 of M_S.
  MasingParameters jenkins{uniform.ei, {}};
  const int n = 2000;
  for (int j = 0; j < n; ++j) {
    const double phi = (j + 0.5) * f.phi_max / n;
    const double c = f.r * f.phi_max / n;
    jenkins.jenkin.push_back({c, c * phi});
  }
  MasingSection masing(jenkins);
  IwanSection iwan(uniform);
  for (const double kappa : {0.5 * f.phi_max, -0.3 * f.phi_max, 1.2 * f.phi_max}) {
    masing.set_trial_curvature(kappa);
    masing.commit();
    EXPECT_NEAR(masing.moment(), iwan_moment_at(iwan, kappa), 1e-6 * uniform.slip_moment) << kappa;
  }
}

TEST(Iwan, TheNumbersAreCheckedAndNamed) {
  auto message = [](IwanParameters p) {
    try {
      IwanSection section(p);
    } catch (const InvalidParameter& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message({2.8, 0.7, 20.0, -1.0, 0.2}).rfind("exponent = -1", 0), 0u);
  EXPECT_EQ(message({2.8, 0.7, 20.0, 0.1, 0.2}).rfind("exponent = 0.1", 0), 0u);
  EXPECT_EQ(message({2.8, 0.7, 20.0, -0.5, -0.1}).rfind("beta = -0.1", 0), 0u);
  EXPECT_EQ(message({2.8, 0.0, 20.0, -0.5, 0.1}).rfind("slip_moment", 0), 0u);
  ASSERT_NE(cable::find_section_law("iwan"), nullptr);
  EXPECT_EQ(cable::find_section_law("iwan")->takes(), "ei, slip_moment, tangent_stiffness, exponent and beta");
}

}  // namespace
}  // namespace stockbridge::section
