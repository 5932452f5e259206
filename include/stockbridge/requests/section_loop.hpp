#pragma once
// The request layer for one cable section driven by a sinusoidal curvature (the
// `loop` command and Python's `loop`): the law chosen by name.

#include <cstddef>
#include <string_view>
#include <vector>

#include "stockbridge/requests/output_table.hpp"
#include "stockbridge/section/bouc_wen_section.hpp"
#include "stockbridge/section/masing_law.hpp"
#include "stockbridge/section/sinusoidal_drive.hpp"

namespace stockbridge::requests {

/// The law and the regularised law's exponent when none is asked for.
inline constexpr std::string_view default_section_law = "exact";
inline constexpr double default_regularised_exponent = 10.0;

/// The loop of a section with `parameters` under `drive`, with the exact Masing
/// law ("exact") or the regularised rate law (3.15) with `exponent`
/// ("regularised"); InvalidParameter naming `law` otherwise ("bouc-wen" has its own
/// parameters: bouc_wen_loop).
section::LoopRecord section_loop(const section::MasingParameters& parameters, const section::SinusoidalDrive& drive,
                                 std::string_view law, double exponent);

/// The loop of a Bouc-Wen section (the law "bouc-wen", MODEL.md section 13) under
/// `drive`; InvalidParameter naming "ei_min", "ei_max" or "chi0".
section::LoopRecord bouc_wen_loop(const section::BoucWenParameters& parameters, const section::SinusoidalDrive& drive);

/// One sample of the loop.
struct LoopSample {
  const section::LoopRecord* record = nullptr;
  std::size_t step = 0;
};
std::vector<LoopSample> loop_samples(const section::LoopRecord& record);

/// The loop CSV's quantities: step, curvature_per_m, moment_n_m, dissipated_energy_j_per_m.
Table<LoopSample> loop_table();

}  // namespace stockbridge::requests
