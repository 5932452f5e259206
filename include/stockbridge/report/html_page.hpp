#pragma once
// A report as one self-contained HTML page: styles inline, figures as inline SVG,
// no script and no reference outside the page, so that it opens anywhere without a
// network and prints on A4 (print styles: page margins, no figure split across
// pages, the tables' header rows repeated). The page is built in reading order: the
// header (what, when, the program's version, the exact command), the verdict and
// the key figures first, then sections of facts, tables, figures and notes.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stockbridge::report {

/// Text made safe inside HTML and SVG (&, <, >, " and ' replaced by entities).
std::string escape(std::string_view text);

/// Now, as a report's header states it: "2026-11-26 12:30 UTC".
std::string utc_now();

/// What every report states at its top.
struct ReportHeader {
  std::string title;         ///< "Span energy balance: ASTER570, 400 m"
  std::string generated_at;  ///< "2026-11-26 12:30 UTC", as the front end read its clock
  std::string command;       ///< the exact command line (empty: none, e.g. from Python)
};

enum class Tone { good, bad, unknown, neutral };

/// A label and its value, as a two-column list shows it ("tension", "28.6 kN").
using Fact = std::pair<std::string, std::string>;

class HtmlPage {
 public:
  explicit HtmlPage(ReportHeader header);

  /// A banner in the verdict's colour: the verdict in capitals, then one line why.
  void verdict(std::string_view verdict, std::string_view reason, Tone tone);
  /// The figures a reader looks for first, as a grid of large numbers.
  void key_figures(const std::vector<Fact>& figures);
  void section(std::string_view heading);
  void paragraph(std::string_view text);
  /// A two-column list of facts (the inputs restated).
  void facts(const std::vector<Fact>& facts);
  /// A table; a cell that starts with a digit, a sign or '.' is right-aligned. A row
  /// whose first cell is marked (`tones`, one per row or empty) is coloured.
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
             const std::vector<Tone>& tones = {});
  /// An inline <svg> (svg()) with its caption, kept whole on a printed page.
  void figure(const std::string& svg_element, std::string_view caption);
  /// A bulleted list; `warnings` styles it as warnings ("none" when empty).
  void list(const std::vector<std::string>& items, bool warnings = false);

  /// The complete document.
  std::string html() const;

 private:
  ReportHeader header_;
  std::string body_;
};

}  // namespace stockbridge::report
