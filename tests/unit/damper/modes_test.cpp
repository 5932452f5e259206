// Linear modes of arms and dampers (damper/modes.hpp): the example's frequencies
// (MODEL.md section 4), the uniform cable's closed form, the tip stiffness against
// finite differences of the nonlinear cantilever in the stick and slip limits, and
// the clamp-free damper against exact facts (heavy clamp, symmetric arms,
// interlacing, massless clamp, the full eigen-equation built here from MODEL.md).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/damper/modes.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "support/damper_fixtures.hpp"

namespace stockbridge::damper {
namespace {

using testing::arm_mass_matrix;
using testing::beam_tip_stiffness;
using testing::damper_of;
using testing::sauter_arm;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// A second, different arm: shorter, lighter, with two elements.
ArmDescription short_arm() {
  ArmDescription a;
  a.name = "short";
  a.mass = 0.55;
  a.inertia = 0.0009;
  a.offset = 0.02;
  a.cable = cable::CableDescription::uniform(0.14, 30, 3.1, {{15.0, 0.6}, {4.0, 0.2}});
  return a;
}

/// A cable whose ei, c and h vary along it (tables), two elements.
cable::CableDescription profiled_cable() {
  cable::CableDescription d;
  d.length = 0.2;
  d.sections = 12;
  d.ei = cable::Profile::table({0.0, 0.08, 0.2}, {3.4, 2.8, 2.2}, "ei");
  cable::JenkinProfile first, second;
  first.c = cable::Profile::table({0.0, 0.2}, {24.0, 14.0}, "c");
  first.h = cable::Profile::table({0.0, 0.1, 0.2}, {0.8, 0.6, 0.5}, "h");
  second.c = cable::Profile::constant(5.0);
  second.h = cable::Profile::table({0.0, 0.2}, {0.2, 0.1}, "h");
  d.jenkin = {first, second};
  return d;
}

std::vector<double> sorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v;
}

std::vector<double> free_frequencies(const LimitModes& modes) {
  std::vector<double> f;
  for (const DamperMode& mode : modes.damper) f.push_back(mode.frequency_hz);
  return f;
}

std::vector<double> held_frequencies(const LimitModes& modes) {
  std::vector<double> f;
  for (const ArmModes& arm : modes.arms) f.insert(f.end(), {arm.frequencies_hz(0), arm.frequencies_hz(1)});
  return sorted(f);
}

// MODEL.md section 4: the verification damper's arms, 21.2 / 68.2 Hz sticking
// (EI = 22.8), 7.4 / 23.9 Hz slipping (EI = 2.8); read from the shipped example.
TEST(Modes, TheExampleArmsHaveTheDissertationsFrequencies) {
  const Damper damper = io::read_damper_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/sauter2003.toml");
  const DamperModes modes = damper_modes(damper);
  ASSERT_EQ(modes.stick.arms.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(modes.stick.arms[k].frequencies_hz(0), 21.2, 0.05);
    EXPECT_NEAR(modes.stick.arms[k].frequencies_hz(1), 68.2, 0.05);
    EXPECT_NEAR(modes.slip.arms[k].frequencies_hz(0), 7.4, 0.05);
    EXPECT_NEAR(modes.slip.arms[k].frequencies_hz(1), 23.9, 0.05);
  }
  EXPECT_EQ(modes.stick.limit, CableLimit::stick);
  EXPECT_EQ(modes.slip.limit, CableLimit::slip);
  EXPECT_EQ(cable_limit_name(CableLimit::stick), "stick");
  EXPECT_EQ(cable_limit_name(CableLimit::slip), "slip");
  // The clamp-free damper: four elastic modes (the rigid-body mode left out), all > 0.
  ASSERT_EQ(modes.stick.damper.size(), 4u);
  ASSERT_EQ(modes.slip.damper.size(), 4u);
  for (const DamperMode& mode : modes.stick.damper) EXPECT_GT(mode.frequency_hz, 1.0);
}

// Uniform cable: K = EI/l^3 [[12, -6 l], [-6 l, 4 l^2]] (F, Q over x, phi; the
// cantilever's convention M(s) = Q + F (l - s), so x = F l^3/(3EI) + Q l^2/(2EI),
// phi = F l^2/(2EI) + Q l/EI, whose inverse this is); Gauss-Legendre with two
// points or more integrates the flexibility's polynomials exactly.
TEST(Modes, UniformCableTipStiffnessIsTheBeamsClosedForm) {
  for (const int sections : {2, 7, 40}) {
    ArmDescription description = sauter_arm(sections);
    const Arm arm(description);
    const double l = description.cable.length;
    const Eigen::Matrix2d stick = linear_tip_stiffness(arm, CableLimit::stick);
    const Eigen::Matrix2d slip = linear_tip_stiffness(arm, CableLimit::slip);
    EXPECT_TRUE(stick.isApprox(beam_tip_stiffness(22.8, l), 1e-12)) << sections << "\n" << stick;
    EXPECT_TRUE(slip.isApprox(beam_tip_stiffness(2.8, l), 1e-12)) << sections << "\n" << slip;
    EXPECT_LT(stick(0, 1), 0.0);  // the sign of the coupling
    EXPECT_TRUE(stick.isApprox(arm.stick_stiffness(), 1e-12));  // the virgin cantilever's
  }
}

// The 2x2 eigenproblem by hand: det(K - lambda M) = 0 is
// det(M) lambda^2 - (K11 M22 + K22 M11 - 2 K12 M12) lambda + det(K) = 0.
TEST(Modes, ArmFrequenciesSolveTheTwoByTwoDeterminant) {
  for (const ArmDescription& description : {sauter_arm(), short_arm()}) {
    const Arm arm(description);
    for (const CableLimit limit : {CableLimit::stick, CableLimit::slip}) {
      double ei = description.cable.ei.at(0.0);
      if (limit == CableLimit::stick) {
        for (const auto& e : description.cable.jenkin) ei += e.c.at(0.0);
      }
      const Eigen::Matrix2d k = beam_tip_stiffness(ei, description.cable.length);
      const Eigen::Matrix2d m = arm_mass_matrix(description);
      const double a = m.determinant();
      const double b = k(0, 0) * m(1, 1) + k(1, 1) * m(0, 0) - 2.0 * k(0, 1) * m(0, 1);
      const double c = k.determinant();
      const double root = std::sqrt(b * b - 4.0 * a * c);
      const double low = std::sqrt((b - root) / (2.0 * a)) / kTwoPi;
      const double high = std::sqrt((b + root) / (2.0 * a)) / kTwoPi;
      const ArmModes modes = arm_modes(arm, limit);
      EXPECT_NEAR(modes.frequencies_hz(0), low, 1e-9 * low);
      EXPECT_NEAR(modes.frequencies_hz(1), high, 1e-9 * high);
      // Shapes: K s = w^2 M s, unit modal mass, x >= 0.
      for (int i = 0; i < 2; ++i) {
        const Eigen::Vector2d s = modes.shapes.col(i);
        const double w2 = std::pow(kTwoPi * modes.frequencies_hz(i), 2);
        EXPECT_LT((k * s - w2 * m * s).norm(), 1e-8 * (k * s).norm());
        EXPECT_NEAR(s.dot(m * s), 1.0, 1e-12);
        EXPECT_GE(s(0), 0.0);
      }
    }
  }
}

/// (F, Q) of the cantilever's trial state.
Eigen::Vector2d tip_loads(const cable::Cantilever& cantilever) {
  const cable::CableState& s = cantilever.trial();
  return {s.tip_force, s.tip_moment(cantilever.cable().length())};
}

// K in the stick limit is the nonlinear cantilever's tangent at small amplitude
// from the virgin state (every element sticks), profiles and two elements included.
TEST(Modes, StickStiffnessIsTheCantileversSmallAmplitudeTangent) {
  ArmDescription description = sauter_arm();
  description.cable = profiled_cable();
  const Arm arm(description);
  const Eigen::Matrix2d k = linear_tip_stiffness(arm, CableLimit::stick);
  cable::Cantilever cantilever{cable::Cable(description.cable)};
  const std::vector<double> virgin_tangent = cantilever.committed().tangent;
  const double l = description.cable.length;
  for (const Eigen::Vector2d& direction : {Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, 1.0),
                                           Eigen::Vector2d(-0.4 * l, 1.0), Eigen::Vector2d(-1.0, -2.0)}) {
    const Eigen::Vector2d step = 1e-6 * direction;  // (x, phi): far below any slip
    ASSERT_TRUE(cantilever.set_trial_tip(step(0), step(1)).converged());
    for (std::size_t i = 0; i < virgin_tangent.size(); ++i) {  // nothing slipped (equal up to the order of the sum)
      EXPECT_NEAR(cantilever.trial().tangent[i], virgin_tangent[i], 1e-12 * virgin_tangent[i]) << i;
    }
    const Eigen::Vector2d expected = k * step;
    EXPECT_LT((tip_loads(cantilever) - expected).norm(), 1e-8 * expected.norm()) << direction.transpose();
  }
}

// K in the slip limit is the cantilever's tangent deep in slip: a large clamp moment
// alone (M(s) = T everywhere, beyond every slip moment) makes every section slip;
// tip increments that raise M(s) everywhere keep them slipping, and the load
// increments are K times the kinematic ones (the map is linear while no section
// changes state, so the finite difference is exact up to Newton's tolerance).
TEST(Modes, SlipStiffnessIsTheCantileversTangentDeepInSlip) {
  ArmDescription description = sauter_arm();
  description.cable = profiled_cable();
  const Arm arm(description);
  const Eigen::Matrix2d k = linear_tip_stiffness(arm, CableLimit::slip);
  const cable::Cable cable(description.cable);
  cable::Cantilever cantilever{cable};
  cantilever.set_trial_loads(3.0, 0.0);  // T = 3 N m > sum h everywhere (1.0 at most)
  cantilever.commit();
  const cable::CableState base = cantilever.committed();
  for (std::size_t i = 0; i < cable.sections(); ++i) ASSERT_EQ(base.tangent[i], cable.law().slip_stiffness(i)) << i;
  const Eigen::Vector2d base_loads(base.tip_force, base.tip_moment(cable.length()));
  const double l = cable.length();
  int checked = 0;
  for (const double ratio : {0.45, 0.5, 0.55}) {  // x / phi near l/2 (pure moment)
    const Eigen::Vector2d step = 1e-4 * Eigen::Vector2d(ratio * l, 1.0);
    ASSERT_TRUE(cantilever.set_trial_tip(base.deflection + step(0), base.rotation + step(1)).converged());
    bool all_slip = true;
    for (std::size_t i = 0; i < cable.sections(); ++i) all_slip = all_slip && cantilever.trial().tangent[i] == cable.law().slip_stiffness(i);
    if (!all_slip) continue;
    const Eigen::Vector2d expected = k * step;
    EXPECT_LT((tip_loads(cantilever) - base_loads - expected).norm(), 1e-6 * expected.norm()) << ratio;
    ++checked;
  }
  EXPECT_EQ(checked, 3);  // three directions span (x, phi) twice over
  // And the limits differ: this is not the stick tangent.
  EXPECT_FALSE(k.isApprox(linear_tip_stiffness(arm, CableLimit::stick), 1e-2));
}

// The clamp-free modes solve the whole damper's equations, built here from MODEL.md
// section 4's kinetic energy m_c x_c'^2/2 + sum m (x_c' + x' - b phi')^2/2 +
// Theta phi'^2/2 and the beam's K on the relative coordinates: (K - w^2 M) q = 0
// for q = (x_c, x_1, phi_1, x_2, phi_2), with unit modal mass q^T M q = 1.
TEST(Modes, ClampFreeModesSolveTheWholeDampersEquations) {
  const ArmDescription left = sauter_arm(), right = short_arm();
  const Damper damper = damper_of({left, right}, 0.7);
  const LimitModes modes = linear_modes(damper, CableLimit::stick);
  ASSERT_EQ(modes.damper.size(), 4u);  // 2K elastic modes; the rigid-body mode is not listed
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(5, 5), stiffness = Eigen::MatrixXd::Zero(5, 5);
  mass(0, 0) = 0.7;
  const std::vector<ArmDescription> arms{left, right};
  for (int k = 0; k < 2; ++k) {
    const ArmDescription& a = arms[static_cast<std::size_t>(k)];
    Eigen::VectorXd centre = Eigen::VectorXd::Zero(5), rotation = Eigen::VectorXd::Zero(5);
    centre << 1.0, 0.0, 0.0, 0.0, 0.0;
    centre(1 + 2 * k) = 1.0;
    centre(2 + 2 * k) = -a.offset;
    rotation(2 + 2 * k) = 1.0;
    mass += a.mass * centre * centre.transpose() + a.inertia * rotation * rotation.transpose();
    double ei = a.cable.ei.at(0.0);
    for (const auto& e : a.cable.jenkin) ei += e.c.at(0.0);
    stiffness.block<2, 2>(1 + 2 * k, 1 + 2 * k) = beam_tip_stiffness(ei, a.cable.length);
  }
  double previous = 0.0;
  for (const DamperMode& mode : modes.damper) {
    EXPECT_GT(mode.frequency_hz, previous);  // ascending, distinct here
    previous = mode.frequency_hz;
    Eigen::VectorXd q(5);
    q << mode.clamp_deflection, mode.arms[0], mode.arms[1];
    const double w2 = std::pow(kTwoPi * mode.frequency_hz, 2);
    EXPECT_LT((stiffness * q - w2 * mass * q).norm(), 1e-8 * (stiffness * q).norm()) << mode.frequency_hz;
    EXPECT_NEAR(q.dot(mass * q), 1.0, 1e-9);
    EXPECT_NEAR(mode.clamp_energy_share + mode.arm_energy_share[0] + mode.arm_energy_share[1], 1.0, 1e-12);
    EXPECT_GE(std::max(std::abs(q(0)), std::max(std::abs(q(1)), std::abs(q(3)))),
              -std::min(q(0), std::min(q(1), q(3))));  // the largest translation is positive
  }
  // The rigid-body mode: q = (1, 0, 0, 0, 0) is a mode at 0 Hz.
  Eigen::VectorXd rigid = Eigen::VectorXd::Zero(5);
  rigid(0) = 1.0;
  EXPECT_EQ((stiffness * rigid).norm(), 0.0);
}

// A clamp far heavier than the arms hardly moves: the clamp-free frequencies tend to
// the clamp-held ones of all arms together (M_r = M - g g^T / m_total -> M).
TEST(Modes, AHeavyClampGivesTheClampHeldFrequencies) {
  const Damper damper = damper_of({sauter_arm(), short_arm()}, 1e9);
  for (const CableLimit limit : {CableLimit::stick, CableLimit::slip}) {
    const LimitModes modes = linear_modes(damper, limit);
    const std::vector<double> held = held_frequencies(modes), free = free_frequencies(modes);
    ASSERT_EQ(free.size(), held.size());
    for (std::size_t i = 0; i < held.size(); ++i) EXPECT_NEAR(free[i], held[i], 1e-6 * held[i]) << i;
    for (const DamperMode& mode : modes.damper) EXPECT_LT(mode.clamp_energy_share, 1e-8);
  }
}

// Two identical arms: with u_1 = -u_2 the clamp's coupling g^T u cancels, so x_c = 0
// and each arm moves as with the clamp held: every clamp-held frequency is a
// clamp-free one (the antisymmetric modes), with the clamp still and the energy
// shared equally. The symmetric modes (u_1 = u_2) move the clamp and lie higher.
TEST(Modes, IdenticalArmsKeepTheClampStillInAntisymmetricModes) {
  const Damper damper = damper_of({sauter_arm(), sauter_arm()}, 0.7);
  for (const CableLimit limit : {CableLimit::stick, CableLimit::slip}) {
    const LimitModes modes = linear_modes(damper, limit);
    ASSERT_EQ(modes.damper.size(), 4u);
    for (const double held : {modes.arms[0].frequencies_hz(0), modes.arms[0].frequencies_hz(1)}) {
      const auto match = std::find_if(modes.damper.begin(), modes.damper.end(), [&](const DamperMode& m) {
        return std::abs(m.frequency_hz - held) < 1e-9 * held;
      });
      ASSERT_NE(match, modes.damper.end()) << held;
      EXPECT_LT(std::abs(match->clamp_deflection), 1e-9 * match->arms[0].norm());
      EXPECT_LT((match->arms[0] + match->arms[1]).norm(), 1e-9 * match->arms[0].norm());
      EXPECT_NEAR(match->arm_energy_share[0], 0.5, 1e-9);
      // Ties decided the same way every time, not by round-off: the first arm.
      EXPECT_GT(match->arms[0](0), 0.0);
      EXPECT_EQ(match->dominant_arm, 0u);
    }
    for (const DamperMode& m : modes.damper) EXPECT_EQ(m.dominant_arm, 0u);
    // The symmetric modes: above the held ones (interlacing), with the clamp moving.
    int moving = 0;
    for (const DamperMode& m : modes.damper) moving += std::abs(m.clamp_deflection) > 1e-3 * m.arms[0].norm();
    EXPECT_EQ(moving, 2);
  }
}

// M_r is M less a rank-one positive term: the clamp-free frequencies interlace with
// the clamp-held ones, held_i <= free_i <= held_{i+1}. For one arm (two distinct held
// frequencies, generic coupling) strictly: held_1 < free_1 < held_2 < free_2.
TEST(Modes, ClampFreeFrequenciesInterlaceWithClampHeldOnes) {
  for (const std::vector<ArmDescription>& arms :
       {std::vector<ArmDescription>{sauter_arm()}, std::vector<ArmDescription>{short_arm()},
        std::vector<ArmDescription>{sauter_arm(), short_arm()},
        std::vector<ArmDescription>{sauter_arm(), short_arm(), sauter_arm()}}) {
    for (const double clamp_mass : {0.05, 0.7, 5.0}) {
      const Damper damper = damper_of(arms, clamp_mass);
      for (const CableLimit limit : {CableLimit::stick, CableLimit::slip}) {
        const LimitModes modes = linear_modes(damper, limit);
        const std::vector<double> held = held_frequencies(modes), free = free_frequencies(modes);
        ASSERT_EQ(free.size(), held.size());
        for (std::size_t i = 0; i < held.size(); ++i) {
          EXPECT_GE(free[i], held[i] * (1.0 - 1e-12)) << i;
          if (i + 1 < held.size()) {
            EXPECT_LE(free[i], held[i + 1] * (1.0 + 1e-12)) << i;
          }
        }
        if (arms.size() == 1) {
          EXPECT_GT(free[0], held[0] * (1.0 + 1e-6));
          EXPECT_LT(free[0], held[1] * (1.0 - 1e-6));
          EXPECT_GT(free[1], held[1] * (1.0 + 1e-6));
        }
      }
    }
  }
}

// A massless clamp carrying one arm transmits no tip force in free vibration
// (m_c x_c'' = F = 0): G stands still, x = -K12/K11 phi, and the arm turns about G
// with stiffness K22 - K12^2/K11 = EI/l (uniform cable): w^2 = EI / (l Theta). The
// other mode is at infinite frequency and is left out.
TEST(Modes, AMasslessClampWithOneArmLeavesOneMode) {
  const ArmDescription arm = sauter_arm();
  const Damper damper = damper_of({arm}, 0.0);
  const DamperModes modes = damper_modes(damper);
  ASSERT_EQ(modes.stick.damper.size(), 1u);
  ASSERT_EQ(modes.slip.damper.size(), 1u);
  const double l = arm.cable.length;
  EXPECT_NEAR(modes.stick.damper[0].frequency_hz, std::sqrt(22.8 / (l * arm.inertia)) / kTwoPi, 1e-9);
  EXPECT_NEAR(modes.slip.damper[0].frequency_hz, std::sqrt(2.8 / (l * arm.inertia)) / kTwoPi, 1e-9);
  EXPECT_EQ(modes.stick.damper[0].clamp_energy_share, 0.0);
  // With two arms and a massless clamp: 2K - 1 = 3 modes, interlacing still.
  const LimitModes two = linear_modes(damper_of({sauter_arm(), short_arm()}, 0.0), CableLimit::stick);
  ASSERT_EQ(two.damper.size(), 3u);
  const std::vector<double> held = held_frequencies(two), free = free_frequencies(two);
  for (std::size_t i = 0; i < free.size(); ++i) {
    EXPECT_GE(free[i], held[i] * (1.0 - 1e-12));
    EXPECT_LE(free[i], held[i + 1] * (1.0 + 1e-12));
  }
}

// The dominant arm is the one holding most of a mode's energy.
TEST(Modes, TheDominantArmHoldsMostOfTheEnergy) {
  const Damper damper = damper_of({sauter_arm(), short_arm()}, 0.7);
  const LimitModes modes = linear_modes(damper, CableLimit::slip);
  std::vector<std::size_t> dominant;
  for (const DamperMode& mode : modes.damper) {
    dominant.push_back(mode.dominant_arm);
    for (const double share : mode.arm_energy_share) EXPECT_LE(share, mode.arm_energy_share[mode.dominant_arm]);
  }
  // Both arms dominate some mode (the arms are far apart in frequency).
  EXPECT_NE(std::count(dominant.begin(), dominant.end(), 0u), 0);
  EXPECT_NE(std::count(dominant.begin(), dominant.end(), 1u), 0);
}

}  // namespace
}  // namespace stockbridge::damper
