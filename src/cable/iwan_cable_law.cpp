#include "stockbridge/cable/iwan_cable_law.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <fmt/format.h>

#include "cable_sums.hpp"
#include "stockbridge/cable/cable.hpp"
#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::cable {

namespace {

section::IwanParameters iwan_parameters(const std::vector<double>& v) {
  return {v.at(0), v.at(1), v.at(2), v.at(3), v.at(4)};
}

std::size_t iwan_count(std::span<const double> memory) { return section::iwan_reversals(memory); }

}  // namespace

IwanCableLaw::IwanCableLaw(const CableDescription& d, std::span<const double> positions) {
  for (double position : positions) {
    const double s = d.profile_position(position);
    const section::IwanParameters p{d.number("ei").at(s), d.number("slip_moment").at(s),
                                    d.number("tangent_stiffness").at(s), d.number("exponent").at(s),
                                    d.number("beta").at(s)};
    ei_.push_back(p.ei);
    tangent_stiffness_.push_back(p.tangent_stiffness);
    backbone_.emplace_back(p);
  }
}

void IwanCableLaw::apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force,
                               CableState& to, CableWorkspace&) const {
  const std::size_t n = cable.sections();
  const std::size_t m = section::kIwanMemorySize;
  const auto s = cable.positions();
  const auto w = cable.weights();
  CableSums sums;
  for (std::size_t i = 0; i < n; ++i) {
    const std::span<double> memory = std::span<double>(to.hysteretic).subspan(i * m, m);
    std::copy_n(from.hysteretic.begin() + static_cast<std::ptrdiff_t>(i * m), m, memory.begin());
    const section::IwanStep step =
        section::iwan_step(backbone_[i], ei_[i], memory, from.curvature[i], clamp_moment - tip_force * s[i], true);
    const double tangent = ei_[i] + step.tangent;
    to.curvature[i] = step.curvature;
    to.tangent[i] = tangent;
    sums.add(w[i], s[i], cable.length(), step.curvature, 1.0 / tangent, step.dissipated);
  }
  sums.store(clamp_moment, tip_force, from, to);
}

double IwanCableLaw::internal_change(const CableState& start, const CableState& end) const {
  const std::size_t m = section::kIwanMemorySize;
  double change = 0.0;
  for (std::size_t i = 0; i < ei_.size(); ++i) {
    const std::span<const double> a = std::span<const double>(start.hysteretic).subspan(i * m, m);
    const std::span<const double> b = std::span<const double>(end.hysteretic).subspan(i * m, m);
    if (iwan_count(a) != iwan_count(b)) return 1.0;
    for (std::size_t j = 0; j < iwan_count(a); ++j) {
      change = std::max({change, std::abs(a[2 * j] - b[2 * j]) / backbone_[i].phi_max,
                         std::abs(a[2 * j + 1] - b[2 * j + 1]) / backbone_[i].slip_moment});
    }
  }
  return change;
}

namespace {

// Per section the derivatives of the curvature and the Iwan part's moment at the
// current state (columns), and of every reversal the memory holds: (d kappa_r, dM_r)
// in columns (i K + j) 2 and + 1. A reversal made in a step is the state before it:
// its derivatives are the current ones then.
class IwanLoadSensitivity final : public LoadSensitivity {
 public:
  IwanLoadSensitivity(const Cable& cable, const IwanCableLaw& law)
      : positions_(cable.positions().begin(), cable.positions().end()),
        weights_(cable.weights().begin(), cable.weights().end()),
        length_(cable.length()),
        law_(law) {}

  void start(Eigen::Index parameters) override {
    const Eigen::Index n = static_cast<Eigen::Index>(positions_.size());
    curvature_.setZero(parameters, n);
    moment_.setZero(parameters, n);
    reversals_.setZero(parameters, n * static_cast<Eigen::Index>(2 * section::kIwanMemory));
  }

  void step(const CableState& from, const CableState& to, Eigen::VectorXd& d_rotation, Eigen::VectorXd& d_deflection,
            Eigen::VectorXd& d_clamp_moment, Eigen::VectorXd& d_tip_force) override {
    const std::size_t n = positions_.size();
    const std::size_t m = section::kIwanMemorySize;
    const Eigen::Index p = curvature_.rows();
    const Eigen::Index per = static_cast<Eigen::Index>(2 * section::kIwanMemory);
    a_.setZero(p, static_cast<Eigen::Index>(n));
    stiffness_.resize(n);
    Eigen::VectorXd rhs_phi = d_rotation, rhs_x = d_deflection;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Index col = static_cast<Eigen::Index>(i);
      const std::span<const double> before = std::span<const double>(from.hysteretic).subspan(i * m, m);
      const std::span<const double> after = std::span<const double>(to.hysteretic).subspan(i * m, m);
      const std::size_t k_before = iwan_count(before), k_after = iwan_count(after);
      // The reversals of `after`, each found among `before`'s (the same place, or two
      // on where a full memory forgot its oldest two) or made at `from`.
      scratch_.setZero(p, per);
      for (std::size_t j = 0; j < k_after; ++j) {
        const double kappa_r = after[2 * j], moment_r = after[2 * j + 1];
        const Eigen::Index to_col = static_cast<Eigen::Index>(2 * j);
        const auto same = [&](std::size_t at) {
          return at < k_before && before[2 * at] == kappa_r && before[2 * at + 1] == moment_r;
        };
        const Eigen::Index base = col * per;
        if (same(j)) {
          scratch_.middleCols(to_col, 2) = reversals_.middleCols(base + to_col, 2);
        } else if (same(j + 2)) {
          scratch_.middleCols(to_col, 2) = reversals_.middleCols(base + to_col + 4, 2);
        } else if (kappa_r == from.curvature[i] || (kappa_r == 1e-300 && from.curvature[i] == 0.0)) {
          scratch_.col(to_col) = curvature_.col(col);
          scratch_.col(to_col + 1) = moment_.col(col);
        }
      }
      reversals_.middleCols(col * per, per) = scratch_;
      const double kappa = to.curvature[i];
      const section::IwanBackbone& bb = law_.backbone(i);
      double slope = 0.0;
      if (k_after == 0) {
        slope = bb.tangent(std::abs(kappa));
      } else {
        const Eigen::Index r = col * per + static_cast<Eigen::Index>(2 * (k_after - 1));
        slope = bb.tangent(0.5 * std::abs(kappa - after[2 * k_after - 2]));
        a_.col(col) = (slope * reversals_.col(r) - reversals_.col(r + 1)) / (law_.ei(i) + slope);
      }
      stiffness_[i] = law_.ei(i) + slope;
      const double w = weights_[i], arm = length_ - positions_[i];
      rhs_phi -= w * a_.col(col);
      rhs_x -= w * arm * a_.col(col);
    }
    const Eigen::Matrix2d inverse = to.flexibility.inverse();
    d_clamp_moment = inverse(0, 0) * rhs_phi + inverse(0, 1) * rhs_x;
    d_tip_force = inverse(1, 0) * rhs_phi + inverse(1, 1) * rhs_x;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Index col = static_cast<Eigen::Index>(i);
      const Eigen::VectorXd d_moment = d_clamp_moment - positions_[i] * d_tip_force;
      curvature_.col(col) = d_moment / stiffness_[i] + a_.col(col);
      moment_.col(col) = d_moment - law_.ei(i) * curvature_.col(col);
    }
  }

  void mirror() override {
    curvature_ = -curvature_;
    moment_ = -moment_;
    reversals_ = -reversals_;
  }

 private:
  std::vector<double> positions_, weights_;
  double length_;
  const IwanCableLaw& law_;
  Eigen::MatrixXd curvature_, moment_, reversals_, scratch_, a_;
  std::vector<double> stiffness_;
};

}  // namespace

std::unique_ptr<LoadSensitivity> IwanCableLaw::load_sensitivity(const Cable& cable) const {
  return std::make_unique<IwanLoadSensitivity>(cable, *this);
}

// The Iwan law's descriptor (section_law_descriptor.hpp).

namespace {

constexpr TypicalRange kExponentRange{"Iwan exponent chi", -0.9, 0.0, "", {}};
constexpr TypicalRange kBetaRange{"Iwan beta (the final delta's weight)", 0.0, 10.0, "", {}};

constexpr LawNumber kIwanNumbers[] = {
    {"ei", "N m^2", "Elastic (minimum) bending stiffness EI", typical::ei, 3, StartRole::stiffness, FitScale::logarithmic},
    {"slip_moment", "N m", "the slip moment M_S", typical::jenkin_h, 1, StartRole::slip, FitScale::logarithmic},
    {"tangent_stiffness", "N m^2", "the Iwan part's stiffness K_T at zero", typical::jenkin_c, 3, StartRole::none,
     FitScale::logarithmic},
    {"exponent", "", "the exponent chi of the slip strengths' density, -1 < chi <= 0", kExponentRange, 0,
     StartRole::none, FitScale::linear},
    {"beta", "", "the weight beta of the density's final delta, >= 0", kBetaRange, 0, StartRole::none,
     FitScale::linear},
};

struct IwanLaw final : SectionLawDescriptor {
  std::string_view name() const override { return "iwan"; }
  std::string_view title() const override { return "Iwan"; }
  int order() const override { return 2; }
  std::span<const LawNumber> numbers() const override { return kIwanNumbers; }

  void validate(const CableDescription& d) const override {
    for (const LawNumber& n : numbers()) {
      d.number(n.key).check_values(n.key, [&n](std::string_view name, double v) {
        if (n.key == "exponent") {
          if (!(std::isfinite(v) && v > -1.0 && v <= 0.0)) throw_invalid(name, v, "a value > -1 and <= 0");
        } else if (n.key == "beta") {
          if (!(std::isfinite(v) && v >= 0.0 && v <= 1e6)) throw_invalid(name, v, "a value from 0 to 1e6");
        } else {
          require_plausible(name, v, n.unit);
        }
      });
    }
  }

  std::string summary(const CableDescription& c, std::string (*number)(double)) const override {
    const double ei = c.number("ei").at(0.0);
    return fmt::format("Iwan law, EI at the clamp {} N m² slipping, {} N m² sticking, slip moment {} N m, exponent {}",
                       number(ei), number(ei + c.number("tangent_stiffness").at(0.0)),
                       number(c.number("slip_moment").at(0.0)), number(c.number("exponent").at(0.0)));
  }

  std::shared_ptr<const CableLaw> make(const CableDescription& d, std::span<const double> positions,
                                       std::span<const double>) const override {
    return std::make_shared<IwanCableLaw>(d, positions);
  }

  std::unique_ptr<section::SectionLaw> section(const std::vector<double>& values) const override {
    return std::make_unique<section::IwanSection>(iwan_parameters(values));
  }

  std::vector<double> moments(const std::vector<double>& values, std::span<const double> curvature) const override {
    const section::IwanParameters p = iwan_parameters(values);
    const section::IwanBackbone backbone(p);
    std::vector<double> memory(section::kIwanMemorySize, 0.0), out;
    double kappa = 0.0;
    for (const double next : curvature) {
      section::iwan_step(backbone, p.ei, memory, kappa, next, false);
      kappa = next;
      out.push_back(p.ei * kappa + section::iwan_moment(backbone, memory, kappa));
    }
    return out;
  }

  /// From the Masing estimate: ei, the slip moment its h, K_T its c, chi -0.5, beta
  /// 0.1; K_T and M_S scaled (local), ei and M_S (global).
  std::vector<std::vector<double>> starts(const MasingEstimate& e, FitKind kind) const override {
    std::vector<std::vector<double>> x;
    for (const auto& [a, b] :
         {std::pair{1.0, 1.0}, std::pair{0.5, 1.0}, std::pair{2.0, 1.0}, std::pair{1.0, 0.7}, std::pair{1.0, 1.4}}) {
      if (kind == FitKind::local) {
        x.push_back({e.ei, b * e.h, a * e.c, -0.5, 0.1});
      } else {
        x.push_back({a * e.ei, b * e.h, e.c, -0.5, 0.1});
      }
    }
    return x;
  }

  /// Logarithms of ei, M_S and K_T; chi = -1 / (1 + e^x) in (-1, 0); beta = e^x.
  std::vector<double> pack(const std::vector<double>& v) const override {
    const double chi = std::clamp(v.at(3), -1.0 + 1e-9, -1e-9);
    return {std::log(v.at(0)), std::log(v.at(1)), std::log(v.at(2)), std::log(-1.0 / chi - 1.0),
            std::log(std::max(v.at(4), 1e-9))};
  }
  std::vector<double> unpack(const std::vector<double>& x) const override {
    return {std::exp(x.at(0)), std::exp(x.at(1)), std::exp(x.at(2)), -1.0 / (1.0 + std::exp(x.at(3))),
            std::exp(x.at(4))};
  }
};

}  // namespace

const SectionLawDescriptor& iwan_section_law() {
  static const IwanLaw law;
  return law;
}

}  // namespace stockbridge::cable
