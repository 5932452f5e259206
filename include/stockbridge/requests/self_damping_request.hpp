#pragma once
// The request layer for the self-damping law fitted to tests (`stockbridge identify
// self-damping`, Python's identify_self_damping): the --json summary, the
// [self_damping] table that -o writes and a span file takes as it is, and the
// terminal's summary line.
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/measurements/self_damping_tests.hpp"

namespace stockbridge::requests {

/// The summary: law ("power"), k, ln_k, l, m, n (each {value, standard_error}; n's
/// standard error null when given), n_given, points, parameters, degrees_of_freedom,
/// residual_rms_ln_p, residual_standard_error_ln_p, r_squared, tensions_n,
/// frequencies_hz, amplitudes_m (the distinct levels tested), notes, warnings (the
/// test file's).
io::JsonObject self_damping_summary(const measurements::SelfDampingFit& fit,
                                    const std::vector<std::string>& warnings = {});

/// The fitted law as a span file's [self_damping] table (law = "power", k, l, m, n,
/// each in shortest round-trip form), the fit's figures and `source` in comments.
std::string self_damping_table(const measurements::SelfDampingFit& fit, std::string_view source);

/// One line: k, l, m, n with their standard errors, the points and the residual.
std::string self_damping_summary_line(const measurements::SelfDampingFit& fit);

}  // namespace stockbridge::requests
