#include "stockbridge/io/span_names.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

span::DamperModel parse_damper_model(std::string_view name) {
  if (name == "travelling") return span::DamperModel::travelling;
  if (name == "weak") return span::DamperModel::weak;
  throw InvalidParameter("damper_model", fmt::format(" = '{}': expected travelling or weak", name));
}

span::PositionObjective parse_position_objective(std::string_view name) {
  if (name == "max_stress") return span::PositionObjective::max_stress;
  if (name == "life") return span::PositionObjective::life;
  throw InvalidParameter("objective", fmt::format(" = \"{}\": expected \"max_stress\" (the largest fymax stress over the "
                                                  "endurance limit) or \"life\"",
                                                  printable(name)));
}

}  // namespace stockbridge::io
