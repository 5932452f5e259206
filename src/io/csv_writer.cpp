#include "stockbridge/io/csv_writer.hpp"

#include <cmath>
#include <iterator>
#include <string>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

CsvWriter::CsvWriter(std::vector<std::string> header) : columns_(header.size()) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (i > 0) text_ += ',';
    text_ += header[i];
  }
  text_ += '\n';
}

void CsvWriter::add_row(std::span<const double> values) { add_row({}, values); }

void CsvWriter::add_row(std::span<const std::string> labels, std::span<const double> values) {
  if (labels.size() + values.size() != columns_) {
    throw Error(fmt::format("CSV row with {} values for {} columns", labels.size() + values.size(), columns_));
  }
  auto out = std::back_inserter(text_);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (i > 0) text_ += ',';
    const std::string& cell = labels[i];
    if (cell.find_first_of(",\"\r\n") == std::string::npos) {
      text_ += cell;
      continue;
    }
    text_ += '"';
    for (const char ch : cell) {
      if (ch == '"') text_ += '"';
      text_ += ch;
    }
    text_ += '"';
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i + labels.size() > 0) text_ += ',';
    if (!std::isnan(values[i])) fmt::format_to(out, "{}", values[i]);
  }
  text_ += '\n';
}

}  // namespace stockbridge::io
