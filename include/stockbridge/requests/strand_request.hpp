#pragma once
// The request layer for a strand's bending-stiffness bounds (`stockbridge strand`,
// Python's load_strand): the summary both front ends give.

#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/strand/strand_bounds.hpp"

namespace stockbridge::requests {

/// {"ei_min_n_m2", "ei_max_n_m2"}: no friction between the wires, and no slip.
io::JsonObject strand_summary(const strand::StrandBounds& bounds);

}  // namespace stockbridge::requests
