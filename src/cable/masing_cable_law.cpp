#include "stockbridge/cable/masing_cable_law.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

#include <Eigen/LU>

#include "cable_sums.hpp"
#include "stockbridge/cable/cable.hpp"
#include "stockbridge/cable/cantilever.hpp"

namespace stockbridge::cable {

MasingCableLaw::MasingCableLaw(const CableDescription& description, std::span<const double> positions,
                               std::span<const double> weights) {
  const std::size_t n = positions.size();
  const std::size_t m = description.jenkin.size();
  ei_.resize(n);
  jenkin_.resize(n * m);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = description.profile_position(positions[i]);
    ei_[i] = description.ei.at(s);
    for (std::size_t j = 0; j < m; ++j) {
      jenkin_[i * m + j] = {description.jenkin[j].c.at(s), description.jenkin[j].h.at(s)};
    }
  }
  for (const JenkinProfile& e : description.jenkin) k0_.push_back(e.k0);
  lever_arm_limit_ = description.lever_arm_limit();
  modified_masing_ = description.uses_modified_masing();
  if (m == 1 && !modified_masing_) fill_one_element_columns(description.length, positions, weights);
}

void MasingCableLaw::fill_one_element_columns(double length, std::span<const double> positions,
                                              std::span<const double> weights) {
  OneElementColumns& columns = one_element_columns_;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const section::Jenkin& e = jenkin_[i];
    const double s = positions[i];
    const double w = weights[i];
    columns.c.push_back(e.c);
    columns.h.push_back(e.h);
    columns.ei.push_back(ei_[i]);
    columns.stick_stiffness.push_back(ei_[i] + e.c);
    columns.slip_compliance.push_back(1.0 / ei_[i]);
    columns.stick_compliance.push_back(1.0 / (ei_[i] + e.c));
    columns.position.push_back(s);
    columns.weight.push_back(w);
    columns.weight_position.push_back(w * s);
    columns.weight_arm.push_back(w * (length - s));
    columns.weight_arm_position.push_back(w * (length - s) * s);
  }
}

double MasingCableLaw::stick_stiffness(std::size_t section) const {
  double k = ei_[section];
  for (const section::Jenkin& e : jenkin(section)) k += e.c;
  return k;
}

double MasingCableLaw::internal_change(const CableState& start, const CableState& end) const {
  const std::size_t m = elements();
  double change = 0.0;
  for (std::size_t i = 0; i < ei_.size(); ++i) {
    const auto elements_here = jenkin(i);
    for (std::size_t e = 0; e < m; ++e) {
      change = std::max(change, std::abs(end.hysteretic[i * m + e] - start.hysteretic[i * m + e]) / elements_here[e].h);
    }
  }
  return change;
}

namespace {

// Branchless selection for the vectorised loop below: a comparison becomes an all-ones
// or all-zero mask and picks the bits of one of two values (exactly that value). With
// `?:` the compiler moves the loads and sums a choice needs into branches, and a loop
// with branches does not run on vectors.
inline std::uint64_t lane_mask(bool condition) { return -static_cast<std::uint64_t>(condition); }
inline double lane_pick(std::uint64_t mask, double if_set, double otherwise) {
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(if_set) & mask) |
                               (std::bit_cast<std::uint64_t>(otherwise) & ~mask));
}

// x86-64 builds carry an AVX2 copy of the loop chosen at load time where the processor
// has it (4 sections a step); the baseline copy serves every other x86-64 processor.
// Not under ThreadSanitizer: the loader runs the copy's resolver before the sanitizer's
// runtime is up, and the program dies before main.
#if defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define STOCKBRIDGE_THREAD_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_THREAD__)
#define STOCKBRIDGE_THREAD_SANITIZER 1
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(STOCKBRIDGE_THREAD_SANITIZER)
#define STOCKBRIDGE_SECTION_LOOP_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define STOCKBRIDGE_SECTION_LOOP_CLONES
#endif

/// apply_loads for cables of one element per section and constant slip moments: each
/// section in closed form (the elastic trial sticks if it stays inside the slip limit,
/// the classification of section::jenkin_slips, else the element slips at +-h and only
/// ei resists), without branches, so that the loop over the sections runs on vectors;
/// the sums of CableSums with the weights multiplied out in the columns.
STOCKBRIDGE_SECTION_LOOP_CLONES
void apply_loads_one_element(const OneElementColumns& col, const CableState& from, double clamp_moment,
                             double tip_force, CableState& to) {
  const std::size_t n = col.position.size();
  const double d_clamp_moment = clamp_moment - from.clamp_moment;
  const double d_tip_force = tip_force - from.tip_force;
  // Raw pointers: the vectoriser must not reload a vector's data from `col` after a store.
  const double *c = col.c.data(), *h = col.h.data(), *ei = col.ei.data(), *stick_stiffness = col.stick_stiffness.data();
  const double *slip_compliance = col.slip_compliance.data(), *stick_compliance = col.stick_compliance.data();
  const double *s = col.position.data(), *w = col.weight.data(), *w_s = col.weight_position.data();
  const double *w_arm = col.weight_arm.data(), *w_arm_s = col.weight_arm_position.data();
  const double* kappa_from = from.curvature.data();
  const double* h_from = from.hysteretic.data();
  double* kappa_to = to.curvature.data();
  double* h_to = to.hysteretic.data();
  double* tangent_to = to.tangent.data();
  double rotation = 0.0, deflection = 0.0, dissipated = 0.0;
  double f00 = 0.0, f01 = 0.0, f10 = 0.0, f11 = 0.0;  // flexibility, f01 and f11 negated
#pragma omp simd reduction(+ : rotation, deflection, dissipated, f00, f01, f10, f11)
  for (std::size_t i = 0; i < n; ++i) {
    const double excess = d_clamp_moment - d_tip_force * s[i];
    const double dk_stick = excess * stick_compliance[i];
    const double elastic = h_from[i] + c[i] * dk_stick;
    const std::uint64_t slips = (lane_mask(dk_stick > 0.0) & lane_mask(elastic >= h[i])) |
                                (lane_mask(dk_stick < 0.0) & lane_mask(elastic <= -h[i]));
    const double bound = std::copysign(h[i], dk_stick);  // +-h, the slip moment reached
    const double dk_slip = (excess - (bound - h_from[i])) * slip_compliance[i];
    const double slip_dissipation = bound * (h_from[i] + c[i] * dk_slip - bound) / c[i];
    const double kappa = kappa_from[i] + lane_pick(slips, dk_slip, dk_stick);
    const double compliance = lane_pick(slips, slip_compliance[i], stick_compliance[i]);
    kappa_to[i] = kappa;
    h_to[i] = lane_pick(slips, bound, elastic);
    tangent_to[i] = lane_pick(slips, ei[i], stick_stiffness[i]);
    rotation += w[i] * kappa;
    deflection += w_arm[i] * kappa;
    dissipated += w[i] * lane_pick(slips, slip_dissipation, 0.0);
    f00 += w[i] * compliance;
    f01 += w_s[i] * compliance;
    f10 += w_arm[i] * compliance;
    f11 += w_arm_s[i] * compliance;
  }
  to.clamp_moment = clamp_moment;
  to.tip_force = tip_force;
  to.rotation = rotation;
  to.deflection = deflection;
  to.flexibility << f00, -f01, f10, -f11;
  to.flexibility_change.setZero();  // piecewise linear: no second order
  to.dissipated = from.dissipated + dissipated;
}

}  // namespace

void MasingCableLaw::apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force,
                                 CableState& to, CableWorkspace& workspace) const {
  if (!one_element_columns_.ei.empty()) {
    apply_loads_one_element(one_element_columns_, from, clamp_moment, tip_force, to);
    return;
  }
  const std::size_t n = cable.sections();
  const std::size_t m = elements();
  const double l = cable.length();
  const auto s = cable.positions();
  const auto w = cable.weights();
  if (modified_masing_ && workspace.jenkin.size() < m) {
    workspace.jenkin.resize(m);
    workspace.hysteretic.resize(m);
  }
  const double lever_cap = lever_arm_limit_;
  const double d_clamp_moment = clamp_moment - from.clamp_moment;
  const double d_tip_force = tip_force - from.tip_force;
  CableSums sums;
  for (std::size_t i = 0; i < n; ++i) {
    // Every state came from loads (T, F), so the committed moment is T - F s exactly.
    double excess = d_clamp_moment - d_tip_force * s[i];
    std::span<const section::Jenkin> jenkin = this->jenkin(i);
    std::span<const double> h_from = std::span<const double>(from.hysteretic).subspan(i * m, m);
    if (modified_masing_) {
      const double moment = clamp_moment - tip_force * s[i];
      const double lever = tip_force != 0.0 ? std::min(std::abs(moment / tip_force), lever_cap) : lever_cap;
      for (std::size_t j = 0; j < m; ++j) {
        const double h = jenkin[j].h + k0_[j] * lever;
        workspace.jenkin[j] = {jenkin[j].c, h};
        workspace.hysteretic[j] = std::clamp(h_from[j], -h, h);
      }
      jenkin = std::span<const section::Jenkin>(workspace.jenkin).first(m);
      h_from = std::span<const double>(workspace.hysteretic).first(m);
      for (std::size_t j = 0; j < m; ++j) excess -= h_from[j] - from.hysteretic[i * m + j];  // moments set back
    }
    double dk = 0.0;
    section::solve_curvature_increment(ei_[i], jenkin, h_from, excess, dk);  // ei > 0: always solvable
    const section::JenkinStep step =
        section::jenkin_step(jenkin, h_from, dk, std::span<double>(to.hysteretic).subspan(i * m, m));
    const double kappa = from.curvature[i] + dk;
    const double tangent = ei_[i] + step.stick_stiffness;
    to.curvature[i] = kappa;
    to.tangent[i] = tangent;
    sums.add(w[i], s[i], l, kappa, 1.0 / tangent, step.dissipated);
  }
  sums.store(clamp_moment, tip_force, from, to);
}

namespace {

// On the current piece of the piecewise-linear cable map (sticking sets fixed),
// per section i with tangent k_i = ei + sum_{sticking e} c_e, the moment-driven
// update gives kappa_new = a_i + M_i / k_i with M_i = T - F s_i, and the tip
// kinematics u = sum_i w_i [1; l - s_i] kappa_new,i close it.
//
// Sensitivities are kept through "anchors": while element e sticks, its moment is
// H = H_anchor + c_e (kappa - kappa_anchor), where the anchor is the end of its last
// slip (where H = +-h does not depend on the path) or the start of the path (whose
// state is held fixed). Hence dH_e = c_e (d kappa - A_e) with A_e = d kappa at the
// anchor, and the derivative of a_i reduces to
//     da_i = sum_{sticking e} (c_e / k_i) A_e,
// so that d(T, F) = J^-1 (du - sum_i w_i [1; l - s_i] da_i), J the flexibility.
// When e slips, A_e becomes the new d kappa = da_i + dM_i / k_i. A section whose
// elements all slip contributes nothing; its anchors are set lazily, from the
// step's (dT, dF), only when an element sticks again.
class MasingLoadSensitivity final : public LoadSensitivity {
 public:
  /// `law` outlives this (cables share their law; the one of the cable driven holds it).
  MasingLoadSensitivity(const Cable& cable, const MasingCableLaw& law)
      : positions_(cable.positions().begin(), cable.positions().end()),
        weights_(cable.weights().begin(), cable.weights().end()),
        length_(cable.length()),
        law_(law) {}

  void start(Eigen::Index parameters) override;
  void begin_pass() override { resum_sticking(); }  // no round-off carried from pass to pass
  void step(const CableState& from, const CableState& to, Eigen::VectorXd& d_rotation, Eigen::VectorXd& d_deflection,
            Eigen::VectorXd& d_clamp_moment, Eigen::VectorXd& d_tip_force) override;
  void mirror() override;

 private:
  /// The sticking sets of the step `from` -> `to`, sections recounted where they changed.
  void update_sticking(const CableState& from, const CableState& to);
  void update_one_element_sticking(const CableState& to);
  /// Section i's sticking elements' part of the sensitivities' right-hand side, anew.
  void recount_section(std::size_t i, double k);
  /// The right-hand side's sticking part summed anew over the sections.
  void resum_sticking();

  std::vector<double> positions_, weights_;
  double length_;
  const MasingCableLaw& law_;
  // The anchor d kappa / dq of every element (column i*m + e), and the elements whose
  // anchor is still to be set from the previous step's load derivatives.
  Eigen::MatrixXd anchor_;
  std::vector<unsigned char> sticking_, partial_, pending_;
  std::vector<double> pending_compliance_;
  // Per section, da_i of its sticking elements (column i), the elements counted in
  // it (kNotCounted: none yet), and the sums over the sections (recount_section).
  static constexpr unsigned char kNotCounted = 2;
  Eigen::MatrixXd contribution_;
  std::vector<unsigned char> counted_sticking_;
  Eigen::VectorXd sticking_sum_phi_, sticking_sum_x_;
  Eigen::VectorXd a_, d_clamp_moment_, d_tip_force_, previous_d_clamp_moment_, previous_d_tip_force_;
};

void MasingLoadSensitivity::start(Eigen::Index parameters) {
  const std::size_t n_sections = positions_.size();
  const std::size_t m = law_.elements();
  anchor_.setZero(parameters, static_cast<Eigen::Index>(n_sections * m));
  pending_.assign(n_sections * m, 0);
  pending_compliance_.assign(n_sections, 0.0);
  contribution_.setZero(parameters, static_cast<Eigen::Index>(n_sections));
  counted_sticking_.assign(n_sections * m, kNotCounted);
  sticking_sum_phi_.setZero(parameters);
  sticking_sum_x_.setZero(parameters);
  previous_d_clamp_moment_.setZero(parameters);
  previous_d_tip_force_.setZero(parameters);
}

void MasingLoadSensitivity::mirror() {
  anchor_ = -anchor_;
  contribution_ = -contribution_;
  sticking_sum_phi_ = -sticking_sum_phi_;
  sticking_sum_x_ = -sticking_sum_x_;
  previous_d_clamp_moment_ = -previous_d_clamp_moment_;
  previous_d_tip_force_ = -previous_d_tip_force_;
}

// Which elements stick in the step `from` -> `to`; where a section's sticking set
// changed or an element sticks again after a step in which its whole section slipped
// (its anchor set from that step's load derivatives), the section is recounted.
void MasingLoadSensitivity::update_sticking(const CableState& from, const CableState& to) {
  const std::size_t n_sections = positions_.size();
  const std::size_t m = law_.elements();
  const std::vector<double>& s = positions_;
  sticking_.resize(n_sections * m);
  partial_.assign(n_sections, 0);
  for (std::size_t i = 0; i < n_sections; ++i) {
    const double dkappa = to.curvature[i] - from.curvature[i];
    const auto jenkin = law_.jenkin(i);
    bool any_stick = false, any_slip = false, changed = false;
    for (std::size_t e = 0; e < m; ++e) {
      const std::size_t ie = i * m + e;
      const bool sticks = !section::jenkin_slips(jenkin[e], from.hysteretic[ie], dkappa);
      sticking_[ie] = sticks;
      any_stick |= sticks;
      any_slip |= !sticks;
      changed |= counted_sticking_[ie] != static_cast<unsigned char>(sticks);
      if (sticks && pending_[ie]) {  // it slipped in the previous step, in a section where all slipped
        anchor_.col(static_cast<Eigen::Index>(ie)) =
            pending_compliance_[i] * (previous_d_clamp_moment_ - s[i] * previous_d_tip_force_);
        pending_[ie] = 0;
        changed = true;
      }
    }
    partial_[i] = any_stick && any_slip;
    if (changed) recount_section(i, to.tangent[i]);
  }
}

// update_sticking for one element per section with constant slip moments: the step's
// tangent says whether the element slipped (exactly ei then, apply_loads), no section is
// partial, and a slipping section's anchor waits for the step in which it sticks again.
void MasingLoadSensitivity::update_one_element_sticking(const CableState& to) {
  const std::size_t n_sections = positions_.size();
  const OneElementColumns& col = law_.one_element_columns();
  sticking_.resize(n_sections);
  for (std::size_t i = 0; i < n_sections; ++i) {
    const bool sticks = to.tangent[i] != col.ei[i];
    sticking_[i] = sticks;
    bool changed = counted_sticking_[i] != static_cast<unsigned char>(sticks);
    if (!sticks) {
      pending_[i] = 1;
      pending_compliance_[i] = col.slip_compliance[i];
    } else if (pending_[i]) {
      anchor_.col(static_cast<Eigen::Index>(i)) =
          col.slip_compliance[i] * (previous_d_clamp_moment_ - col.position[i] * previous_d_tip_force_);
      pending_[i] = 0;
      changed = true;
    }
    if (changed) recount_section(i, to.tangent[i]);
  }
}

void MasingLoadSensitivity::step(const CableState& from, const CableState& to, Eigen::VectorXd& d_rotation,
                                 Eigen::VectorXd& d_deflection, Eigen::VectorXd& d_clamp_moment,
                                 Eigen::VectorXd& d_tip_force) {
  const std::size_t n_sections = positions_.size();
  const std::size_t m = law_.elements();
  const std::vector<double>& s = positions_;
  const bool one_element = !law_.one_element_columns().ei.empty();
  if (one_element) {
    update_one_element_sticking(to);
  } else {
    update_sticking(from, to);
  }
  d_rotation -= sticking_sum_phi_;
  d_deflection -= sticking_sum_x_;
  const Eigen::Matrix2d inverse = to.flexibility.inverse();
  d_clamp_moment_ = inverse(0, 0) * d_rotation + inverse(0, 1) * d_deflection;
  d_tip_force_ = inverse(1, 0) * d_rotation + inverse(1, 1) * d_deflection;
  for (std::size_t i = 0; !one_element && i < n_sections; ++i) {  // one element: done in the sticking update
    const double k = to.tangent[i];
    if (partial_[i]) {
      // d kappa_new = da_i + dM_i / k_i becomes the anchor of every slipping element.
      a_ = (1.0 / k) * (d_clamp_moment_ - s[i] * d_tip_force_) + contribution_.col(static_cast<Eigen::Index>(i));
      for (std::size_t e = 0; e < m; ++e) {
        if (!sticking_[i * m + e]) anchor_.col(static_cast<Eigen::Index>(i * m + e)) = a_;
      }
    } else {
      bool all_slip = true;
      for (std::size_t e = 0; e < m; ++e) all_slip &= !sticking_[i * m + e];
      if (all_slip && m > 0) {
        for (std::size_t e = 0; e < m; ++e) pending_[i * m + e] = 1;
        pending_compliance_[i] = 1.0 / k;
      }
    }
  }
  std::swap(previous_d_clamp_moment_, d_clamp_moment_);
  std::swap(previous_d_tip_force_, d_tip_force_);
  d_clamp_moment = previous_d_clamp_moment_;
  d_tip_force = previous_d_tip_force_;
}

// The sticking elements' part of the right-hand side, sum_i w_i [1; l - s_i] da_i
// with da_i = sum_{sticking e} (c_e / k_i) A_e, changes only where a section's
// sticking set changes or a sticking element's anchor is set: it is kept as a sum
// and corrected section by section (O(changes) instead of O(sections) per step).
void MasingLoadSensitivity::recount_section(std::size_t i, double k) {
  const std::size_t m = law_.elements();
  const auto jenkin = law_.jenkin(i);
  const double w = weights_[i], arm = length_ - positions_[i];
  auto contribution = contribution_.col(static_cast<Eigen::Index>(i));
  a_ = -contribution;
  contribution.setZero();
  for (std::size_t e = 0; e < m; ++e) {
    counted_sticking_[i * m + e] = sticking_[i * m + e];
    if (sticking_[i * m + e]) contribution += (jenkin[e].c / k) * anchor_.col(static_cast<Eigen::Index>(i * m + e));
  }
  a_ += contribution;
  sticking_sum_phi_ += w * a_;
  sticking_sum_x_ += (w * arm) * a_;
}

void MasingLoadSensitivity::resum_sticking() {
  const std::size_t n = positions_.size();
  const double l = length_;
  sticking_sum_phi_.setZero(contribution_.rows());
  sticking_sum_x_.setZero(contribution_.rows());
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = contribution_.col(static_cast<Eigen::Index>(i));
    sticking_sum_phi_ += weights_[i] * c;
    sticking_sum_x_ += (weights_[i] * (l - positions_[i])) * c;
  }
}

}  // namespace

std::unique_ptr<LoadSensitivity> MasingCableLaw::load_sensitivity(const Cable& cable) const {
  return std::make_unique<MasingLoadSensitivity>(cable, *this);
}

}  // namespace stockbridge::cable

// The Masing law's descriptor (section_law_descriptor.hpp).

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/section/masing_section.hpp"
#include "stockbridge/section/regularised_section.hpp"

namespace stockbridge::cable {

namespace {

constexpr LawNumber kMasingNumbers[] = {
    {"ei", "N m^2", "Elastic (minimum) bending stiffness EI (Masing and Iwan laws)", typical::ei, 3, StartRole::stiffness,
     FitScale::logarithmic},
};

struct MasingLaw final : SectionLawDescriptor {
  std::string_view name() const override { return "masing"; }
  std::string_view title() const override { return "Masing"; }
  int order() const override { return 0; }
  std::span<const LawNumber> numbers() const override { return kMasingNumbers; }
  bool jenkin_elements() const override { return true; }

  void validate(const CableDescription& d) const override {
    SectionLawDescriptor::validate(d);
    for (std::size_t j = 0; j < d.jenkin.size(); ++j) {
      const std::string name = fmt::format("jenkin[{}]", j);
      d.jenkin[j].c.check_values(name + ".c", [](std::string_view n, double v) { require_plausible(n, v, "N m^2"); });
      d.jenkin[j].h.check_values(name + ".h", [](std::string_view n, double v) { require_plausible(n, v, "N m"); });
      require_plausible_or_zero(name + ".k0", d.jenkin[j].k0, "N");
    }
  }

  std::vector<const Profile*> profiles(const CableDescription& d) const override {
    std::vector<const Profile*> out{&d.ei};
    for (const JenkinProfile& e : d.jenkin) out.insert(out.end(), {&e.c, &e.h});
    return out;
  }

  std::string summary(const CableDescription& c, std::string (*number)(double)) const override {
    double stick = c.ei.at(0.0);
    for (const JenkinProfile& j : c.jenkin) stick += j.c.at(0.0);
    return fmt::format("{} Jenkin elements, EI at the clamp {} N m² slipping, {} N m² sticking", c.jenkin.size(),
                       number(c.ei.at(0.0)), number(stick));
  }

  std::shared_ptr<const CableLaw> make(const CableDescription& d, std::span<const double> positions,
                                       std::span<const double> weights) const override {
    return std::make_shared<MasingCableLaw>(d, positions, weights);
  }

  std::vector<std::string_view> loop_variants() const override { return {"exact", "regularised"}; }
  std::vector<LawNumber> loop_extras() const override {
    return {{"exponent", "", "Exponent n of the regularised Masing law (3.15); default 10", {}, 0}};
  }

  std::unique_ptr<section::SectionLaw> loop_section(const LoopNumbers& given) const override {
    section::MasingParameters parameters{*given.find("ei"), {}};
    for (const auto& [c, h] : given.jenkin) parameters.jenkin.push_back({c, h});
    if (given.law != "regularised") return std::make_unique<section::MasingSection>(parameters);
    section::RegularisedOptions regularised;
    if (const double* n = given.find("exponent")) regularised.exponent = *n;
    return std::make_unique<section::RegularisedSection>(parameters, regularised);
  }

  std::unique_ptr<section::SectionLaw> section(const std::vector<double>& values) const override {
    return std::make_unique<section::MasingSection>(section::MasingParameters{values.at(0), {}});
  }

  std::vector<double> moments(const std::vector<double>& values, std::span<const double> curvature) const override {
    std::vector<double> out;
    for (double kappa : curvature) out.push_back(values.at(0) * kappa);
    return out;
  }
};

}  // namespace

const SectionLawDescriptor& masing_section_law() {
  static const MasingLaw law;
  return law;
}

}  // namespace stockbridge::cable
