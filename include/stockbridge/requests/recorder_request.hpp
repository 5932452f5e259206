#pragma once
// The request layer for vibration recorders (`stockbridge recorder`, Python's
// recorder; measurements/recorder.hpp): the counts read and checked against the
// span, the record analysed, the bins as the rows every front end shows (CSV
// columns, Python arrays) and the summary (the --json keys).

#include <filesystem>
#include <string>
#include <vector>

#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/measurements/recorder.hpp"
#include "stockbridge/requests/output_table.hpp"

namespace stockbridge::requests {

struct RecorderRequest {
  double days = 0.0;                   ///< the record's length, days (> 0)
  std::vector<std::string> calibrate;  ///< keys, measurements::RecorderOptions
  int points_per_band = measurements::RecorderOptions{}.points_per_band;
};

/// The library's options of a request (InvalidParameter naming "days", "calibrate", ...).
measurements::RecorderOptions recorder_options(const RecorderRequest& request);

/// Reads the counts (read_recorder_counts) and checks them against the span's wind
/// band and the request against the span (a climate; the calibrated keys' laws), all
/// before anything is computed.
measurements::RecorderCounts read_recorder_input(const std::filesystem::path& counts, const io::SpanFile& span,
                                                 const RecorderRequest& request, SlipPolicy policy);

/// Runs the analysis (measurements::analyse_record) with the span file's balance options.
measurements::RecorderResult run_recorder(const measurements::RecorderCounts& counts, const io::SpanFile& span,
                                          const RecorderRequest& request);

/// The bins' CSV quantities, a row per non-empty bin: yb_pp_mm_low, yb_pp_mm_high,
/// frequency_hz_low, frequency_hz_high, cycles, stress_ps_mpa, microstrain_pp,
/// cycles_to_failure, damage.
Table<measurements::RecorderBinResult> recorder_bins_table();

/// The summary: measured, predicted (with bands), calibrated (where asked),
/// frequencies, points_per_band, failed_points, seconds_per_balance.
io::JsonObject recorder_summary(const measurements::RecorderResult& result);

}  // namespace stockbridge::requests
