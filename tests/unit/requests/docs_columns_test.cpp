// The docs' column tables are the library's output descriptors: every table that
// follows a "<!-- columns: NAME -->" line in docs/ equals docs_table of the table
// NAME, and every output table is documented somewhere. With
// STOCKBRIDGE_UPDATE_DOCS=1 the test writes the tables into the docs instead
// (after adding a column: run it once, then read the diff).

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/design_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/requests/cycle_request.hpp"
#include "stockbridge/requests/design_request.hpp"
#include "stockbridge/requests/fatigue_tests_request.hpp"
#include "stockbridge/requests/identify_request.hpp"
#include "stockbridge/requests/line_request.hpp"
#include "stockbridge/requests/impedance_fit_request.hpp"
#include "stockbridge/requests/modes_request.hpp"
#include "stockbridge/requests/recorder_request.hpp"
#include "stockbridge/requests/response_request.hpp"
#include "stockbridge/requests/section_loop.hpp"
#include "stockbridge/requests/simulate_request.hpp"
#include "stockbridge/requests/time_check.hpp"
#include "stockbridge/requests/span_modes_request.hpp"
#include "stockbridge/requests/span_request.hpp"
#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::requests {
namespace {

const std::filesystem::path kDocsSourceDir{STOCKBRIDGE_SOURCE_DIR};

template <class Row>
std::string documented_table(const Table<Row>& table) {
  return docs_table(table.docs());
}

/// Every output table by the name its marker gives, as docs_table writes it.
std::map<std::string, std::string> documented_output_tables() {
  const damper::Damper damper = io::load_damper_file(kDocsSourceDir / "examples/sauter2003.toml").damper;
  const io::SpanFile span = io::load_span_file(kDocsSourceDir / "examples/aster570_400m.toml");
  const io::DesignFile design = io::load_design_file(kDocsSourceDir / "examples/design_aster570.toml");
  GlobalRequest experiment_b;
  experiment_b.experiment = "b";
  std::vector<QuantityDoc> figures;
  for (const auto& q : design_figures()) figures.push_back({q.name, q.unit, q.meaning});
  return {
      {"impedance", documented_table(impedance_table(damper))},
      {"design_figures", docs_table(figures)},
      {"response", documented_table(response_table(damper))},
      {"response_summary", documented_table(point_summary_table(damper))},
      {"modes", documented_table(modes_table())},
      {"cycle", documented_table(cycle_table())},
      {"loop", documented_table(loop_table())},
      {"span", documented_table(span_table(span.span))},
      {"design", documented_table(design_table(design.study))},
      {"identify_local_fitted", documented_table(local_fitted_table())},
      {"identify_global_fitted_a", documented_table(global_fitted_table(GlobalRequest{}))},
      {"identify_global_fitted_b", documented_table(global_fitted_table(experiment_b))},
      {"identify_impedance_fitted", documented_table(fitted_table())},
      {"schedule", documented_table(schedule_table())},
      {"bill", documented_table(bill_table())},
      {"recorder_bins", documented_table(recorder_bins_table())},
      {"fatigue_tests", documented_table(fatigue_tests_table())},
      {"span_modes", documented_table(span_modes_table(SpanModesResult{}))},
      {"span_mode_shapes", documented_table(span_mode_shapes_table(SpanModesResult{}))},
      {"simulate_history", documented_table(simulation_table({"y_at_89mm"}, 1))},
      {"check_time", documented_table(time_check_table(false))},
  };
}

std::vector<std::filesystem::path> markdown_pages() {
  std::vector<std::filesystem::path> pages;
  for (const auto& entry : std::filesystem::directory_iterator(kDocsSourceDir / "docs")) {
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  }
  return pages;
}

std::vector<std::string> docs_page_lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

constexpr std::string_view kMarker = "<!-- columns: ";

/// The marker's table name, or empty for another line.
std::string marked_table(const std::string& line) {
  if (!line.starts_with(kMarker) || !line.ends_with(" -->")) return {};
  return line.substr(kMarker.size(), line.size() - kMarker.size() - 4);
}

TEST(DocsColumns, EveryTableInTheDocsIsTheLibrarysDescriptors) {
  const std::map<std::string, std::string> tables = documented_output_tables();
  const bool update = std::getenv("STOCKBRIDGE_UPDATE_DOCS") != nullptr;
  std::set<std::string> seen;
  for (const std::filesystem::path& page : markdown_pages()) {
    const std::vector<std::string> lines = docs_page_lines(page);
    std::ostringstream rewritten;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      rewritten << lines[i] << '\n';
      const std::string name = marked_table(lines[i]);
      if (name.empty()) continue;
      const auto table = tables.find(name);
      ASSERT_NE(table, tables.end()) << page.filename() << ":" << i + 1 << ": no output table " << name;
      seen.insert(name);
      std::string found;
      while (i + 1 < lines.size() && lines[i + 1].starts_with("|")) found += lines[++i] + "\n";
      rewritten << table->second;
      if (!update) {
        EXPECT_EQ(found, table->second) << page.filename() << ":" << i + 1 << ": the table " << name
                                        << " differs from the library's (STOCKBRIDGE_UPDATE_DOCS=1 rewrites it)";
      }
    }
    if (update) std::ofstream(page) << rewritten.str();
  }
  for (const auto& [name, table] : tables) EXPECT_TRUE(seen.contains(name)) << "no docs page lists the table " << name;
}

}  // namespace
}  // namespace stockbridge::requests
