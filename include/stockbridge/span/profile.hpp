#pragma once
// The standing wave along a span at one frequency's balance (MODEL.md section 15;
// docs/span.md, "Masses and dampers along the span"): the conductor's displacement
// amplitude |Y(x)| and the antinode amplitude of the stretch each x lies in, from
// the ends' transfer chains with the balance's impedances (each half of the span
// from its own end's chain: the energy balance's picture, where the two ends'
// waves meet in the free span at the same antinode amplitude Y).

#include <string>
#include <vector>

#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/span.hpp"

namespace stockbridge::span {

/// A point attachment along the span, as a profile marks it.
struct ProfileAttachment {
  double position = 0.0;  ///< m from end 1
  std::string name;       ///< the damper's or mass's name
  bool mass = false;      ///< a mass (true) or a damper (false)
};

struct SpanProfile {
  double frequency_hz = 0.0;
  std::vector<double> x;             ///< m from end 1, increasing, both clamps included
  std::vector<double> displacement;  ///< |Y(x)|, zero-to-peak, m
  std::vector<double> envelope;      ///< |A| + |B| of the stretch x lies in, m
  std::vector<ProfileAttachment> attachments;  ///< by position
};

/// The profile of `point` (a converged point of `span`'s balance), sampled at least
/// `points_per_wavelength` times a wavelength and at every attachment.
/// InvalidParameter naming "frequency" for a point that did not converge.
SpanProfile span_profile(const Span& span, const BalancePoint& point, int points_per_wavelength = 16);

/// The converged point of the largest judged stress (the governing frequency);
/// InvalidParameter naming "frequency" when no point converged.
const BalancePoint& governing_point(const Span& span, const SpanBalance& balance);
/// Whether `p`, the next point in the band's order, governs instead of `best` (none:
/// no point yet): converged, with a judged stress above best's (the first of the
/// largest governs). governing_point's rule, for a caller that does not hold the points.
bool governs_instead(const Span& span, const BalancePoint& p, const BalancePoint* best);

}  // namespace stockbridge::span
