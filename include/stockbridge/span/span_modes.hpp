#pragma once
// The span's natural frequencies with its attachments (MODEL.md section 15;
// docs/span.md, "Natural frequencies with attachments"). The conductor is the taut
// string of travelling_wave.hpp (c = sqrt(T/m), k = w / c), pinned at both clamps;
// at each attachment x_i the slope jumps,
//
//     T (Y'(x_i+) - Y'(x_i-)) = j w Z_i Y(x_i),   Z_i = j w M_i(w):
//     Y'(x_i+) = Y'(x_i-) - w^2 M_i(w) Y(x_i) / T,
//
// real, since every attachment here is reactive: a rigid mass (M_i constant) or a
// damper at its linear impedance (damper/linear_impedance.hpp: every element
// sticking, M_i(w) the damper's effective mass, with poles at its arms' clamp-held
// frequencies). A natural frequency is a root of the chain's end condition Y(L) = 0,
// carried from Y(0) = 0, Y'(0) = 1 through every attachment in position order.
//
// The roots are found by counting, not by scanning for sign changes: the
// Wittrick-Williams count J(w), the number of natural frequencies below w, is
//
//     J(w) = sum over the string's segments floor(k d_s / pi)   (each segment pinned at both ends)
//          + sum over the dampers their clamp-held modes below w (each arm's two)
//          + the negative pivots of the attachments' dynamic stiffness matrix,
//
// the matrix tridiagonal: a_i = T k (cot(k d_{i-1}) + cot(k d_i)) - w^2 M_i(w),
// b_i = -T k / sin(k d_i). J is exact, whole and non-decreasing, so no root is
// missed however close two lie (a heavy mass splits the span into nearly equal
// halves whose modes pair up) and the dampers' poles need no care; the n-th
// frequency is where J reaches n, bisected to round-off (about 1e-16 relative).
// The shape is then the chain at that frequency. A damper with identical arms
// has modes in which the arms swing against each other and the clamp, and so the
// conductor, stands still: they count in J but are no modes of the span; they are
// recognised by the chain's end condition (not met: the clamp is at the pole of its
// effective mass) and left out (SpanModes::clamp_still_modes).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/span/span.hpp"

namespace stockbridge::span {

/// How the modes take the span's dampers.
enum class ModeDampers {
  removed,  ///< left out (the conductor with its masses)
  linear,   ///< at their linear impedance, every element sticking (a damper known only by a
            ///< measured sheet has none: refused, InvalidParameter naming "dampers")
};
/// "removed" or "linear".
std::string_view mode_dampers_name(ModeDampers dampers);
/// "removed" or "linear"; InvalidParameter naming "dampers" otherwise.
ModeDampers parse_mode_dampers(std::string_view name);

struct SpanModesOptions {
  double max_frequency_hz = 0.0;             ///< the modes below it, Hz (> 0)
  ModeDampers dampers = ModeDampers::linear;
  bool shapes = true;                        ///< sample the shapes (else only frequencies and attachments)
  double samples_per_wavelength = 20.0;      ///< shape samples per wavelength of the highest mode (>= 4)
  int min_samples = 201;                     ///< and at least this many along the span (>= 2)

  /// InvalidParameter naming the field ("max_frequency_hz", "samples_per_wavelength", "min_samples").
  void validate() const;
};

/// More modes below the maximum frequency than this are refused (InvalidParameter naming
/// "max_frequency_hz"): a maximum that high is a unit slip, and the shapes would not fit.
inline constexpr int max_span_modes = 10000;

enum class AttachmentKind { mass, damper };
/// "mass" or "damper".
std::string_view attachment_kind_name(AttachmentKind kind);

/// One point attachment as the modes take it (a mass at several positions is several).
struct ModeAttachment {
  AttachmentKind kind = AttachmentKind::mass;
  std::string name;       ///< the mass's or the damper's name in the span
  double position = 0.0;  ///< m from end 1
  double mass = 0.0;      ///< kg: the rigid mass, or the damper's whole mass (its M_eff at 0 Hz)
};

struct SpanMode {
  int number = 0;            ///< from 1, by increasing frequency
  double frequency_hz = 0.0;
  double wavelength_m = 0.0; ///< c / f, the conductor's own
  /// Y at SpanModes::x, scaled so that the largest |Y| along the span (between the
  /// samples too) is 1, with Y'(0) > 0 (empty without SpanModesOptions::shapes).
  std::vector<double> shape;
  /// Y at each attachment, the same scale (SpanModes::attachments' order).
  std::vector<double> attachment_deflection;
  /// |Y(L)| of the chain at the frequency found, relative to the largest |Y|: the
  /// end condition's residual (round-off: 1e-11 or less on a 400 m span up to 42 Hz;
  /// above 1e-6 the frequency is a clamp-still one, left out).
  double end_residual = 0.0;
};

struct SpanModes {
  double length = 0.0;       ///< m
  double wave_speed = 0.0;   ///< c = sqrt(T / m), m/s
  double max_frequency_hz = 0.0;
  ModeDampers dampers = ModeDampers::linear;
  std::vector<ModeAttachment> attachments;  ///< by position
  std::vector<double> x;                    ///< the shapes' samples, m from end 1: uniform, and each attachment's position
  std::vector<SpanMode> modes;              ///< by increasing frequency
  /// Natural frequencies below the maximum at which the conductor stands still (a
  /// damper's identical arms swinging against each other), left out of `modes`.
  int clamp_still_modes = 0;
  double max_end_residual = 0.0;  ///< the largest SpanMode::end_residual
};

/// The span's natural frequencies below options.max_frequency_hz with its masses and
/// its dampers as `options.dampers` says, and their shapes. Throws InvalidParameter
/// naming the option (validate), or "dampers" for a damper known only by its sheet
/// under ModeDampers::linear.
SpanModes span_modes(const Span& span, const SpanModesOptions& options);

/// The Wittrick-Williams count: how many natural frequencies of the span (with
/// `options.dampers`) lie below `frequency_hz`, the clamp-still ones included.
int span_modes_below(const Span& span, ModeDampers dampers, double frequency_hz);

}  // namespace stockbridge::span
