#pragma once
// The Stockbridge damper (MODEL.md section 4, dissertation 4.2.1): a clamp of
// mass m_c that only translates, x_c(t), and arms k = 1..K, each a cable
// (section 3) carrying a rigid mass m_k with moment of inertia Theta_k about its
// centre of gravity G_k, which lies at the signed distance b_k from the cable tip
// toward the clamp. Per arm, with u = (x, phi) the tip deflection and rotation
// relative to the clamp and (F, Q) the cable's tip force and tip moment:
//
//     [ m    -m b       ] u'' + [F ; Q] = [-m ; m b] x_c''
//     [-m b   Theta+m b^2]
//
// and the shaker force is F_c = m_c x_c'' + sum_k m_k y_G,k'' = m_c x_c'' - sum_k F_k.
// Arms are independent once x_c(t) is prescribed.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/cable/cable.hpp"
#include "stockbridge/core/typical_ranges.hpp"

namespace stockbridge::damper {

struct ArmDescription {
  std::string name;
  double mass = 0.0;     ///< m, kg, > 0
  double inertia = 0.0;  ///< Theta about the centre of gravity, kg m^2, > 0
  double offset = 0.0;   ///< b, m: cable tip to centre of gravity, toward the clamp
  cable::CableDescription cable;

  /// Same mechanics (everything but the name): such arms move alike.
  bool same_mechanics(const ArmDescription& other) const;
};

struct DamperDescription {
  double clamp_mass = 0.0;  ///< m_c, kg, >= 0
  std::vector<ArmDescription> arms;

  /// The values outside the typical ranges of Stockbridge dampers
  /// (core/typical_ranges.hpp), named as a damper file spells them ("arm[1].mass",
  /// "arm[0].cable.ei"); a clamp mass of 0 (left out on purpose) is not one.
  std::vector<UnusualValue> unusual_values() const;
  /// Same mechanics (the clamp mass and every arm's, in order; names aside): such
  /// dampers have the same impedance.
  bool same_mechanics(const DamperDescription& other) const;
};

/// One arm: its constant model (mass matrix, load vector, discretised cable),
/// valid by construction.
class Arm {
 public:
  /// Throws InvalidParameter naming the field as the description spells it
  /// ("mass", "cable.jenkin[0].h").
  explicit Arm(ArmDescription description);

  const ArmDescription& description() const { return description_; }
  const cable::Cable& cable() const { return cable_; }
  /// [[m, -m b], [-m b, Theta + m b^2]], kg and kg m and kg m^2.
  const Eigen::Matrix2d& mass_matrix() const { return mass_matrix_; }
  /// [-m, m b]: the generalised load per unit clamp acceleration.
  const Eigen::Vector2d& load_vector() const { return load_vector_; }
  /// Linear natural frequencies (Hz) with every section at stiffness `ei` (uniform
  /// cables: the all-stick ei + sum c, or the all-slip ei), ascending.
  Eigen::Vector2d natural_frequencies(double uniform_ei) const;
  /// The arm's tip stiffness d(F, Q)/d(x, phi) with every section sticking.
  Eigen::Matrix2d stick_stiffness() const;

 private:
  ArmDescription description_;
  cable::Cable cable_;
  Eigen::Matrix2d mass_matrix_;
  Eigen::Vector2d load_vector_;
};

/// The damper: the clamp and its arms, valid by construction, with the arms that
/// move alike grouped (identical arms are solved once).
class Damper {
 public:
  /// Throws InvalidParameter naming the field as a damper file spells it
  /// ("clamp.mass", "arm[1].cable.jenkin[0].h").
  explicit Damper(DamperDescription description);

  const DamperDescription& description() const { return description_; }
  double clamp_mass() const { return description_.clamp_mass; }
  /// The clamp's and every arm's mass, kg.
  double total_mass() const;
  const std::vector<Arm>& arms() const { return arms_; }
  /// The arm's name from the description, or "arm <k+1>" where it has none.
  std::string arm_name(std::size_t k) const;
  /// How messages name the arm: "arm long", or "arm 2" where it has no name.
  std::string arm_label(std::size_t k) const;
  /// For each arm, the index of the first arm with the same mechanics.
  const std::vector<std::size_t>& representative() const { return representative_; }
  /// The arms that represent themselves (solved; the others copy them).
  const std::vector<std::size_t>& distinct() const { return distinct_; }

 private:
  DamperDescription description_;
  std::vector<Arm> arms_;
  std::vector<std::size_t> representative_;
  std::vector<std::size_t> distinct_;
};

/// Harmonic clamp motion x_c = X sin(W t), velocity V cos(W t), V = W X.
struct Excitation {
  double frequency_hz = 0.0;            ///< f = W / (2 pi), > 0
  double displacement_amplitude = 0.0;  ///< X, m, > 0

  static Excitation from_velocity(double frequency_hz, double velocity_amplitude);
  double angular_frequency() const;  ///< W, rad/s
  double velocity_amplitude() const;  ///< V = W X, m/s
  double period() const;             ///< T = 1/f, s
  void validate() const;
};

}  // namespace stockbridge::damper
