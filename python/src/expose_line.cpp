// A line's damper schedule on threads.
#include "binding_support.hpp"

#include <atomic>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/line_file.hpp"
#include "stockbridge/line/schedule.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/line_request.hpp"
#include "stockbridge/requests/line_run.hpp"

namespace stockbridge::python {

namespace {

/// The line's schedule (requests::run_line on `threads` threads, all sharing one
/// TableCache): the rows in the line's order, the same for any number of threads; a
/// span whose own data makes its scheduling fail is a row with the message as its
/// warning (verdict unknown), as in the command's schedule. The GIL is released while
/// the workers run; Ctrl-C (a signal Python sees) stops them between balances and
/// raises KeyboardInterrupt.
requests::LineSchedule schedule_line(const io::LineFile& file, int threads) {
  line::TableCache cache;
  std::atomic<bool> stop{false};
  bool interrupted = false;
  requests::LineRunOptions options;
  options.threads = threads;
  options.stop = &stop;
  options.heartbeat = [&] {
    if (interrupted) return;
    py::gil_scoped_acquire gil;
    interrupted = PyErr_CheckSignals() != 0;  // KeyboardInterrupt (or the handler's error) set
    if (interrupted) stop.store(true);
  };
  std::optional<requests::LineRun> run;
  {
    py::gil_scoped_release release;
    run.emplace(requests::run_line(file, cache, options));
  }
  if (interrupted) throw py::error_already_set();
  std::map<std::size_t, line::ScheduleRow> rows;
  for (requests::SpanOutcome& o : run->outcomes) rows.emplace(o.index, std::move(*o.row));
  return requests::line_schedule(file, std::move(rows));
}

/// The line command's outputs (stockbridge.line wraps it): the schedule CSV's and the
/// bill CSV's columns as arrays, the --json summary as JSON text and the line file's
/// warnings (each also an UnusualValueWarning).
py::dict line_schedule(const std::optional<std::string>& path, const std::optional<std::string>& text,
                       const std::optional<std::string>& base, int threads, bool report, bool allow_unusual) {
  if (path.has_value() == text.has_value()) {
    throw InvalidParameter("give either file (a line file's path) or text (a line file's contents), one of the two");
  }
  require_in_range("threads", threads, 1, 256);
  const io::LineFile file =
      path ? io::load_line_file(*path, slip_policy(allow_unusual))
           : io::load_line_text(*text, "line(text=...)", base.value_or(std::string()), slip_policy(allow_unusual));
  warn(file.warnings);
  const requests::LineSchedule schedule = schedule_line(file, threads);
  py::dict out;
  out["schedule"] = table_arrays(requests::schedule_table().values(schedule.rows), {schedule.rows.size()});
  out["bill"] = table_arrays(requests::bill_table().values(schedule.bill), {schedule.bill.size()});
  out["summary_json"] = requests::line_summary(file, schedule).str();
  out["warnings"] = file.warnings;
  if (report) out["report_html"] = report::line_report(file, schedule, {report::utc_now(), "", file.warnings});
  return out;
}

}  // namespace

void expose_line(py::module_& m) {
  m.def("_line", &line_schedule, py::arg("file") = py::none(), py::arg("text") = py::none(),
        py::arg("base") = py::none(), py::arg("threads") = 1, py::arg("report") = false, py::arg("allow_unusual") = false,
        "A line's damper schedule (stockbridge.line wraps it): 'schedule' and 'bill', the schedule and bill CSVs' "
        "columns as arrays, the --json summary as 'summary_json', the line file's 'warnings' and with report the "
        "HTML report's text as 'report_html'.");
}

}  // namespace stockbridge::python
