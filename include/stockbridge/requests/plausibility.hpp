#pragma once
// What a request asks for that lies outside the typical ranges of damper tests
// (core/typical_ranges.hpp): accepted, but most often a unit mistake, which the
// front ends show as one warning line per value. Fields are named as the options
// are, without the CLI's dashes ("velocity", "fmax").

#include <optional>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::requests {

/// The amplitudes and frequencies of a sweep outside their typical ranges.
std::vector<UnusualValue> unusual_values(const SweepRequest& request);

/// The same for one excitation (the response command).
std::vector<UnusualValue> unusual_excitation(double frequency_hz, std::optional<double> velocity,
                                             std::optional<double> displacement);

}  // namespace stockbridge::requests
