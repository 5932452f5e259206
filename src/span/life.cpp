#include "stockbridge/span/life.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

/// Checks that the frequencies are > 0 and strictly increasing.
void check_life_frequencies(std::span<const double> frequencies) {
  if (frequencies.empty()) throw InvalidParameter("frequencies", ": none given; expected at least one");
  for (std::size_t i = 0; i < frequencies.size(); ++i) {
    require_plausible(fmt::format("frequencies[{}]", i), frequencies[i], "Hz");
    if (i > 0 && !(frequencies[i] > frequencies[i - 1])) {
      throw_invalid(fmt::format("frequencies[{}]", i), frequencies[i],
                    fmt::format("more than the frequency before ({} Hz): strictly increasing",
                                format_value(frequencies[i - 1])));
    }
  }
}

/// The speed edges of the bins: the band's edges outside, midpoints between the U_i
/// inside, each held in [speed_min, speed_max].
std::vector<double> life_speed_edges(const std::vector<LifeBin>& bins, const WindModel& wind) {
  std::vector<double> edges{wind.speed_min};
  for (std::size_t i = 1; i < bins.size(); ++i) edges.push_back(0.5 * (bins[i - 1].wind_speed + bins[i].wind_speed));
  edges.push_back(wind.speed_max);
  for (double& e : edges) e = std::clamp(e, wind.speed_min, wind.speed_max);
  return edges;
}

}  // namespace

void WeibullWind::validate() const {
  require_plausible("shape", shape, "");
  require_plausible("scale", scale, "m/s");
}

double WeibullWind::cdf(double speed) const {
  if (!(speed > 0.0)) return 0.0;
  return -std::expm1(-std::pow(speed / scale, shape));
}

void LifeModel::validate() const {
  within_field("wind_weibull", [this] { wind_weibull.validate(); });
  require_positive("aeolian_fraction", aeolian_fraction, "");
  if (!(aeolian_fraction <= 1.0)) throw_invalid("aeolian_fraction", aeolian_fraction, "a share of the year, > 0 and <= 1");
}

std::vector<LifeBin> life_bins(std::span<const double> frequencies, const WindModel& wind, double diameter,
                               const WeibullWind& weibull) {
  check_life_frequencies(frequencies);
  std::vector<LifeBin> bins(frequencies.size());
  for (std::size_t i = 0; i < bins.size(); ++i) {
    bins[i].frequency = frequencies[i];
    bins[i].wind_speed = wind.wind_speed(frequencies[i], diameter);
  }
  const std::vector<double> edges = life_speed_edges(bins, wind);
  for (std::size_t i = 0; i < bins.size(); ++i) {
    bins[i].speed_low = edges[i];
    bins[i].speed_high = edges[i + 1];
    bins[i].probability = std::max(0.0, weibull.cdf(edges[i + 1]) - weibull.cdf(edges[i]));
  }
  return bins;
}

LifeEstimate estimate_life(std::span<const double> frequencies, std::span<const double> stresses,
                           const WindModel& wind, double diameter, const LifeModel& life,
                           const SnCurve& line) {
  if (stresses.size() != frequencies.size()) {
    throw InvalidParameter("stresses", fmt::format(": {} given for {} frequencies; expected one per frequency",
                                                   stresses.size(), frequencies.size()));
  }
  for (std::size_t i = 0; i < stresses.size(); ++i) {
    require_non_negative(fmt::format("stresses[{}]", i), stresses[i], "Pa");
  }
  LifeEstimate estimate{0.0, 0.0, life_bins(frequencies, wind, diameter, life.wind_weibull)};
  for (std::size_t i = 0; i < estimate.bins.size(); ++i) {
    LifeBin& bin = estimate.bins[i];
    bin.cycles_per_year = bin.frequency * life.aeolian_fraction * bin.probability * seconds_per_year;
    bin.stress = stresses[i];
    bin.cycles_to_failure = line.cycles_to_failure(bin.stress);
    bin.damage_per_year = bin.cycles_per_year / bin.cycles_to_failure;  // 0 for an infinite N
    estimate.damage_per_year += bin.damage_per_year;
  }
  estimate.life_years = estimate.damage_per_year > 0.0 ? 1.0 / estimate.damage_per_year
                                                       : std::numeric_limits<double>::infinity();
  return estimate;
}

}  // namespace stockbridge::span
