#include "stockbridge/cable/cable.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/gauss_legendre.hpp"

namespace stockbridge::cable {

namespace {

/// `total` points shared among zones of these lengths in proportion to them, at
/// least one each (largest remainders first).
std::vector<int> points_per_zone(const std::vector<double>& lengths, int total) {
  double sum = 0.0;
  for (double l : lengths) sum += l;
  std::vector<int> points(lengths.size());
  std::vector<std::pair<double, std::size_t>> remainders;
  int given = 0;
  for (std::size_t k = 0; k < lengths.size(); ++k) {
    const double share = total * lengths[k] / sum;
    points[k] = std::max(1, static_cast<int>(std::floor(share)));
    given += points[k];
    remainders.emplace_back(share - std::floor(share), k);
  }
  std::sort(remainders.begin(), remainders.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t r = 0; given < total; r = (r + 1) % remainders.size(), ++given) ++points[remainders[r].second];
  return points;
}

}  // namespace

Cable::Cable(CableDescription description) : Cable(std::move(description), make_cable_law) {}

Cable::Cable(CableDescription description, const CableLawMaker& make_law)
    : description_(validated(std::move(description))) {
  const double l = description_.length;
  std::vector<double> edges{0.0};
  for (double b : description_.zone_boundaries()) edges.push_back(b);
  edges.push_back(l);
  std::vector<double> lengths;
  for (std::size_t k = 1; k < edges.size(); ++k) lengths.push_back(edges[k] - edges[k - 1]);
  const std::vector<int> points = points_per_zone(lengths, description_.sections);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const numerics::QuadratureRule rule = numerics::gauss_legendre(points[k], edges[k], edges[k + 1]);
    positions_.insert(positions_.end(), rule.nodes.begin(), rule.nodes.end());
    weights_.insert(weights_.end(), rule.weights.begin(), rule.weights.end());
  }
  law_ = make_law(description_, positions_, weights_);
}

}  // namespace stockbridge::cable
