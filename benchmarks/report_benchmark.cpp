// The reports' cost beside the runs they report: the example span's HTML page (three
// charts of 400 points, the inputs, the tables) from a finished analysis, and one
// chart alone. A report must cost nothing next to the balance it shows.

#include <cmath>
#include <string>

#include <benchmark/benchmark.h>

#include "stockbridge/io/span_file.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/report/svg_chart.hpp"
#include "stockbridge/requests/span_request.hpp"

namespace {

using namespace stockbridge;

const requests::SpanResult& example_result() {
  static const requests::SpanResult result = [] {
    const io::SpanFile file = io::load_span_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/aster570_400m.toml");
    requests::SpanRequest request;
    request.points = 400;
    return requests::run_span(file.span, file.balance, requests::check_span_request(request));
  }();
  return result;
}

void BM_SpanReport(benchmark::State& state) {
  const requests::SpanResult& result = example_result();
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string html = report::span_report(result, {"2026-11-26 12:00 UTC", "stockbridge span", {}});
    bytes = html.size();
    benchmark::DoNotOptimize(html.data());
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_SpanReport)->Unit(benchmark::kMillisecond);

void BM_Chart(benchmark::State& state) {
  report::Chart chart("chart", report::Axis("frequency (Hz)", true), report::Axis("power (W)", true));
  const int n = static_cast<int>(state.range(0));
  for (int s = 0; s < 3; ++s) {
    report::Series series;
    for (int i = 0; i < n; ++i) {
      series.x.push_back(5.0 * std::pow(20.0, static_cast<double>(i) / (n - 1)));
      series.y.push_back(std::exp(std::sin(0.05 * i + s)));
    }
    chart.series.push_back(series);
  }
  for (auto _ : state) benchmark::DoNotOptimize(report::svg(chart).size());
}
BENCHMARK(BM_Chart)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
