// A line's spans on several threads share one TableCache (each table made once,
// whichever thread asks first, the others waiting for it) and give exactly the rows
// they give one at a time, through requests::run_line as the command and Python run a
// line; a stop ends a run as a termination. The ThreadSanitizer preset runs the
// threaded ones ("Threads" in the name).

#include <atomic>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/io/line_file.hpp"
#include "stockbridge/line/schedule.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/requests/line_request.hpp"
#include "stockbridge/requests/line_run.hpp"

namespace stockbridge::line {
namespace {

std::string tiny_line() {
  std::string text = R"([line]
points = 8
search_points = 6
[conductor]
type = "AAAC ASTER570"
[wind]
law = "cigre"
[self_damping]
law = "noiseux-1991"
[fatigue]
cycles = 5e8
[dampers]
types = [ { name = "sb1", file = ")" + std::string(STOCKBRIDGE_SOURCE_DIR) + R"(/examples/sauter2003.toml" } ]
max_per_end = 1
position_max = 3.0
)";
  for (const char* span : {"A", "B", "C", "D"}) {
    text += std::string("[[span]]\nid = \"") + span + "\"\nlength = 350\ntension_fraction = 0.15\n";
  }
  return text;
}

TEST(LineScheduleThreads, SpansOnFourThreadsShareTheirTablesAndGiveTheRowsOfOne) {
  const io::LineFile file = io::load_line_text(tiny_line(), "line(text=...)");
  const std::size_t spans = file.line.spans().size();
  std::vector<std::string> alone(spans), together(spans);
  TableCache one;
  for (std::size_t i = 0; i < spans; ++i) alone[i] = requests::schedule_record(schedule_span(file.line, i, one).row);
  // requests::run_line, as the command and Python run a line: four threads, one cache.
  TableCache shared;
  requests::LineRunOptions options;
  options.threads = 4;
  int heartbeats = 0, outcomes = 0;
  options.heartbeat = [&] { ++heartbeats; };  // on this thread
  options.on_outcome = [&](const requests::SpanOutcome& o, const std::string& record) {
    ++outcomes;
    EXPECT_EQ(o.end, requests::SpanEnd::scheduled);
    EXPECT_EQ(record, requests::schedule_record(*o.row));
  };
  const requests::LineRun run = requests::run_line(file, shared, options);
  EXPECT_EQ(run.termination, Termination::converged);
  ASSERT_EQ(run.outcomes.size(), spans);
  for (std::size_t i = 0; i < spans; ++i) {
    EXPECT_EQ(run.outcomes[i].index, i);
    together[i] = requests::schedule_record(*run.outcomes[i].row);
  }
  EXPECT_EQ(together, alone);
  EXPECT_EQ(outcomes, static_cast<int>(spans));
  EXPECT_GT(heartbeats, 0);
  EXPECT_EQ(shared.tables(), one.tables()) << "every table made once";
  EXPECT_EQ(shared.nodes(), one.nodes());
}

TEST(LineScheduleThreads, AStopEndsTheRunInterruptedWithoutAnExceptionAndNoRow) {
  const io::LineFile file = io::load_line_text(tiny_line(), "line(text=...)");
  TableCache cache;
  const std::atomic<bool> stop{true};
  requests::LineRunOptions options;
  options.threads = 2;
  options.stop = &stop;
  options.todo = {3, 1};
  const requests::LineRun run = requests::run_line(file, cache, options);
  EXPECT_EQ(run.termination, Termination::interrupted);
  ASSERT_EQ(run.outcomes.size(), 2u);
  for (const requests::SpanOutcome& o : run.outcomes) {
    EXPECT_EQ(o.end, requests::SpanEnd::interrupted);
    EXPECT_FALSE(o.row.has_value());
  }
  EXPECT_EQ(run.outcomes[0].index, 1u);  // in the line's order
  EXPECT_EQ(cache.tables(), 0);
  options.todo = {4};
  EXPECT_THROW(requests::run_line(file, cache, options), InvalidParameter);  // a span the line does not have
}

TEST(LineRunOutcome, AFailedSpansRecordGivesItsTypedOutcomeAndReasonBack) {
  const io::LineFile file = io::load_line_text(tiny_line(), "line(text=...)");
  requests::SpanOutcome failed{2, requests::SpanEnd::failed, "", requests::failed_row(file, 2, "tension: too low")};
  const std::string record = requests::span_outcome_record(failed);
  EXPECT_TRUE(record.starts_with("failed\t"));
  const requests::SpanOutcome back = requests::parse_span_outcome(record);
  EXPECT_EQ(back.end, requests::SpanEnd::failed);
  EXPECT_EQ(back.index, 2u);
  EXPECT_EQ(back.reason, "tension: too low");
  EXPECT_EQ(requests::schedule_record(*back.row), requests::schedule_record(*failed.row));
  // A scheduled span's record is the row's, as journals before the mark hold them.
  const requests::SpanOutcome plain = requests::parse_span_outcome(requests::schedule_record(*failed.row));
  EXPECT_EQ(plain.end, requests::SpanEnd::scheduled);
  EXPECT_TRUE(requests::span_outcome_record({0, requests::SpanEnd::interrupted, "stopped", std::nullopt}).empty());
  EXPECT_EQ(requests::span_end_name(requests::SpanEnd::failed), "failed");
}

}  // namespace
}  // namespace stockbridge::line
