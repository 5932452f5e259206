// A damper design study's search.
#include "binding_support.hpp"

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include "stockbridge/design/search.hpp"
#include "stockbridge/io/design_file.hpp"
#include "stockbridge/requests/design_request.hpp"

namespace stockbridge::python {

namespace {

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

}  // namespace

void expose_design(py::module_& m) {
  m.def("_design", &design_search, py::arg("file"), py::arg("samples") = py::none(), py::arg("polish") = py::none(),
        py::arg("threads") = requests::DesignRequest{}.threads,
        py::arg("round_digits") = requests::DesignRequest{}.round_digits, py::arg("allow_unusual") = false,
        "A design study's search (stockbridge.design wraps it): the design CSV's columns as arrays, 'stage', "
        "'columns', 'variables', the --json summary as 'summary_json' and best.toml's text as 'best_damper'.");
}

}  // namespace stockbridge::python
