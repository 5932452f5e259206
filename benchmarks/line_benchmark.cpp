// One span's schedule from the example line (examples/line_example.toml): the
// undamped balance, the position search for one, two (and three) dampers per end,
// and the polished balance of each arrangement found, one core. The spans differ in
// cost by ten times (BM_LineSpan/k: span k of the line); the tables are made once
// per run (TableCache, shared by a run's spans) and kept across iterations here, as a
// line's later spans find them.

#include <string>

#include <benchmark/benchmark.h>

#include "stockbridge/io/line_file.hpp"
#include "stockbridge/line/schedule.hpp"

namespace {

using namespace stockbridge;

const io::LineFile& example_line() {
  static const io::LineFile file = io::load_line_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/line_example.toml");
  return file;
}

line::TableCache& shared_tables() {
  static line::TableCache cache;
  return cache;
}

void BM_LineSpan(benchmark::State& state) {
  const io::LineFile& file = example_line();
  const auto index = static_cast<std::size_t>(state.range(0));
  line::schedule_span(file.line, index, shared_tables());  // the tables, made once as in a run
  int per_end = 0, balances = 0;
  for (auto _ : state) {
    const line::SpanSchedule s = line::schedule_span(file.line, index, shared_tables());
    per_end = s.row.per_end;
    balances = s.row.balances;
  }
  state.counters["per_end"] = per_end;
  state.counters["search_balances"] = balances;
}
// T01-T02 and T07-T08 (2 per end), T17-T18 (1), T37-T38 (Linnet: none)
BENCHMARK(BM_LineSpan)->Arg(0)->Arg(6)->Arg(16)->Arg(36)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
