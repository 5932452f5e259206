// libFuzzer target: a line's spans CSV (docs/line.md: id, length_m, a tension column,
// optionally terrain, conductor, wind speeds), read through a fixed line file that
// names it (spans = "spans.csv"), beside a damper file and a conductor file the rows
// may name (beside_files.hpp). Either one library error (stockbridge::Error) of one
// line that begins with a file of the folder (the CSV's row, or the line file's
// key), or a line whose spans have distinct ids, tensions below their conductors'
// strength and room for the dampers; nothing else.

#include <optional>
#include <set>
#include <string>

#include "beside_files.hpp"
#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/line_file.hpp"

namespace {

constexpr std::string_view kLine =
    "spans = \"spans.csv\"\n[conductor]\ntype = \"AAAC ASTER570\"\n[wind]\nlaw = \"cigre\"\n[self_damping]\nlaw = \"noiseux-1991\"\n"
    "[fatigue]\ncycles = 5e8\n[dampers]\ntypes = [ { name = \"sb1\", file = \"d.toml\" } ]\nposition_max = 6.0\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  static const std::filesystem::path line_file = [] {
    return fuzz::write_beside_files(false) ? fuzz::as_file(kLine, "line.toml") : std::filesystem::path();
  }();
  fuzz::require(!line_file.empty(), "the line file and the files beside it are written");
  fuzz::as_file(data, size, "spans.csv");
  std::optional<io::LineFile> file;
  try {
    file = io::load_line_file(line_file);
  } catch (const Error& e) {
    fuzz::require_one_line_naming(e.what(), fuzz::folder());
    return 0;
  }
  const line::Line& l = file->line;
  fuzz::require(!l.spans().empty(), "a line has spans");
  std::set<std::string> ids;
  for (const line::LineSpan& s : l.spans()) {
    fuzz::require(!s.id.empty() && ids.insert(s.id).second, "span ids are given and distinct");
    fuzz::require(s.span.tension() > 0.0 && s.span.tension() < s.span.conductor().rated_tensile_strength,
                  "a tension below the RTS");
    fuzz::require(l.rules().positions.position_max < s.span.length() / 2, "dampers within half a span");
  }
  for (const std::string& w : file->warnings) fuzz::require_one_line(w);
  return 0;
}
