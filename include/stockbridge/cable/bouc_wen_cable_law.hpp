#pragma once
// The Bouc-Wen law of the cable (RTE's slenderpy, MODEL.md section 13): at each
// section M = EI_min chi + (EI_max - EI_min) chi0 eta with chi0 d eta = d chi -
// |d chi| eta. Its internal variable is eta, one a section. A monotone step is
// exact in closed form in the curvature (section::bouc_wen_update); driven by its
// moment it solves EI_min u + (EI_max - EI_min) a (1 - e^-u) = s dM / chi0 for the
// curvature travelled u = |d chi| / chi0 (a = 1 - s eta_from, s the step's sign):
// the left side is increasing and concave. The rest of the way from any u solves an
// equation of the same kind: where it is short (|r| <= 0.03, r = -g / g') the inverse
// series to fifth order covers it without an exponential, to round-off once r is
// within 1e-3; farther off Halley's step and one exponential. The solve starts from
// the last evaluation's travel where that is close, else from u = 0 for a short step,
// else from the quadratic Taylor model's root (on slenderpy's damper 1.54 steps and
// 0.39 exponentials a group of four sections).
// The sections are solved four at a time on vector lanes (src/cable/exp_minus_one.hpp).

#include <span>
#include <vector>

#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/cable/cable_law.hpp"

namespace stockbridge::cable {

/// Which build of the section loops a Bouc-Wen law runs. The two agree to round-off
/// (the AVX2 build fuses multiplies and adds).
enum class BoucWenKernels {
  best,      ///< AVX2 with FMA where the processor has both, else the x86-64 baseline's
  baseline,  ///< the x86-64 baseline's on any processor (a test holds the builds to each other)
};

class BoucWenCableLaw final : public CableLaw {
 public:
  BoucWenCableLaw(const CableDescription& description, std::span<const double> positions,
                  BoucWenKernels kernels = BoucWenKernels::best);

  double ei_min(std::size_t i) const { return ei_min_[i]; }
  double ei_max(std::size_t i) const { return ei_min_[i] + hysteretic_[i]; }
  double chi0(std::size_t i) const { return chi0_[i]; }
  /// Whether the section loops run their AVX2-with-FMA build: with BoucWenKernels::best
  /// where the processor has both; else the x86-64 baseline's.
  bool uses_avx2() const { return avx2_; }
  /// The sections' numbers in order (padded beyond the cable's sections).
  const double* ei_min_data() const { return ei_min_.data(); }
  const double* hysteretic_data() const { return hysteretic_.data(); }
  const double* chi0_data() const { return chi0_.data(); }

  std::size_t internal_variables() const override { return 1; }
  double stick_stiffness(std::size_t section) const override { return ei_max(section); }
  double slip_stiffness(std::size_t section) const override { return ei_min_[section]; }
  bool has_flexibility_change() const override { return true; }
  void apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force, CableState& to,
                   CableWorkspace& workspace) const override;
  double internal_change(const CableState& start, const CableState& end) const override;
  std::size_t periodic_coordinates(const Cable& cable) const override;
  void coordinates(const CableState& state, Eigen::VectorXd& z) const override;
  /// Each eta kept within [-1, 1].
  bool shift(const Cable& cable, CableState& state, const Eigen::VectorXd& dz) const override;
  std::unique_ptr<LoadSensitivity> load_sensitivity(const Cable& cable) const override;

 private:
  // One a section, padded to whole groups of four (apply_loads solves four at a time).
  std::vector<double> ei_min_;
  std::vector<double> hysteretic_;  // EI_max - EI_min, N m^2
  std::vector<double> chi0_;
  std::vector<double> inverse_chi0_;
  bool avx2_ = false;
};

/// The curvature travelled, over chi0, by a monotone step that raises a Bouc-Wen
/// section's moment by `excess` (any sign) from `eta_from`: u >= 0 with
/// ei_min u + hysteretic a (1 - e^-u) = |excess| / chi0, a = 1 - sign(excess) eta_from;
/// and e^-u - 1, which the step's eta, tangent and dissipation take. `start`: a
/// travel the solve may start from (as the cable's solves start from the last
/// evaluation's), used where g there is within 1e-3 of the target; the result does
/// not depend on it beyond round-off.
struct BoucWenTravel {
  double u = 0.0;
  double decay_minus_one = 0.0;
};
BoucWenTravel bouc_wen_travel(double ei_min, double hysteretic, double chi0, double eta_from, double excess,
                              const BoucWenTravel& start = {});

}  // namespace stockbridge::cable
