#pragma once
// Bounds on the bending stiffness of a helically stranded wire (MODEL.md
// section 7, dissertation appendix A.1, (A.1)-(A.5)).
//
// A strand is a straight core wire of radius r_c and layers j = 1..L of N_j wires
// of radius r_j laid on the pitch radius R_j with lay length lambda_j (the axial
// length of one full turn of a wire). The lay angle alpha_j between a wire and
// the strand axis is
//     tan alpha_j = 2 pi R_j / lambda_j
// (the dissertation's (A.3) prints alpha_j = 2 pi R_j / lambda_j; MODEL.md uses the
// geometric tangent, which is what the helix gives).
//
// Two limiting cases bracket the bending stiffness of a real strand:
//   * no friction between the wires, every wire bends about its own axis (A.4):
//         EI_min = E (pi r_c^4 / 4 + sum_j N_j pi r_j^4 / 4)
//   * no slip, the strand bends as one beam (Lanteigne 1985, (A.1) without the
//     finite-length term B_ij, which vanishes over whole lay lengths):
//         EI_max = E (pi r_c^4 / 4 + sum_j N_j / 2 pi r_j^2 (r_j^2 / 2 + R_j^2) cos^3 alpha_j)
//
// Strands of several materials (ACSR: a steel core and steel layers under
// aluminium layers; MODEL.md section 11): both bounds hold wire by wire with each
// wire's own modulus, E_c for the core's terms and E_j for layer j's:
//         EI_min = E_c pi r_c^4 / 4 + sum_j E_j N_j pi r_j^4 / 4
// and EI_max likewise. A layer or the core without a modulus of its own takes the
// strand's youngs_modulus.
//
// EI_max > EI_min whenever cos^3 alpha_j > r_j^2 / (r_j^2 + 2 R_j^2) in every layer,
// which holds for any real strand (R_j >= r_j gives alpha_j < 46 deg; lay angles
// are typically 5-20 deg). validate() makes it hold: the geometry must be possible,
// each layer outside the one below with room for its wires (check_layer_position)
// and a lay angle below 45 degrees (check_lay_angle).
//
// Units: SI throughout (m, Pa, N m^2).

#include <optional>
#include <string_view>
#include <vector>

namespace stockbridge::strand {

/// One helical layer of identical wires.
struct StrandLayer {
  int count = 0;              ///< N_j, number of wires in the layer, 1..1000
  double wire_radius = 0.0;   ///< r_j, radius of each wire, m, > 0
  double pitch_radius = 0.0;  ///< R_j, distance of the wire axes from the strand axis, m, > 0
  double lay_length = 0.0;    ///< lambda_j, axial length of one turn of a wire, m, > 0, finite
  std::optional<double> youngs_modulus = std::nullopt;  ///< E_j, Pa, > 0; none: the strand's youngs_modulus
};

/// Constant description of a strand: a core wire and any number of layers (possibly none).
struct Strand {
  double core_radius = 0.0;         ///< r_c, radius of the core wire, m, > 0
  double youngs_modulus = 210e9;    ///< E, Pa, > 0 (default: steel); every wire's unless it has its own
  std::vector<StrandLayer> layers;  ///< layers from the inside out
  std::optional<double> core_youngs_modulus = std::nullopt;  ///< E_c, Pa, > 0; none: youngs_modulus
};

/// The modulus of the core wire, E_c (its own, or the strand's), Pa.
double core_modulus(const Strand& strand);
/// The modulus of a layer's wires, E_j (its own, or the strand's), Pa.
double layer_modulus(const Strand& strand, const StrandLayer& layer);
/// Whether every wire has the same modulus (one material, as far as bending goes).
bool single_modulus(const Strand& strand);

/// The two limiting bending stiffnesses of a strand.
struct StrandBounds {
  double ei_min = 0.0;  ///< no friction between the wires (A.4), N m^2
  double ei_max = 0.0;  ///< no slip between the wires (A.1) without B_ij, N m^2
};

/// Lay angle alpha of a layer, rad, from tan alpha = 2 pi R / lambda (in [0, pi/2)).
double lay_angle(const StrandLayer& layer);

/// Throws InvalidParameter naming `<name>.pitch_radius` unless the layer's wires lie
/// outside the radius `inner_radius` (the core's, or the layer below's R + r):
/// R >= inner_radius + r, and fit side by side around the strand axis:
/// N asin(r / R) <= pi (both up to 2 %, for data rounded by hand; the classic 1 + 6
/// strand of equal wires meets both exactly).
void check_layer_position(const StrandLayer& layer, double inner_radius, std::string_view name);

/// Throws InvalidParameter naming `<name>.lay_length` unless the lay angle is below
/// 45 degrees, lambda > 2 pi R (real strands: 10 to 20 degrees). Steeper layers are
/// not helical wires in bending, and would give ei_max < ei_min.
void check_lay_angle(const StrandLayer& layer, std::string_view name);

/// Throws InvalidParameter naming the field, e.g.
/// "layer[1].lay_length = -0.05: expected a finite value > 0 (m)".
/// Every length and E (the strand's, the core's and each layer's own, where given) must
/// be finite and > 0; counts run from 1 to 1000; each layer's
/// geometry passes check_layer_position and check_lay_angle.
/// (Straight wires, lambda -> inf, are approximated by any very long lay length.)
void validate(const Strand& strand);

/// EI_min and EI_max of `strand` (validated first; throws InvalidParameter, or
/// NumericalError if absurd sizes take them outside a double's range, overflowing or
/// underflowing).
StrandBounds strand_bounds(const Strand& strand);

}  // namespace stockbridge::strand
