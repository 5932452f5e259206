#pragma once
// What a user says about a damper cable (MODEL.md sections 2 and 3): its length,
// how finely to integrate along it, and the Masing parameters as profiles over
// s, optionally mirrored from a cable of another length, optionally with the
// modified Masing model's load-dependent slip moment.

#include <optional>
#include <string_view>
#include <vector>

#include "stockbridge/cable/profile.hpp"
#include "stockbridge/cable/section_law_descriptor.hpp"
#include "stockbridge/core/typical_ranges.hpp"

namespace stockbridge::cable {

/// One distributed Jenkin element.
struct JenkinProfile {
  Profile c = Profile::constant(0.0);  ///< N m^2, > 0
  Profile h = Profile::constant(0.0);  ///< slip moment h0, N m, > 0
  /// Modified Masing model (3.7): h = h0 + k0 |M| / |F|, k0 in N, >= 0; 0 = off.
  double k0 = 0.0;

  bool operator==(const JenkinProfile&) const = default;
};

/// Integration points along a cable: at least two, since with one Gauss point the
/// tip's deflection is always l/2 times its rotation (the cable could not be
/// clamped at one end and guided at the other, as in experiment (b) and the damper).
inline constexpr int min_sections = 2;
inline constexpr int max_sections = 5000;
/// A profile segment shorter than this fraction of the cable's length is a jump.
inline constexpr double zone_ramp_fraction = 1e-3;

struct CableDescription {
  double length = 0.0;   ///< l, m
  int sections = 40;     ///< Gauss-Legendre integration points along the cable
  /// The section law (section_law_descriptor.hpp): the Masing law unless a file says otherwise.
  const SectionLawDescriptor* law = &default_section_law();
  /// The elastic part, N m^2, > 0 everywhere, of a law that has one (key "ei": Masing, Iwan).
  Profile ei = Profile::constant(0.0);
  /// The Masing law's Jenkin elements (a law with jenkin_elements()).
  std::vector<JenkinProfile> jenkin;
  /// The law's other numbers, in the order of its keys (Bouc-Wen: ei_min, ei_max, chi0).
  std::vector<Profile> numbers;

  /// Mirror method (3.6): the profiles were identified on a cable of this length
  /// l_id; the cable uses p(s) for s <= l/2 and p(l - s) beyond. Needs l <= 2 l_id.
  std::optional<double> mirror_length;
  /// Modified Masing model: cap of the lever arm |M|/|F| (m); default: the length.
  /// Also used where F = 0.
  std::optional<double> lever_arm_cap;

  /// The profile of the law's number `key` ("ei", "ei_min"): InvalidParameter naming
  /// `key` if the law has no such number. Writing one of a law whose `numbers` are
  /// not yet filled fills them with zeros first.
  const Profile& number(std::string_view key) const;
  Profile& number(std::string_view key);

  /// Throws InvalidParameter naming the bad field ("length", "jenkin[0].h.value[2]",
  /// "ei_max.value[1]", ...).
  void validate() const;
  /// The position at which the profiles are read for the cable's point s (mirror method).
  double profile_position(double s) const;
  /// Where a profile jumps: the middle of every table segment shorter than
  /// zone_ramp_fraction of the length (a zone boundary, as slenderpy's messenger
  /// has), in the cable's coordinate s (mirrored beyond l/2 under the mirror
  /// method), ascending, strictly inside (0, l). The cable integrates each zone
  /// with its own Gauss-Legendre rule, so that no quadrature cell straddles a jump.
  std::vector<double> zone_boundaries() const;
  /// The lever-arm cap in force (m).
  double lever_arm_limit() const { return lever_arm_cap.value_or(length); }
  bool uses_modified_masing() const;
  /// The values outside the typical ranges of damper cables (core/typical_ranges.hpp),
  /// named as validate() names them ("ei", "jenkin[0].h.value[2]").
  std::vector<UnusualValue> unusual_values() const;

  bool operator==(const CableDescription&) const = default;

  /// The simplest cable: constant parameters.
  static CableDescription uniform(double length, int sections, double ei, std::vector<std::pair<double, double>> jenkin_c_h);
  /// The simplest cable of a law of numbers: each number constant, in the law's key order.
  static CableDescription uniform(const SectionLawDescriptor& law, double length, int sections,
                                  const std::vector<double>& values);
  /// The law's numbers at s = 0, in key order (a cable of constant numbers: the fits').
  LawValues values() const;
};

}  // namespace stockbridge::cable
