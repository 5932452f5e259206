#pragma once
// Typed errors of the stockbridge library.
//
// The library never prints and never aborts: invalid input throws one of the
// types below, with a message that names the quantity (file, key, line), the
// offending value and what was expected. Numerical non-convergence is *not* an
// exception: solvers report it in their summaries.

#include <stdexcept>
#include <string>
#include <string_view>

namespace stockbridge {

/// Base of every error the library throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A parameter or option has a value outside its admissible range
/// (negative stiffness, slip moment <= 0, cycles < 1, ...). It carries the path of
/// the offending field as the description files spell it
/// ("arm[1].cable.jenkin[0].h"), so that a reader can point at the file's line
/// without re-wording the message: what() is the field followed by the detail
/// ("arm[1].mass" + " = -1: expected a finite value > 0 (kg)").
class InvalidParameter : public Error {
 public:
  InvalidParameter(std::string field, std::string detail);
  /// A message that names no single field.
  explicit InvalidParameter(const std::string& message);

  const std::string& field() const { return field_; }
  const std::string& detail() const { return detail_; }
  /// The same error seen from the enclosing description: the field becomes
  /// "<parent>.<field>" ("<parent><field>" for an index such as "[0].h").
  InvalidParameter within(std::string_view parent) const;

 private:
  std::string field_;
  std::string detail_;
};

/// A file could not be read, or its contents are malformed
/// (syntax, missing or unknown key, wrong type, bad cell).
class InputError : public Error {
 public:
  using Error::Error;
};

/// A value outside its typical range that the readers refuse (typical_ranges.hpp,
/// SlipPolicy): one a unit slip explains (a tension of 30.3 where N is expected:
/// 30.3 kN?), or a measured sheet's value outside what a shaker test gives. The
/// message names the file, line (or row and column), key, value and the likely unit;
/// the front ends add how to accept it as given (--allow-unusual, allow_unusual=True).
class UnusualValueError : public InputError {
 public:
  using InputError::InputError;
};

/// A file could not be written.
class OutputError : public Error {
 public:
  using Error::Error;
};

/// A well-posed computation has no solution for the given data
/// (e.g. a moment beyond what a section with ei = 0 can carry).
class NumericalError : public Error {
 public:
  using Error::Error;
};

/// A long computation was asked to stop (its caller's stop request: Ctrl-C) and
/// stopped between two of its steps; nothing it had not finished is returned.
class Interrupted : public Error {
 public:
  using Error::Error;
};

/// Formats a number the way every message shows it (shortest round-trip form).
std::string format_value(double value);

/// Text from a user's file as a message quotes it, so that a message stays one
/// line: control characters as escapes (\n, \r, \t, \x1b, ...), and at most
/// `max_bytes` bytes kept (then "...", never cutting a UTF-8 character).
std::string printable(std::string_view text, std::size_t max_bytes = 60);
/// The offset of the first byte of `text` that is not part of well-formed UTF-8 (a
/// byte printable() shows as \xNN), or std::string_view::npos where all of it is.
std::size_t first_non_utf8(std::string_view text);

/// Throws InvalidParameter "<name> = <value>: expected <expected>".
[[noreturn]] void throw_invalid(std::string_view name, double value, std::string_view expected);

/// Checks that `value` is finite and > 0; `name` and `unit` go into the message.
void require_positive(std::string_view name, double value, std::string_view unit);
/// Checks that `value` is finite and >= 0.
void require_non_negative(std::string_view name, double value, std::string_view unit);
/// Checks that `value` is finite.
void require_finite(std::string_view name, double value, std::string_view unit);
/// The magnitudes a description may hold, in SI units. A value outside is a unit
/// mistake (no damper has a 1e13 m cable or a 1e-13 kg mass), and admitting it
/// would let the arithmetic overflow (a fuzzing finding: length = 1.1e307).
inline constexpr double smallest_magnitude = 1e-12;
inline constexpr double largest_magnitude = 1e12;
/// Checks that `value` is finite and > 0 (the message of require_positive), then
/// smallest_magnitude <= value <= largest_magnitude.
void require_plausible(std::string_view name, double value, std::string_view unit);
/// The same, 0 also allowed.
void require_plausible_or_zero(std::string_view name, double value, std::string_view unit);
/// Checks lo <= value <= hi for an integer count.
void require_in_range(std::string_view name, long long value, long long lo, long long hi);

/// Runs `build` and re-throws its InvalidParameter as seen from `parent`
/// (InvalidParameter::within): for a description that holds another.
template <class Build>
auto within_field(std::string_view parent, Build&& build) -> decltype(build()) {
  try {
    return build();
  } catch (const InvalidParameter& e) {
    throw e.within(parent);
  }
}

/// `value` after its validate() member accepted it (throws otherwise): for member
/// initialisers, so that an object is never built from bad parameters.
template <class T>
T validated(T value) {
  value.validate();
  return value;
}

}  // namespace stockbridge
