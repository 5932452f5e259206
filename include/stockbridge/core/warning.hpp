#pragma once
// Warnings as data. What the library accepts but is most often a mistake (a value
// in the wrong unit, a drive beyond the model's small deflections, a fit that does
// not follow its data) is returned with the result, never printed: the CLI prints
// one "warning: " line each (a request setting's name as its flag, "--velocity"),
// Python raises stockbridge.UnusualValueWarning, the JSON summaries list them.

#include <string>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"

namespace stockbridge {

struct Warning {
  std::string message;   ///< the whole line, as Python shows it ("velocity = 100: outside the typical ...")
  bool setting = false;  ///< begins with a request setting's name (the CLI shows it as its flag)

  bool operator==(const Warning&) const = default;
};

/// A setting's value outside its typical range ("velocity = 100: outside ...").
Warning setting_warning(const UnusualValue& value);
std::vector<Warning> setting_warnings(const std::vector<UnusualValue>& values);
/// Lines that need no flag (a file's located warnings, a result's).
std::vector<Warning> plain_warnings(const std::vector<std::string>& lines);
/// The lines as Python and the JSON show them.
std::vector<std::string> warning_messages(const std::vector<Warning>& warnings);

}  // namespace stockbridge
