// A line's spans on several threads share one TableCache (each table made once,
// whichever thread asks first, the others waiting for it) and give exactly the rows
// they give one at a time. The ThreadSanitizer preset runs it ("Threads" in the name).

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/io/line_file.hpp"
#include "stockbridge/line/schedule.hpp"
#include "stockbridge/requests/line_request.hpp"

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
  TableCache shared;
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      for (std::size_t i = next++; i < spans; i = next++) {
        together[i] = requests::schedule_record(schedule_span(file.line, i, shared).row);
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(together, alone);
  EXPECT_EQ(shared.tables(), one.tables()) << "every table made once";
  EXPECT_EQ(shared.nodes(), one.nodes());
}

}  // namespace
}  // namespace stockbridge::line
