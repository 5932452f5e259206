// Reading cable files: the simple form, profiles, mirror, modified Masing, and one
// precise error for every kind of mistake.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/cable_file.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::io {
namespace {

std::filesystem::path cable_directory() {
  return std::filesystem::temp_directory_path() / ("stockbridge-cable-file-" + std::to_string(::getpid()));
}

cable::CableDescription read_cable(const std::string& contents) {
  return read_cable_file(testing::write_temp_file(cable_directory(), "cable.toml", contents)).description();
}

std::string cable_error_of(const std::string& contents) {
  try {
    read_cable(contents);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(CableFile, SimpleFormAsInTheIssue) {
  const cable::CableDescription d = read_cable(
      "[cable]\nlength = 0.3        # m\nsections = 40\nei = 2.8\njenkin = [ { c = 20.0, h = 0.7 } ]\n");
  EXPECT_EQ(d.length, 0.3);
  EXPECT_EQ(d.sections, 40);
  EXPECT_EQ(d.ei.at(0.1), 2.8);
  ASSERT_EQ(d.jenkin.size(), 1u);
  EXPECT_EQ(d.jenkin[0].c.at(0.0), 20.0);
  EXPECT_EQ(d.jenkin[0].h.at(0.0), 0.7);
  EXPECT_FALSE(d.mirror_length.has_value());
}

TEST(CableFile, ProfilesMirrorAndModifiedMasing) {
  const cable::CableDescription d = read_cable(R"(
[cable]
length = 0.1875
sections = 30
ei = { s = [0.0, 0.15, 0.3], value = [3.2, 2.8, 2.6] }
mirror_length = 0.3
lever_arm_cap = 0.25
[[cable.jenkin]]
c = 20
h = { s = [0.0, 0.3], value = [0.8, 0.6] }
k0 = 0.5
[[cable.jenkin]]
c = 4.0
h = 0.1
)");
  EXPECT_DOUBLE_EQ(d.ei.at(0.075), 3.0);
  ASSERT_EQ(d.jenkin.size(), 2u);
  EXPECT_DOUBLE_EQ(d.jenkin[0].h.at(0.15), 0.7);
  EXPECT_EQ(d.jenkin[0].k0, 0.5);
  EXPECT_EQ(*d.mirror_length, 0.3);
  EXPECT_EQ(*d.lever_arm_cap, 0.25);
}

TEST(CableFile, AcceptsCrlfLineEnds) {
  const cable::CableDescription d = read_cable("[cable]\r\nlength = 0.3\r\nsections = 10\r\nei = 2.8\r\n");
  EXPECT_EQ(d.sections, 10);
  EXPECT_TRUE(d.jenkin.empty());
}

TEST(CableFile, EachMistakeGetsOnePreciseLine) {
  const std::string file = (cable_directory() / "cable.toml").string();
  EXPECT_EQ(cable_error_of("[cable]\nsections = 40\nei = 2.8\n"),
            file + ":1: missing key 'length' in [cable]: expected a number");
  EXPECT_EQ(cable_error_of("[cable]\nlength = -0.3\nsections = 40\nei = 2.8\n"),
            file + ":2: cable.length = -0.3: expected a finite value > 0 (m)");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = 2.8\nlenght = 3\n"),
            file + ":5: unknown key 'cable.lenght': expected one of ei, jenkin, law, length, lever_arm_cap, mirror_length, sections");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40.5\nei = 2.8\n"),
            file + ":3: cable.sections: the number 40.5: expected an integer from 2 to 5000");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 0\nei = 2.8\n"),
            file + ":3: cable.sections: 0: expected an integer from 2 to 5000");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = \"stiff\"\n"),
            file + ":4: cable.ei: the string \"stiff\": expected a number or a profile { s = [...], value = [...] }");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = 2.8\njenkin = [ { c = 20.0, h = 0 } ]\n"),
            file + ":5: cable.jenkin[0].h = 0: expected a finite value > 0 (N m)");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = 2.8\njenkin = [ { c = 20.0, h = 0.7, x = 1 } ]\n"),
            file + ":5: unknown key 'cable.jenkin[0].x': expected one of c, h, k0");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = nan\n"),
            file + ":4: cable.ei = nan: expected a finite value > 0 (N m^2)");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = { s = [0, 0.2, 0.1], value = [1, 2, 3] }\n"),
            file + ":4: cable.ei.s[2] = 0.1: expected positions increasing strictly (previous 0.2 m)");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = { s = [0, 0.2], value = [1, -2] }\n"),
            file + ":4: cable.ei.value[1] = -2: expected a finite value > 0 (N m^2)");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.7\nsections = 40\nei = 2.8\nmirror_length = 0.3\n"),
            file + ":2: cable.length = 0.7: expected at most twice mirror_length = 0.3 m for the mirror method");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = 2.8\n[extra]\n"),
            file + ":5: unknown key 'extra': expected one of cable");
  EXPECT_EQ(cable_error_of("length = 0.3\n"), file + ":1: missing key 'cable' in the top level: expected a table");
  EXPECT_EQ(cable_error_of("[cable\nlength = 0.3\n"), file + ":1:7: TOML syntax error: Error while parsing table header: expected ']', saw '\\n'");
  EXPECT_EQ(cable_error_of(""), file + ":1: missing key 'cable' in the top level: expected a table");
  // Bytes that are not UTF-8 (issue 49): the parser names a position (not always the
  // byte's: here the end of the line before); the message quotes the byte's line.
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\n\xff = 1\n"),
            file + ":2:13: TOML syntax error: Encountered invalid utf-8 sequence: line 3 reads '\\xff = 1'");
  const std::string long_line = cable_error_of("[cable]\nname = \"" + std::string(50, 'a') + "\xfe\"\n");
  EXPECT_NE(long_line.find(": line 2 reads '..." + std::string(20, 'a') + "\\xfe\"'"), std::string::npos) << long_line;
  // Control characters the user's text brings in (quoted keys, strings) are escaped: one line.
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = 2.8\n\"a\\nb\" = 3\n").rfind(file + ":5: unknown key 'cable.a\\nb'", 0), 0u);
  EXPECT_EQ(cable_error_of("[cable]\nlength = \"0.3\\r\"\nsections = 40\nei = 2.8\n"),
            file + ":2: cable.length: the string \"0.3\\r\": expected a number");
  // Fuzzing finding: an absurd magnitude overflowed the flexibility (every sample failed).
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.11e308\nsections = 40\nei = 2.8\n"),
            file + ":2: cable.length = 1.1e+307: expected a value from 1e-12 to 1e+12; one outside is a unit mistake (m)");
  EXPECT_EQ(cable_error_of("[cable]\nlength = 0.3\nsections = 40\nei = 1e-13\n"),
            file + ":4: cable.ei = 1e-13: expected a value from 1e-12 to 1e+12; one outside is a unit mistake (N m^2)");
}

TEST(CableFile, MissingFile) {
  EXPECT_THROW(read_cable_file(cable_directory() / "nope.toml"), InputError);
}

}  // namespace
}  // namespace stockbridge::io
