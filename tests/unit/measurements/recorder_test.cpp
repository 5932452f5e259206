// Vibration recorders (measurements/recorder.hpp): the damage equals an
// independent Miner sum, the calibration finds the turbulence intensity a record
// was made with, the two file forms read alike, bad counts are named by file and
// line, and the calibrated span file read back predicts what the calibration did.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/measurements/recorder.hpp"

namespace stockbridge::measurements {
namespace {

/// ASTER570 (MODEL.md 9's check numbers) without dampers: a balance in milliseconds.
std::string recorder_span_text(double turbulence) {
  return fmt::format(R"(
[conductor]
name = "ASTER570"
mass_per_length = 1.571
diameter = 0.03105
rated_tensile_strength = 185300
ei_min = 28.28
outer_wire_diameter = 0.00345
outer_wire_modulus = 68e9
aluminium_layers = 4
[span]
length = 400
tension_fraction = 0.15
[wind]
law = "foti"
turbulence_intensity = {}   # the site's assumption
[self_damping]
law = "noiseux-1991"
[fatigue]
cycles = 5e8
wind_weibull = {{ shape = 2.0, scale = 4.0 }}
aeolian_fraction = 0.3
)",
                     turbulence);
}

std::filesystem::path recorder_dir() {
  const auto dir = std::filesystem::temp_directory_path() / ("stockbridge-recorder-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path recorder_write(const std::string& name, const std::string& text) {
  const auto path = recorder_dir() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

io::SpanFile recorder_span(double turbulence) {
  return io::load_span_text(recorder_span_text(turbulence), "test span");
}

/// The Safe Border Line of several layers inverted here, apart from span/fatigue.cpp.
double independent_cycles(double stress_mpa) {
  const double low = std::pow(stress_mpa / 450.0, -1.0 / 0.2);
  if (low <= 1.56e7) return low;
  const double high = std::pow(stress_mpa / 263.0, -1.0 / 0.17);
  return std::max(high, 1.56e7);
}

TEST(Recorder, DamagePerYearIsAnIndependentMinerSum) {
  const io::SpanFile span = recorder_span(0.1);
  const auto path = recorder_write("miner.csv",
                                   "\xEF\xBB\xBFyb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\r\n"
                                   "0.1,0.2,10,15,1e6\r\n0.2,0.4,10,15,2e5\r\n0.4,0.8,15,20,3e4\r\n"
                                   "0,0.1,15,20,5e6\r\n0.8,1.2,20,30,120\r\n");
  const RecorderCounts counts = read_recorder_counts(path);
  ASSERT_EQ(counts.bins.size(), 5u);
  const double days = 40.0;
  const std::vector<RecorderBinResult> bins = judge_bins(counts, span.span);
  const DamageFigures f = measured_figures(bins, span.span, days);
  // K = E_a d_a p^2 / (4 (exp(-p x_b) - 1 + p x_b)), p = sqrt(T / EI_min), written out.
  const double tension = 0.15 * 185300.0;
  const double p = std::sqrt(tension / 28.28);
  const double k = 68e9 * 0.00345 * p * p / (4.0 * (std::exp(-p * 0.089) - 1.0 + p * 0.089));
  const double upper_mm[] = {0.2, 0.4, 0.8, 0.1, 1.2};
  const double cycles[] = {1e6, 2e5, 3e4, 5e6, 120};
  double damage = 0.0;
  for (int i = 0; i < 5; ++i) damage += cycles[i] / independent_cycles(k * upper_mm[i] * 1e-3 / 1e6);
  EXPECT_NEAR(f.damage_per_year / (damage * 365.25 / days), 1.0, 1e-6);
  EXPECT_NEAR(f.life_years * damage * 365.25 / days, 1.0, 1e-6);
  EXPECT_DOUBLE_EQ(f.max_yb, 1.2e-3);
  EXPECT_NEAR(f.max_stress, k * 1.2e-3, 1e-6 * k * 1.2e-3);
  double above = 0.0;
  for (int i = 0; i < 5; ++i) above += k * upper_mm[i] * 1e-3 > span.span.endurance_limit() ? cycles[i] : 0.0;
  EXPECT_NEAR(f.fraction_above_endurance, above / f.cycles, 1e-12);
  EXPECT_GT(above, 0.0);
}

TEST(Recorder, MatrixFormReadsAsTheNeutralForm) {
  const auto neutral = recorder_write("neutral.csv",
                                      "yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n"
                                      "0.1,0.2,10,15,100\n0.2,0.4,15,20,7\n0.1,0.2,15,20,3\n");
  const auto matrix = recorder_write("matrix.csv", "yb_pp_mm,10-15 hz,15-20 Hz\n0.1-0.2,100,3\n0.2-0.4,,7\n");
  const RecorderCounts a = read_recorder_counts(neutral);
  const RecorderCounts b = read_recorder_counts(matrix);
  EXPECT_TRUE(b.matrix_form);
  ASSERT_EQ(a.bins.size(), b.bins.size());
  EXPECT_EQ(a.bands, b.bands);
  double sa = 0.0, sb = 0.0;
  for (const auto& x : a.bins) sa += x.cycles * x.yb_high * x.frequency_low;
  for (const auto& x : b.bins) sb += x.cycles * x.yb_high * x.frequency_low;
  EXPECT_DOUBLE_EQ(sa, sb);
}

/// The error's message of reading (and checking against the span) `text`.
std::string recorder_refusal(const std::string& name, const std::string& text) {
  const auto path = recorder_write(name, text);
  try {
    const RecorderCounts c = read_recorder_counts(path);
    check_recorder_band(c, recorder_span(0.1).span);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Recorder, BadCountsAreNamedByFileAndLine) {
  const std::string header = "yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n";
  const std::string inverted = recorder_refusal("inverted.csv", header + "0.1,0.2,10,15,1\n0.4,0.2,10,15,1\n");
  EXPECT_NE(inverted.find("inverted.csv:3: yb_pp_mm_low, yb_pp_mm_high = 0.4 to 0.2 mm"), std::string::npos) << inverted;
  const std::string overlap = recorder_refusal("overlap.csv", header + "0.1,0.3,10,15,1\n0.2,0.4,12,14,1\n");
  EXPECT_NE(overlap.find("overlap.csv:3:"), std::string::npos) << overlap;
  EXPECT_NE(overlap.find("line 2"), std::string::npos) << overlap;
  const std::string negative = recorder_refusal("negative.csv", header + "0.1,0.3,10,15,-4\n");
  EXPECT_NE(negative.find("negative.csv:2: cycles = -4"), std::string::npos) << negative;
  const std::string outside = recorder_refusal("outside.csv", header + "0.1,0.3,50,60,4\n");
  EXPECT_NE(outside.find("outside.csv:2: frequency bin 50 to 60 Hz: outside the span's wind band"), std::string::npos)
      << outside;
  const std::string metres = recorder_refusal("metres.csv", header + "0.0001,0.0002,10,15,4\n");
  EXPECT_NE(metres.find("metres.csv:2: yb_pp_mm_low = 0.0001"), std::string::npos) << metres;
  EXPECT_NE(metres.find("in m?"), std::string::npos) << metres;
  const std::string cell = recorder_refusal("cell.csv", "yb_pp_mm,10-15 hz\n0.1-0.2,many\n");
  EXPECT_NE(cell.find("cell.csv:2, column '10-15 hz': 'many'"), std::string::npos) << cell;
  const std::string column = recorder_refusal("column.csv", "yb_pp_mm,15-10 hz\n0.1-0.2,1\n");
  EXPECT_NE(column.find("column.csv: header, column 2 '15-10 hz'"), std::string::npos) << column;
}

TEST(Recorder, TurbulenceIntensityOfAnotherLawIsRefusedNamingTheLaw) {
  std::string text = recorder_span_text(0.1);
  text.replace(text.find("law = \"foti\""), 12, "law = \"cigre\"");
  text.replace(text.find("turbulence_intensity = 0.1 "), 27, "");
  const io::SpanFile span = io::load_span_text(text, "cigre span");
  try {
    with_parameter(span.span, "wind.turbulence_intensity", 0.1);
    FAIL() << "accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_NE(std::string(e.what()).find("'cigre'"), std::string::npos) << e.what();
  }
}

// predict_record takes the balance at recorder_frequencies: one at other frequencies,
// or with too few points, is refused naming the balance, the point and the frequency.
TEST(Recorder, APredictionFromABalanceAtOtherFrequenciesIsRefusedNamingTheBalance) {
  const RecorderCounts counts = read_recorder_counts(recorder_write(
      "other_balance.csv", "yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n0.1,0.2,10,14,1\n"));
  const io::SpanFile made = recorder_span(0.1);
  std::vector<double> frequencies = recorder_frequencies(counts, made.span, 2);
  ASSERT_EQ(frequencies.size(), 2u);
  for (double& f : frequencies) f *= 1.01;
  const span::SpanTables tables(made.span, frequencies, made.balance.table);
  const span::SpanBalance other = span::run_balance(made.span, tables, made.balance);
  try {
    predict_record(counts, made.span, other, 2, 30.0);
    FAIL() << "accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.field(), "balance");
    EXPECT_EQ(std::string(e.what()).rfind("balance.points[0] at ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected"), std::string::npos) << e.what();
  }
  try {
    predict_record(counts, made.span, span::SpanBalance{}, 2, 30.0);
    FAIL() << "accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(std::string(e.what()).rfind("balance: 0 points, expected more", 0), 0u) << e.what();
  }
}

/// A record made by the span's own balance at `truth`: per band the balance's
/// cycles spread over Yb bins (a factor 1.5 wide) by a lognormal of sigma 0.35 in
/// ln Yb about the balance's Yb, each band's centre moved by a fixed scatter.
std::string recorder_made_record(const io::SpanFile& made, const RecorderCounts& bands_only, int points_per_band) {
  const span::SpanTables tables(made.span, recorder_frequencies(bands_only, made.span, points_per_band), made.balance.table);
  const span::SpanBalance b = span::run_balance(made.span, tables, made.balance);
  const RecorderPrediction p = predict_record(bands_only, made.span, b, points_per_band, 30.0);
  const double shift[] = {0.02, -0.02, 0.015, -0.015, 0.01, -0.01};
  std::string text = "yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n";
  for (std::size_t k = 0; k < p.bands.size(); ++k) {
    const RecorderBand& band = p.bands[k];
    const double centre = band.predicted_mean_ln_yb + shift[k % 6];
    for (int j = -8; j <= 8; ++j) {
      const double lo = std::pow(1.5, j), hi = std::pow(1.5, j + 1);  // mm: each edge written once, the same on both sides
      const auto cdf = [&](double yb) { return 0.5 * std::erfc(-(std::log(yb) - centre) / (0.35 * std::sqrt(2.0))); };
      const double n = std::round(band.predicted_cycles * (cdf(hi) - cdf(lo)));
      if (n > 0) text += fmt::format("{},{},{},{},{}\n", lo, hi, band.frequency_low, band.frequency_high, n);
    }
  }
  return text;
}

TEST(Recorder, CalibrationRecoversTheTurbulenceIntensityOfTheRecord) {
  const double truth = 0.06;
  std::string bands = "yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n";
  for (const double f : {7.0, 10.0, 14.0, 20.0, 28.0, 40.0}) bands += fmt::format("0.1,0.2,{},{},1\n", f, f * 1.4 < 41.7 ? f * 1.4 : 41.7);
  const RecorderCounts layout = read_recorder_counts(recorder_write("bands.csv", bands));
  const auto path = recorder_write("made.csv", recorder_made_record(recorder_span(truth), layout, 2));
  // (the undamped span's record reaches past 10 mm, a Yb the reader otherwise refuses as um)
  const RecorderCounts counts = read_recorder_counts(path, SlipPolicy::warn);
  const io::SpanFile assumed = recorder_span(0.2);
  RecorderOptions options;
  options.days = 30.0;
  options.points_per_band = 2;
  options.calibrate = {"wind.turbulence_intensity"};
  const RecorderResult r = analyse_record(counts, assumed.span, assumed.balance, options);
  ASSERT_TRUE(r.calibration);
  const RecorderCalibration& c = *r.calibration;
  EXPECT_TRUE(c.converged) << c.message;
  EXPECT_NEAR(c.values[0].value, truth, 0.1 * truth);
  EXPECT_LT(c.residual_after, c.residual_before);
  EXPECT_GT(c.values[0].standard_error, 0.0);
  EXPECT_LT(c.values[0].standard_error, 0.5 * truth);
  // The prediction at the span file's 0.2 underestimates the record's amplitudes.
  EXPECT_LT(r.predicted.figures.damage_per_year, c.prediction.figures.damage_per_year);

  // The calibrated span file, read back, predicts what the calibration did.
  const auto source = recorder_write("assumed.toml", recorder_span_text(0.2));
  const std::string text = calibrated_span_text(source, c.values);
  EXPECT_NE(text.find("# the site's assumption"), std::string::npos) << text;
  const auto written = recorder_write("calibrated.toml", text);
  const io::SpanFile back = io::load_span_file(written);
  EXPECT_NEAR(back.span.wind().turbulence_intensity, c.values[0].value, 1e-9 * c.values[0].value);
  RecorderOptions plain = options;
  plain.calibrate.clear();
  const RecorderResult again = analyse_record(counts, back.span, back.balance, plain);
  EXPECT_NEAR(again.predicted.figures.damage_per_year, c.prediction.figures.damage_per_year,
              1e-6 * c.prediction.figures.damage_per_year);
}

TEST(Recorder, PowerScaleIsAddedBelowItsTableAndReadBack) {
  const auto source = recorder_write("scale.toml", recorder_span_text(0.1));
  const std::string text = calibrated_span_text(source, {{"wind.power_scale", 1.0, 0.8125, 0.01}});
  const io::SpanFile back = io::load_span_file(recorder_write("scaled.toml", text));
  EXPECT_DOUBLE_EQ(back.span.wind().power_scale, 0.8125);
  // The wind's power is scaled, nothing else.
  const io::SpanFile plain = recorder_span(0.1);
  EXPECT_NEAR(back.span.wind().power(0.01, 20.0, 0.03105, 400.0), 0.8125 * plain.span.wind().power(0.01, 20.0, 0.03105, 400.0),
              1e-12);
}

}  // namespace
}  // namespace stockbridge::measurements
