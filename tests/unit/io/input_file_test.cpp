// The files an input names (io/input_file.hpp): found where a file is there, else one
// InputError with the input's location, the name as written, where it was looked for
// and where relative paths start.

#include <filesystem>
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/input_file.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::io {
namespace {

std::filesystem::path input_file_directory() {
  return std::filesystem::temp_directory_path() / ("stockbridge-input-file-" + std::to_string(::getpid()));
}

std::string missing_file_message(const std::function<void()>& look) {
  try {
    look();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(InputFile, AFileThereIsReturnedAsLookedFor) {
  const std::filesystem::path path = testing::write_temp_file(input_file_directory(), "cable.toml", "x = 1\n");
  EXPECT_EQ(existing_input_file(path), path);
  EXPECT_EQ(existing_input_file("damper.toml:3: arm.cable.file: ",
                                {"cable.toml", path, "cable file", "the damper file's folder"}),
            path);
}

TEST(InputFile, AMissingNamedFileIsOneMessageWithWhereItWasLookedFor) {
  const std::filesystem::path path = input_file_directory() / "nope.toml";
  EXPECT_EQ(missing_file_message([&] {
              existing_input_file("damper.toml:3: arm[0].cable.file: ",
                                  {"nope.toml", path, "cable file", "the damper file's folder"});
            }),
            "damper.toml:3: arm[0].cable.file: \"nope.toml\": expected an existing cable file (looked for " +
                path.string() + "; relative paths start at the damper file's folder)");
  EXPECT_EQ(missing_file_message([&] {
              existing_input_file("line.toml:9: conductor = ", {"nope.toml", path, "conductor file",
                                                                "the line file's folder", "a catalogue type"});
            }),
            "line.toml:9: conductor = \"nope.toml\": expected an existing conductor file (looked for " +
                path.string() + "; relative paths start at the line file's folder) or a catalogue type");
}

TEST(InputFile, AFolderIsNoFile) {
  const std::filesystem::path folder = input_file_directory();
  std::filesystem::create_directories(folder);
  EXPECT_EQ(missing_file_message([&] { existing_input_file(folder); }), folder.string() + ": no such file");
  EXPECT_NE(missing_file_message([&] {
              existing_input_file("", {"folder", folder, "CSV file", "the span file's folder"});
            }).find("expected an existing CSV file"),
            std::string::npos);
  EXPECT_EQ(missing_file_message([&] { existing_input_file(folder / "none.csv"); }),
            (folder / "none.csv").string() + ": no such file");
}

}  // namespace
}  // namespace stockbridge::io
