// A damper known by its vendor's sheet at one clamp velocity (IEC 61897's test as it
// often is) and by its drawing: the span balances the damper's model fitted to the
// sheet (fit_from, identify impedance --free), which interpolates in amplitude
// physically where no sheet of one curve can. The sheet is the asymmetric damper's
// own Z at 0.1 m/s; the drawing has its masses and cable lengths 15-20 % off and the
// cable guessed. The fitted numbers come within 2 % of the damper that made the
// sheet, and so does the span's largest stress; the fit is kept in a cache beside the
// span file and read back; a sheet of one curve without fit_from is refused naming it.

#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/span/analysis.hpp"
#include "support/temp_file.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::span {
namespace {

const std::string kExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";

/// The asymmetric damper (the truth) and its drawing, both on `sections`-section cables.
std::string damper_text(const std::string& example, int sections) {
  const io::DamperFile file = io::load_damper_file(kExamples + example);
  damper::DamperDescription d = file.damper.description();
  for (damper::ArmDescription& arm : d.arms) arm.cable.sections = sections;
  return io::damper_file_toml(d, "");
}

std::string span_text(const std::string& damper_keys) {
  return "[conductor]\ntype = \"ACSR Drake\"\n[span]\nlength = 300\ntension_fraction = 0.2\n[wind]\nlaw = \"cigre\"\n"
         "[self_damping]\nlaw = \"noiseux-1991\"\n[fatigue]\ncycles = 5e8\n[[damper]]\nposition = 1.0\n" +
         damper_keys;
}

/// The folder of one run: the truth, the drawing, the truth's sheet at 0.1 m/s.
std::filesystem::path fit_folder() {
  const int sections = testing::scaled(16, 8);
  const auto dir = std::filesystem::temp_directory_path() / fmt::format("stockbridge-sheet-fit-{}", ::getpid());
  std::filesystem::remove_all(dir);
  testing::write_temp_file(dir, "truth.toml", damper_text("asymmetric_damper.toml", sections));
  testing::write_temp_file(dir, "drawing.toml", damper_text("vendor_damper_start.toml", sections));
  damper::SweepSpec spec;
  spec.frequencies = damper::log_spaced(5.0, 60.0, 16);
  spec.amplitudes = {0.1};
  std::string sheet = "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n";
  for (const damper::SweepRun& run : damper::run_sweep(io::read_damper_file(dir / "truth.toml"), spec)) {
    for (const damper::ImpedancePoint& p : run.points) {
      EXPECT_TRUE(p.converged());
      sheet += fmt::format("{},{},{},{}\n", p.frequency_hz, run.amplitude, p.impedance.real(), p.impedance.imag());
    }
  }
  testing::write_temp_file(dir, "sheet.csv", sheet);
  return dir;
}

constexpr const char* kFitted =
    "impedance = \"sheet.csv\"\nfit_from = \"drawing.toml\"\n"
    "free = [\"arm.long.mass\", \"arm.short.mass\", \"arm.long.cable.length\", \"arm.short.cable.length\"]\n";

TEST(SheetFit, AOneVelocitySheetBalancesThroughTheModelFittedToItWithin2Percent) {
  const auto dir = fit_folder();
  testing::write_temp_file(dir, "fitted.toml", span_text(kFitted));
  testing::write_temp_file(dir, "truth_span.toml", span_text("file = \"truth.toml\"\n"));
  const io::SpanFile fitted = io::load_span_file(dir / "fitted.toml");
  const SpanDamper& d = fitted.span.dampers().front();
  ASSERT_TRUE(d.damper && d.fit);
  EXPECT_FALSE(d.fit->cached);
  EXPECT_FALSE(d.fit->poor_fit || d.fit->lack_of_fit) << d.fit->summary();
  EXPECT_EQ(d.fit->points, 16);
  const damper::DamperDescription truth = io::read_damper_file(dir / "truth.toml").description();
  const damper::DamperDescription& got = d.damper->description();
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(got.arms[k].mass / truth.arms[k].mass, 1.0, 0.02) << k;
    EXPECT_NEAR(got.arms[k].cable.length / truth.arms[k].cable.length, 1.0, 0.02) << k;
  }
  const std::vector<double> f = band_frequencies(fitted.span, 20);
  const double with_fit = analyse_span(fitted.span, f, {}).balance.summary.max_stress_fymax;
  const double with_truth =
      analyse_span(io::load_span_file(dir / "truth_span.toml").span, f, {}).balance.summary.max_stress_fymax;
  EXPECT_NEAR(with_fit / with_truth, 1.0, 0.02);

  // The second read takes the cache: the same damper, not fitted again.
  const io::SpanFile again = io::load_span_file(dir / "fitted.toml");
  ASSERT_TRUE(again.span.dampers().front().fit);
  EXPECT_TRUE(again.span.dampers().front().fit->cached);
  EXPECT_EQ(io::damper_file_toml(again.span.dampers().front().damper->description(), ""),
            io::damper_file_toml(got, ""));
  EXPECT_EQ(again.span.dampers().front().fit->rms_relative_error, d.fit->rms_relative_error);
}

TEST(SheetFit, AOneCurveSheetWithoutFitFromIsRefusedNamingIt) {
  const auto dir = fit_folder();
  testing::write_temp_file(dir, "sheet_only.toml", span_text("impedance = \"sheet.csv\"\n"));
  try {
    io::load_span_file(dir / "sheet_only.toml");
    ADD_FAILURE() << "a sheet of one curve accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("damper[0].impedance: \"sheet.csv\": 1 curve(s)"), std::string::npos) << what;
    EXPECT_NE(what.find("a sheet of one amplitude takes fit_from = the damper's file"), std::string::npos) << what;
  }
  testing::write_temp_file(dir, "free_alone.toml", span_text("impedance = \"sheet.csv\"\nfree = [\"arm.long.mass\"]\n"));
  EXPECT_THROW(io::load_span_file(dir / "free_alone.toml"), InputError);
  testing::write_temp_file(dir, "bad_free.toml",
                           span_text("impedance = \"sheet.csv\"\nfit_from = \"drawing.toml\"\nfree = [\"arm.middle.mass\"]\n"));
  try {
    io::load_span_file(dir / "bad_free.toml");
    ADD_FAILURE() << "a number the drawing lacks accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("damper[0].free: "), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace stockbridge::span
