// Outputs described once: a table's columns expand each family member by member
// with the members' names, and its values give the CSV (labels first), one JSON
// row (NaN as null, a count as an integer, a masked flag null) and the docs' rows.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/requests/output_table.hpp"

namespace stockbridge::requests {
namespace {

struct Reading {
  std::string site;
  double load = 0.0;
  std::vector<double> per_arm;
  double flag = 1.0;
};

Table<Reading> reading_table(const std::vector<std::string>& arms) {
  return Table<Reading>(
      {
          {"site", "", "where", ColumnKind::label, {}, [](const Reading& r, std::size_t) { return r.site; }},
          {"load_n", "N", "the load | total", ColumnKind::number, [](const Reading& r, std::size_t) { return r.load; }, {}},
          {"<arm>_x_m", "m", "each arm's x", ColumnKind::number,
           [](const Reading& r, std::size_t k) { return r.per_arm[k]; }, {}},
          {"<arm>_twice_x_m", "m", "twice that", ColumnKind::number,
           [](const Reading& r, std::size_t k) { return 2.0 * r.per_arm[k]; }, {}},
          {"steps", "", "a count", ColumnKind::count, [](const Reading& r, std::size_t) { return r.load; }, {}},
          {"ok", "", "a flag", ColumnKind::flag, [](const Reading& r, std::size_t) { return r.flag; }, {}},
      },
      {{"<arm>", arms}});
}

TEST(OutputTable, AFamilyExpandsMemberByMemberWithTheMembersNames) {
  EXPECT_EQ(reading_table({"left", "right"}).names(),
            (std::vector<std::string>{"site", "load_n", "left_x_m", "left_twice_x_m", "right_x_m", "right_twice_x_m",
                                      "steps", "ok"}));
}

TEST(OutputTable, ValuesGiveTheCsvWithLabelsFirstAndEmptyCellsForNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Reading> rows{{"a", 3.0, {0.5, nan}, 1.0}, {"b", 4.0, {1.5, 2.5}, 0.0}};
  EXPECT_EQ(reading_table({"left", "right"}).values(rows).csv(),
            "site,load_n,left_x_m,left_twice_x_m,right_x_m,right_twice_x_m,steps,ok\n"
            "a,3,0.5,1,,,3,1\n"
            "b,4,1.5,3,2.5,5,4,0\n");
}

// Rows written to a file one by one (rows or pointers to them) give the text the
// whole table's values give, header included; no rows give the header alone.
TEST(OutputTable, ACsvFileWrittenRowByRowIsTheWholeTablesCsv) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Reading> rows{{"a,b", 3.0, {0.5, nan}, 1.0}, {"c", 4.0, {1.5, 2.5}, 0.0}};
  const Table<Reading> table = reading_table({"left", "right"});
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "stockbridge-rows-streamed.csv";
  const auto text_of = [&] {
    std::ostringstream text;
    text << std::ifstream(path, std::ios::binary).rdbuf();
    return text.str();
  };
  write_csv_file(path, table, rows);
  EXPECT_EQ(text_of(), table.values(rows).csv());
  write_csv_file(path, table, std::vector<const Reading*>{&rows[1]});
  EXPECT_EQ(text_of(), table.values(rows[1]).csv());
  write_csv_file(path, table, std::vector<Reading>{});
  EXPECT_EQ(text_of(), "site,load_n,left_x_m,left_twice_x_m,right_x_m,right_twice_x_m,steps,ok\n");
  std::filesystem::remove(path);
}

TEST(OutputTable, AJsonRowHasNullForNaNIntegersForCountsAndNullForAMaskedFlag) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const TableValues values = reading_table({"k"}).values(Reading{"a", 3.0, {nan}, nan});
  EXPECT_EQ(values.json_row(0).str(),
            R"({"site": "a", "load_n": 3, "k_x_m": null, "k_twice_x_m": null, "steps": 3, "ok": null})");
  EXPECT_EQ(values.column("k_x_m").family, "x_m");
  EXPECT_EQ(values.column("k_x_m").member, 0U);
  EXPECT_THROW(static_cast<void>(values.column("nothing")), std::out_of_range);
}

TEST(OutputTable, TheDocsListAFamilyByItsPatternAndEscapeBars) {
  EXPECT_EQ(docs_table(reading_table({"left"}).docs()),
            "| column | unit | meaning |\n|---|---|---|\n"
            "| `site` |  | where |\n"
            "| `load_n` | N | the load \\| total |\n"
            "| `<arm>_x_m` | m | each arm's x |\n"
            "| `<arm>_twice_x_m` | m | twice that |\n"
            "| `steps` |  | a count |\n"
            "| `ok` |  | a flag |\n");
}

TEST(OutputTable, AFamilyNamedByItsPlaceholderAloneIsAColumnPerMemberNamedAsIt) {
  const Table<Reading> table({{"<variable>", "", "each variable", ColumnKind::number,
                               [](const Reading& r, std::size_t k) { return r.per_arm[k]; }, {}}},
                             {{"<variable>", {"arm.left.mass", "position"}}});
  EXPECT_EQ(table.names(), (std::vector<std::string>{"arm.left.mass", "position"}));
  EXPECT_EQ(table.values(Reading{"a", 0.0, {0.8, 1.2}, 1.0}).csv(), "arm.left.mass,position\n0.8,1.2\n");
}

TEST(OutputTable, AFamilyWithoutMembersIsAProgrammingError) {
  EXPECT_THROW(Table<Reading>({{"<damper>_x_m", "m", "x", ColumnKind::number, {}, {}}}), std::logic_error);
}

TEST(OutputTable, ColumnPrefixesAreTheNamesWhereTheyCanAllServeElseNumbered) {
  EXPECT_EQ(column_prefixes({"left", "right"}, "arm"), (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(column_prefixes({"left", "left"}, "arm"), (std::vector<std::string>{"arm1", "arm2"}));
  EXPECT_EQ(column_prefixes({"left", "a b"}, "arm"), (std::vector<std::string>{"arm1", "arm2"}));
  EXPECT_EQ(column_prefixes({"left", ""}, "damper"), (std::vector<std::string>{"damper1", "damper2"}));
  EXPECT_EQ(column_prefixes({"shaker", "right"}, "arm", {"shaker"}), (std::vector<std::string>{"arm1", "arm2"}));
}

}  // namespace
}  // namespace stockbridge::requests
