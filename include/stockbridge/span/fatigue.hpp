#pragma once
// Bending stress in the outer wires of a vibrating conductor, and the CIGRE Safe
// Border Line (MODEL.md section 9; docs/span.md).
//
// Near a clamp the conductor is a tensioned beam (span/conductor.hpp): with the
// loop amplitude S of the standing wave next to the clamp, the clamped beam's shape
// is (k1, p1: beam_wavenumbers, r = k1 / p1)
//     y(x) = S [sin(k1 x) - r cos(k1 x) + r exp(-p1 x)] / sqrt(1 + r^2),
// which bends the conductor at the clamp to the curvature S k p (to first order
// in k / p). The stresses, zero-to-peak, of an outer wire of diameter d_a and
// modulus E_a:
//   * fymax (EPRI): sigma_a = pi d_a E_a sqrt(m / EI_min) f S;
//   * Poffenberger-Swart: sigma_a = K Y_b, with Y_b the peak-to-peak displacement at
//     x_b = 89 mm from the clamp (relative to it) and
//         K = E_a d_a p^2 / (4 (exp(-p x_b) - 1 + p x_b)),  p = sqrt(T / EI_min);
//     bending_amplitude gives Y_b = 2 y(x_b) from the beam shape above, so that
//     both forms agree (to within (k x_b)^2); the string shape 2 S sin(k x_b) alone
//     would overstate Y_b (by 50 % for ASTER570), since it ignores that the clamp
//     also holds the conductor's slope;
//   * at a point force of amplitude F (a damper's clamp, F = |Z| v):
//         sigma = E_a d_a |F| / (4 p EI_min).
// The Safe Border Line (CIGRE WG 22.04; EPRI "Orange Book") bounds the
// Poffenberger-Swart stress a conductor survives N cycles of:
//     sigma_a [MPa] = a N^b:  one aluminium layer  730 N^-0.2  (N <= 2e7),    430 N^-0.17 beyond;
//                             several layers       450 N^-0.2  (N <= 1.56e7), 263 N^-0.17 beyond.
// The two branches do not meet at the knee: the line steps down there, from 25.30
// to 24.68 MPa (one layer) and from 16.39 to 15.74 MPa (several). cycles_to_failure
// inverts it piecewise; a stress inside the step fails at the knee.
//
// An S-N curve (SnCurve) generalises the line: power-law branches sigma = a N^b,
// each up to its cycles, the last to every N. The Safe Border Line is one (two
// branches and the step); an S-N table (io/sn_curve_file.hpp: a curve fitted to a
// conductor's own fatigue tests, measurements/fatigue_tests.hpp) is another, read
// log-log piecewise linear between its points and extrapolated along its end
// segments. A span's `[fatigue] curve` puts a table in the line's place.
//
// Units: SI (Pa, m, N, Hz); the Safe Border Line's a in MPa as published.

#include <string>
#include <vector>

#include "stockbridge/span/conductor.hpp"

namespace stockbridge::span {

/// x_b of the Poffenberger-Swart formula: 89 mm (3.5 in) from the clamp's last point of contact.
inline constexpr double poffenberger_swart_distance = 0.089;

/// sigma_a = pi d_a E_a sqrt(m / EI_min) f S, Pa (S: loop amplitude next to the clamp, m).
double fymax_stress(const Conductor& conductor, double frequency, double loop_amplitude);

/// K = E_a d_a p^2 / (4 (exp(-p x_b) - 1 + p x_b)), Pa/m.
double poffenberger_swart_factor(const Conductor& conductor, double tension,
                                 double x_b = poffenberger_swart_distance);

/// Y_b = 2 y(x_b), peak-to-peak, m: the clamped tensioned beam's displacement at x_b
/// for the loop amplitude S (m) next to the clamp at `frequency` (Hz).
double bending_amplitude(const Conductor& conductor, double tension, double frequency, double loop_amplitude,
                         double x_b = poffenberger_swart_distance);

/// sigma_a = K Y_b, Pa (Y_b peak-to-peak, m).
double poffenberger_swart_stress(const Conductor& conductor, double tension, double bending_amplitude,
                                 double x_b = poffenberger_swart_distance);

/// sigma = E_a d_a |F| / (4 p EI_min), Pa: the stress next to a point force of
/// amplitude |F| (N), e.g. a damper's clamp force |Z| v.
double point_force_stress(const Conductor& conductor, double tension, double force_amplitude);

/// The outer wires' peak-to-peak bending strain, microstrain, of a zero-to-peak
/// stress (Pa): 2 sigma / E_a x 1e6 (the strain engineers quote, MODEL.md section 11).
double bending_strain_pp_microstrain(const Conductor& conductor, double stress);

/// sigma_a [MPa] = a N^b on two branches, switching after `knee` cycles.
struct SafeBorderLine {
  double a_low = 0.0;   ///< MPa, N <= knee
  double b_low = 0.0;
  double knee = 0.0;    ///< cycles
  double a_high = 0.0;  ///< MPa, N > knee
  double b_high = 0.0;

  /// The stress (Pa, zero-to-peak) the conductor survives `cycles` (> 0) of.
  double endurance_limit(double cycles) const;
  /// The cycles to failure at `stress` (Pa): the inverse of endurance_limit, the knee
  /// for a stress inside its step, infinite for a stress <= 0.
  double cycles_to_failure(double stress) const;
};

/// CIGRE's line for `aluminium_layers` (1: the single-layer line; 2 or more: the
/// multi-layer one); throws InvalidParameter naming "aluminium_layers" below 1.
SafeBorderLine safe_border_line(int aluminium_layers);

/// One branch of an S-N curve: sigma [MPa] = a (N / anchor)^b for N up to `until`
/// cycles (the last branch: infinity), from where the branch before it ends. The
/// anchor keeps a steep segment of a table (a step sampled) in range: a is the
/// stress at the anchor (the Safe Border Line's: anchor 1, a as published).
struct SnBranch {
  double a = 0.0;       ///< MPa
  double b = 0.0;       ///< < 0
  double until = 0.0;   ///< cycles
  double anchor = 1.0;  ///< cycles
};

/// An S-N curve: the zero-to-peak stress a conductor survives N cycles of, on
/// power-law branches in order of N (each b < 0; a branch may step down at its
/// start, as the Safe Border Line does at its knee).
class SnCurve {
 public:
  /// The Safe Border Line as a curve (two branches), named as reports name it.
  SnCurve(const SafeBorderLine& line, std::string name = "the CIGRE Safe Border Line");  // NOLINT: a line is a curve
  /// Branches in order (`until` strictly increasing, the last infinite; b < 0):
  /// InvalidParameter naming "branches" otherwise.
  SnCurve(std::vector<SnBranch> branches, std::string name, std::string source = {});

  /// A table: stresses (MPa, zero-to-peak) strictly decreasing against cycles strictly
  /// increasing, the same number >= 2 of each, read log-log piecewise linear and
  /// extrapolated along the end segments. InvalidParameter naming "stress_mpa" or
  /// "cycles" (with the index) otherwise.
  static SnCurve from_table(const std::vector<double>& stress_mpa, const std::vector<double>& cycles,
                            std::string name, std::string source = {});

  /// The stress (Pa, zero-to-peak) the conductor survives `cycles` (> 0) of.
  double endurance_limit(double cycles) const;
  /// The cycles to failure at `stress` (Pa): the inverse of endurance_limit, a
  /// branch's start for a stress inside a step there, infinite for a stress <= 0.
  double cycles_to_failure(double stress) const;

  const std::vector<SnBranch>& branches() const { return branches_; }
  /// "the CIGRE Safe Border Line (one aluminium layer)", or a table's own name.
  const std::string& name() const { return name_; }
  /// Where the curve comes from: the table's file (empty for the Safe Border Line).
  const std::string& source() const { return source_; }
  /// The name, with the file where there is one: "'Drake tests, mean - 2 s' (curve.toml)".
  std::string description() const;

 private:
  std::vector<SnBranch> branches_;
  std::string name_;
  std::string source_;
};

/// The Safe Border Line for `aluminium_layers` as a curve, named by its layers
/// ("the CIGRE Safe Border Line (one aluminium layer)", "(several aluminium layers)").
SnCurve safe_border_curve(int aluminium_layers);

}  // namespace stockbridge::span
