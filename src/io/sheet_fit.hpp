#pragma once
// A damper model fitted to a measured sheet from the damper's drawing (a span or
// line file's `fit_from`, docs/span.md "A sheet of one velocity"): the fit of
// identify impedance --free, kept in a cache beside the file that asks for it and
// keyed by the inputs' digest, so that a second run reads it back instead of
// fitting again. Library-internal.

#include <filesystem>
#include <string>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/damper/damper.hpp"
#include "stockbridge/span/span.hpp"

namespace stockbridge::io {

/// What a fit gives the span: the model, how it was fitted, the files it read and
/// what the user should know (a fit that does not follow its sheet).
struct FittedSheet {
  damper::Damper damper;
  span::SheetFit fit;
  std::vector<std::filesystem::path> inputs;  ///< the sheet, the drawing and its cable files
  std::vector<std::string> warnings;
};

/// The folder of the fits' cache beside a span or line file's folder.
std::filesystem::path fit_cache_directory(const std::filesystem::path& base_directory);

/// The drawing `start` (a damper file) with its cables and the numbers `free` fitted
/// to the measured sheet `sheet` (identification::identify_impedance, one Jenkin
/// element, the sheet's scatter assumed 1 %), from `cache` where a fit of the same
/// inputs is there, else fitted and written there (a cache that cannot be written
/// is a warning). `sheet_name` and `start_name` as the file gives them, for reports.
/// Throws InputError for a bad sheet or drawing (their own messages) and
/// InvalidParameter naming "free" for a number the drawing does not have.
FittedSheet fit_damper_to_sheet(const std::filesystem::path& sheet, const std::string& sheet_name,
                                const std::filesystem::path& start, const std::string& start_name,
                                const std::vector<std::string>& free, const std::filesystem::path& cache,
                                SlipPolicy policy);

}  // namespace stockbridge::io
