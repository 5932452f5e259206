#pragma once
// A measured impedance: the points of a shaker test (the clamp's excitation and Z
// there), grouped into curves by the amplitude each holds. The impedance fit
// (identification/impedance_identification.hpp) fits a damper to it; a span's
// measured sheet (span/impedance_sheet.hpp) interpolates it; io reads it from CSV.

#include <complex>
#include <cstddef>
#include <vector>

#include "stockbridge/damper/damper.hpp"
#include "stockbridge/damper/tracker.hpp"

namespace stockbridge::damper {

/// One measured point: the clamp's excitation and the impedance there.
struct MeasuredImpedance {
  Excitation excitation;
  std::complex<double> impedance;  ///< Z, N s/m, nonzero
};

struct ImpedanceMeasurement {
  std::vector<MeasuredImpedance> points;
  /// What each curve holds constant: the points are grouped into curves by it.
  HeldAmplitude held = HeldAmplitude::velocity;
  /// Throws InvalidParameter naming the point ("point 3: frequency_hz = -1: expected > 0"):
  /// a frequency or |Z| outside the magnitudes a description may hold (1e-12 to 1e12,
  /// core/error.hpp), a displacement not > 0, Z not finite or zero.
  void validate() const;
};

/// The measured curves: the points whose held amplitude lies within 10 % of the
/// smallest of them, each curve's point indices in frequency order; curves in
/// increasing amplitude.
std::vector<std::vector<std::size_t>> measured_curves(const ImpedanceMeasurement& measurement);

}  // namespace stockbridge::damper
