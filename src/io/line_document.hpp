#pragma once
// A line file's document as read (private to the library): what a --details span
// file copies its shared tables from (line_file.cpp reads it, line_details.cpp writes
// a span file from it).

#include <toml++/toml.h>

namespace stockbridge::io {

struct LineDocument {
  toml::table table;
};

}  // namespace stockbridge::io
