#pragma once
// The solver options shared by the damper commands (impedance, response).

#include <string>

#include <CLI/CLI.hpp>

#include "stockbridge/damper/impedance.hpp"

namespace stockbridge::cli {

struct SolverFlags {
  std::string method = "hb";
  int harmonics = 9;
  int samples = 0;
  int steps = 256;
  int max_iterations = 100;
  double energy_tolerance = 0.01;

  void add_to(CLI::App& command);
  damper::SolverOptions options() const;
};

}  // namespace stockbridge::cli
