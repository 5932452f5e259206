#include "stockbridge/report/html_page.hpp"

#include <cctype>
#include <chrono>
#include <ctime>

#include <fmt/format.h>

#include "stockbridge/version.hpp"

namespace stockbridge::report {

namespace {

constexpr std::string_view kStyle = R"css(
:root { color-scheme: light; }
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; font-size: 10.5pt; line-height: 1.4; color: #1d1d1d;
       max-width: 960px; margin: 1.5em auto; padding: 0 1em; }
h1 { font-size: 17pt; margin: 0 0 0.2em 0; }
h2 { font-size: 12.5pt; margin: 1.4em 0 0.5em 0; border-bottom: 1px solid #bbb; padding-bottom: 0.15em;
     break-after: avoid; page-break-after: avoid; }
.header { color: #555; font-size: 9pt; margin-bottom: 1em; }
.header code { font-size: 8.5pt; word-break: break-all; background: #f3f3f3; padding: 0 0.2em; }
.verdict { border-left: 6px solid; padding: 0.6em 0.9em; margin: 0.8em 0; break-inside: avoid; }
.verdict strong { font-size: 14pt; margin-right: 0.6em; letter-spacing: 0.03em; }
.good { background: #e6f4ea; border-color: #1e8e3e; }
.bad { background: #fce8e6; border-color: #d93025; }
.unknown { background: #fef7e0; border-color: #e37400; }
.neutral { background: #eef2f7; border-color: #5f6f86; }
.figures { display: grid; grid-template-columns: repeat(auto-fill, minmax(190px, 1fr)); gap: 0.5em; margin: 0.6em 0;
           break-inside: avoid; }
.figures div { border: 1px solid #d4d4d4; border-radius: 4px; padding: 0.35em 0.6em; }
.figures span { display: block; color: #555; font-size: 8.5pt; }
.figures b { font-size: 12.5pt; }
dl.facts { display: grid; grid-template-columns: max-content 1fr; gap: 0.15em 1.2em; margin: 0.4em 0; }
dl.facts dt { color: #444; }
dl.facts dd { margin: 0; }
table { border-collapse: collapse; width: 100%; font-size: 8.5pt; margin: 0.5em 0; }
th, td { border: 1px solid #ccc; padding: 0.15em 0.35em; text-align: left; vertical-align: top; }
th { background: #eef0f3; }
td.n { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
tr.good td:first-child { border-left: 4px solid #1e8e3e; }
tr.bad td:first-child { border-left: 4px solid #d93025; }
tr.unknown td:first-child { border-left: 4px solid #e37400; }
figure { margin: 0.8em 0; break-inside: avoid; page-break-inside: avoid; }
figure svg { display: block; width: 100%; height: auto; max-height: 230mm; }
figcaption { font-size: 9pt; color: #444; margin-top: 0.2em; }
ul.warnings li { color: #8a3b00; }
@page { size: A4; margin: 14mm 12mm 16mm 12mm; }
@media print {
  body { max-width: none; margin: 0; padding: 0; font-size: 9.5pt; }
  thead { display: table-header-group; }
  tr { break-inside: avoid; page-break-inside: avoid; }
  .verdict, .figures div { -webkit-print-color-adjust: exact; print-color-adjust: exact; }
}
)css";

std::string tone_class(Tone tone) {
  switch (tone) {
    case Tone::good: return "good";
    case Tone::bad: return "bad";
    case Tone::unknown: return "unknown";
    case Tone::neutral: return "neutral";
  }
  return "neutral";
}

/// A number, a list of them ("0.63; 4.73") or the placeholder "-": right-aligned and
/// kept on one line. A cell with words ("4 at 1 m", "7.99 at sphere at 130 m") is text
/// and wraps.
bool numeric_cell(std::string_view cell) {
  if (cell.empty()) return false;
  const char c = cell.front();
  const bool starts = std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
  return starts && cell.find_first_not_of("0123456789+-.eE;, ") == std::string_view::npos;
}

}  // namespace

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

HtmlPage::HtmlPage(ReportHeader header) : header_(std::move(header)) {}

void HtmlPage::verdict(std::string_view verdict, std::string_view reason, Tone tone) {
  body_ += fmt::format("<div class=\"verdict {}\"><strong>{}</strong>{}</div>\n", tone_class(tone), escape(verdict),
                       escape(reason));
}

void HtmlPage::key_figures(const std::vector<Fact>& figures) {
  body_ += "<div class=\"figures\">";
  for (const auto& [label, value] : figures) {
    body_ += fmt::format("<div><span>{}</span><b>{}</b></div>", escape(label), escape(value));
  }
  body_ += "</div>\n";
}

void HtmlPage::section(std::string_view heading) { body_ += fmt::format("<h2>{}</h2>\n", escape(heading)); }

void HtmlPage::paragraph(std::string_view text) { body_ += fmt::format("<p>{}</p>\n", escape(text)); }

void HtmlPage::facts(const std::vector<Fact>& facts) {
  body_ += "<dl class=\"facts\">";
  for (const auto& [label, value] : facts) body_ += fmt::format("<dt>{}</dt><dd>{}</dd>", escape(label), escape(value));
  body_ += "</dl>\n";
}

void HtmlPage::table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                     const std::vector<Tone>& tones) {
  body_ += "<table><thead><tr>";
  for (const std::string& h : header) body_ += fmt::format("<th>{}</th>", escape(h));
  body_ += "</tr></thead><tbody>";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    body_ += r < tones.size() ? fmt::format("<tr class=\"{}\">", tone_class(tones[r])) : std::string("<tr>");
    for (const std::string& cell : rows[r]) {
      body_ += fmt::format("<td{}>{}</td>", numeric_cell(cell) ? " class=\"n\"" : "", escape(cell));
    }
    body_ += "</tr>";
  }
  body_ += "</tbody></table>\n";
}

void HtmlPage::figure(const std::string& svg_element, std::string_view caption) {
  body_ += fmt::format("<figure>{}<figcaption>{}</figcaption></figure>\n", svg_element, escape(caption));
}

void HtmlPage::list(const std::vector<std::string>& items, bool warnings) {
  if (items.empty()) {
    body_ += "<p>None.</p>\n";
    return;
  }
  body_ += warnings ? "<ul class=\"warnings\">" : "<ul>";
  for (const std::string& item : items) body_ += fmt::format("<li>{}</li>", escape(item));
  body_ += "</ul>\n";
}

std::string HtmlPage::html() const {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">";
  out += fmt::format("<title>{}</title><style>{}</style></head>\n<body>\n", escape(header_.title), kStyle);
  out += fmt::format("<h1>{}</h1>\n<div class=\"header\">stockbridge {} &middot; generated {}", escape(header_.title),
                     escape(version()), escape(header_.generated_at));
  if (!header_.command.empty()) out += fmt::format("<br>command: <code>{}</code>", escape(header_.command));
  out += "</div>\n" + body_ + "</body></html>\n";
  return out;
}

}  // namespace stockbridge::report
