// stockbridge._core: the Python binding. It holds no logic: each function converts
// its arguments, calls the library with the GIL released, and returns numpy arrays.

#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <condition_variable>
#include <exception>
#include <filesystem>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "stockbridge/cable/experiment.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/design/search.hpp"
#include "stockbridge/identification/global_identification.hpp"
#include "stockbridge/identification/impedance_identification.hpp"
#include "stockbridge/identification/local_identification.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/design_file.hpp"
#include "stockbridge/io/line_file.hpp"
#include "stockbridge/io/measured_impedance_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/io/strand_file.hpp"
#include "stockbridge/line/schedule.hpp"
#include "stockbridge/measurements/self_damping_tests.hpp"
#include "stockbridge/report/fatigue_tests_report.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/conductor_request.hpp"
#include "stockbridge/requests/cycle_request.hpp"
#include "stockbridge/requests/design_request.hpp"
#include "stockbridge/requests/fatigue_tests_request.hpp"
#include "stockbridge/requests/identify_request.hpp"
#include "stockbridge/requests/impedance_fit_request.hpp"
#include "stockbridge/requests/line_request.hpp"
#include "stockbridge/requests/plausibility.hpp"
#include "stockbridge/requests/modes_request.hpp"
#include "stockbridge/requests/response_request.hpp"
#include "stockbridge/requests/self_damping_request.hpp"
#include "stockbridge/requests/section_loop.hpp"
#include "stockbridge/requests/recorder_request.hpp"
#include "stockbridge/requests/span_request.hpp"
#include "stockbridge/requests/strand_request.hpp"
#include "stockbridge/requests/sweep_request.hpp"
#include "stockbridge/strand/strand_bounds.hpp"
#include "stockbridge/version.hpp"

namespace py = pybind11;
using namespace stockbridge;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// allow_unusual=True: a value a unit slip explains is a warning, not an error.
SlipPolicy slip_policy(bool allow_unusual) { return allow_unusual ? SlipPolicy::warn : SlipPolicy::refuse; }

/// Each warning line as a Python UnusualValueWarning (a UserWarning), where the CLI
/// prints "warning: ..." (values outside the typical ranges: unit mistakes).
void warn(const std::vector<std::string>& lines) {
  // Kept for the interpreter's life (a static py::object would be released after it ends).
  static const py::handle category = py::object(py::module_::import("stockbridge").attr("UnusualValueWarning")).release();
  for (const std::string& line : lines) {
    if (PyErr_WarnEx(category.ptr(), line.c_str(), 2) != 0) throw py::error_already_set();
  }
}

template <class Loaded>
auto warned(Loaded loaded) {
  warn(loaded.warnings);
  if constexpr (requires { loaded.damper; }) {
    return std::move(loaded.damper);
  } else {
    return std::move(loaded.cable);
  }
}

py::array_t<double> array(const std::vector<double>& values) { return py::array_t<double>(values.size(), values.data()); }

/// Labels as nested lists of `shape` (rows in C order): a list of str for one
/// dimension, a list of such lists for two.
py::list label_lists(const std::vector<std::string>& labels, const std::vector<std::size_t>& shape) {
  if (shape.size() < 2) return py::cast(labels);
  py::list rows;
  const std::size_t width = labels.size() / std::max<std::size_t>(shape[0], 1);
  for (std::size_t r = 0; r < shape[0]; ++r) {
    rows.append(py::cast(std::vector<std::string>(labels.begin() + static_cast<std::ptrdiff_t>(r * width),
                                                  labels.begin() + static_cast<std::ptrdiff_t>((r + 1) * width))));
  }
  return rows;
}

/// One column's values as a numpy array of `shape` (rows in C order): numbers as
/// float64, counts as int64, flags as bool; a label column as a list of str.
py::object column_array(const requests::TableValues::Column& c, const std::vector<std::size_t>& shape) {
  switch (c.kind) {
    case requests::ColumnKind::label: return label_lists(c.labels, shape);
    case requests::ColumnKind::flag: {  // true where 1 (false where masked: NaN)
      py::array_t<bool> a(shape);
      bool* out = a.mutable_data();
      for (std::size_t i = 0; i < c.numbers.size(); ++i) out[i] = c.numbers[i] == 1.0;
      return a;
    }
    case requests::ColumnKind::count: {
      py::array_t<long long> a(shape);
      long long* out = a.mutable_data();
      for (std::size_t i = 0; i < c.numbers.size(); ++i) out[i] = static_cast<long long>(c.numbers[i]);
      return a;
    }
    case requests::ColumnKind::number: break;
  }
  py::array_t<double> a(shape);
  std::copy(c.numbers.begin(), c.numbers.end(), a.mutable_data());
  return a;
}

/// A table's columns as a dict of arrays by the CSV's names, each of `shape`; with
/// `stack_families`, a family's columns (one per arm) stacked into one array of
/// (members, *shape) by the family's name ("x_m").
py::dict table_arrays(const requests::TableValues& table, const std::vector<std::size_t>& shape,
                      bool stack_families = false) {
  py::dict out;
  std::map<std::string, std::vector<const requests::TableValues::Column*>> families;
  std::vector<std::string> order;
  for (const requests::TableValues::Column& c : table.columns) {
    if (!stack_families || c.family.empty()) {
      out[py::str(c.name)] = column_array(c, shape);
      continue;
    }
    if (!families.contains(c.family)) order.push_back(c.family);
    families[c.family].push_back(&c);
  }
  for (const std::string& family : order) {
    const auto& members = families[family];
    std::vector<std::size_t> stacked{members.size()};
    stacked.insert(stacked.end(), shape.begin(), shape.end());
    py::array_t<double> a(stacked);
    double* data = a.mutable_data();
    for (const auto* c : members) data = std::copy(c->numbers.begin(), c->numbers.end(), data);
    out[py::str(family)] = a;
  }
  return out;
}

/// Row r of a table as Python scalars by name: float, int, bool or str.
void add_row(py::dict& out, const requests::TableValues& table, std::size_t r) {
  for (const requests::TableValues::Column& c : table.columns) {
    switch (c.kind) {
      case requests::ColumnKind::label: out[py::str(c.name)] = c.labels[r]; break;
      case requests::ColumnKind::flag: out[py::str(c.name)] = c.numbers[r] == 1.0; break;
      case requests::ColumnKind::count: out[py::str(c.name)] = static_cast<long long>(c.numbers[r]); break;
      case requests::ColumnKind::number: out[py::str(c.name)] = c.numbers[r]; break;
    }
  }
}

std::vector<double> amplitudes_of(const py::object& value) {
  if (value.is_none()) return {};
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) return {value.cast<double>()};
  return value.cast<std::vector<double>>();
}

/// The CLI's solver flags by the same names (None: the method's default).
requests::SolverSettings solver_settings(const std::string& method, std::optional<int> harmonics,
                                         std::optional<int> samples, std::optional<int> steps,
                                         std::optional<int> max_iterations, std::optional<int> max_periods,
                                         std::optional<double> energy_tolerance, bool full_period) {
  return {method, harmonics, samples, steps, max_iterations, max_periods, energy_tolerance,
          full_period ? std::optional<bool>(false) : std::nullopt};
}

py::dict impedance(const damper::Damper& d, const std::optional<std::vector<double>>& frequencies,
                   const py::object& velocity, const py::object& displacement, double fmin, double fmax, int points,
                   const std::string& method, std::optional<int> harmonics, std::optional<int> samples,
                   std::optional<int> steps, std::optional<int> max_iterations, std::optional<int> max_periods,
                   std::optional<double> energy_tolerance, bool full_period, int threads, bool allow_unusual) {
  requests::SweepRequest request;
  request.velocities = amplitudes_of(velocity);
  request.displacements = amplitudes_of(displacement);
  if (frequencies) {
    if (frequencies->empty()) throw InvalidParameter("frequencies", ": an empty list, expected at least one frequency (Hz)");
    request.frequencies = *frequencies;
  }
  request.grid = {fmin, fmax, points};
  request.solver =
      solver_settings(method, harmonics, samples, steps, max_iterations, max_periods, energy_tolerance, full_period);
  request.threads = threads;
  const damper::SweepSpec spec = requests::sweep_spec(request);
  std::vector<std::string> unusual;
  for (const UnusualValue& u : requests::unusual_values(request)) judge_unusual(u, "", slip_policy(allow_unusual), unusual);
  warn(unusual);
  std::vector<damper::SweepRun> runs;
  {
    py::gil_scoped_release release;
    runs = damper::run_sweep(d, spec);
  }
  const std::vector<std::size_t> shape{runs.size(), spec.frequencies.size()};
  const std::vector<const damper::ImpedancePoint*> rows = requests::sweep_points(runs);
  py::dict out = table_arrays(requests::impedance_table(d).values(rows), shape);
  for (const auto& [name, values] : table_arrays(requests::impedance_point_notes_table().values(rows), shape)) {
    out[name] = values;
  }
  out["frequency_hz"] = array(spec.frequencies);  // 1-D: the frequencies
  out["amplitude"] = array(spec.amplitudes);
  out["arms"] = requests::arm_column_prefixes(d);  // the <arm> of the per-arm columns, as the CSV's
  return out;
}

py::dict response(const damper::Damper& d, double frequency, std::optional<double> velocity, std::optional<double> displacement,
                  const std::string& method, std::optional<int> harmonics, std::optional<int> samples,
                  std::optional<int> steps, std::optional<int> max_iterations, std::optional<int> max_periods,
                  std::optional<double> energy_tolerance, bool full_period, bool allow_unusual) {
  const requests::ResponseRequest request{
      frequency, velocity, displacement,
      solver_settings(method, harmonics, samples, steps, max_iterations, max_periods, energy_tolerance, full_period)};
  requests::validate(request);
  std::vector<std::string> unusual;  // warned of with the result's warnings
  for (const UnusualValue& u : requests::unusual_excitation(frequency, velocity, displacement)) {
    judge_unusual(u, "", slip_policy(allow_unusual), unusual);
  }
  std::optional<requests::ResponseResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_response(d, request));
  }
  warn(warning_messages(result->warnings));
  const damper::ImpedancePoint& point = result->state.point;
  py::dict out = table_arrays(requests::response_table(d).values(requests::response_samples(*result)),
                              {result->time.size()}, true);
  add_row(out, requests::point_summary_table(d).values(point), 0);  // converged, termination, power_w, figures, ...
  out["arms"] = requests::arm_column_prefixes(d);  // the rows of the per-arm arrays, named as the CSV's columns
  out["message"] = point.converged() ? point.note : point.failure;
  out["impedance"] = point.converged() ? point.impedance : std::complex<double>(kNaN, kNaN);
  return out;
}

py::dict cycle(const cable::Cable& cable, const std::string& experiment, double amplitude, int cycles, int points) {
  const requests::CycleRequest request{experiment, amplitude, cycles, points};
  std::optional<requests::CycleResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_cycle(cable, request));
  }
  warn(warning_messages(result->warnings));
  py::dict out = table_arrays(requests::cycle_table().values(requests::cycle_samples(*result)),
                              {result->record.samples.size()});
  out["last_cycle_dissipation_j"] = result->record.summary.slider_dissipation;
  out["last_cycle_loop_work_j"] = result->record.summary.loop_work;
  return out;
}

py::dict loop(std::optional<double> ei, const std::vector<std::pair<double, double>>& jenkin, double amplitude,
              int cycles, int points, const std::string& law, std::optional<double> exponent, const py::kwargs& numbers) {
  const section::SinusoidalDrive drive{amplitude, cycles, points};
  cable::LoopNumbers given{law, {}, jenkin};
  if (ei) given.numbers.emplace_back("ei", *ei);
  if (exponent) given.numbers.emplace_back("exponent", *exponent);
  for (const auto& [key, value] : numbers) {
    if (!value.is_none()) given.numbers.emplace_back(py::cast<std::string>(key), py::cast<double>(value));
  }
  const requests::LoopSpelling spelling{[](std::string_view key) { return std::string(key); },
                                        [](std::string_view name) { return "law = '" + std::string(name) + "'"; }};
  section::LoopRecord record;
  {
    py::gil_scoped_release release;
    record = requests::section_loop(given, drive, spelling);
  }
  py::dict out = table_arrays(requests::loop_table().values(requests::loop_samples(record)), {record.curvature.size()});
  out["last_cycle_dissipation_j_per_m"] = record.last_cycle_dissipation();
  return out;
}

py::list jenkin_list(const std::vector<std::pair<double, double>>& c_h) {
  py::list list;
  for (const auto& [c, h] : c_h) {
    py::dict e;
    e["c"] = c;
    e["h"] = h;
    list.append(e);
  }
  return list;
}

/// A JSON summary of the library as Python objects (json.loads: null as None).
py::dict from_json(const io::JsonObject& json) {
  return py::module_::import("json").attr("loads")(json.str()).cast<py::dict>();
}

py::dict identify_local(const std::vector<double>& curvature, const std::vector<double>& moment, int elements,
                        const std::string& optimizer, const std::string& law) {
  const requests::LocalRequest request{law, elements, optimizer};
  std::optional<requests::LocalResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_local({curvature, moment}, request));
  }
  py::dict out = from_json(requests::local_summary(*result));
  out["cycle_errors"] = array(result->fit.cycle_errors);
  return out;
}

py::dict identify_global(const std::string& experiment, double length, const std::vector<double>& prescribed,
                         const std::vector<double>& measured, const std::string& method, int sections, int elements,
                         const std::string& optimizer, const std::string& law) {
  const requests::GlobalRequest request{law, experiment, length, method, sections, elements, optimizer};
  std::optional<requests::GlobalResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_global(request, prescribed, measured, "the record"));
  }
  warn(warning_messages(result->warnings));
  py::dict out = from_json(requests::global_summary(request, *result));
  out["cable"] = cable::Cable(result->fit.cable);
  return out;
}

/// The identification from a measured impedance (stockbridge.identify_impedance wraps
/// it): the --fitted CSV's columns as arrays, the --json summary as JSON text, the
/// cable files' texts and the fitted damper.
py::dict identify_impedance(const damper::Damper& start, const std::optional<std::string>& input,
                            const std::optional<std::vector<double>>& frequency,
                            const std::optional<std::vector<double>>& velocity,
                            const std::optional<std::vector<double>>& displacement,
                            const std::optional<std::vector<std::complex<double>>>& z, int elements, bool fit_clamp_mass,
                            const std::vector<std::string>& free, double rms_limit, int threads,
                            const std::optional<double>& scatter, bool allow_unusual) {
  const bool arrays = frequency || velocity || displacement || z;
  if (input.has_value() == arrays) {
    throw InvalidParameter("give either input (a measured CSV's path) or frequency, velocity (or displacement) and z");
  }
  if (arrays && (!frequency || !z || velocity.has_value() == displacement.has_value())) {
    throw InvalidParameter("give frequency, z and one of velocity or displacement (arrays of one value per point)");
  }
  const identification::ImpedanceIdentificationOptions options =
      requests::fit_options({elements, fit_clamp_mass, threads, free, rms_limit, scatter});
  io::MeasuredImpedanceFile measured;
  if (input) {
    measured = io::load_measured_impedance(*input, slip_policy(allow_unusual));
  } else {
    measured.measurement =
        requests::measurement_from_arrays(*frequency, velocity ? *velocity : *displacement, velocity.has_value(), *z);
  }
  warn(measured.warnings);
  const identification::ImpedanceMeasurement& m = measured.measurement;
  identification::ImpedanceIdentification fit;
  {
    py::gil_scoped_release release;
    fit = identification::identify_impedance(start.description(), m, options);
  }
  const std::string source = input ? *input : std::string("the measurement");
  warn(warning_messages(requests::fit_warnings(fit, source)));
  const py::dict fitted = table_arrays(requests::fitted_table().values(requests::fitted_points(m, fit)), {m.points.size()});
  py::list cable_files;
  for (std::size_t t = 0; t < fit.types(); ++t) {
    cable_files.append(requests::fitted_cable_file(fit, t, input ? *input : std::string("arrays")));
  }
  py::dict out;
  out["summary_json"] = requests::fit_summary(m, fit, start, source, measured.warnings).str();
  out["fitted"] = fitted;
  out["cable_files"] = cable_files;
  out["cable"] = cable::Cable(fit.damper.arms.front().cable);
  out["damper"] = damper::Damper(fit.damper);
  out["damper_file"] = requests::fitted_damper_file(fit, input ? *input : std::string("arrays"));
  return out;
}

/// The self-damping law fitted to tests (stockbridge.identify_self_damping wraps
/// it): the --json summary as a dict and 'table', the [self_damping] table -o writes.
py::dict identify_self_damping(const std::optional<std::string>& file, const std::optional<std::vector<double>>& tension,
                               const std::optional<std::vector<double>>& frequency,
                               const std::optional<std::vector<double>>& amplitude,
                               const std::optional<std::vector<double>>& power, const std::optional<double>& n,
                               bool allow_unusual) {
  const bool arrays = tension || frequency || amplitude || power;
  if (file.has_value() == arrays) {
    throw InvalidParameter("give either file (a test CSV's path) or tension, frequency, amplitude and power");
  }
  if (arrays && !(tension && frequency && amplitude && power)) {
    throw InvalidParameter("give tension, frequency, amplitude and power (arrays of one value per test)");
  }
  const measurements::SelfDampingTests tests =
      file ? measurements::load_self_damping_tests(*file, slip_policy(allow_unusual))
           : measurements::self_damping_tests_from_arrays(*tension, *frequency, *amplitude, *power,
                                                          slip_policy(allow_unusual));
  warn(tests.warnings);
  measurements::SelfDampingFit fit;
  try {
    fit = measurements::fit_self_damping(tests.tests, n);
  } catch (const InvalidParameter& e) {
    if (file && e.field() != "n") throw InputError(fmt::format("{}: {}", *file, e.what()));
    throw;
  }
  py::dict out = from_json(requests::self_damping_summary(fit, tests.warnings));
  out["table"] = requests::self_damping_table(fit, file ? *file : std::string("arrays"));
  return out;
}

/// A measured impedance file's warnings (values outside the typical ranges, phases
/// in radians), for the plots: stockbridge.plot impedance draws the file itself.
std::vector<std::string> measured_impedance_warnings(const std::string& path) {
  return io::load_measured_impedance(path, SlipPolicy::warn).warnings;
}

/// The span command's CSV columns as arrays (one value per frequency) and its --json
/// summary as JSON text (the package's span() parses it into a dict).
/// A recorder's counts against a span (stockbridge.recorder wraps it): the bins
/// CSV's columns as arrays, the --json summary as 'summary_json'.
py::dict recorder_counts(const std::string& span_path, const std::string& counts_path, double days,
                         const std::vector<std::string>& calibrate, int points_per_band, bool allow_unusual) {
  requests::RecorderRequest request;
  request.days = days;
  request.calibrate = calibrate;
  request.points_per_band = points_per_band;
  requests::recorder_options(request);
  io::SpanFile file = io::load_span_file(span_path, slip_policy(allow_unusual));
  measurements::RecorderCounts counts;
  try {
    counts = requests::read_recorder_input(counts_path, file, request, slip_policy(allow_unusual));
  } catch (const InvalidParameter& e) {
    throw InputError(span_path + ": " + e.what());
  }
  warn(file.warnings);
  warn(counts.warnings);
  std::optional<measurements::RecorderResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_recorder(counts, file, request));
  }
  const requests::TableValues columns = requests::recorder_bins_table().values(result->bins);
  py::dict out = table_arrays(columns, {result->bins.size()});
  out["columns"] = columns.names();
  out["summary_json"] = requests::recorder_summary(*result).str();
  return out;
}

py::dict span_balance(const std::optional<std::string>& path, const std::optional<std::string>& text,
                      const std::optional<std::string>& base,
                      const std::optional<std::vector<double>>& frequencies, int points, bool no_dampers,
                      const std::optional<std::string>& damper_model,
                      const std::optional<std::pair<double, double>>& optimize_position, double spacing_min,
                      const std::string& objective, int threads, bool report, bool allow_unusual) {
  if (path.has_value() == text.has_value()) {
    throw InvalidParameter("give either file (a span file's path) or text (a span file's contents), one of the two");
  }
  requests::SpanRequest request;
  if (frequencies) {
    if (frequencies->empty()) throw InvalidParameter("frequencies", ": an empty list, expected at least one frequency (Hz)");
    request.frequencies = *frequencies;
  }
  request.points = points;
  request.no_dampers = no_dampers;
  request.damper_model = damper_model;
  if (optimize_position) {
    request.position_min = optimize_position->first;
    request.position_max = optimize_position->second;
  }
  request.spacing_min = spacing_min;
  request.objective = objective;
  request.threads = threads;
  requests::validate(request);
  io::SpanFile file =
      path ? io::load_span_file(*path, slip_policy(allow_unusual))
           : io::load_span_text(*text, "span(text=...)", base.value_or(std::string()), slip_policy(allow_unusual));
  warn(file.warnings);
  std::optional<requests::SpanResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_span(file.span, file.balance, request));
  }
  const span::SpanAnalysis& a = result->analysis;
  const std::vector<std::size_t> shape{a.balance.points.size()};
  const requests::TableValues columns = requests::span_table(a.span).values(a.balance.points);
  py::dict out = table_arrays(columns, shape);
  for (const auto& [name, values] : table_arrays(requests::span_point_notes_table().values(a.balance.points), shape)) {
    out[name] = values;
  }
  out["dampers"] = requests::span_damper_prefixes(a.span);  // the <damper> of the per-damper columns
  out["columns"] = columns.names();
  out["summary_json"] = requests::span_summary(*result).str();
  if (report) {
    std::vector<std::string> warnings = file.warnings;
    for (const std::string& w : a.warnings) warnings.push_back(w);
    out["report_html"] = report::span_report(*result, {report::utc_now(), "", warnings});
  }
  return out;
}

/// The spans of a line scheduled on `threads` workers, each taking the next span
/// not yet taken (as the line command deals them), all sharing one TableCache; the
/// rows in the line's order, the same for any number of threads. A span whose own
/// data makes its scheduling fail is a row with the message as its warning (verdict
/// unknown), as in the command's schedule. The GIL is released while the workers
/// run; Ctrl-C (a signal Python sees) stops them between balances and raises
/// KeyboardInterrupt.
std::vector<line::ScheduleRow> schedule_line(const io::LineFile& file, int threads) {
  const std::size_t spans = file.line.spans().size();
  std::vector<std::optional<line::ScheduleRow>> rows(spans);
  line::TableCache cache;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::condition_variable finished;
  int running = 0;
  std::exception_ptr failure;
  const auto stopped = [&stop] { return stop.load(); };
  const auto work = [&] {
    for (std::size_t i = next++; i < spans && !stop.load(); i = next++) {
      try {
        rows[i] = line::schedule_span(file.line, i, cache, stopped).row;
      } catch (const Interrupted&) {
        break;
      } catch (const InvalidParameter& e) {
        rows[i] = requests::failed_row(file, i, e.what());
      } catch (const NumericalError& e) {
        rows[i] = requests::failed_row(file, i, e.what());
      } catch (...) {  // anything else ends the schedule: raised once the workers are done
        const std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        stop.store(true);
        break;
      }
    }
    const std::lock_guard lock(mutex);
    --running;
    finished.notify_all();
  };
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::vector<std::jthread> workers;  // joined when they go out of scope, whatever happens
    const int count = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads), spans));
    try {
      for (int k = 0; k < count; ++k) {
        {
          const std::lock_guard lock(mutex);
          ++running;
        }
        try {
          workers.emplace_back(work);
        } catch (...) {
          const std::lock_guard lock(mutex);
          --running;
          throw;
        }
      }
    } catch (...) {
      stop.store(true);
      throw;
    }
    std::unique_lock lock(mutex);
    while (!finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return running == 0; })) {
      if (interrupted) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        interrupted = PyErr_CheckSignals() != 0;  // KeyboardInterrupt (or the handler's error) set
      }
      if (interrupted) stop.store(true);
      lock.lock();
    }
  }
  if (interrupted) throw py::error_already_set();
  if (failure) std::rethrow_exception(failure);
  std::vector<line::ScheduleRow> schedule;
  schedule.reserve(spans);
  for (std::optional<line::ScheduleRow>& row : rows) schedule.push_back(std::move(*row));
  return schedule;
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
  const std::vector<line::ScheduleRow> rows = schedule_line(file, threads);
  const std::vector<line::BillLine> bill = line::bill_of_materials(file.line, rows);
  py::dict out;
  out["schedule"] = table_arrays(requests::schedule_table().values(rows), {rows.size()});
  out["bill"] = table_arrays(requests::bill_table().values(bill), {bill.size()});
  out["summary_json"] = requests::line_summary(file, rows).str();
  out["warnings"] = file.warnings;
  if (report) out["report_html"] = report::line_report(file, rows, {report::utc_now(), "", file.warnings});
  return out;
}

/// The design command's CSV columns as arrays (one value per candidate, in the CSV's
/// order: the base, the samples, the polishes), its --json summary as JSON text (the
/// package's design() parses it into a dict) and best.toml's text (None when no
/// candidate is feasible).
py::dict design_search(const std::string& path, std::optional<int> samples, std::optional<int> polish, int threads,
                       int round_digits, bool allow_unusual) {
  requests::DesignRequest request;
  request.samples = samples;
  request.polish = polish;
  request.threads = threads;
  request.round_digits = round_digits;
  requests::validate(request);
  const io::DesignFile file = io::load_design_file(path, slip_policy(allow_unusual));
  warn(file.warnings);
  const design::SearchOptions options = requests::search_options(file.search, request);
  std::optional<design::DesignResult> result;
  std::optional<design::Evaluation> rounded;
  {
    py::gil_scoped_release release;
    design::ThreadRunner runner(threads);
    result.emplace(design::run_search(file.study, options, runner));
    rounded = requests::rounded_best(file.study, *result, round_digits);
  }
  const requests::TableValues columns = requests::design_table(file.study).values(result->evaluations);
  py::dict out = table_arrays(columns, {result->evaluations.size()});
  out["columns"] = columns.names();
  std::vector<std::string> variables;
  for (const design::DesignVariable& v : file.study.variables()) variables.push_back(v.name);
  out["variables"] = variables;
  // The command's --json adds its wall time, which Python leaves out.
  const design::Evaluation* built = rounded ? &*rounded : nullptr;
  out["summary_json"] =
      requests::design_summary(file.study, *result, {options.samples, options.polish, 1, threads, round_digits, built}).str();
  out["best_damper"] =
      requests::best_damper_file(file.study, *result, std::filesystem::path(path).filename().string(), built);
  return out;
}

/// The modes command's JSON as a dict (the same keys), arms named as the CSV's columns.
py::dict modes(const damper::Damper& d) {
  std::optional<requests::ModesResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_modes(d));
  }
  return from_json(requests::modes_summary(*result));
}

/// `stockbridge fatigue-tests` (stockbridge.fatigue_tests wraps it): the output CSV's
/// columns as arrays ('table'), the --json summary as 'summary_json', the design
/// curve's S-N file text ('curve_toml', None where the fit's slope gives no curve),
/// the file's 'warnings' and with report the HTML page's text.
void bind_fatigue_tests(py::module_& m) {
  m.def(
      "_fatigue_tests",
      [](const std::string& file, const std::optional<std::string>& conductor, bool allow_unusual, bool report) {
        requests::FatigueTestsRequest request;
        request.file = file;
        request.conductor = conductor;
        request.policy = slip_policy(allow_unusual);
        const requests::FatigueTestsOutcome outcome = requests::run_fatigue_tests(request);
        warn(outcome.warnings);
        py::dict out;
        out["table"] = table_arrays(requests::fatigue_tests_values(outcome.result), {outcome.result.tests.size()});
        out["summary_json"] = requests::fatigue_tests_summary(outcome).str();
        out["curve_toml"] = outcome.result.fit.b < 0.0 ? py::object(py::str(requests::fatigue_tests_curve_toml(outcome)))
                                                       : py::object(py::none());
        out["warnings"] = outcome.warnings;
        if (report) out["report_html"] = report::fatigue_tests_report(outcome, {report::utc_now(), "", outcome.warnings});
        return out;
      },
      py::arg("file"), py::arg("conductor") = py::none(), py::arg("allow_unusual") = false, py::arg("report") = false,
      "A conductor's fatigue tests (stockbridge.fatigue_tests wraps it).");
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "stockbridge: nonlinear impedance of Stockbridge dampers (C++ library binding)";
  m.attr("__version__") = std::string(stockbridge::version());

  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<InvalidParameter> invalid_parameter(m, "InvalidParameter", PyExc_ValueError);
  static py::exception<UnusualValueError> unusual_value_error(m, "UnusualValueError", input_error.ptr());
  static py::exception<NumericalError> numerical_error(m, "NumericalError", error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const UnusualValueError& e) {
      unusual_value_error((std::string(e.what()) + " (allow_unusual=True takes it as given)").c_str());
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const InvalidParameter& e) {
      invalid_parameter(e.what());
    } catch (const NumericalError& e) {
      numerical_error(e.what());
    } catch (const Error& e) {
      error(e.what());
    }
  });

  py::class_<cable::Cable> cable_class(m, "Cable",
                                       "A cable (length, sections, section law and its numbers), validated and discretised");
  cable_class.def_property_readonly("length", &cable::Cable::length, "m")
      .def_property_readonly("sections", [](const cable::Cable& c) { return c.description().sections; })
      .def_property_readonly("law", [](const cable::Cable& c) { return std::string(c.description().law->name()); },
                             ("the section law: " + cable::section_law_names(true)).c_str());
  // Every law's numbers as properties, each key once: its value at the clamp, None
  // under a law without it.
  std::vector<std::string> number_keys;
  for (const cable::SectionLawDescriptor* law : cable::section_laws()) {
    for (const cable::LawNumber& n : law->numbers()) {
      const std::string key(n.key);
      if (std::find(number_keys.begin(), number_keys.end(), key) != number_keys.end()) continue;
      number_keys.push_back(key);
      std::vector<std::string> owners;
      for (const cable::SectionLawDescriptor* o : cable::section_laws()) {
        if (cable::number_index(*o, key) >= 0) owners.push_back(std::string(o->title()));
      }
      cable_class.def_property_readonly(
          key.c_str(),
          [key](const cable::Cable& c) -> std::optional<double> {
            if (cable::number_index(*c.description().law, key) < 0) return std::nullopt;
            return c.description().number(key).at(0.0);
          },
          fmt::format("{}{}{} (at the clamp; None under a law without it: the {} law{} take{} it)", n.unit,
                      n.unit.empty() ? "" : ", ", n.description, cable::joined_with_and(owners),
                      owners.size() > 1 ? "s" : "", owners.size() > 1 ? "" : "s")
              .c_str());
    }
  }
  cable_class
      .def_property_readonly(
          "jenkin",
          [](const cable::Cable& c) {
            std::vector<std::pair<double, double>> c_h;
            for (const auto& e : c.description().jenkin) c_h.emplace_back(e.c.at(0.0), e.h.at(0.0));
            return jenkin_list(c_h);
          },
          "[{'c': N m^2, 'h': N m}, ...] (at the clamp)")
      .def("toml", [](const cable::Cable& c) { return io::cable_table_toml(c.description()); },
           "The keys of a [cable] table for this cable (what cable and damper files accept).")
      .def(
          "with_length",
          [](const cable::Cable& c, double length) {
            cable::CableDescription d = c.description();
            d.length = length;
            return cable::Cable(std::move(d));
          },
          py::arg("length"), "A copy of this cable cut to another length, m (its parameters and sections kept).")
      .def(
          "save",
          [](const cable::Cable& c, const std::string& path, const std::string& comment) {
            io::write_file_atomically(path, io::cable_file_toml(c.description(), comment));
          },
          py::arg("path"), py::arg("comment") = "",
          "Write this cable as a cable file (TOML) that load_cable, the cycle command and damper files' "
          "[arm.cable] file = ... read; `comment` goes on top as TOML comments.");
  py::class_<damper::Damper>(m, "Damper", "A damper (clamp mass and arms), validated")
      .def_property_readonly("clamp_mass", &damper::Damper::clamp_mass, "kg")
      .def_property_readonly("arms", [](const damper::Damper& d) {
        py::list names;
        for (std::size_t k = 0; k < d.arms().size(); ++k) names.append(d.arm_name(k));
        return names;
      });

  m.def(
      "load_cable",
      [](const std::string& path, bool allow_unusual) {
        return warned(io::load_cable_file(path, slip_policy(allow_unusual)));
      },
      py::arg("path"), py::arg("allow_unusual") = false,
      "Read a cable TOML file (an UnusualValueWarning for each value outside the typical ranges; UnusualValueError "
      "for one a unit slip explains, unless allow_unusual).");
  m.def(
      "load_damper",
      [](const std::string& path, bool allow_unusual) {
        return warned(io::load_damper_file(path, slip_policy(allow_unusual)));
      },
      py::arg("path"), py::arg("allow_unusual") = false,
      "Read a damper TOML file (an UnusualValueWarning for each value outside the typical ranges; UnusualValueError "
      "for one a unit slip explains, unless allow_unusual).");
  m.def(
      "_cable_from_toml",
      [](std::string_view text, std::string_view source, bool allow_unusual) {
        return warned(io::load_cable_text(text, source, slip_policy(allow_unusual)));
      },
      py::arg("text"), py::arg("source"), py::arg("allow_unusual") = false,
      "A cable from TOML text (make_cable builds it): the cable file reader's keys, checks, messages and warnings.");
  m.def(
      "_damper_from_toml",
      [](std::string_view text, std::string_view source, bool allow_unusual) {
        return warned(io::load_damper_text(text, source, slip_policy(allow_unusual)));
      },
      py::arg("text"), py::arg("source"), py::arg("allow_unusual") = false,
        "A damper from TOML text (make_damper builds it): the damper file reader's keys, checks, messages and warnings.");
  // The defaults are the library requests' (the CLI's too); the package's wrappers read theirs here.
  py::dict defaults;
  defaults["span_points"] = requests::SpanRequest{}.points;
  defaults["span_threads"] = requests::SpanRequest{}.threads;
  defaults["span_spacing_min"] = requests::SpanRequest{}.spacing_min;
  defaults["span_objective"] = requests::SpanRequest{}.objective;
  defaults["design_threads"] = requests::DesignRequest{}.threads;
  defaults["design_round_digits"] = requests::DesignRequest{}.round_digits;
  defaults["fit_elements"] = requests::ImpedanceFitRequest{}.elements;
  defaults["fit_clamp_mass"] = requests::ImpedanceFitRequest{}.fit_clamp_mass;
  defaults["fit_threads"] = requests::ImpedanceFitRequest{}.threads;
  defaults["fit_rms_limit"] = requests::ImpedanceFitRequest{}.rms_limit;
  m.attr("_defaults") = defaults;
  const requests::FrequencyGrid grid;
  const requests::SolverSettings solver;
  const requests::ImpedanceFitRequest fit;
  m.def("impedance", &impedance, py::arg("damper"), py::arg("frequencies") = py::none(), py::arg("velocity") = py::none(),
        py::arg("displacement") = py::none(), py::arg("fmin") = grid.fmin, py::arg("fmax") = grid.fmax, py::arg("points") = grid.points,
        py::arg("method") = solver.method, py::arg("harmonics") = py::none(), py::arg("samples") = py::none(),
        py::arg("steps") = py::none(), py::arg("max_iterations") = py::none(), py::arg("max_periods") = py::none(),
        py::arg("energy_tolerance") = py::none(), py::arg("full_period") = false, py::arg("threads") = requests::SweepRequest{}.threads,
        py::arg("allow_unusual") = false,
        "Z(f, amplitude) over `frequencies` (or fmin..fmax, `points` log-spaced): arrays of shape (amplitudes, "
        "frequencies) named as the impedance CSV's columns (the design figures per arm as '<arm>_power_w' and "
        "'<arm>_mass_amplitude_m', the arms named in 'arms'); NaN where a point did not converge (see 'converged', "
        "'termination' and 'messages'). Solver settings left None take the method's default.");
  m.def("response", &response, py::arg("damper"), py::arg("frequency"), py::arg("velocity") = py::none(),
        py::arg("displacement") = py::none(), py::arg("method") = solver.method, py::arg("harmonics") = py::none(),
        py::arg("samples") = py::none(), py::arg("steps") = py::none(), py::arg("max_iterations") = py::none(),
        py::arg("max_periods") = py::none(), py::arg("energy_tolerance") = py::none(), py::arg("full_period") = false,
        py::arg("allow_unusual") = false,
        "One steady period; per-arm arrays have shape (arms, samples). A point that did not converge is returned "
        "as its last iterate with converged = False, its termination and message (NaN where nothing was computed). "
        "The point's design figures are numbers named as the impedance CSV's columns.");
  m.def("_span", &span_balance, py::arg("file") = py::none(), py::arg("text") = py::none(),
        py::arg("base") = py::none(),
        py::arg("frequencies") = py::none(), py::arg("points") = requests::SpanRequest{}.points,
        py::arg("no_dampers") = false, py::arg("damper_model") = py::none(),
        py::arg("optimize_position") = py::none(), py::arg("spacing_min") = requests::SpanRequest{}.spacing_min,
        py::arg("objective") = requests::SpanRequest{}.objective, py::arg("threads") = requests::SpanRequest{}.threads,
        py::arg("report") = false, py::arg("allow_unusual") = false,
        "The span's energy balance (stockbridge.span wraps it): the span CSV's columns as arrays, "
        "'converged', 'termination', 'messages', 'dampers', 'columns', the --json summary as 'summary_json' and "
        "with report the HTML report's text as 'report_html'.");
  m.def("_recorder", &recorder_counts, py::arg("span"), py::arg("counts"), py::arg("days"),
        py::arg("calibrate") = std::vector<std::string>{},
        py::arg("points_per_band") = measurements::RecorderOptions{}.points_per_band, py::arg("allow_unusual") = false,
        "A vibration recorder's counts against a span (stockbridge.recorder wraps it): the bins CSV's columns "
        "as arrays, 'columns', and the --json summary as 'summary_json'.");
  bind_fatigue_tests(m);
  m.def("_line", &line_schedule, py::arg("file") = py::none(), py::arg("text") = py::none(),
        py::arg("base") = py::none(), py::arg("threads") = 1, py::arg("report") = false, py::arg("allow_unusual") = false,
        "A line's damper schedule (stockbridge.line wraps it): 'schedule' and 'bill', the schedule and bill CSVs' "
        "columns as arrays, the --json summary as 'summary_json', the line file's 'warnings' and with report the "
        "HTML report's text as 'report_html'.");
  m.def("_design", &design_search, py::arg("file"), py::arg("samples") = py::none(), py::arg("polish") = py::none(),
        py::arg("threads") = requests::DesignRequest{}.threads,
        py::arg("round_digits") = requests::DesignRequest{}.round_digits, py::arg("allow_unusual") = false,
        "A design study's search (stockbridge.design wraps it): the design CSV's columns as arrays, 'stage', "
        "'columns', 'variables', the --json summary as 'summary_json' and best.toml's text as 'best_damper'.");
  m.def("modes", &modes, py::arg("damper"),
        "Linear natural frequencies (Hz), every element sticking and every one slipping, as the modes command's "
        "JSON: 'arms' (each arm, clamp held: name, stick_hz, slip_hz) and 'damper' (clamp free, the rigid-body "
        "mode left out: stick_hz, slip_hz, and stick_modes/slip_modes with each arm's share of the energy).");
  m.def("cycle", &cycle, py::arg("cable"), py::arg("experiment"), py::arg("amplitude"),
        py::arg("cycles") = requests::CycleRequest{}.cycles, py::arg("points") = requests::CycleRequest{}.points,
        "Experiment 'a' (tip force) or 'b' (tip rotation) on a cable.");
  const requests::LocalRequest local;
  const requests::GlobalRequest global;
  m.def("identify_local", &identify_local, py::arg("curvature"), py::arg("moment"), py::arg("elements") = local.elements,
        py::arg("optimizer") = local.optimizer, py::arg("law") = local.law,
        "Masing parameters (law='masing': ei, jenkin) or Bouc-Wen ones (law='bouc-wen': ei_min, ei_max, chi0) of a "
        "section from a moment-curvature record.");
  m.def("identify_global", &identify_global, py::arg("experiment"), py::arg("length"), py::arg("prescribed"),
        py::arg("measured"), py::arg("method") = global.method, py::arg("sections") = global.sections,
        py::arg("elements") = global.elements, py::arg("optimizer") = global.optimizer, py::arg("law") = global.law,
        "Constant cable parameters from a cycle of experiment (a) or (b), by the Masing law or (law='bouc-wen', "
        "method='fit') the Bouc-Wen law; 'cable' is a Cable ready for make_damper.");
  m.def("_identify_impedance", &identify_impedance, py::arg("damper"), py::arg("input") = py::none(),
        py::arg("frequency") = py::none(), py::arg("velocity") = py::none(), py::arg("displacement") = py::none(),
        py::arg("z") = py::none(), py::arg("elements") = fit.elements, py::arg("fit_clamp_mass") = fit.fit_clamp_mass,
        py::arg("free") = fit.free, py::arg("rms_limit") = fit.rms_limit, py::arg("threads") = fit.threads,
        py::arg("scatter") = py::none(), py::arg("allow_unusual") = false,
        "The identification from a measured impedance (stockbridge.identify_impedance wraps it).");
  m.def("_identify_self_damping", &identify_self_damping, py::arg("file") = py::none(),
        py::arg("tension") = py::none(), py::arg("frequency") = py::none(), py::arg("amplitude") = py::none(),
        py::arg("power") = py::none(), py::arg("n") = py::none(), py::arg("allow_unusual") = false,
        "The self-damping law fitted to tests (stockbridge.identify_self_damping wraps it).");
  m.def("_measured_impedance_warnings", &measured_impedance_warnings, py::arg("path"),
        "A measured impedance CSV's warnings (values outside the typical ranges, phases in radians), as lines; "
        "InputError for a file identify impedance refuses.");
  m.def("loop", &loop, py::arg("ei") = py::none(), py::arg("jenkin") = std::vector<std::pair<double, double>>{},
        py::arg("amplitude"), py::arg("cycles") = section::SinusoidalDrive{}.cycles,
        py::arg("points") = section::SinusoidalDrive{}.points, py::arg("law") = std::string(requests::default_loop_law),
        py::arg("exponent") = py::none(),
        "One section driven by kappa = amplitude sin(2 pi k / points), as the loop command: the law's numbers by key "
        "(Cable's properties; ei and jenkin = [(c, h), ...] in N m^2 and N m for law 'masing', its variants 'exact' "
        "and 'regularised' (with exponent, default 10); ei_min, ei_max (N m^2) and chi0 (1/m) for law 'bouc-wen').");
  m.def(
      "load_strand",
      [](const std::string& path) {
        const strand::Strand s = io::read_strand_file(path);
        return from_json(requests::strand_summary(strand::strand_bounds(s)));
      },
      py::arg("path"), "A strand file's bending-stiffness bounds, as the strand command: {ei_min_n_m2, ei_max_n_m2}.");
  m.def(
      "strand_bounds",
      [](double core_radius, const std::vector<std::tuple<int, double, double, double>>& layers, double youngs_modulus) {
        strand::Strand s;
        s.core_radius = core_radius;
        s.youngs_modulus = youngs_modulus;
        for (const auto& [count, r, pitch, lay] : layers) s.layers.push_back({count, r, pitch, lay});
        strand::validate(s);
        const strand::StrandBounds b = strand::strand_bounds(s);
        return std::make_pair(b.ei_min, b.ei_max);
      },
      py::arg("core_radius"), py::arg("layers"), py::arg("youngs_modulus") = strand::Strand{}.youngs_modulus,
      "(EI_min, EI_max) in N m^2; layers = [(count, wire_radius, pitch_radius, lay_length), ...] in m.");
  m.def(
      "conductor",
      [](const std::string& type) { return from_json(requests::conductor_summary(io::catalogue_conductor(type))); },
      py::arg("type"),
      "A conductor of the catalogue (case, spaces and hyphens aside, e.g. 'acsr-drake'), as `stockbridge conductors "
      "TYPE --json`: a dict of type, stranding, source and the span file's [conductor] values with units "
      "(mass_per_length_kg_m, diameter_m, rated_tensile_strength_n, ei_min_n_m2, ei_max_n_m2, outer_wire_diameter_m, "
      "outer_wire_modulus_pa, aluminium_layers), EI_min and the rest derived from the stranding.");
  m.def(
      "conductors",
      [] {
        py::list out;
        for (const span::StrandedConductor& c : io::conductor_catalogue()) out.append(from_json(requests::conductor_summary(c)));
        return out;
      },
      "The catalogue: one dict per conductor, as conductor() gives it.");
  m.def(
      "load_conductor",
      [](const std::string& path) { return from_json(requests::conductor_summary(io::read_conductor_file(path))); },
      py::arg("path"), "A conductor file (the catalogue's format, docs/file-formats.md), as conductor() gives an entry.");
}
