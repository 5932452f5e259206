#pragma once
// The request layer for conductor fatigue tests (`stockbridge fatigue-tests`,
// Python's fatigue_tests; measurements/fatigue_tests.hpp): the file read, the tests
// of one conductor kept where asked, the stresses, the censored Basquin fit, and what
// both front ends give: the per-test table, the JSON summary, the design curve's file.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/measurements/fatigue_tests.hpp"
#include "stockbridge/requests/output_table.hpp"

namespace stockbridge::requests {

struct FatigueTestsRequest {
  std::filesystem::path file;            ///< the fatigue-test CSV
  std::optional<std::string> conductor;  ///< keep only this conductor's rows (as the file names it, or its type)
  SlipPolicy policy = SlipPolicy::refuse;
};

struct FatigueTestsOutcome {
  std::string file;                           ///< as given
  std::optional<std::string> conductor;       ///< the filter, if any
  measurements::FatigueTestsResult result;
  std::vector<std::filesystem::path> inputs;  ///< the CSV and the conductor files it names
  std::vector<std::string> warnings;
};

/// Reads, filters, evaluates and fits. Throws InputError for the file's bad cells and,
/// naming the file, where the tests kept do not determine a fit (fewer than 3
/// failures at 2 stresses); InvalidParameter naming "conductor" where the filter
/// keeps no row.
FatigueTestsOutcome run_fatigue_tests(const FatigueTestsRequest& request);

/// One test with its stress, as the table reads it.
struct FatigueTestRow {
  const measurements::FatigueTest* test = nullptr;
  const measurements::FatigueTestPoint* point = nullptr;
};
/// The per-test output: the input columns, then stress_ps_mpa, microstrain_pp,
/// sbl_cycles and below_sbl.
Table<FatigueTestRow> fatigue_tests_table();
TableValues fatigue_tests_values(const measurements::FatigueTestsResult& result);

/// The S-N curve's name for the fitted design curve ("ACSR Drake fatigue tests, mean - 2 s").
std::string fatigue_tests_curve_name(const FatigueTestsOutcome& outcome);
/// The design curve's S-N curve file text (io/sn_curve_file.hpp); InvalidParameter
/// naming "b" where the fit's slope is not < 0.
std::string fatigue_tests_curve_toml(const FatigueTestsOutcome& outcome);

/// {"file", "conductor", "tests", "fit": {"a", "b", "scatter", "a_standard_error",
/// "b_standard_error", "scatter_standard_error", "failures", "runouts", "log_likelihood",
/// "iterations", "design_a", "design_b", "below_sbl": {"count", "fraction", "tests"}},
/// "safe_border_lines": [{"aluminium_layers", "name", "branches": [{"a", "b", "until"}]}]}.
io::JsonObject fatigue_tests_summary(const FatigueTestsOutcome& outcome);

}  // namespace stockbridge::requests
