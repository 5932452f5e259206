#pragma once
// The impedance fit's variables (impedance_identification.cpp): per cable type its
// law's numbers, then the damper numbers options.free names, then the clamp mass, as
// the optimiser's x; the damper they stand for; and the fit's constants. Private to
// the identification module.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>

#include "fit_core.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/damper_numbers.hpp"
#include "stockbridge/identification/impedance_identification.hpp"

namespace stockbridge::identification::impedance_fit {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The model runs converged to this (the harmonic balance's residual and periodicity
/// tolerances, tighter than the sweep's defaults): the difference quotients divide by
/// the step below.
inline constexpr double kModelTolerance = 1e-8;
/// The forward-difference step of the log parameters: about the square root of the
/// model's relative accuracy.
inline constexpr double kDifferenceStep = 1e-4;
/// The scatter of Z (relative, per real component) at which parameters' resolutions are stated.
inline constexpr double kStatedScatter = 0.01;
/// A parameter that this scatter moves by more than this fraction of its value is not determined.
inline constexpr double kUndeterminedResolution = 0.5;
/// Nor one whose estimate is correlated beyond this with one not determined.
inline constexpr double kTiedCorrelation = 0.999;
/// Each residual where the variables lie beyond fit_core::Search::variable_limit or
/// the model refuses the parameters: far above any fit, so that no step goes there.
inline constexpr double kRejected = 1e3;
/// Iterations from each start before the best is polished.
inline constexpr int kExploreJacobians = 3;
/// The starts are explored on cables of at most this many sections (about 0.5 %
/// off in Z, a third of the cost); the best is polished on the description's.
inline constexpr int kExploreSections = 12;
/// An RMS relative error below this reproduces the data to the model's accuracy:
/// no further start can do better.
inline constexpr double kReproducedError = 1e-6;
/// The starts: (ei, every h) scaled from the starting values.
inline constexpr std::pair<double, double> kStartFactors[] = {{1.0, 1.0}, {1.0, 0.5}, {1.0, 2.0}, {1.0, 0.25}, {0.7, 1.0}, {1.4, 1.0}};

/// The constant value of a profile, or InvalidParameter naming it.
double constant_value(const cable::Profile& profile, const std::string& name);

/// The key prefix of arm k's cable in messages and cable files ("arm[1].cable.").
std::string arm_key(std::size_t arm);

/// A number of the damper fitted with the cables (options.free): its path and how
/// the optimiser's variable x stands for it.
struct DamperNumber {
  std::string path;   ///< canonical: "arm.<name>.<field>" ("arm[k].<field>" for an unnamed arm)
  std::size_t arm = 0;
  std::string field;  ///< "mass", "inertia", "offset", "cable.length"
  std::string unit;
  bool logarithmic = true;  ///< value = start exp(x); else start + scale x
  double start = 0.0;
  double scale = 1.0;

  double value(double x) const { return logarithmic ? start * std::exp(x) : start + scale * x; }
};

/// The fitted numbers of options.free (the clamp mass apart: it has its own variable).
std::vector<DamperNumber> damper_numbers(const damper::DamperDescription& start, const std::vector<std::string>& free);

/// The numbers of the damper options.free leaves fixed (the lack of fit's suspects):
/// each arm's mass, inertia, offset and cable length not freed, parametrised as `free`
/// would fit them (a mass, inertia or length that is not > 0 is left out: it has no
/// logarithm). The clamp mass apart (its column is analytic).
std::vector<DamperNumber> fixed_numbers(const damper::DamperDescription& start, const std::vector<DamperNumber>& free);

/// The optimiser's variables and the damper they stand for. Per cable type: the
/// logarithms, relative to the starting values, of its law's numbers (Masing: ei,
/// c_0, h_0, c_1, h_1, ...; a law of numbers: each number, by its logarithm or in
/// steps of its starting value (FitScale); a step the cable does not accept, such as
/// Bouc-Wen's ei_max < ei_min, is refused by it); then
/// the numbers of options.free (DamperNumber); then, when fitted, the clamp mass's
/// change in units of the damper's mass.
class FitVariables {
 public:
  FitVariables(const damper::DamperDescription& start, const ImpedanceIdentificationOptions& options)
      : start_(start), type_of_arm_(cable_types(start)), numbers_(damper_numbers(start, options.free)),
        law_(common_law(start, options.elements)) {
    fit_clamp_mass_ = options.fit_clamp_mass ||
                      std::find(options.free.begin(), options.free.end(), "clamp.mass") != options.free.end();
    const int elements = options.elements;
    const std::size_t types = *std::max_element(type_of_arm_.begin(), type_of_arm_.end()) + 1;
    for (std::size_t t = 0; t < types; ++t) {
      const std::size_t arm = first_arm(t);
      prefixes_.push_back(types > 1 ? arm_key(arm) : "");
      if (numbered()) {
        number_reference_.push_back(starting_numbers(start.arms[arm].cable, arm_key(arm)));
        continue;
      }
      reference_.push_back(starting_parameters(start.arms[arm].cable, elements, arm_key(arm)));
      k0_.push_back(starting_k0(start.arms[arm].cable, elements, arm_key(arm)));
    }
    mass_scale_ = start.clamp_mass;
    for (const damper::ArmDescription& a : start.arms) mass_scale_ += a.mass;
  }

  const cable::SectionLawDescriptor* law() const { return law_; }
  /// A law of numbers (not the Masing law's Jenkin elements).
  bool numbered() const { return !law_->jenkin_elements(); }
  /// Jenkin elements per type (none under a law of numbers).
  int elements() const { return numbered() ? 0 : static_cast<int>(reference_.front().jenkin.size()); }
  int per_type() const { return numbered() ? static_cast<int>(law_->numbers().size()) : 1 + 2 * elements(); }
  int cable_variables() const { return per_type() * static_cast<int>(types()); }
  int size() const { return cable_variables() + static_cast<int>(numbers_.size()) + (fit_clamp_mass_ ? 1 : 0); }
  std::size_t types() const { return prefixes_.size(); }
  const std::vector<std::size_t>& type_of_arm() const { return type_of_arm_; }
  bool fits_clamp_mass() const { return fit_clamp_mass_; }
  int clamp_mass_index() const { return size() - 1; }
  double mass_scale() const { return mass_scale_; }
  const std::vector<DamperNumber>& numbers() const { return numbers_; }
  /// The number of options.free variable i stands for, or nullptr for a cable's or the clamp mass's.
  const DamperNumber* number(int i) const {
    const int k = i - cable_variables();
    return k >= 0 && k < static_cast<int>(numbers_.size()) ? &numbers_[static_cast<std::size_t>(k)] : nullptr;
  }

  /// Each type's parameters at x, in the packed order (none under the Bouc-Wen law).
  std::vector<section::MasingParameters> cables(const Eigen::VectorXd& x) const {
    std::vector<section::MasingParameters> out;
    for (std::size_t t = 0; t < reference_.size(); ++t) {
      const section::MasingParameters& r = reference_[t];
      const int o = per_type() * static_cast<int>(t);
      section::MasingParameters p{r.ei * std::exp(x(o)), {}};
      for (int j = 0; j < elements(); ++j) {
        p.jenkin.push_back({r.jenkin[j].c * std::exp(x(o + 1 + 2 * j)), r.jenkin[j].h * std::exp(x(o + 2 + 2 * j))});
      }
      out.push_back(p);
    }
    return out;
  }

  /// Each type's numbers at x under a law of numbers (none under the Masing law).
  std::vector<cable::LawValues> law_cables(const Eigen::VectorXd& x) const {
    std::vector<cable::LawValues> out;
    for (std::size_t t = 0; t < number_reference_.size(); ++t) {
      const std::vector<double>& r = number_reference_[t];
      const int o = per_type() * static_cast<int>(t);
      cable::LawValues values{law_, {}};
      for (int k = 0; k < per_type(); ++k) {
        const double scale = linear_scale(o + k);
        values.values.push_back(scale > 0.0 ? r[static_cast<std::size_t>(k)] + scale * x(o + k)
                                            : r[static_cast<std::size_t>(k)] * std::exp(x(o + k)));
      }
      out.push_back(std::move(values));
    }
    return out;
  }

  /// The step of cable variable i (< cable_variables()) that moves linearly (its
  /// starting value's size, or 1 for a start of 0); 0 for a logarithmic one.
  double linear_scale(int i) const {
    if (!numbered() || i >= cable_variables()) return 0.0;
    const std::size_t k = static_cast<std::size_t>(i % per_type());
    if (law_->numbers()[k].fit_scale == cable::FitScale::logarithmic) return 0.0;
    const double r = std::abs(number_reference_[static_cast<std::size_t>(i / per_type())][k]);
    return r > 0.0 ? r : 1.0;
  }

  /// The value of cable variable i (< cable_variables()) at x.
  double cable_value(const Eigen::VectorXd& x, int i) const {
    const std::size_t t = static_cast<std::size_t>(i / per_type());
    const int k = i % per_type();
    if (numbered()) return law_cables(x)[t][static_cast<std::size_t>(k)];
    const section::MasingParameters p = cables(x)[t];
    return k == 0 ? p.ei : (k - 1) % 2 == 0 ? p.jenkin[(k - 1) / 2].c : p.jenkin[(k - 1) / 2].h;
  }

  double clamp_mass(const Eigen::VectorXd& x) const {
    return start_.clamp_mass + (fit_clamp_mass_ ? mass_scale_ * x(clamp_mass_index()) : 0.0);
  }

  /// The damper at x, with the clamp mass given (each arm keeps what is not fitted:
  /// its sections (at most `max_sections`), mirror length and lever-arm cap).
  damper::DamperDescription damper(const Eigen::VectorXd& x, double clamp_mass, int max_sections = cable::max_sections) const {
    const std::vector<section::MasingParameters> fitted = cables(x);
    const std::vector<cable::LawValues> fitted_numbers = law_cables(x);
    damper::DamperDescription d = start_;
    d.clamp_mass = clamp_mass;
    for (std::size_t k = 0; k < numbers_.size(); ++k) {
      damper::set_damper_number(d, numbers_[k].path, numbers_[k].value(x(cable_variables() + static_cast<int>(k))));
    }
    for (std::size_t k = 0; k < d.arms.size(); ++k) {
      const std::size_t t = type_of_arm_[k];
      cable::CableDescription& c = d.arms[k].cable;
      c.sections = std::min(c.sections, max_sections);
      if (numbered()) {
        const auto keys = law_->numbers();
        for (std::size_t n = 0; n < keys.size(); ++n) c.number(keys[n].key) = cable::Profile::constant(fitted_numbers[t][n]);
        continue;
      }
      c.ei = cable::Profile::constant(fitted[t].ei);
      c.jenkin.clear();
      for (std::size_t j = 0; j < fitted[t].jenkin.size(); ++j) {
        c.jenkin.push_back({cable::Profile::constant(fitted[t].jenkin[j].c), cable::Profile::constant(fitted[t].jenkin[j].h),
                            k0_[t][j]});
      }
    }
    return d;
  }

  /// The names of the variables' parameters as a cable file (and damper file) names them.
  std::string name(int i) const {
    if (fit_clamp_mass_ && i == clamp_mass_index()) return "clamp.mass";
    if (const DamperNumber* n = number(i)) return n->path;
    const std::string& prefix = prefixes_[static_cast<std::size_t>(i / per_type())];
    const int k = i % per_type();
    if (numbered()) return prefix + std::string(law_->numbers()[static_cast<std::size_t>(k)].key);
    if (k == 0) return prefix + "ei";
    return fmt::format("{}jenkin[{}].{}", prefix, (k - 1) / 2, (k - 1) % 2 == 0 ? "c" : "h");
  }
  std::string unit(int i) const {
    if (fit_clamp_mass_ && i == clamp_mass_index()) return "kg";
    if (const DamperNumber* n = number(i)) return n->unit;
    if (numbered()) return std::string(law_->numbers()[static_cast<std::size_t>(i % per_type())].unit);
    return i % per_type() == 0 || (i % per_type() - 1) % 2 == 0 ? "N m^2" : "N m";
  }
  std::string type_prefix(std::size_t t) const { return prefixes_[t]; }

  /// The same point with each type's elements in order of slip curvature h / c (as
  /// the fits report them; the model does not depend on their order).
  Eigen::VectorXd sorted(const Eigen::VectorXd& x) const {
    Eigen::VectorXd out = x;
    const std::vector<section::MasingParameters> unsorted = cables(x);
    for (std::size_t t = 0; t < unsorted.size(); ++t) {
      const section::MasingParameters p = fit_core::sorted_by_slip_curvature(unsorted[t]);
      const int o = per_type() * static_cast<int>(t);
      for (int j = 0; j < elements(); ++j) {
        out(o + 1 + 2 * j) = std::log(p.jenkin[j].c / reference_[t].jenkin[j].c);
        out(o + 2 + 2 * j) = std::log(p.jenkin[j].h / reference_[t].jenkin[j].h);
      }
    }
    return out;
  }

  /// The directions in the variables along which Z does not change at all: the
  /// damper's scalings. With the quasi-static cable, lengths and offsets times s,
  /// inertias times s^2, ei and c times s^3 and h times s (the arm masses kept) give
  /// the same clamp force for the same clamp motion: each arm's tip rotates 1/s times
  /// as much, its moments are s times as large, its forces the same (under the
  /// Bouc-Wen law: ei_min and ei_max times s^3, chi0, a curvature, times s^-2). One direction per
  /// cable type whose every arm has its cable length and inertia free and its offset
  /// free or 0, and no element with the modified Masing model's k0 (whose lever-arm
  /// cap does not scale). Each direction has unit length.
  std::vector<Eigen::VectorXd> scalings(const Eigen::VectorXd& x) const {
    std::vector<Eigen::VectorXd> out;
    for (std::size_t t = 0; t < types(); ++t) {
      Eigen::VectorXd g = Eigen::VectorXd::Zero(size());
      const int o = per_type() * static_cast<int>(t);
      g(o) = 3.0;
      for (int k = 0; numbered() && k < per_type(); ++k) {
        if (linear_scale(o + k) == 0.0) g(o + k) = law_->numbers()[static_cast<std::size_t>(k)].scaling_power;
      }
      for (int j = 0; j < elements(); ++j) {
        g(o + 1 + 2 * j) = 3.0;
        g(o + 2 + 2 * j) = 1.0;
        if (k0_[t][static_cast<std::size_t>(j)] != 0.0) g.setZero();
      }
      for (std::size_t k = 0; k < start_.arms.size() && g.norm() > 0.0; ++k) {
        if (type_of_arm_[k] != t) continue;
        auto free_index = [&](const std::string& field) {
          for (std::size_t i = 0; i < numbers_.size(); ++i) {
            if (numbers_[i].arm == k && numbers_[i].field == field) return cable_variables() + static_cast<int>(i);
          }
          return -1;
        };
        const int length = free_index("cable.length"), inertia = free_index("inertia"), offset = free_index("offset");
        if (length < 0 || inertia < 0 || (offset < 0 && start_.arms[k].offset != 0.0)) {
          g.setZero();
          break;
        }
        g(length) = 1.0;
        g(inertia) = 2.0;
        if (offset >= 0) {
          const DamperNumber& n = numbers_[static_cast<std::size_t>(offset - cable_variables())];
          g(offset) = n.value(x(offset)) / n.scale;  // d(offset)/ds = offset, in the variable's units
        }
      }
      if (g.norm() > 0.0) out.push_back(g.normalized());
    }
    return out;
  }

  /// The starting points: the starting values with ei and every h scaled (the
  /// Bouc-Wen law: ei_min and ei_max, and chi0 for h; the numbers of the damper at
  /// the start's).
  std::vector<Eigen::VectorXd> starts() const {
    std::vector<Eigen::VectorXd> out;
    for (const auto& [ei_factor, h_factor] : kStartFactors) {
      Eigen::VectorXd x = Eigen::VectorXd::Zero(size());
      for (std::size_t t = 0; t < types(); ++t) {
        const int o = per_type() * static_cast<int>(t);
        x(o) = std::log(ei_factor);
        for (int k = 0; numbered() && k < per_type(); ++k) {
          const cable::LawNumber& n = law_->numbers()[static_cast<std::size_t>(k)];
          const double factor = n.start_role == cable::StartRole::stiffness ? ei_factor
                                : n.start_role == cable::StartRole::slip    ? h_factor
                                                                            : 1.0;
          x(o + k) = linear_scale(o + k) > 0.0 ? 0.0 : std::log(factor);
        }
        for (int j = 0; j < elements(); ++j) x(o + 2 + 2 * j) = std::log(h_factor);
      }
      out.push_back(x);
    }
    return out;
  }

 private:
  std::size_t first_arm(std::size_t type) const {
    return static_cast<std::size_t>(std::find(type_of_arm_.begin(), type_of_arm_.end(), type) - type_of_arm_.begin());
  }

  /// The law of every arm's cable (one law per fit); `elements` must be 1 (the
  /// option's default) under the Bouc-Wen law.
  static const cable::SectionLawDescriptor* common_law(const damper::DamperDescription& start, int elements) {
    const cable::SectionLawDescriptor* law = start.arms.front().cable.law;
    for (std::size_t k = 1; k < start.arms.size(); ++k) {
      if (start.arms[k].cable.law != law) {
        throw InvalidParameter(arm_key(k) + "law",
                               fmt::format(" = \"{}\" but arm[0]'s is \"{}\": expected one section law for every "
                                           "arm (identify impedance fits one law)",
                                           start.arms[k].cable.law->name(), law->name()));
      }
    }
    if (!law->jenkin_elements() && elements != 1) {
      throw InvalidParameter("elements", fmt::format(" = {}: Jenkin elements belong to the Masing law; the start's "
                                                     "cables are law = \"{}\" ({} are fitted)",
                                                     elements, law->name(), law->takes()));
    }
    return law;
  }

  /// The start's numbers under a law of numbers, constants the law can fit from (check_start).
  std::vector<double> starting_numbers(const cable::CableDescription& c, const std::string& key) const {
    std::vector<double> values;
    for (const cable::LawNumber& n : law_->numbers()) values.push_back(constant_value(c.number(n.key), key + std::string(n.key)));
    law_->check_start(values, key);
    return values;
  }

  /// The start's elements where it has `elements` of them, otherwise their sums
  /// spread over `elements` (fit_core::spread_over_elements).
  static section::MasingParameters starting_parameters(const cable::CableDescription& c, int elements,
                                                       const std::string& key) {
    const double ei = constant_value(c.ei, key + "ei");
    section::MasingParameters p{ei, {}};
    double c_total = 0.0, h_total = 0.0;
    for (std::size_t j = 0; j < c.jenkin.size(); ++j) {
      const section::Jenkin e{constant_value(c.jenkin[j].c, fmt::format("{}jenkin[{}].c", key, j)),
                              constant_value(c.jenkin[j].h, fmt::format("{}jenkin[{}].h", key, j))};
      p.jenkin.push_back(e);
      c_total += e.c;
      h_total += e.h;
    }
    if (p.jenkin.empty()) {
      throw InvalidParameter(key + "jenkin", ": no elements: expected starting values of c and h (N m^2, N m)");
    }
    if (static_cast<int>(p.jenkin.size()) == elements) return p;
    return fit_core::spread_over_elements(ei, c_total, h_total, elements);
  }

  static std::vector<double> starting_k0(const cable::CableDescription& c, int elements, const std::string& key) {
    if (static_cast<int>(c.jenkin.size()) == elements) {
      std::vector<double> k0;
      for (const cable::JenkinProfile& e : c.jenkin) k0.push_back(e.k0);
      return k0;
    }
    for (std::size_t j = 0; j < c.jenkin.size(); ++j) {
      if (c.jenkin[j].k0 != 0.0) {
        throw InvalidParameter(fmt::format("{}jenkin[{}].k0", key, j),
                               fmt::format(" = {}: the modified Masing model with {} elements in the file but {} to "
                                           "fit: expected as many elements as fitted",
                                           format_value(c.jenkin[j].k0), c.jenkin.size(), elements));
      }
    }
    return std::vector<double>(static_cast<std::size_t>(elements), 0.0);
  }

  damper::DamperDescription start_;
  std::vector<std::size_t> type_of_arm_;
  std::vector<DamperNumber> numbers_;
  bool fit_clamp_mass_ = false;
  std::vector<std::string> prefixes_;
  const cable::SectionLawDescriptor* law_;
  std::vector<section::MasingParameters> reference_;        ///< per type, under the Masing law
  std::vector<std::vector<double>> k0_;
  std::vector<std::vector<double>> number_reference_;  ///< per type, under a law of numbers
  double mass_scale_ = 0.0;
};

}  // namespace stockbridge::identification::impedance_fit
