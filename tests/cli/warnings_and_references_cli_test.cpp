// Issue 13: values outside the typical ranges warn (one line each, naming the value
// and the range, exit 0), and a damper file's arms reuse a cable file cut to length.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

namespace stockbridge::testing {
namespace {

const std::string kSource = STOCKBRIDGE_SOURCE_DIR;
const std::string kMeasured = kSource + "/examples/cycle_measured_a.csv";

int count(const std::string& text, const std::string& word) {
  int n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

const std::string kCable = "[cable]\nlength = 0.3\nsections = 40\nei = 2.8\njenkin = [ { c = 20.0, h = 0.7 } ]\n";

std::string arm_with_cable_file(const std::string& name, const std::string& cable_keys) {
  return "[[arm]]\nname = \"" + name + "\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n[arm.cable]\n" + cable_keys;
}

// A unit slip in a damper file is refused: exit 2, one line naming the file, line,
// key, value and the likely unit, nothing written; --allow-unusual takes each
// unusual value as given, one warning each, and the run goes on.
TEST(UnusualValuesCli, EachUnitMistakeInADamperFileIsRefusedOrWithAllowUnusualWarnsOnItsLine) {
  const auto dir = scratch_directory("unusual-damper");
  std::string text = read_text(kDamperExample);
  text.replace(text.find("mass = 0.856"), 12, "mass = 863");
  text.replace(text.find("inertia = 0.001814"), 18, "inertia = 1815");
  text.replace(text.find("ei = 2.8"), 8, "ei = 4.9e6");
  write(dir / "d.toml", text);
  const CliResult refused = run_cli("impedance d.toml --velocity 0.1 --frequencies 10 -o z.csv --quiet", dir);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.stderr_lines(), 1) << refused.err;
  EXPECT_NE(refused.err.find("stockbridge: d.toml:12: arm[0].mass = 863: outside the typical 0.05 to 20 kg of the arm "
                             "mass (in g? 863 g = 0.863 kg) (--allow-unusual takes it as given)"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "z.csv"));
  const CliResult r = run_cli("impedance d.toml --velocity 0.1 --frequencies 10 -o z.csv --quiet --allow-unusual", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count(r.err, "warning: "), 3) << r.err;
  EXPECT_NE(r.err.find("warning: d.toml:12: arm[0].mass = 863: outside the typical 0.05 to 20 kg"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("d.toml:13: arm[0].inertia = 1815: outside the typical 1e-06 to 0.5 kg m^2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("arm[0].cable.ei = 4900000: outside the typical 0.1 to 1000 N m^2"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "z.csv"));
}

TEST(UnusualValuesCli, TheShippedExampleAndItsSweepSayNothing) {
  const auto dir = scratch_directory("usual");
  const CliResult r = run_cli("impedance '" + kDamperExample + "' --velocity 0.2,0.05 --frequencies 5,50 -o z.csv --quiet", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

TEST(UnusualValuesCli, OptionsOutsideTheTypicalRangesWarnOncePerValue) {
  const auto dir = scratch_directory("unusual-options");
  // 100 m/s a slip of mm/s: refused alone; 2000 Hz no slip explains: a warning.
  const CliResult slip = run_cli("impedance '" + kDamperExample + "' --velocity 100,0.1 --frequencies 20 -o z.csv --quiet", dir);
  EXPECT_EQ(slip.exit_code, 2);
  EXPECT_EQ(slip.err, "stockbridge: --velocity = 100: outside the typical 0.001 to 2 m/s of the clamp velocity amplitude "
                      "(in mm/s? 100 mm/s = 0.1 m/s) (--allow-unusual takes it as given)\n");
  const CliResult sweep = run_cli(
      "impedance '" + kDamperExample + "' --velocity 100,0.1 --frequencies 2000 -o z.csv --quiet --allow-unusual", dir);
  EXPECT_EQ(count(sweep.err, "warning: "), 2) << sweep.err;
  EXPECT_NE(sweep.err.find("warning: --velocity = 100: outside the typical 0.001 to 2 m/s"), std::string::npos) << sweep.err;
  EXPECT_NE(sweep.err.find("warning: --frequencies = 2000: outside the typical 0.5 to 500 Hz"), std::string::npos) << sweep.err;

  const CliResult refused = run_cli("response '" + kDamperExample + "' --frequency 20 --displacement 2 -o t.csv", dir);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--displacement = 2: outside the typical 1e-06 to 0.05 m of the clamp displacement "
                             "amplitude (in mm? 2 mm = 0.002 m)"),
            std::string::npos)
      << refused.err;
  const CliResult response =
      run_cli("response '" + kDamperExample + "' --frequency 20 --displacement 2 -o t.csv --allow-unusual", dir);
  EXPECT_NE(response.err.find("warning: --displacement = 2: outside the typical 1e-06 to 0.05 m"), std::string::npos)
      << response.err;

  write(dir / "c.toml", kCable);
  const CliResult cycle = run_cli("cycle c.toml --experiment a --amplitude 30 --cycles 1 --points 8 -o cycle.csv", dir);
  EXPECT_NE(cycle.err.find("warning: --amplitude = 30: more than 0.3 of the cable's length 0.3 m"), std::string::npos)
      << cycle.err;
  const CliResult fine = run_cli("cycle c.toml --experiment a --amplitude 0.03 --cycles 1 --points 8 -o cycle.csv", dir);
  EXPECT_EQ(fine.err.find("warning"), std::string::npos) << fine.err;
}

TEST(UnusualValuesCli, GlobalIdentificationWarnsOfTheLengthDeflectionsInMmAndALargeFourStepError) {
  const auto dir = scratch_directory("unusual-identify");
  const CliResult four_step =
      run_cli("identify global --experiment a --length 0.3 --input '" + kMeasured + "' --method four-step", dir);
  EXPECT_EQ(four_step.exit_code, 0) << four_step.err;
  EXPECT_EQ(count(four_step.err, "warning: "), 1) << four_step.err;
  EXPECT_NE(four_step.err.find("relative L1 error 0.457 is large"), std::string::npos) << four_step.err;
  EXPECT_NE(four_step.err.find("--method fit"), std::string::npos) << four_step.err;

  const CliResult length =
      run_cli("identify global --experiment a --length 300 --input '" + kMeasured + "' --method four-step", dir);
  EXPECT_NE(length.err.find("warning: --length = 300: outside the typical 0.03 to 1 m"), std::string::npos) << length.err;

  // The measured cycle with its deflections written in mm under the x_m header.
  std::istringstream in(read_text(kMeasured));
  std::string line, mm;
  std::getline(in, line);
  mm = line + "\n";
  while (std::getline(in, line)) {
    const std::size_t a = line.find(','), b = line.find(',', a + 1);
    mm += line.substr(0, a + 1) + std::to_string(1000.0 * std::stod(line.substr(a + 1, b - a - 1))) + line.substr(b) + "\n";
  }
  write(dir / "mm.csv", mm);
  const CliResult in_mm = run_cli("identify global --experiment a --length 0.3 --input mm.csv --method four-step", dir);
  EXPECT_NE(in_mm.err.find("warning: mm.csv: x_m reaches"), std::string::npos) << in_mm.err;
  EXPECT_NE(in_mm.err.find("deflections in mm"), std::string::npos) << in_mm.err;
}

/// The example span in `dir` (with its damper file), its [fatigue] cycles 500: a
/// value outside the typical 1e6 to 1e10 that no unit slip explains, warned of.
std::string span_with_a_warning(const std::filesystem::path& dir) {
  std::filesystem::copy_file(kDamperExample, dir / "sauter2003.toml");
  std::string text = read_text(kSource + "/examples/aster570_400m.toml");
  text.replace(text.find("cycles = 5e8"), 12, "cycles = 500");
  return text;
}

/// `text` without the lines from the one starting with `from` to the one before `to`.
std::string without_lines(std::string text, const std::string& from, const std::string& to) {
  const std::size_t a = text.find(from), b = text.find(to, a);
  text.erase(a, b - a);
  return text;
}

// Warnings are held until the computation starts: a run refused with exit 2 prints
// its one line alone, also where an option is refused against the file read.
TEST(UnusualValuesCli, ARefusedRunPrintsItsOneLineWithoutTheFilesWarnings) {
  const auto dir = scratch_directory("refused-warnings");
  const std::string text = span_with_a_warning(dir);
  write(dir / "span.toml", text);
  const CliResult warned = run_cli("span span.toml --frequencies 10,20 --no-dampers --quiet -o out.csv", dir);
  EXPECT_EQ(warned.exit_code, 0) << warned.err;
  EXPECT_EQ(warned.stderr_lines(), 1) << warned.err;
  EXPECT_NE(warned.err.find("warning: span.toml:"), std::string::npos) << warned.err;
  EXPECT_NE(warned.err.find("fatigue.cycles = 500: outside the typical 1e+06 to 1e+10"), std::string::npos) << warned.err;
  std::filesystem::remove(dir / "out.csv");

  // No [[damper]] to place.
  write(dir / "bare.toml", without_lines(text, "[[damper]]", "[fatigue]"));
  const CliResult bare = run_cli("span bare.toml --frequencies 10,20 --optimize-position 0.5:3 -o out.csv", dir);
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_EQ(bare.err, "stockbridge: optimize_position: the span file has no [[damper]] to place\n");
  // The life as the objective of a span without a climate.
  write(dir / "no_climate.toml", without_lines(text, "wind_weibull", "\n\n") + "\n");
  const CliResult life =
      run_cli("span no_climate.toml --frequencies 10,20 --optimize-position 0.5:3 --objective life -o out.csv", dir);
  EXPECT_EQ(life.exit_code, 2);
  EXPECT_EQ(life.stderr_lines(), 1) << life.err;
  EXPECT_NE(life.err.find("objective = \"life\": the span gives no climate"), std::string::npos) << life.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
}

TEST(UnusualValuesCli, ARefusedLineRunPrintsItsOneLineWithoutTheFilesWarnings) {
  const auto dir = scratch_directory("refused-line-warnings");
  write(dir / "line.toml", std::string(R"([line]
points = 10
search_points = 8
[conductor]
type = "AAAC ASTER570"
[wind]
law = "cigre"
[self_damping]
law = "noiseux-1991"
[fatigue]
cycles = 500
[dampers]
types = [ { name = "sb1", file = ")") + kDamperExample + R"(" } ]
[[span]]
id = "T1/T2"
length = 300
tension_fraction = 0.15
[[span]]
id = "T1:T2"
length = 300
tension_fraction = 0.15
)");
  // --details names each span's files by its id: both ids give T1_T2.
  const CliResult r = run_cli("line line.toml -o schedule.csv --details spans", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find("--details: two spans' ids give the file name T1_T2"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "schedule.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "schedule.csv.journal"));
}

TEST(CableReferenceCli, ArmsCutOneCableFileToTheirLengthsAsIfWrittenOut) {
  const auto dir = scratch_directory("cable-reference");
  std::filesystem::create_directories(dir / "cables");
  write(dir / "cables" / "identified.toml", kCable);
  const std::string reference = "file = \"cables/identified.toml\"\nlength = 0.1875\n";
  write(dir / "by_reference.toml", "[clamp]\nmass = 0.7\n" + arm_with_cable_file("left", reference) +
                                       arm_with_cable_file("right", reference));
  const CliResult copied = run_cli("impedance '" + kDamperExample + "' --velocity 0.2 --frequencies 8,20,40 -o copied.csv --quiet", dir);
  ASSERT_EQ(copied.exit_code, 0) << copied.err;
  // From another working directory: the reference is relative to the damper file.
  std::filesystem::create_directories(dir / "elsewhere");
  const CliResult referenced = run_cli("impedance ../by_reference.toml --velocity 0.2 --frequencies 8,20,40 -o ../referenced.csv --quiet",
                                       dir / "elsewhere");
  ASSERT_EQ(referenced.exit_code, 0) << referenced.err;
  EXPECT_EQ(read_text(dir / "referenced.csv"), read_text(dir / "copied.csv"));
}

TEST(CableReferenceCli, AReferencedCableIsAnInputAndItsParametersAreNotOverridden) {
  const auto dir = scratch_directory("cable-reference-bad");
  write(dir / "cable.toml", kCable);
  write(dir / "d.toml", "[clamp]\nmass = 0.7\n" + arm_with_cable_file("a", "file = \"cable.toml\"\nlength = 0.15\n"));
  const CliResult overwrite = run_cli("impedance d.toml --velocity 0.1 --frequencies 20 -o cable.toml", dir);
  EXPECT_EQ(overwrite.exit_code, 2);
  EXPECT_NE(overwrite.err.find("-o cable.toml: is a cable file the damper file references"), std::string::npos) << overwrite.err;
  EXPECT_EQ(read_text(dir / "cable.toml"), kCable);

  write(dir / "ei.toml", "[clamp]\nmass = 0.7\n" + arm_with_cable_file("a", "file = \"cable.toml\"\nei = 3.0\n"));
  const CliResult ei = run_cli("impedance ei.toml --velocity 0.1 --frequencies 20 -o z.csv", dir);
  EXPECT_EQ(ei.exit_code, 2);
  EXPECT_EQ(ei.stderr_lines(), 1) << ei.err;
  EXPECT_NE(ei.err.find("ei.toml:10: arm[0].cable.ei: given beside file = \"cable.toml\""), std::string::npos) << ei.err;

  write(dir / "bad.toml", kCable + "colour = 1\n");
  write(dir / "d2.toml", "[clamp]\nmass = 0.7\n" + arm_with_cable_file("a", "file = \"bad.toml\"\n"));
  const CliResult bad = run_cli("impedance d2.toml --velocity 0.1 --frequencies 20 -o z.csv", dir);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("bad.toml:6: unknown key 'cable.colour'"), std::string::npos) << bad.err;  // located in the cable file
  EXPECT_FALSE(std::filesystem::exists(dir / "z.csv"));

  write(dir / "mm.toml", "[clamp]\nmass = 0.7\n" + arm_with_cable_file("a", "file = \"cable.toml\"\nlength = 150\n"));
  const CliResult mm = run_cli("impedance mm.toml --velocity 0.1 --frequencies 20 -o z.csv --quiet", dir);
  EXPECT_EQ(mm.exit_code, 2);
  EXPECT_NE(mm.err.find("stockbridge: mm.toml:10: arm[0].cable.length = 150: outside the typical 0.03 to 1 m of the "
                        "damper cable length (in mm? 150 mm = 0.15 m)"),
            std::string::npos)
      << mm.err;
}

}  // namespace
}  // namespace stockbridge::testing
