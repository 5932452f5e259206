// The impedance of a damper at 20 Hz and a clamp velocity amplitude of 0.2 m/s,
// computed as `stockbridge impedance DAMPER.toml --frequencies 20 --velocity 0.2`
// computes it: the file read and checked by the library's reader, the point solved
// by its sweep with the default solver settings (harmonic balance).
//
//   impedance_point DAMPER.toml

#include <cstdio>
#include <string>
#include <vector>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/requests/sweep_request.hpp"
#include "stockbridge/version.hpp"

int main(int argc, char** argv) {
  namespace sb = stockbridge;
  if (argc != 2) {
    std::fprintf(stderr, "usage: impedance_point DAMPER.toml\n");
    return 2;
  }
  try {
    const sb::damper::Damper damper = sb::io::read_damper_file(argv[1]);
    sb::requests::SweepRequest request;  // the program's options, by the same names
    request.frequencies = {20.0};         // Hz
    request.velocities = {0.2};           // clamp velocity amplitude, m/s
    const std::vector<sb::damper::SweepRun> runs = sb::damper::run_sweep(damper, sb::requests::sweep_spec(request));
    const sb::damper::ImpedancePoint& point = runs.front().points.front();
    if (!point.converged()) {
      std::fprintf(stderr, "impedance_point: not converged: %s\n", point.failure.c_str());
      return 3;
    }
    // %.17g: the exact double, to compare with the program's CSV.
    std::printf("stockbridge %s: Z(20 Hz, 0.2 m/s) = %.17g %+.17gi N s/m\n",
                std::string(sb::version()).c_str(), point.impedance.real(), point.impedance.imag());
    return 0;
  } catch (const sb::Error& e) {  // bad file or value: one line, as the program says it
    std::fprintf(stderr, "impedance_point: %s\n", e.what());
    return 2;
  }
}
