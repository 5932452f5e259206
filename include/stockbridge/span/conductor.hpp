#pragma once
// The conductor of a span and its taut-string quantities (MODEL.md section 9).
//
// A span is a conductor of mass per length m and diameter D stretched by a tension
// T between two clamps. For the wavelengths of aeolian vibration (0.3 to 30 m) the
// conductor is a taut string:
//     wave speed       c = sqrt(T / m)                       (m/s)
//     wavenumber       k = 2 pi f / c                         (rad/m)
//     wavelength       lambda = c / f                         (m)
//     wave impedance   Z0 = sqrt(T m)                         (N s/m)
// Its bending stiffness matters only within a few 1/p = sqrt(EI_min / T) of a
// clamp or a point force, where the stresses are (span/fatigue.hpp). There the
// tensioned beam EI y'''' - T y'' - m w^2 y = 0 has the wavenumbers of
// beam_wavenumbers: a travelling k1 (-> k as EI -> 0) and a decaying p1 (-> p).
//
// Units: SI throughout (kg/m, m, N, N m^2, Pa, Hz).

#include <string>
#include <string_view>

namespace stockbridge::span {

/// What a conductor's wires are made of (MODEL.md sections 11 and 15): galvanised
/// steel (a stainless tube counts as steel), aluminium, aluminium alloy, or
/// aluminium-clad steel (20SA and the other grades of IEC 61232). Each wire carries its
/// own modulus; the material decides how a span is judged: the CIGRE Safe Border Line
/// is stated for outer wires of aluminium or aluminium alloy only.
enum class WireMaterial { steel, aluminium, aluminium_alloy, aluminium_clad_steel };

/// "steel", "aluminium", "aluminium-alloy", "aluminium-clad-steel".
std::string_view wire_material_name(WireMaterial material);
/// The material of a name as wire_material_name writes it ("aluminum", "aluminum-alloy"
/// and "aluminum-clad-steel" also accepted); throws InvalidParameter naming `field` otherwise.
WireMaterial parse_wire_material(std::string_view name, std::string_view field = "material");
/// Aluminium or aluminium alloy: the wires the Safe Border Line is stated for.
bool is_aluminium(WireMaterial material);

/// What a span file's [conductor] table says; validate() checks it once.
struct Conductor {
  std::string name;                     ///< for reports only (e.g. "ASTER570")
  double mass_per_length = 0.0;         ///< m, kg/m
  double diameter = 0.0;                ///< D, outer diameter, m
  double rated_tensile_strength = 0.0;  ///< RTS, N
  double ei_min = 0.0;                  ///< bending stiffness of the free wires, N m^2
  double ei_max = 0.0;                  ///< no-slip bending stiffness, N m^2; 0: not given (only Foti's self-damping needs it)
  double outer_wire_diameter = 0.0;     ///< d_a, diameter of an outer-layer wire, m
  double outer_wire_modulus = 0.0;      ///< E_a, Young's modulus of the outer wires, Pa
  int aluminium_layers = 1;             ///< picks the Safe Border Line: 1, or several (2..10); 0 without aluminium layers
  /// The outer wires' material: the Safe Border Line judges a span only where it is
  /// aluminium or aluminium alloy (Span refuses it otherwise).
  WireMaterial outer_wire_material = WireMaterial::aluminium;
  /// Where the values come from, for reports: "the catalogue's ACSR Drake", "the
  /// conductor file drake.toml", "the [conductor] keys", with the keys given beside
  /// ("; diameter given"); and the stranding where it is known ("26/7: ...").
  std::string source;
  std::string stranding;

  /// Throws InvalidParameter naming the field as a span file spells it
  /// ("mass_per_length = -1: expected a finite value > 0 (kg/m)"): every magnitude
  /// plausible (core/error.hpp), ei_max 0 or >= ei_min, outer_wire_diameter < diameter,
  /// aluminium_layers from 1 to 10 (from 0 where the outer wires are not aluminium).
  void validate() const;
  /// Whether the outer wires are aluminium or aluminium alloy, which the CIGRE Safe
  /// Border Line is stated for.
  bool safe_border_line_applies() const { return is_aluminium(outer_wire_material); }
};

/// Throws InvalidParameter naming `field` unless 0 < tension < RTS (a conductor
/// stretched to its rated strength breaks).
void check_tension(const Conductor& conductor, double tension, const std::string& field = "tension");

/// T = fraction RTS; throws InvalidParameter naming `field` unless 0 < fraction < 1
/// (a fraction from 1 to 100 is named as the percentage it likely is).
double tension_from_fraction(const Conductor& conductor, double fraction,
                             const std::string& field = "tension_fraction");

/// g, m/s^2: the standard gravity of the catenary parameter.
inline constexpr double standard_gravity = 9.80665;

/// T = (H/w) m g from the catenary parameter H/w (m), the horizontal tension per
/// weight per length; the difference between the horizontal tension and the
/// tension along the conductor is negligible for aeolian vibration (MODEL.md
/// section 11). Throws InvalidParameter naming `field` unless H/w is plausible (> 0)
/// and the tension below the rated tensile strength.
double tension_from_catenary_parameter(const Conductor& conductor, double catenary_parameter,
                                       const std::string& field = "catenary_parameter");

/// H/w = T / (m g), m.
double catenary_parameter(const Conductor& conductor, double tension);

/// c = sqrt(T / m), m/s.
double wave_speed(const Conductor& conductor, double tension);
/// k = 2 pi f / c, rad/m.
double wavenumber(const Conductor& conductor, double tension, double frequency);
/// lambda = c / f, m.
double wavelength(const Conductor& conductor, double tension, double frequency);
/// Z0 = sqrt(T m), N s/m: the force per velocity of a travelling wave.
double wave_impedance(const Conductor& conductor, double tension);
/// p = sqrt(T / EI_min), 1/m: the inverse length over which a clamp bends the conductor.
double bending_decay(const Conductor& conductor, double tension);

/// Lilien's default factor of the self-damping power law, k = D[mm] / sqrt(m[kg/m] RTS[kN])
/// (ASTER570: 31.05 / sqrt(1.571 * 185.3) = 1.82).
double lilien_k(const Conductor& conductor);

/// The two wavenumbers of the tensioned beam at w = 2 pi f:
///     k1^2 = (sqrt(T^2 + 4 EI m w^2) - T) / (2 EI),  p1^2 = (sqrt(T^2 + 4 EI m w^2) + T) / (2 EI),
/// so that sin(k1 x), cos(k1 x), exp(-p1 x) solve EI y'''' - T y'' - m w^2 y = 0 (EI = EI_min).
struct BeamWavenumbers {
  double travelling = 0.0;  ///< k1, rad/m
  double decaying = 0.0;    ///< p1, 1/m
};
BeamWavenumbers beam_wavenumbers(const Conductor& conductor, double tension, double frequency);

}  // namespace stockbridge::span
