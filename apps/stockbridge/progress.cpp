#include "progress.hpp"

#include <cstdio>

#include <fmt/format.h>
#include <unistd.h>

namespace stockbridge::cli {

namespace {
constexpr double kPlainInterval = 10.0;  // s, between plain lines and before the first
constexpr int kBarWidth = 30;
}  // namespace

ProgressReport::ProgressReport(Invocation& invocation, std::string what, bool quiet, std::string unit)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      quiet_(quiet),
      terminal_(::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {
  invocation.flush_warnings();  // the inputs are read and checked: what they warn of comes before the progress
}

std::string ProgressReport::line(int done, int total, double seconds) const {
  const double rate = seconds > 0.0 ? done / seconds : 0.0;
  const std::string left = rate > 0.0 ? fmt::format(", about {:.0f} s left", (total - done) / rate) : "";
  return fmt::format("{}/{} {}, {:.1f} {}/s{}", done, total, unit_, rate, unit_, left);
}

void ProgressReport::operator()(int done, int total) {
  if (quiet_) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) {
    const int filled = total > 0 ? kBarWidth * done / total : kBarWidth;
    const std::string text = fmt::format("\r{}: [{}{}] {}", what_, std::string(filled, '#'),
                                         std::string(kBarWidth - filled, ' '), line(done, total, seconds));
    fmt::print(stderr, "{}\x1b[K", text);  // erase what a longer earlier line left
    if (done == total) fmt::print(stderr, "\r\x1b[K");
    std::fflush(stderr);
    return;
  }
  if (done == total || seconds < kPlainInterval || seconds - last_plain_ < kPlainInterval) return;
  last_plain_ = seconds;
  fmt::print(stderr, "{}: {}\n", what_, line(done, total, seconds));
}

}  // namespace stockbridge::cli
