#pragma once
// The names a user types for the span's choices (a span or line file's keys, the
// command line's and Python's options), parsed into the span layer's enums; the span
// layer itself takes only the enums (and names them back for outputs:
// span::damper_model_name, span::position_objective_name).

#include <string_view>

#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/position_search.hpp"

namespace stockbridge::io {

/// "travelling" or "weak"; InvalidParameter naming "damper_model" otherwise.
span::DamperModel parse_damper_model(std::string_view name);

/// "max_stress" or "life"; InvalidParameter naming "objective" otherwise.
span::PositionObjective parse_position_objective(std::string_view name);

}  // namespace stockbridge::io
