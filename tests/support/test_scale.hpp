#pragma once
// How long the long tests may run. The sanitizer and ThreadSanitizer test presets
// set STOCKBRIDGE_TEST_SCALE=short: the same code paths run on fewer points,
// starts or seeds (under the sanitizers each evaluation costs 10-50 times more),
// so that those builds still cover the sweeps and the identification.

#include <cstdlib>
#include <string_view>

namespace stockbridge::testing {

/// True when STOCKBRIDGE_TEST_SCALE=short (sanitizer builds).
inline bool short_tests() {
  const char* scale = std::getenv("STOCKBRIDGE_TEST_SCALE");
  return scale != nullptr && std::string_view(scale) == "short";
}

/// `full` normally, `reduced` under STOCKBRIDGE_TEST_SCALE=short.
template <class T>
T scaled(T full, T reduced) {
  return short_tests() ? reduced : full;
}

}  // namespace stockbridge::testing
