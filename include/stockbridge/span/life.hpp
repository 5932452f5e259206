#pragma once
// A span's fatigue life from the wind's climate (docs/span.md, "Life").
//
// The balance gives, at frequencies f_1 < ... < f_n, the stress amplitude sigma_i
// (Poffenberger-Swart, zero-to-peak) the span vibrates with. Each frequency stands
// for the wind speeds U_i = f_i D / St; the speed axis is cut into bins at the
// midpoints between neighbouring U_i, the outer bins closed by the aeolian band's
// edges speed_min and speed_max (every edge held inside the band, so that a
// frequency outside the band gets an empty bin). With wind speeds Weibull
// distributed, F(U) = 1 - exp(-(U / scale)^shape), a bin [U_lo, U_hi] holds the
// probability p_i = F(U_hi) - F(U_lo); the bins together hold
// F(speed_max) - F(speed_min). Assumptions (each one conservative or neutral):
//   * the conductor vibrates at f_i whenever the wind is in bin i and the air is
//     steady enough (aeolian_fraction: the share of the year with steady low wind,
//     the same for every speed of the band);
//   * one cycle per period: n_i = f_i * aeolian_fraction * p_i * 365.25 days per year;
//   * every cycle at the balance's amplitude (no spectrum of amplitudes);
//   * Miner's rule against the span's S-N curve (Span::sn_curve: the Safe Border Line, or
//     the [fatigue] curve given): damage per year D = sum n_i / N(sigma_i),
//     life = 1 / D years (infinite when D = 0).

#include <span>
#include <vector>

#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {

inline constexpr double seconds_per_year = 365.25 * 86400.0;

/// Weibull-distributed wind speeds; no defaults: they are a site's climate.
struct WeibullWind {
  double shape = 0.0;  ///< k (> 0; 2: Rayleigh)
  double scale = 0.0;  ///< c, m/s (> 0)

  /// Throws InvalidParameter naming "shape" or "scale".
  void validate() const;
  /// F(U) = 1 - exp(-(U / scale)^shape) (0 for U <= 0).
  double cdf(double speed) const;
};

/// What a span file's [fatigue] table says about the climate; validate() checks it once.
struct LifeModel {
  WeibullWind wind_weibull;
  double aeolian_fraction = 0.0;  ///< in (0, 1]

  /// Throws InvalidParameter naming "wind_weibull.shape", "wind_weibull.scale" or "aeolian_fraction".
  void validate() const;
};

/// One frequency's share of a year.
struct LifeBin {
  double frequency = 0.0;          ///< f_i, Hz
  double wind_speed = 0.0;         ///< U_i = f_i D / St, m/s
  double speed_low = 0.0;          ///< the bin's edges, m/s
  double speed_high = 0.0;
  double probability = 0.0;        ///< p_i
  double cycles_per_year = 0.0;    ///< n_i
  double stress = 0.0;             ///< sigma_i, Pa
  double cycles_to_failure = 0.0;  ///< N(sigma_i) (infinite for sigma_i = 0)
  double damage_per_year = 0.0;    ///< n_i / N(sigma_i)
};

struct LifeEstimate {
  double damage_per_year = 0.0;  ///< Miner's sum over the bins
  double life_years = 0.0;       ///< 1 / damage_per_year; infinite when it is 0
  std::vector<LifeBin> bins;
};

/// The bins' edges and probabilities (no stresses yet): frequencies strictly
/// increasing and > 0 (InvalidParameter naming "frequencies" otherwise).
std::vector<LifeBin> life_bins(std::span<const double> frequencies, const WindModel& wind, double diameter,
                               const WeibullWind& weibull);

/// Miner's damage and the life for `stresses` (Pa, one per frequency, finite and >= 0;
/// InvalidParameter naming "stresses" otherwise). Models valid (validated).
LifeEstimate estimate_life(std::span<const double> frequencies, std::span<const double> stresses,
                           const WindModel& wind, double diameter, const LifeModel& life,
                           const SnCurve& line);

}  // namespace stockbridge::span
