// Damper files: the model validates, the reader points at the offending key's own
// line with the field's path (InvalidParameter::field), its message unchanged.

#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"
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

std::string error_of(const std::string& contents) {
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
  EXPECT_EQ(error_of(text), ":22: arm[1].cable.jenkin[0].h = -0.5: expected a finite value > 0 (N m)");
}

TEST(DamperFile, AnArmValueIsAtItsKeysLine) {
  std::string second = arm("short", "0.7");
  const std::string inertia = "inertia = 0.001814";
  second = second.substr(0, second.find(inertia)) + "inertia = -1" + second.substr(second.find(inertia) + inertia.size());
  EXPECT_EQ(error_of("[clamp]\nmass = 0.7\n" + arm("long", "0.7") + second),
            ":16: arm[1].inertia = -1: expected a finite value > 0 (kg m^2)");
  std::string beyond = arm("short", "0.7");
  const std::string offset = "offset = 0.0325";
  beyond = beyond.substr(0, beyond.find(offset)) + "offset = 0.3" + beyond.substr(beyond.find(offset) + offset.size());
  EXPECT_EQ(error_of("[clamp]\nmass = 0.7\n" + beyond),
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

TEST(InvalidParameter, CarriesTheFieldPathThroughNestedDescriptions) {
  const InvalidParameter e("h", " = -1: expected a finite value > 0 (N m)");
  const InvalidParameter nested = e.within("jenkin[0]").within("cable").within("arm[1]");
  EXPECT_EQ(nested.field(), "arm[1].cable.jenkin[0].h");
  EXPECT_EQ(std::string(nested.what()), "arm[1].cable.jenkin[0].h = -1: expected a finite value > 0 (N m)");
  EXPECT_EQ(InvalidParameter("[2]", " = 0: expected a value > 0").within("frequency").field(), "frequency[2]");
}

}  // namespace
}  // namespace stockbridge::io
