#pragma once
// A conductor as a standard or a data sheet gives it (MODEL.md sections 7, 9, 11):
// its mass per length, diameter and rated tensile strength, and its stranding, a
// core wire and layers of round wires, each of one material with its own modulus.
// From the stranding come the quantities a span needs (span::Conductor): EI_min
// and EI_max (the strand's bounds, wire by wire with each wire's modulus), the
// outer wires' diameter, modulus and material, and the number of aluminium layers.
// The materials (WireMaterial, span/conductor.hpp): steel, aluminium, aluminium
// alloy and aluminium-clad steel; earth wires and OPGW are strands of these too
// (MODEL.md section 15), some without an aluminium layer.
//
// The layers touch: the core wire of diameter d_c on the axis, layer j's wires of
// diameter d_j on the pitch radius
//     R_1 = d_c / 2 + d_1 / 2,   R_j = R_{j-1} + d_{j-1} / 2 + d_j / 2,
// and layer j's outer diameter is D_j = 2 R_j + d_j. Its lay length is given, or
// its lay ratio k_j, the standards' lay length over the layer's outer diameter
// (EN 50182, ASTM B232): lambda_j = k_j D_j.
//
// Units: SI throughout (kg/m, m, N, Pa, N m^2).

#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/span/conductor.hpp"
#include "stockbridge/strand/strand_bounds.hpp"

namespace stockbridge::span {

/// The core wire, or one layer of identical wires.
struct ConductorLayer {
  WireMaterial material = WireMaterial::aluminium;
  double youngs_modulus = 0.0;  ///< E, Pa
  int count = 1;                ///< wires in the layer (the core: 1)
  double wire_diameter = 0.0;   ///< d, m
  double lay_length = 0.0;      ///< lambda, m; 0 where lay_ratio is given (and for the core)
  double lay_ratio = 0.0;       ///< lambda / the layer's outer diameter; 0 where lay_length is given
};

/// A conductor by its data sheet and its stranding.
struct StrandedConductor {
  std::string type;                     ///< e.g. "ACSR Drake": the name span files select it by
  std::string source;                   ///< where the values come from (free text, for reports)
  double mass_per_length = 0.0;         ///< m, kg/m
  double diameter = 0.0;                ///< D, m (within 2 % of the stranding's outer diameter)
  double rated_tensile_strength = 0.0;  ///< RTS, N
  ConductorLayer core;                  ///< the core wire (count 1, no lay)
  std::vector<ConductorLayer> layers;   ///< from the inside out, at least one

  /// Throws InvalidParameter naming the field as a conductor file spells it
  /// ("layer[1].wire_diameter = -1: expected a finite value > 0 (m)"): the
  /// magnitudes plausible (core/error.hpp), counts 1 to 1000, exactly one of
  /// lay_length and lay_ratio per layer with a lay angle below 45 degrees, room for
  /// each layer's wires side by side (2 % slack for rounded data), the diameter
  /// within 2 % of the stranding's, and at most 10 aluminium or aluminium-alloy layers
  /// (none: a steel or aluminium-clad steel earth wire).
  void validate() const;
};

/// The layers' pitch radii R_j, m (the layers touching, see the top of this file).
std::vector<double> pitch_radii(const StrandedConductor& conductor);
/// The stranding's outer diameter, 2 R_L + d_L (the core's diameter without layers), m.
double stranding_diameter(const StrandedConductor& conductor);
/// Layer j's lay length, m: its own, or its lay ratio times its outer diameter.
double lay_length(const StrandedConductor& conductor, std::size_t layer);

/// The strand of the conductor's wires for strand::strand_bounds (validated first).
strand::Strand strand_of(const StrandedConductor& conductor);
/// The conductor a span file's [conductor] table describes (validated first):
/// name = type, the data sheet's m, D and RTS, ei_min and ei_max from strand_of,
/// the outer layer's wire diameter, modulus and material, and the number of layers
/// (the core not counted) of aluminium or aluminium alloy.
Conductor conductor_of(const StrandedConductor& conductor);

/// The stranding in words: "26/7: steel 1+6 x 3.45 mm, aluminium 10+16 x 4.44 mm"
/// (aluminium wires / steel wires, or the wire count of a conductor of one material;
/// then each run of wires of one material and diameter, from the core out).
std::string stranding_label(const StrandedConductor& conductor);

}  // namespace stockbridge::span
