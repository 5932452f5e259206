#pragma once
// A damper known by its measured impedance sheet (IEC 61897's characteristic test,
// IEEE 664; MODEL.md section 11; docs/span.md, "A damper from a measured sheet"):
// Z against frequency along a few curves, each at one clamp velocity (or one
// displacement) amplitude, as `stockbridge impedance` writes it or a shaker test
// gives it (io/measured_impedance_file.hpp reads it).
//
// Z(f, v) between the measured points: along each curve linearly in log f (Re Z and
// Im Z), which puts every curve that covers f at its clamp velocity there (the held
// velocity, or 2 pi f X for a displacement); across the curves monotone cubic in
// log v (Fritsch-Carlson, span/impedance_table.hpp), as the model's tables are. The
// rules where the sheet says nothing:
//   * frequencies where fewer than two curves were measured: Z is not known (the
//     balance there does not converge, naming the sheet's frequencies);
//   * clamp velocities below the lowest curve: Z held at the lowest curve's (small
//     amplitudes stick, and Z no longer depends on v), noted at the point;
//   * above the highest curve: held too while the balance searches, but a balance
//     whose damper ends up there is not trusted (not converged, naming the sheet's
//     highest velocity): the arms' resonances move with the amplitude, and nothing
//     tells where.
// Its own error: every_other() gives the sheets of every other curve, whose balances
// bound the full sheet's interpolation error (analysis.hpp's band).

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/damper/measured_impedance.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {

/// One curve of a sheet at one frequency.
struct SheetNode {
  double velocity = 0.0;            ///< the clamp velocity amplitude there, m/s
  std::complex<double> impedance;   ///< Z, N s/m
};

class ImpedanceSheet {
 public:
  /// Throws InvalidParameter naming the sheet (`name`) unless the measurement is valid
  /// (ImpedanceMeasurement::validate) with at least two curves of at least two points
  /// measured over a common band of frequencies.
  ImpedanceSheet(damper::ImpedanceMeasurement measurement, std::string name);

  const std::string& name() const { return name_; }
  int curves() const { return static_cast<int>(curves_.size()); }
  /// The lowest and highest frequency at which at least two curves were measured, Hz.
  Interval frequency_range() const;
  /// Each curve measured at `frequency` (within its first and last point), by
  /// increasing clamp velocity; empty outside every curve.
  std::vector<SheetNode> nodes_at(double frequency) const;
  /// The sheet of every other curve: parity 0 keeps the 1st, 3rd, ... (by amplitude),
  /// 1 the 2nd, 4th, ...; none where fewer than two curves would remain.
  std::optional<ImpedanceSheet> every_other(int parity) const;

 private:
  struct Curve {
    std::vector<double> log_f;
    std::vector<std::complex<double>> z;
    double amplitude = 0.0;  ///< the held amplitude: velocity (m/s) or displacement (m)
  };
  ImpedanceSheet(std::vector<Curve> curves, damper::HeldAmplitude held, std::string name);

  std::vector<Curve> curves_;
  damper::HeldAmplitude held_;
  std::string name_;
};

}  // namespace stockbridge::span
