// libFuzzer target: span files, with a damper file and a measured sheet beside them
// for [[damper]] file = "d.toml" and impedance = "sheet.csv" (the seeds use both), and
// the conductor catalogue for type = "...". Either one InputError line naming a file
// of the span (the span file, or a file it names), or a span (validated by
// construction) whose tension lies between 0 and the rated strength; nothing else.

#include <optional>

#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/span_file.hpp"

namespace {

const char* const kDamper =
    "[clamp]\nmass = 0.7\n[[arm]]\nname = \"a\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n"
    "[arm.cable]\nlength = 0.1875\nsections = 8\nei = 2.8\njenkin = [ { c = 20.0, h = 0.7 } ]\n";
const char* const kSheet =
    "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n5,0.05,1,80\n20,0.05,5,200\n60,0.05,10,400\n"
    "5,0.2,10,70\n20,0.2,50,150\n60,0.2,40,300\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  static const bool beside = [] {
    const auto damper = fuzz::as_file(reinterpret_cast<const std::uint8_t*>(kDamper), std::char_traits<char>::length(kDamper), "d.toml");
    const auto sheet = fuzz::as_file(reinterpret_cast<const std::uint8_t*>(kSheet), std::char_traits<char>::length(kSheet), "sheet.csv");
    return !damper.empty() && !sheet.empty();
  }();
  fuzz::require(beside, "the files beside the span file are written");
  const auto path = fuzz::as_file(data, size, "span.toml");
  std::optional<io::SpanFile> file;
  try {
    file = io::load_span_file(path);
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path.parent_path());
    return 0;
  }
  const span::Span& s = file->span;
  fuzz::require(s.tension() > 0.0 && s.tension() < s.conductor().rated_tensile_strength, "a tension below the RTS");
  for (const span::SpanDamper& d : s.dampers()) {
    fuzz::require(d.damper.has_value() != d.measured(), "a damper has its model or its sheet");
  }
  return 0;
}
