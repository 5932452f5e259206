// The version: one number, project(VERSION) in the top-level CMakeLists.txt, in the
// generated header, in the library linked in, and in its parts.

#include <string>

#include <gtest/gtest.h>

#include "stockbridge/version.hpp"

namespace stockbridge {
namespace {

TEST(Version, HeaderAndLibraryCarryTheProjectsVersion) {
  EXPECT_EQ(version_string, STOCKBRIDGE_PROJECT_VERSION);
  EXPECT_EQ(version(), version_string);
  EXPECT_EQ(std::to_string(version_major) + "." + std::to_string(version_minor) + "." + std::to_string(version_patch),
            version_string);
}

}  // namespace
}  // namespace stockbridge
