#include "stockbridge/core/warning.hpp"

namespace stockbridge {

Warning setting_warning(const UnusualValue& value) { return {value.message(), true}; }

std::vector<Warning> setting_warnings(const std::vector<UnusualValue>& values) {
  std::vector<Warning> out;
  for (const UnusualValue& u : values) out.push_back(setting_warning(u));
  return out;
}

std::vector<Warning> plain_warnings(const std::vector<std::string>& lines) {
  std::vector<Warning> out;
  for (const std::string& line : lines) out.push_back({line, false});
  return out;
}

std::vector<std::string> warning_messages(const std::vector<Warning>& warnings) {
  std::vector<std::string> out;
  for (const Warning& w : warnings) out.push_back(w.message);
  return out;
}

}  // namespace stockbridge
