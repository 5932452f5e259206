#pragma once
// The ranges in which the values of real Stockbridge dampers and their tests lie.
// A value outside is accepted (a study may go there on purpose) but is most often
// a unit mistake (a cable length in mm, a mass in g, an inertia in kg cm^2): front
// ends show one warning line per such value, naming it and its typical range.
// docs/file-formats.md lists the same table (a test keeps the two equal).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stockbridge {

struct TypicalRange {
  std::string_view quantity;  ///< what the range is of, as the docs' table names it
  double min = 0.0;
  double max = 0.0;
  std::string_view unit;

  bool contains(double value) const { return value >= min && value <= max; }
};

/// The typical ranges, in SI units.
namespace typical {
inline constexpr TypicalRange cable_length{"damper cable length", 0.03, 1.0, "m"};
inline constexpr TypicalRange ei{"cable bending stiffness ei", 0.1, 1000.0, "N m^2"};
inline constexpr TypicalRange jenkin_c{"Jenkin element stiffness c", 0.1, 10000.0, "N m^2"};
inline constexpr TypicalRange jenkin_h{"Jenkin element slip moment h", 0.001, 100.0, "N m"};
inline constexpr TypicalRange clamp_mass{"clamp mass", 0.05, 20.0, "kg"};
inline constexpr TypicalRange arm_mass{"arm mass", 0.05, 20.0, "kg"};
inline constexpr TypicalRange arm_inertia{"arm inertia about its centre of gravity", 1e-6, 0.5, "kg m^2"};
inline constexpr TypicalRange arm_offset{"|offset| of an arm's centre of gravity", 0.0, 0.3, "m"};
inline constexpr TypicalRange frequency{"excitation frequency", 0.5, 500.0, "Hz"};
inline constexpr TypicalRange velocity{"clamp velocity amplitude", 0.001, 2.0, "m/s"};
inline constexpr TypicalRange displacement{"clamp displacement amplitude", 1e-6, 0.05, "m"};
/// A damper's |Z| at its clamp: the whole damper's mass line i W M over the test
/// band (a 0.5 kg damper at 0.5 Hz gives 1.6 N s/m, a 10 kg one at 500 Hz 31000).
inline constexpr TypicalRange impedance{"damper impedance |Z|", 1.0, 50000.0, "N s/m"};
/// Of the cable's length: the quasi-static cantilever is a small-deflection model.
inline constexpr TypicalRange tip_deflection_ratio{"tip deflection / cable length", 0.0, 0.3, ""};
inline constexpr TypicalRange tip_rotation{"tip rotation", 0.0, 0.5, "rad"};
inline constexpr TypicalRange conductor_diameter{"conductor diameter", 0.004, 0.08, "m"};
inline constexpr TypicalRange conductor_mass_per_length{"conductor mass per length", 0.03, 8.0, "kg/m"};
inline constexpr TypicalRange span_length{"span length", 20.0, 3000.0, "m"};

/// Every range above, in the order of the docs' table.
const std::vector<TypicalRange>& all();
}  // namespace typical

/// A value outside its typical range: `field` as the description files or the
/// options spell it ("arm[0].mass", "--velocity").
struct UnusualValue {
  std::string field;
  double value = 0.0;
  TypicalRange range;
  /// The likely slip where one is ("mm/s?"); empty: "a unit mistake?".
  std::string hint;

  /// "arm[0].mass = 863: outside the typical 0.05 to 20 kg of an arm mass (a unit mistake?)"
  std::string message() const;
};

/// The value as an UnusualValue if it lies outside `range`.
std::optional<UnusualValue> unusual(std::string field, double value, const TypicalRange& range);
/// Appends `unusual(field, value, range)` to `out` if there is one.
void check_typical(std::vector<UnusualValue>& out, std::string field, double value, const TypicalRange& range);

}  // namespace stockbridge
