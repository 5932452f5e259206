#include "stockbridge/core/digest.hpp"

#include <fstream>
#include <iterator>

#include <fmt/format.h>

namespace stockbridge {

ContentDigest& ContentDigest::add(std::string_view bytes) {
  for (const unsigned char c : bytes) h_ = (h_ ^ c) * 1099511628211ULL;
  for (const unsigned char c : fmt::format("|{}|", bytes.size())) h_ = (h_ ^ c) * 1099511628211ULL;
  return *this;
}

ContentDigest& ContentDigest::add_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  add(path.string());
  return add(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
}

std::string ContentDigest::hex() const { return fmt::format("{:016x}", h_); }

}  // namespace stockbridge
