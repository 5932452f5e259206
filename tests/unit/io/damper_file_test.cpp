// Damper files: the model validates, the reader points at the offending key's own
// line with the field's path (InvalidParameter::field), its message unchanged.

#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::io {
namespace {

/// One [[arm]] of ten lines: its name and its Jenkin element's slip moment h.
std::string arm(const std::string& name, const std::string& h) {
  return "[[arm]]\nname = \"" + name +
         "\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n"
         "[arm.cable]\nlength = 0.1875\nsections = 8\nei = 2.8\njenkin = [ { c = 20.0, h = " + h + " } ]\n";
}

std::string damper_error_of(const std::string& contents) {
  const auto path = testing::write_temp_file(std::filesystem::temp_directory_path() /
                                                 ("stockbridge-damper-file-" + std::to_string(::getpid())),
                                             "damper.toml", contents);
  try {
    read_damper_file(path);
  } catch (const InputError& e) {
    return std::string(e.what()).substr(path.string().size());
  }
  return "accepted";
}

TEST(DamperFile, AnErrorInTheSecondArmsCableIsAtItsOwnLine) {
  // Line 14 + 10 = the second arm's jenkin line (the first arm takes lines 3-12).
  const std::string text = "[clamp]\nmass = 0.7\n" + arm("long", "0.7") + arm("short", "-0.5");
  EXPECT_EQ(damper_error_of(text), ":22: arm[1].cable.jenkin[0].h = -0.5: expected a finite value > 0 (N m)");
}

TEST(DamperFile, AnArmValueIsAtItsKeysLine) {
  std::string second = arm("short", "0.7");
  const std::string inertia = "inertia = 0.001814";
  second = second.substr(0, second.find(inertia)) + "inertia = -1" + second.substr(second.find(inertia) + inertia.size());
  EXPECT_EQ(damper_error_of("[clamp]\nmass = 0.7\n" + arm("long", "0.7") + second),
            ":16: arm[1].inertia = -1: expected a finite value > 0 (kg m^2)");
  std::string beyond = arm("short", "0.7");
  const std::string offset = "offset = 0.0325";
  beyond = beyond.substr(0, beyond.find(offset)) + "offset = 0.3" + beyond.substr(beyond.find(offset) + offset.size());
  EXPECT_EQ(damper_error_of("[clamp]\nmass = 0.7\n" + beyond),
            ":7: arm[0].offset = 0.3: expected |offset| < the cable length 0.1875 m (the centre of gravity lies on the arm)");
}

TEST(DamperFile, TextFromAFrontEndIsCheckedAlikeAndNamedWithoutLines) {
  const damper::Damper damper = read_damper_text("[clamp]\nmass = 0.7\n" + arm("a", "0.7"), "make_damper");
  EXPECT_EQ(damper.arm_name(0), "a");
  try {
    read_damper_text("[clamp]\nmass = 0.7\n" + arm("a", "-0.7"), "make_damper");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "make_damper: arm[0].cable.jenkin[0].h = -0.7: expected a finite value > 0 (N m)");
  }
}

std::filesystem::path reference_directory() {
  return std::filesystem::temp_directory_path() / ("stockbridge-cable-reference-" + std::to_string(::getpid()));
}

/// One [[arm]] whose [arm.cable] holds `cable_keys`.
std::string arm_keys(const std::string& cable_keys) {
  return "[[arm]]\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n[arm.cable]\n" + cable_keys;
}

std::string heavy_arm_keys(const std::string& cable_keys) {
  return "[[arm]]\nmass = 863\ninertia = 0.001814\noffset = 0.0325\n[arm.cable]\n" + cable_keys;
}

TEST(DamperFile, AnArmTakesAReferencedCableFileWithItsOverrides) {
  const auto dir = reference_directory();
  testing::write_temp_file(dir / "cables", "profiled.toml",
                           "[cable]\nlength = 0.3\nsections = 12\nei = { s = [0, 0.3], value = [3.0, 2.6] }\n"
                           "jenkin = [ { c = 20.0, h = 0.7, k0 = 0.5 } ]\n");
  const auto path = testing::write_temp_file(
      dir, "damper.toml",
      "[clamp]\nmass = 0.7\n" + arm_keys("file = \"cables/profiled.toml\"\n") +
          arm_keys("file = \"cables/profiled.toml\"\nlength = 0.15\nsections = 30\nmirror_length = 0.3\nlever_arm_cap = 0.1\n"));
  const DamperFile file = load_damper_file(path);
  const cable::CableDescription whole = read_cable_file(dir / "cables" / "profiled.toml").description();
  EXPECT_EQ(file.damper.arms()[0].cable().description(), whole);
  cable::CableDescription cut = whole;
  cut.length = 0.15;
  cut.sections = 30;
  cut.mirror_length = 0.3;
  cut.lever_arm_cap = 0.1;
  EXPECT_EQ(file.damper.arms()[1].cable().description(), cut);
  ASSERT_EQ(file.cable_files.size(), 2u);
  EXPECT_EQ(file.cable_files[0], dir / "cables/profiled.toml");
  EXPECT_TRUE(file.warnings.empty());
}

TEST(DamperFile, AReferencedCableFileIsCheckedWhereItsValuesAre) {
  const auto dir = reference_directory();
  testing::write_temp_file(dir, "cable.toml", "[cable]\nlength = 0.3\nsections = 8\nei = -2.8\n");
  const auto bad = testing::write_temp_file(dir, "bad.toml", "[clamp]\nmass = 0.7\n" + arm_keys("file = \"cable.toml\"\n"));
  EXPECT_THROW(
      {
        try {
          load_damper_file(bad);
        } catch (const InputError& e) {
          EXPECT_EQ(std::string(e.what()), (dir / "cable.toml").string() + ":4: cable.ei = -2.8: expected a finite value > 0 (N m^2)");
          throw;
        }
      },
      InputError);
  const auto missing = testing::write_temp_file(dir, "missing.toml", "[clamp]\nmass = 0.7\n" + arm_keys("file = \"nope.toml\"\n"));
  try {
    load_damper_file(missing);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.toml:8: arm[0].cable.file: \"nope.toml\": expected an existing cable file"),
              std::string::npos)
        << e.what();
  }
  testing::write_temp_file(dir, "good.toml", "[cable]\nlength = 0.3\nsections = 8\nei = 2.8\n");
  for (const std::string key : {"ei = 3.0", "jenkin = []", "colour = 1"}) {
    const auto d = testing::write_temp_file(dir, "d.toml", "[clamp]\nmass = 0.7\n" + arm_keys("file = \"good.toml\"\n" + key + "\n"));
    EXPECT_THROW(load_damper_file(d), InputError) << key;
  }
  // The overridden length is the damper file's own value, checked at its line.
  const auto long_arm = testing::write_temp_file(
      dir, "long.toml", "[clamp]\nmass = 0.7\n" + arm_keys("file = \"good.toml\"\nlength = -1\n"));
  try {
    load_damper_file(long_arm);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("long.toml:9: arm[0].cable.length = -1"), std::string::npos) << e.what();
  }
}

TEST(DamperFile, ValuesOutsideTheTypicalRangesWarnOnceAtTheirLines) {
  const auto dir = reference_directory();
  testing::write_temp_file(dir, "stiff.toml", "[cable]\nlength = 0.3\nsections = 8\nei = 4.9e6\n");
  const auto path = testing::write_temp_file(
      dir, "warned.toml",
      "[clamp]\nmass = 0\n" + arm_keys("file = \"stiff.toml\"\nlength = 0.2\n") +
          heavy_arm_keys("file = \"stiff.toml\"\nlength = 157\n"));
  // The mass in g and the length in mm are slips: refused at the first, the mass's line.
  try {
    load_damper_file(path);
    ADD_FAILURE() << "slips accepted";
  } catch (const UnusualValueError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ":11: arm[1].mass = 863: outside the typical 0.05 to 20 kg of the "
                                                     "arm mass (in g? 863 g = 0.863 kg)");
  }
  const DamperFile file = load_damper_file(path, SlipPolicy::warn);
  ASSERT_EQ(file.warnings.size(), 3u);  // the cable file's ei once, the mass and the length; not the clamp's 0
  EXPECT_EQ(file.warnings[0], (dir / "stiff.toml").string() +
                                  ":4: cable.ei = 4900000: outside the typical 0.1 to 1000 N m^2 of the cable bending "
                                  "stiffness ei (a unit mistake?)");
  EXPECT_EQ(file.warnings[1], path.string() + ":11: arm[1].mass = 863: outside the typical 0.05 to 20 kg of the arm mass "
                                              "(in g? 863 g = 0.863 kg)");
  EXPECT_NE(file.warnings[2].find(":16: arm[1].cable.length = 157: outside the typical 0.03 to 1 m"), std::string::npos)
      << file.warnings[2];
  EXPECT_TRUE(load_damper_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/sauter2003.toml").warnings.empty());
}

TEST(InvalidParameter, CarriesTheFieldPathThroughNestedDescriptions) {
  const InvalidParameter e("h", " = -1: expected a finite value > 0 (N m)");
  const InvalidParameter nested = e.within("jenkin[0]").within("cable").within("arm[1]");
  EXPECT_EQ(nested.field(), "arm[1].cable.jenkin[0].h");
  EXPECT_EQ(std::string(nested.what()), "arm[1].cable.jenkin[0].h = -1: expected a finite value > 0 (N m)");
  EXPECT_EQ(InvalidParameter("[2]", " = 0: expected a value > 0").within("frequency").field(), "frequency[2]");
}

}  // namespace
}  // namespace stockbridge::io
