#include "stockbridge/requests/output_table.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "stockbridge/io/csv_writer.hpp"

namespace stockbridge::requests {

std::vector<std::string> TableValues::names() const {
  std::vector<std::string> out;
  for (const Column& c : columns) out.push_back(c.name);
  return out;
}

const TableValues::Column& TableValues::column(std::string_view name) const {
  for (const Column& c : columns) {
    if (c.name == name) return c;
  }
  throw std::out_of_range(fmt::format("no column {}", name));
}

std::string TableValues::csv(bool header) const {
  std::size_t labels = 0;
  while (labels < columns.size() && columns[labels].kind == ColumnKind::label) ++labels;
  for (std::size_t c = labels; c < columns.size(); ++c) {
    if (columns[c].kind == ColumnKind::label) throw std::logic_error("TableValues::csv: a label after a number");
  }
  io::CsvWriter csv(names());
  const std::size_t header_size = header ? 0 : csv.text().size();
  std::vector<std::string> label_row(labels);
  std::vector<double> number_row(columns.size() - labels);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < labels; ++c) label_row[c] = columns[c].labels[r];
    for (std::size_t c = labels; c < columns.size(); ++c) number_row[c - labels] = columns[c].numbers[r];
    csv.add_row(label_row, number_row);
  }
  return csv.text().substr(header_size);
}

io::JsonObject TableValues::json_row(std::size_t r) const {
  io::JsonObject json;
  for (const Column& c : columns) {
    switch (c.kind) {
      case ColumnKind::number: json.add(c.name, c.numbers[r]); break;
      case ColumnKind::count:
        if (std::isfinite(c.numbers[r])) {
          json.add(c.name, static_cast<long long>(c.numbers[r]));
        } else {
          json.add_null(c.name);
        }
        break;
      case ColumnKind::flag:
        if (std::isfinite(c.numbers[r])) {
          json.add(c.name, c.numbers[r] == 1.0);
        } else {
          json.add_null(c.name);
        }
        break;
      case ColumnKind::label: json.add(c.name, c.labels[r]); break;
    }
  }
  return json;
}

std::string docs_table(const std::vector<QuantityDoc>& quantities) {
  std::string out = "| column | unit | meaning |\n|---|---|---|\n";
  const auto escaped = [](const std::string& text) {
    std::string s;
    for (const char ch : text) {
      if (ch == '|') s += '\\';
      s += ch;
    }
    return s;
  };
  for (const QuantityDoc& q : quantities) {
    out += fmt::format("| `{}` | {} | {} |\n", q.name, escaped(q.unit), escaped(q.meaning));
  }
  return out;
}

std::vector<std::string> column_prefixes(const std::vector<std::string>& names, std::string_view fallback,
                                         const std::vector<std::string>& reserved) {
  bool usable = true;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& name = names[k];
    const bool word = !name.empty() && std::all_of(name.begin(), name.end(), [](char ch) {
      return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
    });
    const bool taken = std::find(reserved.begin(), reserved.end(), name) != reserved.end() ||
                       std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(k), name) != names.begin() + static_cast<std::ptrdiff_t>(k);
    usable = usable && word && !taken;
  }
  if (usable) return names;
  std::vector<std::string> numbered;
  for (std::size_t k = 0; k < names.size(); ++k) numbered.push_back(fmt::format("{}{}", fallback, k + 1));
  return numbered;
}

}  // namespace stockbridge::requests
