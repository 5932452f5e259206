#pragma once
// A digest of inputs, to tell them apart: a journal's, a cache's key. FNV-1a over
// 64 bits, each piece followed by its length (so that "ab" + "c" and "a" + "bc"
// differ); enough to tell inputs apart, not a defence against forgery.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace stockbridge {

class ContentDigest {
 public:
  ContentDigest& add(std::string_view bytes);
  /// A file's path and its bytes (a missing file adds its path alone).
  ContentDigest& add_file(const std::filesystem::path& path);
  /// 16 hex digits.
  std::string hex() const;

 private:
  std::uint64_t h_ = 1469598103934665603ULL;
};

}  // namespace stockbridge
