#pragma once
// Reading design study files (TOML, format in docs/design.md):
//
//   damper = "sauter2003.toml"        # the base design (relative to this file)
//   spans = ["aster570_400m.toml"]    # span files; their [[damper]] entries become the candidate
//   objective = "max_stress"          # or "life"
//   samples = 256                     # space-filling start
//   polish = 4                        # best candidates polished locally
//   seed = 1
//   [[variable]]
//   name = "arm.left.mass"            # a damper number by its path, or "position"
//   min = 0.5
//   max = 3.0
//   [[tie]]
//   name = "arm.right.mass"
//   equals = "arm.left.mass"
//   [constraints]
//   total_mass_max = 4.0
//   messenger_curvature_max = 0.5
//
// and optionally points (frequencies per span band, 100) and polish_evaluations (40).

#include <filesystem>
#include <string>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/design/search.hpp"
#include "stockbridge/design/study.hpp"

namespace stockbridge::io {

struct DesignFile {
  design::DesignStudy study;
  design::SearchOptions search;
  std::filesystem::path damper_file;             ///< the base damper's file
  std::vector<std::filesystem::path> inputs;     ///< every file read (a command must not overwrite them)
  std::vector<std::string> warnings;             ///< the damper's and spans' unusual values, located
};

/// Reads a design file, its damper and span files; InputError naming the file, line,
/// key, value and expectation; a value a unit slip explains refused under `policy`
/// (as load_span_file).
DesignFile load_design_file(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);

}  // namespace stockbridge::io
