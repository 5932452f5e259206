#pragma once
// The request layer for one cable section driven by a sinusoidal curvature (the
// `loop` command and Python's `loop`): the law chosen by name.

#include <string_view>

#include "stockbridge/section/masing_law.hpp"
#include "stockbridge/section/sinusoidal_drive.hpp"

namespace stockbridge::requests {

/// The loop of a section with `parameters` under `drive`, with the exact Masing
/// law ("exact") or the regularised rate law (3.15) with `exponent`
/// ("regularised"); InvalidParameter naming `law` otherwise.
section::LoopRecord section_loop(const section::MasingParameters& parameters, const section::SinusoidalDrive& drive,
                                 std::string_view law, double exponent);

}  // namespace stockbridge::requests
