#include "stockbridge/core/error.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace stockbridge {

InvalidParameter::InvalidParameter(std::string field, std::string detail)
    : Error(field + detail), field_(std::move(field)), detail_(std::move(detail)) {}

InvalidParameter::InvalidParameter(const std::string& message) : Error(message), detail_(message) {}

InvalidParameter InvalidParameter::within(std::string_view parent) const {
  if (field_.empty()) return InvalidParameter(std::string(parent), ": " + detail_);
  const std::string joined = field_.front() == '[' ? fmt::format("{}{}", parent, field_) : fmt::format("{}.{}", parent, field_);
  return InvalidParameter(joined, detail_);
}

std::string format_value(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{}", value);
}

namespace {

/// The length of the well-formed UTF-8 character at text[i] (a byte >= 0x80), or 0
/// where it is not one (a stray continuation byte, a sequence cut short, an overlong
/// form, a surrogate, beyond U+10FFFF).
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  char32_t code = 0;
  if (lead >= 0xC2 && lead <= 0xDF) length = 2, code = lead & 0x1F;
  else if (lead >= 0xE0 && lead <= 0xEF) length = 3, code = lead & 0x0F;
  else if (lead >= 0xF0 && lead <= 0xF4) length = 4, code = lead & 0x07;
  else return 0;
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
  if (overlong || (code >= 0xD800 && code <= 0xDFFF) || code > 0x10FFFF) return 0;
  return length;
}

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string out;
  std::size_t i = 0;
  for (; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const std::size_t length = byte >= 0x80 ? utf8_length(text, i) : 1;
    if (i + std::max<std::size_t>(length, 1) > max_bytes) break;  // never a character cut
    switch (text[i]) {
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (byte < 0x20 || byte == 0x7F || length == 0) {
          out += fmt::format("\\x{:02x}", byte);  // a control character, or a byte that is not UTF-8
        } else {
          out.append(text.substr(i, length));
          i += length - 1;
        }
    }
  }
  if (i < text.size()) out += "...";
  return out;
}

std::size_t first_non_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (static_cast<unsigned char>(text[i]) < 0x80) continue;
    const std::size_t length = utf8_length(text, i);
    if (length == 0) return i;
    i += length - 1;
  }
  return std::string_view::npos;
}

void throw_invalid(std::string_view name, double value, std::string_view expected) {
  throw InvalidParameter(std::string(name), fmt::format(" = {}: expected {}", format_value(value), expected));
}

namespace {
std::string with_unit(std::string_view what, std::string_view unit) {
  return unit.empty() ? std::string(what) : fmt::format("{} ({})", what, unit);
}
}  // namespace

void require_positive(std::string_view name, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value > 0)) throw_invalid(name, value, with_unit("a finite value > 0", unit));
}

void require_non_negative(std::string_view name, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value >= 0)) throw_invalid(name, value, with_unit("a finite value >= 0", unit));
}

void require_plausible(std::string_view name, double value, std::string_view unit) {
  require_positive(name, value, unit);
  if (value < smallest_magnitude || value > largest_magnitude) {
    throw_invalid(name, value,
                  with_unit(fmt::format("a value from {:g} to {:g}; one outside is a unit mistake", smallest_magnitude,
                                        largest_magnitude),
                            unit));
  }
}

void require_plausible_or_zero(std::string_view name, double value, std::string_view unit) {
  require_non_negative(name, value, unit);
  if (value != 0.0) require_plausible(name, value, unit);
}

void require_finite(std::string_view name, double value, std::string_view unit) {
  if (!std::isfinite(value)) throw_invalid(name, value, with_unit("a finite value", unit));
}

void require_in_range(std::string_view name, long long value, long long lo, long long hi) {
  if (value < lo || value > hi) {
    throw InvalidParameter(std::string(name), fmt::format(" = {}: expected an integer from {} to {}", value, lo, hi));
  }
}

}  // namespace stockbridge
