#pragma once
// The request layer for one cable section driven by a sinusoidal curvature (the
// `loop` command and Python's `loop`): the law chosen by name.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/requests/output_table.hpp"
#include "stockbridge/cable/section_law_descriptor.hpp"
#include "stockbridge/section/sinusoidal_drive.hpp"

namespace stockbridge::requests {

/// The law when none is asked for: the Masing law's exact variant.
inline constexpr std::string_view default_loop_law = "exact";

/// How a front end spells what `loop` takes, for its messages: a key ("--ei-min" or
/// "ei_min") and the law asked for ("--law bouc-wen" or "law = 'bouc-wen'").
struct LoopSpelling {
  std::string (*key)(std::string_view key);
  std::string (*law)(std::string_view name);
};
/// The command line's: "--ei-min", "--law bouc-wen".
LoopSpelling command_line_spelling();

/// The names `loop` takes for a law: each law's and its variants ("masing, exact,
/// regularised, bouc-wen").
std::vector<std::string> loop_law_names();

/// The loop of a section of the law `given.law` (a law's name or one of its
/// variants: the Masing law's "exact" and "regularised") with the numbers given,
/// under `drive`: InvalidParameter for an unknown law ("law"), numbers of another
/// law, or numbers missing (in the words of `spelling`).
section::LoopRecord section_loop(const cable::LoopNumbers& given, const section::SinusoidalDrive& drive,
                                 const LoopSpelling& spelling);

/// One sample of the loop.
struct LoopSample {
  const section::LoopRecord* record = nullptr;
  std::size_t step = 0;
};
std::vector<LoopSample> loop_samples(const section::LoopRecord& record);

/// The loop CSV's quantities: step, curvature_per_m, moment_n_m, dissipated_energy_j_per_m.
Table<LoopSample> loop_table();

}  // namespace stockbridge::requests
