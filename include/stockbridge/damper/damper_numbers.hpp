#pragma once
// The numbers of a damper description by the path a damper file spells them:
//
//   clamp.mass
//   arm.<name>.mass | inertia | offset            (or arm[<k>]., k from 0)
//   arm.<name>.cable.length | ei | mirror_length | lever_arm_cap
//   arm.<name>.cable.jenkin[<k>].c | h | k0
//
// what a design study varies. A cable parameter given as a profile along the cable
// is not one number and is refused, as is a path that names nothing.

#include <string>
#include <string_view>

#include "stockbridge/damper/damper.hpp"

namespace stockbridge::damper {

/// The number at `path`; InvalidParameter naming the path and what was expected.
double damper_number(const DamperDescription& damper, std::string_view path);

/// Sets the number at `path` (not validated here: the damper's constructor does).
void set_damper_number(DamperDescription& damper, std::string_view path, double value);

/// The arm an "arm.<name>..." or "arm[<k>]..." path names: its index, and the rest
/// of the path after the arm ("mass", "cable.length"); InvalidParameter otherwise.
struct ArmPath {
  std::size_t arm = 0;
  std::string field;
};
ArmPath split_arm_path(const DamperDescription& damper, std::string_view path);

}  // namespace stockbridge::damper
