#include "stockbridge/requests/strand_request.hpp"

namespace stockbridge::requests {

io::JsonObject strand_summary(const strand::StrandBounds& bounds) {
  return io::JsonObject().add("ei_min_n_m2", bounds.ei_min).add("ei_max_n_m2", bounds.ei_max);
}

}  // namespace stockbridge::requests
