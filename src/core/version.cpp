#include "stockbridge/version.hpp"

namespace stockbridge {

std::string_view version() { return version_string; }

}  // namespace stockbridge
