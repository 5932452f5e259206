#pragma once
// The power a vibrating conductor dissipates by itself (self-damping: friction
// between its wires), MODEL.md section 9; sources in docs/span.md.
//
// Power laws, fitted to measurements on laboratory spans:
//     P_s = L k Y^l f^m / (T / 1000)^n                        (W)
// with Y the antinode amplitude (m), f the frequency (Hz), T the tension (N, so
// T / 1000 in kN) and L the span length (m); k by default Lilien's
// D[mm] / sqrt(m[kg/m] RTS[kN]) (span/conductor.hpp). Exponents by source:
//     noiseux-1991          2.44   5.63   2.76
//     kraus-hagedorn-1991   2.47   5.38   2.80
//     seppa-1971            2.5    5.75   2.8
//     moecks-schmidt-1989   2.45   5.38   2.4
//     claren-diana-1969     2.0    4.0    1.5 .. 3      (n: the user's, within the range)
//     tompkins-1956         2.3 .. 2.6   5.0 .. 6.0   1.9   (l, m: the user's)
//     polimi-2000           2.43   5.5    2
//     power                 the user's l, m, n
// A source that published an exponent only as a range leaves the choice to the
// user: the model asks for it (and checks it lies in the range) rather than
// picking a value the source did not give.
//
// foti: Foti & Martinelli (2018), from the slip between the wires. A cross-section
// bent to a curvature amplitude chi dissipates per cycle and per length
//     dW(chi) = EI_max chi^3 / (2 chi0)   (micro-slip, chi <= chi0)
//     dW(chi) = EI_max chi^2 / 2          (gross slip, chi > chi0)
// (chi0: the limit curvature, `limit_curvature`). Along a standing wave of
// curvature amplitude chi_m = k^2 Y, the average over a loop gives
//     P_s = L f EI_max [ (2/pi) G1 chi_m^3 / chi0 + G2 chi_m^2 / (4 pi) ],
//     G1 = 1/3 - 3/8 cos t + 1/24 cos 3t,   G2 = pi - 2t + sin 2t,
//     t = asin(min(1, chi0 / chi_m))   (t = pi/2: micro-slip everywhere),
// the closed form (eqs. (23)-(30) of the paper) as RTE's dohl implements it
// (rte-france/pallas-dohl, damping_power_foti; the paper itself was not read). A
// test checks that it is the loop average of the local law above.

#include <optional>
#include <string_view>

#include "stockbridge/span/conductor.hpp"

namespace stockbridge::span {

enum class SelfDampingLaw {
  noiseux_1991,
  kraus_hagedorn_1991,
  seppa_1971,
  moecks_schmidt_1989,
  claren_diana_1969,
  tompkins_1956,
  polimi_2000,
  power,
  foti
};

/// The names above ("noiseux-1991", ..., "power", "foti"); throws InvalidParameter
/// naming "law" otherwise.
SelfDampingLaw parse_self_damping_law(std::string_view name);
std::string_view self_damping_law_name(SelfDampingLaw law);

/// An exponent as its source published it: lo == hi for a value, lo < hi for a range.
struct PublishedExponent {
  double lo = 0.0;
  double hi = 0.0;
  bool is_range() const { return lo < hi; }
};
struct PublishedExponents {
  PublishedExponent l, m, n;
};
/// The exponents of a named power law; none for power and foti.
std::optional<PublishedExponents> published_exponents(SelfDampingLaw law);

/// The exponents of P_s = L k Y^l f^m / (T / 1000)^n.
struct PowerLawExponents {
  double l = 0.0;
  double m = 0.0;
  double n = 0.0;
};

/// What a span file's [self_damping] table says; validate() checks it once.
struct SelfDampingModel {
  SelfDampingLaw law = SelfDampingLaw::noiseux_1991;
  std::optional<double> k;                ///< the power laws' factor; none: Lilien's
  std::optional<double> l, m, n;          ///< power: all three; a named law: only those it gives as a range
  std::optional<double> limit_curvature;  ///< foti: chi0, 1/m

  /// Throws InvalidParameter naming the field ("k", "l", "n", "limit_curvature"): an
  /// exponent the law needs and lacks, one it fixes itself, one outside its source's
  /// range, a setting the law does not use.
  void validate() const;
  /// validate(), and what the law needs of the conductor: foti needs ei_max (throws
  /// InvalidParameter naming "conductor.ei_max", the full path in a span file).
  void validate_with(const Conductor& conductor) const;

  /// The exponents in use (a power law: the published ones completed by the user's).
  PowerLawExponents exponents() const;
  /// k in use: the given one or Lilien's.
  double factor(const Conductor& conductor) const;
  /// P_s in W: amplitude Y (m), frequency f (Hz), tension T (N), span length L (m).
  double power(double amplitude, double frequency, const Conductor& conductor, double tension,
               double span_length) const;
};

/// k Y^l f^m / (T / 1000)^n: the power laws' self-damping per length, W/m.
double power_law_self_damping(double k, const PowerLawExponents& exponents, double amplitude, double frequency,
                              double tension);
/// Foti & Martinelli's self-damping per length, W/m (chi0 = limit_curvature, 1/m).
double foti_self_damping(const Conductor& conductor, double tension, double limit_curvature, double amplitude,
                         double frequency);

}  // namespace stockbridge::span
