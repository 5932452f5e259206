#pragma once
// The discretised cable: Gauss-Legendre points s_i with weights w_i along
// [0, l] (one rule a zone where the profiles jump, CableDescription::zone_boundaries;
// the sections shared among the zones in proportion to their lengths, at least one
// each), and its section law's numbers at each point (the model, constant; its
// state lives in CableState).

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/cable/cable_law.hpp"

namespace stockbridge::cable {

/// Makes a cable's section law at its Gauss points (`positions`, with their `weights`).
using CableLawMaker = std::function<std::shared_ptr<const CableLaw>(
    const CableDescription& description, std::span<const double> positions, std::span<const double> weights)>;

class Cable {
 public:
  /// Validates the description (InvalidParameter) and discretises it; its law is the
  /// one the description names (make_cable_law).
  explicit Cable(CableDescription description);
  /// The same with the law `make_law` makes, which must be the law the description
  /// names, with options of its own (BoucWenCableLaw's kernels).
  Cable(CableDescription description, const CableLawMaker& make_law);

  const CableDescription& description() const { return description_; }
  double length() const { return description_.length; }
  std::size_t sections() const { return positions_.size(); }

  std::span<const double> positions() const { return positions_; }  ///< s_i, m
  std::span<const double> weights() const { return weights_; }      ///< w_i, m
  /// The section law at the points (shared by copies of the cable: it is constant).
  const CableLaw& law() const { return *law_; }

 private:
  CableDescription description_;
  std::vector<double> positions_;
  std::vector<double> weights_;
  std::shared_ptr<const CableLaw> law_;
};

}  // namespace stockbridge::cable
