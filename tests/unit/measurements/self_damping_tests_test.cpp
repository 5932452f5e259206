// The self-damping law fitted to tests: exact recovery from noiseless points, the
// standard errors of a factorial design by hand, the one-tension case, the designs
// refused, the reader's errors and slips, and the -o table read back by a span file.

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/measurements/self_damping_tests.hpp"
#include "stockbridge/requests/self_damping_request.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::measurements {
namespace {

constexpr double kSdtK = 1.872, kSdtL = 2.44, kSdtM = 5.63, kSdtN = 2.76;

double sdt_law_power(double tension, double frequency, double amplitude) {
  return kSdtK * std::pow(amplitude, kSdtL) * std::pow(frequency, kSdtM) / std::pow(tension / 1000.0, kSdtN);
}

/// 3 tensions x 4 frequencies x 3 amplitudes on the law, noiseless.
std::vector<SelfDampingTest> sdt_noiseless(const std::vector<double>& tensions = {20000.0, 28000.0, 35000.0}) {
  std::vector<SelfDampingTest> tests;
  for (double t : tensions) {
    for (double f : {10.0, 20.0, 35.0, 50.0}) {
      for (double product : {0.02, 0.05, 0.11}) {
        const double y = product / f * (1.0 + 0.1 * t / 35000.0);  // amplitudes not all f-proportional
        tests.push_back({t, f, y, sdt_law_power(t, f, y)});
      }
    }
  }
  return tests;
}

TEST(SelfDampingFit, RecoversANoiselessLawExactly) {
  const SelfDampingFit fit = fit_self_damping(sdt_noiseless());
  EXPECT_NEAR(fit.k.value, kSdtK, 1e-9 * kSdtK);
  EXPECT_NEAR(fit.l.value, kSdtL, 1e-10);
  EXPECT_NEAR(fit.m.value, kSdtM, 1e-10);
  EXPECT_NEAR(fit.n.value, kSdtN, 1e-10);
  EXPECT_LT(fit.residual_rms, 1e-12);
  EXPECT_NEAR(fit.r_squared, 1.0, 1e-12);
  EXPECT_FALSE(fit.n_given);
  EXPECT_EQ(fit.points, 36u);
  EXPECT_EQ(fit.tensions, (std::vector<double>{20000.0, 28000.0, 35000.0}));
  EXPECT_EQ(fit.frequencies.size(), 4u);
  EXPECT_TRUE(fit.notes.empty());
}

// A 2^3 factorial design in ln Y, ln f, ln(T/1000) (levels c -+ 1) with residuals
// +-delta along the three-way interaction, orthogonal to every column: the estimates
// stay the law's, SSR = 8 delta^2 on 4 degrees of freedom, s^2 = 2 delta^2, and with
// X^T X of the centred columns 8 I the slopes' standard errors are
// sqrt(s^2 / 8) = delta / 2, ln k's (delta / 2) sqrt(1 + c_Y^2 + c_f^2 + c_T^2).
TEST(SelfDampingFit, StandardErrorsOfAFactorialDesignByHand) {
  const double delta = 0.05, cy = std::log(0.002), cf = std::log(20.0), ct = std::log(25.0);
  std::vector<SelfDampingTest> tests;
  for (int a : {-1, 1}) {
    for (int b : {-1, 1}) {
      for (int c : {-1, 1}) {
        const double y = std::exp(cy + a), f = std::exp(cf + b), t = 1000.0 * std::exp(ct + c);
        tests.push_back({t, f, y, sdt_law_power(t, f, y) * std::exp(delta * a * b * c)});
      }
    }
  }
  SelfDampingFit fit;
  ASSERT_NO_THROW(fit = fit_self_damping(tests, std::nullopt)) << "the design's levels lie outside no check";
  EXPECT_NEAR(fit.l.value, kSdtL, 1e-12);
  EXPECT_NEAR(fit.m.value, kSdtM, 1e-12);
  EXPECT_NEAR(fit.n.value, kSdtN, 1e-12);
  EXPECT_NEAR(fit.ln_k.value, std::log(kSdtK), 1e-11);
  EXPECT_NEAR(fit.l.standard_error, delta / 2.0, 1e-12);
  EXPECT_NEAR(fit.m.standard_error, delta / 2.0, 1e-12);
  EXPECT_NEAR(fit.n.standard_error, delta / 2.0, 1e-12);
  const double se_ln_k = delta / 2.0 * std::sqrt(1.0 + cy * cy + cf * cf + ct * ct);
  EXPECT_NEAR(fit.ln_k.standard_error, se_ln_k, 1e-12);
  EXPECT_NEAR(fit.k.standard_error, kSdtK * se_ln_k, 1e-10);
  EXPECT_NEAR(fit.residual_rms, delta, 1e-14);
  EXPECT_NEAR(fit.residual_standard_error, delta * std::sqrt(2.0), 1e-14);
}

TEST(SelfDampingFit, OneTensionNeedsNAndSaysSo) {
  const std::vector<SelfDampingTest> tests = sdt_noiseless({28000.0});
  try {
    (void)fit_self_damping(tests);
    FAIL() << "one tension fitted without n";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.field(), "n");
    EXPECT_NE(std::string(e.what()).find("one tension (28000 N)"), std::string::npos) << e.what();
  }
  const SelfDampingFit fit = fit_self_damping(tests, kSdtN);
  EXPECT_TRUE(fit.n_given);
  EXPECT_EQ(fit.parameters, 3u);
  EXPECT_EQ(fit.n.value, kSdtN);
  EXPECT_TRUE(std::isnan(fit.n.standard_error));
  EXPECT_NEAR(fit.k.value, kSdtK, 1e-9 * kSdtK);
  EXPECT_NEAR(fit.l.value, kSdtL, 1e-10);
  EXPECT_NEAR(fit.m.value, kSdtM, 1e-10);
  ASSERT_EQ(fit.notes.size(), 1u);
  EXPECT_NE(fit.notes[0].find("n is not determined"), std::string::npos) << fit.notes[0];
  // A wrong n moves k (the tension factor 28^(n - n_true) is absorbed by k), not l or m.
  const SelfDampingFit wrong = fit_self_damping(tests, kSdtN + 0.5);
  EXPECT_NEAR(wrong.k.value, kSdtK * std::pow(28.0, 0.5), 1e-8);
  EXPECT_NEAR(wrong.l.value, kSdtL, 1e-10);
}

TEST(SelfDampingFit, RefusesDesignsThatLeaveAnExponentOpen) {
  const auto field_of = [](const std::vector<SelfDampingTest>& tests, std::optional<double> n) {
    try {
      (void)fit_self_damping(tests, n);
    } catch (const InvalidParameter& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  std::vector<SelfDampingTest> tests = sdt_noiseless();
  EXPECT_EQ(field_of({tests.begin(), tests.begin() + 4}, 2.0), "accepted");  // 4 points, 3 parameters
  EXPECT_EQ(field_of({tests.begin(), tests.begin() + 3}, 2.0), "points");
  std::vector<SelfDampingTest> four{tests[0], tests[5], tests[13], tests[30]};
  EXPECT_EQ(field_of(four, std::nullopt), "points");  // 4 parameters need 5 points
  std::vector<SelfDampingTest> one_frequency, one_amplitude, collinear;
  for (SelfDampingTest t : tests) {
    t.frequency = 20.0;
    one_frequency.push_back(t);
  }
  for (SelfDampingTest t : tests) {
    t.amplitude = 0.002;
    one_amplitude.push_back(t);
  }
  for (SelfDampingTest t : tests) {
    t.amplitude = 0.05 / t.frequency;  // ln Y = ln 0.05 - ln f
    collinear.push_back(t);
  }
  EXPECT_EQ(field_of(one_frequency, std::nullopt), "frequency_hz");
  EXPECT_EQ(field_of(one_amplitude, std::nullopt), "amplitude_m");
  EXPECT_EQ(field_of(collinear, std::nullopt), "points");
}

TEST(SelfDampingTests, ReadsAFileAndRefusesUnitSlips) {
  const auto dir = std::filesystem::temp_directory_path() / "stockbridge_self_damping_tests";
  const auto good = testing::write_temp_file(
      dir, "good.csv",
      "\xEF\xBB\xBFtension_n,frequency_hz,amplitude_m,power_w_per_m,comment\r\n28000,20,0.002,0.01,a\r\n"
      "28000,30,0.001,0.02,b\r\n");
  const SelfDampingTests read = load_self_damping_tests(good);
  ASSERT_EQ(read.tests.size(), 2u);
  EXPECT_EQ(read.tests[1].frequency, 30.0);
  EXPECT_EQ(read.tests[1].amplitude, 0.001);
  EXPECT_TRUE(read.warnings.empty());
  const auto message = [&](const std::string& name, const std::string& text, SlipPolicy policy) {
    try {
      (void)load_self_damping_tests(testing::write_temp_file(dir, name, text), policy);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string header = "tension_n,frequency_hz,amplitude_m,power_w_per_m\n";
  EXPECT_EQ(message("kn.csv", header + "28000,20,0.002,0.01\n28,20,0.002,0.01\n", SlipPolicy::refuse),
            (dir / "kn.csv").string() +
                ":3: column 'tension_n' = 28: outside the typical 1000 to 500000 N of the conductor tension (in kN? "
                "28 kN = 28000 N); a self-damping test's values lie within it");
  EXPECT_NE(message("mm.csv", header + "28000,20,2,0.01\n", SlipPolicy::refuse).find(":2: column 'amplitude_m' = 2:"),
            std::string::npos);
  EXPECT_NE(message("mw.csv", header + "28000,20,0.002,120\n", SlipPolicy::refuse).find("(in mW/m?"),
            std::string::npos);
  EXPECT_EQ(message("mw.csv", header + "28000,20,0.002,120\n", SlipPolicy::warn), "accepted");
  EXPECT_EQ(message("zero.csv", header + "28000,20,0,0.01\n", SlipPolicy::refuse),
            (dir / "zero.csv").string() + ":2: column 'amplitude_m' = 0: expected > 0");
  EXPECT_NE(message("missing.csv", "tension_n,frequency_hz,amplitude_m\n1,2,3\n", SlipPolicy::refuse)
                .find("power_w_per_m"),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(SelfDampingTests, ArraysNameTheIndex) {
  try {
    (void)self_damping_tests_from_arrays({28000, 28}, {20, 30}, {0.002, 0.001}, {0.01, 0.02});
    FAIL() << "a tension in kN accepted";
  } catch (const UnusualValueError& e) {
    EXPECT_NE(std::string(e.what()).find("tension[1] = 28:"), std::string::npos) << e.what();
  }
  try {
    (void)self_damping_tests_from_arrays({28000, 28000}, {20, -30}, {0.002, 0.001}, {0.01, 0.02});
    FAIL() << "a negative frequency accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.field(), "frequency[1]");
  }
}

// The table -o writes, as a span file's [self_damping], gives the fitted P back:
// the span's self-damping per length at each test point equals the law's.
TEST(SelfDampingTests, TheWrittenTableIsTheSpanFilesLaw) {
  const std::vector<SelfDampingTest> tests = sdt_noiseless();
  const SelfDampingFit fit = fit_self_damping(tests);
  const std::string table = requests::self_damping_table(fit, "tests.csv");
  const std::string span_text = "[conductor]\ntype = \"ACSR Drake\"\n[span]\nlength = 300\ntension = 28000\n"
                                "[wind]\nlaw = \"cigre\"\n[fatigue]\ncycles = 5e8\n" + table;
  const io::SpanFile file = io::load_span_text(span_text, "span.toml");
  const span::Span& s = file.span;
  EXPECT_EQ(s.self_damping().law, span::SelfDampingLaw::power);
  for (const SelfDampingTest& t : tests) {
    const double p = s.self_damping().power(t.amplitude, t.frequency, s.conductor(), t.tension, s.length()) / s.length();
    EXPECT_NEAR(p, t.power, 1e-9 * t.power) << t.tension << " N, " << t.frequency << " Hz";
  }
}

}  // namespace
}  // namespace stockbridge::measurements
