#pragma once
// Where the tests find the source tree and the program. One file holds the two
// places (test_paths.cpp, compiled with them); every test file sees them through
// these names (the build includes this header in each), so that its text and its
// compile are the same in any clone and ccache shares them (CMakeLists.txt).

namespace stockbridge_test_paths {
const char* source_dir();  ///< the source tree, an absolute path
const char* cli();         ///< the stockbridge program, an absolute path
}  // namespace stockbridge_test_paths

#define STOCKBRIDGE_SOURCE_DIR (::stockbridge_test_paths::source_dir())
#define STOCKBRIDGE_CLI (::stockbridge_test_paths::cli())
