#pragma once
// Journal records (private to the library): a result as one line of text,
// tab-separated fields, numbers in their shortest round-trip form (they read back
// bit for bit), text escaped; and the digest of a run's inputs that a journal's
// first line holds, so that a journal of other inputs is never resumed.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace stockbridge::requests::record_text {

/// '\\', tab, line feed and carriage return escaped.
std::string escaped(std::string_view text);
std::string unescaped(std::string_view text);

/// Throws InvalidParameter naming "record".
[[noreturn]] void bad_record(std::string_view why);

/// A record's fields, read in order; each read throws (bad_record) past the end or
/// on a field that is not what was asked.
class RecordFields {
 public:
  explicit RecordFields(std::string_view record);
  std::string text();
  double number();
  long long integer();
  bool done() const { return next_ == fields_.size(); }

 private:
  std::string_view next();
  std::vector<std::string_view> fields_;
  std::size_t next_ = 0;
};

/// A digest (hex) of the program's version, `text` (the description file's bytes)
/// and every input file's path and bytes.
std::string input_fingerprint(std::string_view text, const std::vector<std::filesystem::path>& inputs);

}  // namespace stockbridge::requests::record_text
