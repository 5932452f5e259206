#pragma once
// The ranges in which the values of real Stockbridge dampers, spans and their tests
// lie. A value outside is most often a unit mistake (a cable length in mm, a mass in
// g, a tension in kN). Where the range's usual slip explains it (the value read in
// the slip's unit lands in the range) the readers refuse it (SlipPolicy::refuse, the
// default: UnusualValueError naming the key, the value and the likely unit); a study
// that goes there on purpose says so (SlipPolicy::warn: the CLI's --allow-unusual,
// Python's allow_unusual=True). Any other value outside is accepted with one warning
// line naming it and its typical range. docs/file-formats.md lists the same table (a
// test keeps the two equal).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stockbridge {

/// A unit a value is often given in by mistake instead of the range's (SI) unit:
/// the value read in `unit` is `factor` times as much in SI (mm: 1e-3, kN: 1e3).
struct UnitSlip {
  double factor = 0.0;    ///< 0: none
  std::string_view unit;  ///< "mm", "kN", "GPa", "%", "rad"
};

struct TypicalRange {
  std::string_view quantity;  ///< what the range is of, as the docs' table names it
  double min = 0.0;
  double max = 0.0;
  std::string_view unit;
  UnitSlip slip;  ///< the usual slip, named when the value read in its unit lies in the range

  bool contains(double value) const { return value >= min && value <= max; }
  /// The value, in the range's unit, it would be if given in the slip's unit and
  /// that lands in the range.
  std::optional<double> slipped(double value) const;
};

/// What a reader does with a value outside its typical range that the range's unit
/// slip explains: refuse it (UnusualValueError), or accept it with a warning (a study
/// beyond the usual on purpose: --allow-unusual, allow_unusual=True).
enum class SlipPolicy { refuse, warn };

/// The typical ranges, in SI units.
namespace typical {
inline constexpr TypicalRange cable_length{"damper cable length", 0.03, 1.0, "m", {1e-3, "mm"}};
inline constexpr TypicalRange ei{"cable bending stiffness ei", 0.1, 1000.0, "N m^2", {}};
inline constexpr TypicalRange jenkin_c{"Jenkin element stiffness c", 0.1, 10000.0, "N m^2", {}};
inline constexpr TypicalRange bouc_wen_chi0{"Bouc-Wen curvature scale chi0", 0.001, 10.0, "1/m", {}};
inline constexpr TypicalRange jenkin_h{"Jenkin element slip moment h", 0.001, 100.0, "N m", {}};
inline constexpr TypicalRange clamp_mass{"clamp mass", 0.05, 20.0, "kg", {1e-3, "g"}};
inline constexpr TypicalRange arm_mass{"arm mass", 0.05, 20.0, "kg", {1e-3, "g"}};
inline constexpr TypicalRange arm_inertia{"arm inertia about its centre of gravity", 1e-6, 0.5, "kg m^2", {1e-4, "kg cm^2"}};
inline constexpr TypicalRange arm_offset{"offset of an arm's centre of gravity", -0.3, 0.3, "m", {1e-3, "mm"}};
inline constexpr TypicalRange frequency{"excitation frequency", 0.5, 500.0, "Hz", {}};
inline constexpr TypicalRange velocity{"clamp velocity amplitude", 0.001, 2.0, "m/s", {1e-3, "mm/s"}};
inline constexpr TypicalRange displacement{"clamp displacement amplitude", 1e-6, 0.05, "m", {1e-3, "mm"}};
/// A damper's |Z| at its clamp: the whole damper's mass line i W M over the test
/// band (a 0.5 kg damper at 0.5 Hz gives 1.6 N s/m, a 10 kg one at 500 Hz 31000).
inline constexpr TypicalRange impedance{"damper impedance |Z|", 1.0, 50000.0, "N s/m", {1e3, "kN s/m"}};
/// Of the cable's length: the quasi-static cantilever is a small-deflection model.
inline constexpr TypicalRange tip_deflection_ratio{"tip deflection / cable length", 0.0, 0.3, "", {}};
inline constexpr TypicalRange tip_rotation{"tip rotation", 0.0, 0.5, "rad", {}};
inline constexpr TypicalRange conductor_diameter{"conductor diameter", 0.004, 0.08, "m", {1e-3, "mm"}};
inline constexpr TypicalRange conductor_mass_per_length{"conductor mass per length", 0.03, 8.0, "kg/m", {1e-3, "g/m"}};
inline constexpr TypicalRange span_length{"span length", 20.0, 3000.0, "m", {1e3, "km"}};
inline constexpr TypicalRange rated_tensile_strength{"conductor rated tensile strength", 5e3, 1.5e6, "N", {1e3, "kN"}};
inline constexpr TypicalRange conductor_ei_min{"conductor bending stiffness ei_min (free wires)", 0.5, 2000.0, "N m^2", {}};
inline constexpr TypicalRange conductor_ei_max{"conductor bending stiffness ei_max (no slip)", 10.0, 1e5, "N m^2", {}};
inline constexpr TypicalRange outer_wire_diameter{"outer wire diameter", 1e-3, 6e-3, "m", {1e-3, "mm"}};
inline constexpr TypicalRange outer_wire_modulus{"outer wire Young's modulus", 4e10, 2.2e11, "Pa", {1e9, "GPa"}};
inline constexpr TypicalRange span_tension{"conductor tension", 1e3, 5e5, "N", {1e3, "kN"}};
inline constexpr TypicalRange tension_fraction{"tension as a fraction of the rated tensile strength", 0.03, 0.4, "",
                                               {1e-2, "%"}};
inline constexpr TypicalRange catenary_parameter{"catenary parameter H/w", 300.0, 4000.0, "m", {}};
inline constexpr TypicalRange damper_position{"damper position from the span clamp", 0.1, 10.0, "m", {1e-3, "mm"}};
inline constexpr TypicalRange attachment_mass{"mass along the span (warning sphere, marker)", 0.5, 50.0, "kg", {1e-3, "g"}};
inline constexpr TypicalRange strouhal{"Strouhal number", 0.1, 0.3, "", {}};
inline constexpr TypicalRange wind_speed{"wind speed of aeolian vibration", 0.2, 15.0, "m/s", {1.0 / 3.6, "km/h"}};
inline constexpr TypicalRange turbulence_intensity{"turbulence intensity", 0.0, 0.5, "", {1e-2, "%"}};
inline constexpr TypicalRange self_damping_l{"self-damping exponent l (amplitude)", 1.5, 3.0, "", {}};
inline constexpr TypicalRange self_damping_m{"self-damping exponent m (frequency)", 3.5, 6.5, "", {}};
inline constexpr TypicalRange self_damping_n{"self-damping exponent n (tension)", 1.0, 3.5, "", {}};
inline constexpr TypicalRange fatigue_cycles{"cycles of the endurance limit", 1e6, 1e10, "", {}};
inline constexpr TypicalRange endurance_limit{"endurance limit (zero-to-peak stress)", 2e6, 5e7, "Pa", {1e6, "MPa"}};
inline constexpr TypicalRange endurance_limit_mpa{"endurance limit in MPa (zero-to-peak stress)", 2.0, 50.0, "MPa",
                                                  {1e-6, "Pa"}};
inline constexpr TypicalRange limit_pp_microstrain{"peak-to-peak bending strain limit", 50.0, 500.0, "microstrain",
                                                   {1e6, "strain"}};
inline constexpr TypicalRange weibull_shape{"Weibull shape of the wind speed", 1.0, 4.0, "", {}};
inline constexpr TypicalRange weibull_scale{"Weibull scale of the wind speed", 1.0, 15.0, "m/s", {1.0 / 3.6, "km/h"}};
inline constexpr TypicalRange aeolian_fraction{"share of the year with aeolian vibration", 0.01, 1.0, "", {1e-2, "%"}};
inline constexpr TypicalRange yb_distance{"distance x_b of the bending amplitude Yb from the clamp", 0.05, 0.15, "m",
                                          {1e-3, "mm"}};
/// A vibration recorder's Yb bin edge (peak-to-peak at x_b), in mm as recorder files
/// give it; a value in um is the usual slip, one in m the other (measurements/recorder.hpp).
inline constexpr TypicalRange recorder_yb{"recorder bending amplitude Yb (peak-to-peak)", 0.005, 10.0, "mm",
                                          {1e-3, "um"}};
/// A self-damping test's antinode amplitude (single peak) and dissipated power per
/// length (IEEE 563, IEC 62567; measurements/self_damping_tests.hpp).
inline constexpr TypicalRange self_damping_amplitude{"antinode amplitude of a self-damping test", 1e-5, 0.05, "m",
                                                     {1e-3, "mm"}};
inline constexpr TypicalRange self_damping_power{"self-damping power per length of a test", 1e-6, 50.0, "W/m",
                                                 {1e-3, "mW/m"}};
/// A fatigue test's Yb (fatigue-test files give it in mm; measurements/fatigue_tests_file.hpp).
inline constexpr TypicalRange yb_pp_mm{"peak-to-peak bending amplitude Yb of a fatigue test", 0.01, 5.0, "mm", {1e3, "m"}};

/// Every range above, in the order of the docs' table.
const std::vector<TypicalRange>& all();
}  // namespace typical

/// A value outside its typical range: `field` as the description files or the
/// options spell it ("arm[0].mass", "--velocity").
struct UnusualValue {
  std::string field;
  double value = 0.0;
  TypicalRange range;
  /// A hint where no slip of the range explains the value ("rad/s, or a frequency
  /// beyond a shaker test's?"); empty: "a unit mistake?".
  std::string hint;

  /// The range's unit slip explains the value (TypicalRange::slipped).
  bool slip_explained() const { return range.slipped(value).has_value(); }

  /// "arm[0].mass = 863: outside the typical 0.05 to 20 kg of the arm mass (a unit mistake?)",
  /// or, where the range's slip explains it, "conductor.diameter = 28.14: outside the
  /// typical 0.004 to 0.08 m of the conductor diameter (in mm? 28.14 mm = 0.02814 m)"
  std::string message() const;
};

/// The value as an UnusualValue if it lies outside `range`.
std::optional<UnusualValue> unusual(std::string field, double value, const TypicalRange& range);
/// Appends `unusual(field, value, range)` to `out` if there is one.
void check_typical(std::vector<UnusualValue>& out, std::string field, double value, const TypicalRange& range);

/// A reader's judgement of a value outside its typical range, `location` its place
/// ("span.toml:16: "): a UnusualValueError where its slip explains it and `policy`
/// refuses slips, else a warning line appended to `warnings`.
void judge_unusual(const UnusualValue& value, const std::string& location, SlipPolicy policy,
                   std::vector<std::string>& warnings);
/// The same for a located line about values that hang together implausibly (a
/// span's sag): refused under SlipPolicy::refuse, else a warning.
void judge_implausible(std::string line, SlipPolicy policy, std::vector<std::string>& warnings);

}  // namespace stockbridge
