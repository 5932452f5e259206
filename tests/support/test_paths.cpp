// The places test_paths.hpp names, from the build (tests/CMakeLists.txt).
#include "support/test_paths.hpp"

namespace stockbridge_test_paths {
const char* source_dir() { return STOCKBRIDGE_TEST_SOURCE_DIR; }
const char* cli() { return STOCKBRIDGE_TEST_CLI; }
}  // namespace stockbridge_test_paths
