// Dampers on a span end by travelling waves: the closed-form limits of MODEL.md
// section 9 and the energy identity P_d = sum Re Z_j w^2 |Y_j|^2 / 2.

#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "stockbridge/span/travelling_wave.hpp"

namespace stockbridge::span {
namespace {

using namespace std::complex_literals;
constexpr double kPi = std::numbers::pi;

/// ASTER570 at 15 % RTS, 20 Hz: T = 27795 N, m = 1.571 kg/m.
StringWave aster_wave(double f = 20.0) {
  const double tension = 0.15 * 185300.0, m = 1.571;
  const double c = std::sqrt(tension / m), w = 2.0 * kPi * f;
  return {w, w / c, std::sqrt(tension * m)};
}

TEST(TravellingWave, WithoutDampersTheLoopIsTheAntinode) {
  const EndResponse r = end_response(aster_wave(), {}, {}, 0.01);
  EXPECT_NEAR(r.loop_amplitude, 0.01, 1e-15);
  EXPECT_NEAR(r.incoming, 0.005, 1e-15);
  EXPECT_NEAR(r.outgoing, 0.005, 1e-15);
  EXPECT_NEAR(r.absorbed_power, 0.0, 1e-12);
}

TEST(TravellingWave, ADamperAtANodeAbsorbsNothing) {
  const StringWave wave = aster_wave();
  const EndResponse r = end_response(wave, {kPi / wave.wavenumber}, {150.0 + 40.0i}, 0.01);
  EXPECT_NEAR(std::abs(r.damper_displacement[0]), 0.0, 1e-15);
  EXPECT_NEAR(r.absorbed_power, 0.0, 1e-9);
  EXPECT_NEAR(r.loop_amplitude, 0.01, 1e-14);
}

TEST(TravellingWave, AMatchedDamperAtAQuarterWaveAbsorbsTheWholeIncomingWave) {
  const StringWave wave = aster_wave();
  const EndResponse r = end_response(wave, {0.5 * kPi / wave.wavenumber}, {wave.wave_impedance}, 0.01);
  EXPECT_NEAR(r.outgoing, 0.0, 1e-15);
  EXPECT_NEAR(r.incoming, 0.01, 1e-15);
  const double w = wave.angular_frequency;
  EXPECT_NEAR(r.absorbed_power, 0.5 * wave.wave_impedance * w * w * 1e-4, 1e-12 * r.absorbed_power);
}

TEST(TravellingWave, AWeakDamperGivesTheClassicWeakForm) {
  const StringWave wave = aster_wave();
  const double a = 1.2, w = wave.angular_frequency, y = 0.01;
  for (const double scale : {1e-2, 1e-3, 1e-4}) {
    const std::complex<double> z = scale * wave.wave_impedance * (1.0 + 0.5i);
    const EndResponse r = end_response(wave, {a}, {z}, y);
    const double weak = 0.5 * z.real() * w * w * y * y * std::pow(std::sin(wave.wavenumber * a), 2);
    EXPECT_NEAR(r.absorbed_power, weak, 3.0 * scale * weak) << scale;  // first order in |Z| / Z0
  }
}

TEST(TravellingWave, APureMassIsTheClosedFormOfAStringWithAPointMass) {
  // Left of the mass S sin(k x); right a standing wave C sin(k (x - a) + theta) of
  // antinode |C| = Y. Continuity and the jump T (Y'+ - Y'-) = -w^2 M Y(a) give
  // S / Y = 1 / sqrt(sin^2(k a) + (cos(k a) - mu sin(k a))^2), mu = w^2 M / (T k).
  const StringWave wave = aster_wave();
  const double w = wave.angular_frequency, k = wave.wavenumber, mass = 2.5;
  const double tension = wave.wave_impedance * w / k;  // Z0 = T / c = T k / w
  const double mu = w * w * mass / (tension * k);
  for (const double a : {0.3, 1.0, 2.2, 4.0}) {
    const EndResponse r = end_response(wave, {a}, {1i * w * mass}, 0.02);
    const double ka = k * a;
    const double expected = 1.0 / std::sqrt(std::pow(std::sin(ka), 2) + std::pow(std::cos(ka) - mu * std::sin(ka), 2));
    EXPECT_NEAR(r.loop_amplitude / 0.02, expected, 1e-12 * expected) << a;
    EXPECT_NEAR(r.absorbed_power, 0.0, 1e-9) << a;
  }
}

/// 1 to 3 dampers (by `trial`) at random positions along an end, with random impedances.
struct RandomEnd {
  std::vector<double> positions;
  std::vector<std::complex<double>> z;
};
RandomEnd random_end(std::mt19937& random, int trial, double spacing, double re_z, double im_z) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RandomEnd end;
  double a = 0.0;
  for (int j = 0; j < 1 + trial % 3; ++j) {
    a += spacing * (0.2 + u(random));
    end.positions.push_back(a);
    end.z.emplace_back(re_z * u(random), im_z * (u(random) - 0.5));
  }
  return end;
}

TEST(TravellingWave, TheEndAbsorbsWhatItsDampersDissipate) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const StringWave wave = aster_wave(5.0 + 100.0 * u(random));
    const RandomEnd end = random_end(random, trial, 2.0, 400.0, 600.0);
    const EndResponse r = end_response(wave, end.positions, end.z, 0.005 + 0.02 * u(random));
    EXPECT_NEAR(r.absorbed_power, r.damper_power, 1e-10 * std::max(1.0, r.damper_power)) << trial;
    EXPECT_GE(r.damper_power, 0.0);
  }
}

// The polish's Jacobian rests on this: the exact change of the response with the
// impedances, against central differences along random directions (the response
// is smooth in Z away from a node of a damper, where log |Y_j| is not).
TEST(TravellingWave, TheTangentIsTheDifferenceQuotientOfTheResponse) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const StringWave wave = aster_wave(5.0 + 40.0 * u(random));
    RandomEnd end = random_end(random, trial, 1.5, 300.0, 400.0);
    const std::vector<double>& positions = end.positions;
    std::vector<std::complex<double>>& z = end.z;
    std::vector<std::complex<double>> direction;
    for (std::complex<double>& zj : z) {
      zj += 50.0;  // away from a damper of no resistance
      direction.emplace_back(u(random) - 0.5, u(random) - 0.5);
    }
    const double antinode = 0.01;
    const EndResponseTangent t = end_response_tangent(wave, positions, z, direction, antinode);
    const double h = 1e-4;
    const auto moved = [&](double step) {
      std::vector<std::complex<double>> zs = z;
      for (std::size_t j = 0; j < zs.size(); ++j) zs[j] += step * direction[j];
      return end_response(wave, positions, zs, antinode);
    };
    const EndResponse plus = moved(h), minus = moved(-h);
    const double d_power = (plus.absorbed_power - minus.absorbed_power) / (2.0 * h);
    EXPECT_NEAR(t.absorbed_power, d_power, 1e-6 * std::max(1.0, std::abs(d_power))) << trial;
    for (std::size_t j = 0; j < positions.size(); ++j) {
      const double d_log = (std::log(std::abs(plus.damper_displacement[j])) - std::log(std::abs(minus.damper_displacement[j]))) /
                           (2.0 * h);
      EXPECT_NEAR(t.log_displacement[j], d_log, 1e-6 * std::max(1.0, std::abs(d_log))) << trial << ", damper " << j;
    }
  }
}

// The balance's fixed point takes its Newton steps on this: a chain made once gives
// end_response's displacements, and every column of its Jacobian d ln|Y_j| / d s_m
// (dZ_m = slope_m ds_m) is end_response_tangent along that damper alone, with a
// mass in the chain.
TEST(TravellingWave, AChainsJacobianIsTheTangentAlongEachDamper) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    const StringWave wave = aster_wave(5.0 + 40.0 * u(random));
    RandomEnd end = random_end(random, trial, 1.5, 300.0, 400.0);
    for (std::complex<double>& zj : end.z) zj += 50.0;
    EndAttachments masses;
    masses.mass_positions = {0.5 * end.positions.back() + 0.3, end.positions.back() + 4.0};
    masses.masses = {8.0, 15.0};
    const double antinode = 0.01;
    const std::size_t n = end.z.size();
    const EndChain chain(wave, end.positions, masses);
    const EndResponse r = end_response(wave, end.positions, end.z, antinode, masses);
    std::vector<std::complex<double>> y(n), slopes;
    chain.displacements(end.z.data(), antinode, y.data());
    for (std::size_t j = 0; j < n; ++j) {
      EXPECT_NEAR(std::abs(y[j] - r.damper_displacement[j]), 0.0, 1e-14 * std::abs(r.damper_displacement[j])) << trial;
      slopes.emplace_back(u(random) - 0.5, u(random) - 0.5);
    }
    std::vector<double> jacobian(n * n);
    chain.log_displacement_jacobian(end.z.data(), slopes.data(), jacobian.data());
    for (std::size_t m = 0; m < n; ++m) {
      std::vector<std::complex<double>> direction(n, 0.0);
      direction[m] = slopes[m];
      const EndResponseTangent t = end_response_tangent(wave, end.positions, end.z, direction, antinode, masses);
      for (std::size_t j = 0; j < n; ++j) {
        EXPECT_NEAR(jacobian[j * n + m], t.log_displacement[j], 1e-12 * std::max(1.0, std::abs(t.log_displacement[j])))
            << trial << ": damper " << j << " along " << m;
      }
    }
  }
}

}  // namespace
}  // namespace stockbridge::span
