// libFuzzer target: design study files (docs/design.md), io::load_design_file on the
// fuzzed text beside a damper file (d.toml, one arm named "a") and a span file
// (span.toml, that damper at 1 m) it may name (beside_files.hpp). Either one library
// error (stockbridge::Error) of one line that begins with a file of the folder, or a
// study whose candidates at the variables' bounds and at the base values build
// their dampers and spans (or refuse with a typed error of one line: a candidate
// may be no valid damper); nothing else.

#include <optional>
#include <vector>

#include "beside_files.hpp"
#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/damper.hpp"
#include "stockbridge/io/design_file.hpp"

namespace {

/// A candidate's damper and its spans, as a search would build them.
void build_candidate(const stockbridge::design::DesignStudy& study, const std::vector<double>& x) {
  using namespace stockbridge;
  try {
    const damper::Damper damper(study.damper_of(x));
    for (std::size_t k = 0; k < study.spans().size(); ++k) {
      const span::Span s = study.span_with(k, damper, study.position_on(k, x));
      fuzz::require(s.dampers().size() == study.spans()[k].span.dampers().size(), "a candidate's span keeps its dampers");
    }
  } catch (const Error& e) {
    fuzz::require_one_line(e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  static const bool beside = fuzz::write_beside_files();
  fuzz::require(beside, "the files beside the design file are written");
  const auto path = fuzz::as_file(data, size, "design.toml");
  std::optional<io::DesignFile> file;
  try {
    file = io::load_design_file(path);
  } catch (const Error& e) {
    fuzz::require_one_line_naming(e.what(), fuzz::folder());
    return 0;
  }
  const design::DesignStudy& study = file->study;
  fuzz::require(!study.variables().empty() && !study.spans().empty(), "a study has variables and spans");
  std::vector<double> low, high;
  for (const design::DesignVariable& v : study.variables()) {
    fuzz::require(v.min < v.max, "a variable's min below its max");
    low.push_back(v.min);
    high.push_back(v.max);
  }
  build_candidate(study, low);
  build_candidate(study, high);
  build_candidate(study, study.base_values());
  for (const std::string& w : file->warnings) fuzz::require_one_line(w);
  return 0;
}
