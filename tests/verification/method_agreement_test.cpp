// The four periodic solvers agree (where the steady state is unique): harmonic
// balance, trigonometric collocation, time integration and shooting, on Re Z and
// Im Z of the shipped damper, within 0.5 % of |Z|.

#include <complex>
#include <initializer_list>
#include <map>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/io/damper_file.hpp"

namespace stockbridge::damper {
namespace {

struct AgreementCase {
  double frequency_hz;
  double velocity;
};

class MethodAgreement : public ::testing::TestWithParam<AgreementCase> {};

/// The damper of an example file (read once).
const Damper& example(const std::string& name) {
  static std::map<std::string, Damper> dampers;
  auto found = dampers.find(name);
  if (found == dampers.end()) {
    found = dampers.emplace(name, io::read_damper_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/" + name)).first;
  }
  return found->second;
}

std::complex<double> impedance_by(const Damper& damper, Method method, const Excitation& e) {
  SolverOptions options;
  options.method = method;
  const DamperSteadyState s = solve_steady_state(damper, e, options);
  EXPECT_TRUE(s.point.converged()) << method_name(method) << ": " << s.point.failure;
  return s.point.impedance;
}

/// Each of `methods` within 0.5 % of |Z| of harmonic balance, on Re Z and Im Z.
void expect_agreement(const Damper& damper, const AgreementCase& c, std::initializer_list<Method> methods) {
  const Excitation e = Excitation::from_velocity(c.frequency_hz, c.velocity);
  const std::complex<double> reference = impedance_by(damper, Method::harmonic_balance, e);
  for (const Method method : methods) {
    const std::complex<double> z = impedance_by(damper, method, e);
    EXPECT_LT(std::abs(z.real() - reference.real()), 5e-3 * std::abs(reference)) << method_name(method);
    EXPECT_LT(std::abs(z.imag() - reference.imag()), 5e-3 * std::abs(reference)) << method_name(method);
  }
}

TEST_P(MethodAgreement, WithinHalfAPercent) {
  expect_agreement(example("sauter2003.toml"), GetParam(),
                   {Method::collocation, Method::time_integration, Method::shooting});
}

INSTANTIATE_TEST_SUITE_P(SauterDamper, MethodAgreement,
                         ::testing::Values(AgreementCase{12.0, 0.2}, AgreementCase{16.0, 0.2}, AgreementCase{30.0, 0.2}, AgreementCase{50.0, 0.2},
                                           AgreementCase{16.0, 0.05}, AgreementCase{50.0, 0.05}),
                         [](const ::testing::TestParamInfo<AgreementCase>& info) {
                           char name[64];
                           std::snprintf(name, sizeof name, "f%d_v%d", static_cast<int>(info.param.frequency_hz),
                                         static_cast<int>(info.param.velocity * 100));
                           return std::string(name);
                         });

// The same on slenderpy's damper, whose messenger follows the Bouc-Wen law: harmonic
// balance, collocation and time integration within 0.5 % of |Z| below, between and
// above the arm's modes; shooting at one of them (below).
class BoucWenMethodAgreement : public ::testing::TestWithParam<AgreementCase> {};

TEST_P(BoucWenMethodAgreement, WithinHalfAPercent) {
  expect_agreement(example("slenderpy_damper.toml"), GetParam(), {Method::collocation, Method::time_integration});
}

INSTANTIATE_TEST_SUITE_P(SlenderpyDamper, BoucWenMethodAgreement,
                         ::testing::Values(AgreementCase{15.0, 0.2}, AgreementCase{40.0, 0.2}, AgreementCase{80.0, 0.05}),
                         [](const ::testing::TestParamInfo<AgreementCase>& info) {
                           char name[64];
                           std::snprintf(name, sizeof name, "f%d_v%d", static_cast<int>(info.param.frequency_hz),
                                         static_cast<int>(info.param.velocity * 100));
                           return std::string(name);
                         });

// Shooting on the Bouc-Wen damper: the law's memory settles only geometrically, by
// exp(-2 chi_a / chi0) a cycle in a section swinging by chi_a, so the shots' memory
// goes on from where the last stage left it (shooting.hpp) through 800-2200
// periods; 11-26 s an arm, so at one point.
TEST(BoucWenShooting, AgreesWithHarmonicBalanceBetweenTheModes) {
  expect_agreement(example("slenderpy_damper.toml"), {40.0, 0.2}, {Method::shooting});
}

}  // namespace
}  // namespace stockbridge::damper
