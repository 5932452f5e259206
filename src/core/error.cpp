#include "stockbridge/core/error.hpp"

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

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string out;
  std::size_t kept = text.size();
  if (kept > max_bytes) {
    kept = max_bytes;
    while (kept > 0 && (static_cast<unsigned char>(text[kept]) & 0xC0) == 0x80) --kept;  // a continuation byte
  }
  for (const char ch : text.substr(0, kept)) {
    const auto byte = static_cast<unsigned char>(ch);
    switch (ch) {
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (byte < 0x20 || byte == 0x7F) {
          out += fmt::format("\\x{:02x}", byte);
        } else {
          out += ch;
        }
    }
  }
  if (kept < text.size()) out += "...";
  return out;
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
