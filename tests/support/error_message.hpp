#pragma once
// The message of the InvalidParameter an action throws, for exact-message checks.

#include <functional>
#include <string>

#include "stockbridge/core/error.hpp"

namespace stockbridge::testing {

inline std::string invalid_parameter_message(const std::function<void()>& action) {
  try {
    action();
  } catch (const InvalidParameter& e) {
    return e.what();
  }
  return "(no InvalidParameter thrown)";
}

}  // namespace stockbridge::testing
