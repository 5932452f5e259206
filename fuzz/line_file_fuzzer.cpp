// libFuzzer target: line files (docs/line.md) as TOML text, io::load_line_text with
// the fuzzer's folder as the base of relative paths, where a damper file (d.toml), a
// measured sheet (sheet.csv), a spans CSV (spans.csv) and a conductor file (c.toml)
// lie for the line to name (beside_files.hpp). Either one library error
// (stockbridge::Error) of one line that begins with a file of the folder, or a line
// (validated by construction) whose spans have distinct ids, lengths, tensions below
// their conductors' strength and room for the dampers, and damper types each with
// its model or its sheet; nothing else (another exception, a crash, a hang).

#include <optional>
#include <set>
#include <string>

#include "beside_files.hpp"
#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/line_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  static const bool beside = fuzz::write_beside_files();
  fuzz::require(beside, "the files beside the line file are written");
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string source = (fuzz::folder() / "line.toml").string();
  std::optional<io::LineFile> file;
  try {
    file = io::load_line_text(text, source, fuzz::folder());
  } catch (const Error& e) {
    // The line file's location, or that of a file it names (all in the folder).
    fuzz::require_one_line_naming(e.what(), fuzz::folder());
    return 0;
  }
  const line::Line& l = file->line;
  fuzz::require(!l.spans().empty() && !l.types().empty(), "a line has spans and damper types");
  std::set<std::string> ids;
  for (const line::LineSpan& s : l.spans()) {
    fuzz::require(!s.id.empty() && ids.insert(s.id).second, "span ids are given and distinct");
    fuzz::require(s.span.length() > 0.0, "a span's length > 0");
    fuzz::require(s.span.tension() > 0.0 && s.span.tension() < s.span.conductor().rated_tensile_strength,
                  "a tension below the RTS");
    fuzz::require(l.rules().positions.position_max < s.span.length() / 2, "dampers within half a span");
  }
  for (const line::DamperType& t : l.types()) {
    fuzz::require(!t.name.empty(), "a damper type has a name");
    fuzz::require(t.damper.damper.has_value() != t.damper.measured(), "a damper type has its model or its sheet");
  }
  for (const std::string& w : file->warnings) fuzz::require_one_line(w);
  return 0;
}
