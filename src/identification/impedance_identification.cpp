#include "stockbridge/identification/impedance_identification.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "fit_core.hpp"
#include "least_squares.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/core/parallel.hpp"
#include "stockbridge/design/damper_numbers.hpp"

namespace stockbridge::identification {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Points whose held amplitudes lie within this ratio of a curve's smallest belong to it.
constexpr double kCurveAmplitudeRatio = 1.1;
/// The model runs converged to this (the harmonic balance's residual and periodicity
/// tolerances, tighter than the sweep's defaults): the difference quotients divide by
/// the step below.
constexpr double kModelTolerance = 1e-8;
/// The forward-difference step of the log parameters: about the square root of the
/// model's relative accuracy.
constexpr double kDifferenceStep = 1e-4;
/// The scatter of Z (relative, per real component) at which parameters' resolutions are stated.
constexpr double kStatedScatter = 0.01;
/// A parameter that this scatter moves by more than this fraction of its value is not determined.
constexpr double kUndeterminedResolution = 0.5;
/// Nor one whose estimate is correlated beyond this with one not determined.
constexpr double kTiedCorrelation = 0.999;
/// Each residual where the variables lie beyond fit_core::Search::variable_limit or
/// the model refuses the parameters: far above any fit, so that no step goes there.
constexpr double kRejected = 1e3;
/// Iterations from each start before the best is polished.
constexpr int kExploreJacobians = 3;
/// The starts are explored on cables of at most this many sections (about 0.5 %
/// off in Z, a third of the cost); the best is polished on the description's.
constexpr int kExploreSections = 12;
/// An RMS relative error below this reproduces the data to the model's accuracy:
/// no further start can do better.
constexpr double kReproducedError = 1e-6;
/// The starts: (ei, every h) scaled from the starting values.
constexpr std::pair<double, double> kStartFactors[] = {{1.0, 1.0}, {1.0, 0.5}, {1.0, 2.0}, {1.0, 0.25}, {0.7, 1.0}, {1.4, 1.0}};

double held_amplitude(const damper::Excitation& e, damper::HeldAmplitude held) {
  return held == damper::HeldAmplitude::velocity ? e.velocity_amplitude() : e.displacement_amplitude;
}

/// The constant value of a profile, or InvalidParameter naming it.
double constant_value(const cable::Profile& profile, const std::string& name) {
  if (!profile.is_constant()) {
    throw InvalidParameter(name, ": a profile along the cable: identify impedance fits constant parameters (give the "
                                 "starting value as a number)");
  }
  return profile.values()[0];
}

std::string arm_key(std::size_t arm) { return fmt::format("arm[{}].cable.", arm); }

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

/// An option's path refused: InvalidParameter naming the option and the path.
[[noreturn]] void refuse_free(const std::string& path, std::string_view why) {
  throw InvalidParameter("free", fmt::format(" = {}: {}", printable(path), why));
}

/// The fitted numbers of options.free (the clamp mass apart: it has its own variable).
std::vector<DamperNumber> damper_numbers(const damper::DamperDescription& start, const std::vector<std::string>& free) {
  std::vector<DamperNumber> out;
  std::vector<std::pair<std::size_t, std::string>> seen;  // (arm, field) of each
  bool clamp_mass = false;
  for (const std::string& path : free) {
    if (path == "clamp.mass") {
      if (clamp_mass) refuse_free(path, "given twice: expected each number once");
      clamp_mass = true;
      continue;
    }
    design::ArmPath arm;
    try {
      arm = design::split_arm_path(start, path);
    } catch (const InvalidParameter& e) {
      refuse_free(path, e.detail().substr(e.detail().starts_with(": ") ? 2 : 0));
    }
    static const std::pair<const char*, const char*> kFields[] = {
        {"mass", "kg"}, {"inertia", "kg m^2"}, {"offset", "m"}, {"cable.length", "m"}};
    const auto field = std::find_if(std::begin(kFields), std::end(kFields),
                                    [&](const auto& f) { return arm.field == f.first; });
    if (field == std::end(kFields)) {
      refuse_free(path, fmt::format("{}: expected {} (every cable type's own numbers, ei, c and h or ei_min, ei_max and chi0, are fitted anyway)",
                                    arm.field.starts_with("cable.") ? "a cable parameter or setting, not fitted as a "
                                                                      "number of the damper"
                                                                    : "not a number the fit can free",
                                    free_damper_numbers));
    }
    if (std::find(seen.begin(), seen.end(), std::make_pair(arm.arm, arm.field)) != seen.end()) {
      refuse_free(path, "given twice (perhaps once by name and once by index): expected each number once");
    }
    seen.emplace_back(arm.arm, arm.field);
    const damper::ArmDescription& a = start.arms[arm.arm];
    DamperNumber n;
    n.path = a.name.empty() ? fmt::format("arm[{}].{}", arm.arm, arm.field) : fmt::format("arm.{}.{}", a.name, arm.field);
    n.arm = arm.arm;
    n.field = arm.field;
    n.unit = field->second;
    n.start = design::damper_number(start, path);
    n.logarithmic = arm.field != "offset";
    if (n.logarithmic && !(n.start > 0.0)) {
      refuse_free(path, fmt::format("is {} in the damper: fitted in logarithms, it must start > 0", format_value(n.start)));
    }
    // An offset moves in units of its start's magnitude, at least 1 cm.
    n.scale = n.logarithmic ? 1.0 : std::max(std::abs(n.start), 0.01);
    out.push_back(n);
  }
  return out;
}

/// The numbers of the damper options.free leaves fixed (the lack of fit's suspects):
/// each arm's mass, inertia, offset and cable length not freed, parametrised as `free`
/// would fit them (a mass, inertia or length that is not > 0 is left out: it has no
/// logarithm). The clamp mass apart (its column is analytic).
std::vector<DamperNumber> fixed_numbers(const damper::DamperDescription& start, const std::vector<DamperNumber>& free) {
  static const std::pair<const char*, const char*> kFields[] = {
      {"mass", "kg"}, {"inertia", "kg m^2"}, {"offset", "m"}, {"cable.length", "m"}};
  std::vector<DamperNumber> out;
  for (std::size_t k = 0; k < start.arms.size(); ++k) {
    const damper::ArmDescription& a = start.arms[k];
    for (const auto& entry : kFields) {
      // Not a structured binding: clang before 16 cannot capture one in the lambda.
      const char* const field = entry.first;
      const char* const unit = entry.second;
      auto same = [&](const DamperNumber& n) { return n.arm == k && n.field == field; };
      if (std::any_of(free.begin(), free.end(), same)) continue;
      DamperNumber n;
      n.path = a.name.empty() ? fmt::format("arm[{}].{}", k, field) : fmt::format("arm.{}.{}", a.name, field);
      n.arm = k;
      n.field = field;
      n.unit = unit;
      n.start = design::damper_number(start, n.path);
      n.logarithmic = n.field != "offset";
      if (n.logarithmic && !(n.start > 0.0)) continue;
      n.scale = n.logarithmic ? 1.0 : std::max(std::abs(n.start), 0.01);
      out.push_back(n);
    }
  }
  return out;
}

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
      design::set_damper_number(d, numbers_[k].path, numbers_[k].value(x(cable_variables() + static_cast<int>(k))));
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

/// Each point's solution (a tracker's checkpoint, one path per distinct arm), and
/// which arms were distinct: a fitted mass or length can make arms alike or apart,
/// and a checkpoint warm-starts only a damper with the same distinct arms.
struct Checkpoints {
  std::vector<damper::DamperTracker::Checkpoint> points;
  std::vector<std::size_t> distinct;
};

/// The model at every measured point. Each curve is solved from `warm` where given
/// (per point, the solution there for nearby parameters: a Newton step or two,
/// where following the curve from its first frequency takes substeps near every
/// resonance), else, or where a point fails from it, along the curve in frequency
/// order. `solutions` (if given) receives each point's solution, to warm-start the
/// next parameters (empty where it did not converge).
std::vector<damper::ImpedancePoint> solve_points(const damper::Damper& damper, const ImpedanceMeasurement& m,
                                                 const damper::SolverOptions& solver, const Checkpoints* warm,
                                                 Checkpoints* solutions) {
  std::vector<damper::ImpedancePoint> points(m.points.size());
  if (solutions) *solutions = {std::vector<damper::DamperTracker::Checkpoint>(m.points.size()), damper.distinct()};
  auto keep = [&](damper::DamperTracker& tracker, std::size_t i) {
    if (solutions && points[i].converged()) solutions->points[i] = tracker.checkpoint();
  };
  for (const std::vector<std::size_t>& curve : measured_curves(m)) {
    damper::DamperTracker tracker(damper, solver, m.held);
    bool warm_started = warm && warm->points.size() == m.points.size() && warm->distinct == damper.distinct() &&
                        std::all_of(curve.begin(), curve.end(), [&](std::size_t i) { return !warm->points[i].empty(); });
    for (std::size_t k = 0; k < curve.size() && warm_started; ++k) {
      tracker.restore(warm->points[curve[k]]);
      points[curve[k]] = tracker.solve(m.points[curve[k]].excitation);
      warm_started = points[curve[k]].converged();
      keep(tracker, curve[k]);
    }
    if (warm_started) continue;
    damper::DamperTracker along(damper, solver, m.held);
    for (const std::size_t i : curve) {
      points[i] = along.solve(m.points[i].excitation);
      keep(along, i);
    }
  }
  return points;
}

/// The model at one point of the variables: the residuals, where it converged, and
/// its solutions (to warm-start nearby points).
struct Evaluation {
  Eigen::VectorXd x;
  Eigen::VectorXd residuals;
  std::vector<bool> converged;
  Checkpoints solutions;
};

/// The relative complex residuals of the model's Z against the measured one (Z = 0
/// where the model did not converge).
class ImpedanceProblem : public least_squares::Problem {
 public:
  /// The model's cables have at most `max_sections` sections.
  ImpedanceProblem(const FitVariables& variables, const ImpedanceMeasurement& measurement,
                   const ImpedanceIdentificationOptions& options, int max_sections = cable::max_sections)
      : variables_(variables), measurement_(measurement), options_(options), max_sections_(max_sections) {}

  int variables() const override { return variables_.size(); }
  int residual_count() const override { return 2 * static_cast<int>(measurement_.points.size()); }

  /// Levenberg-Marquardt's points are warm-started from the best so far (its
  /// current iterate), the Jacobian's columns from the point they differentiate at
  /// (on `threads` threads: the columns are independent model runs).
  Eigen::VectorXd residuals(const Eigen::VectorXd& x) override { return evaluated(x).residuals; }
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x) override {
    const Evaluation at = evaluated(x);
    Eigen::MatrixXd jacobian(residual_count(), variables());
    std::vector<int> columns(static_cast<std::size_t>(variables()));
    std::iota(columns.begin(), columns.end(), 0);
    if (variables_.fits_clamp_mass()) {
      jacobian.col(variables_.clamp_mass_index()) = clamp_mass_column(at);
      columns.pop_back();
    }
    run_in_parallel(columns.size(), [&](std::size_t k) {
      Eigen::VectorXd shifted = x;
      shifted(columns[k]) += kDifferenceStep;
      jacobian.col(columns[k]) = (evaluate(shifted, &at).residuals - at.residuals) / kDifferenceStep;
    });
    return jacobian;
  }

  /// The Jacobian columns, at x, of numbers of the damper the variables keep fixed:
  /// dr/dq for each number's variable q as `free` would fit it (DamperNumber), by the
  /// same forward differences as jacobian()'s (on `threads` threads), then where
  /// `clamp_mass` the clamp mass's (analytic, per the damper's mass).
  Eigen::MatrixXd fixed_number_columns(const Eigen::VectorXd& x, const std::vector<DamperNumber>& numbers, bool clamp_mass) {
    const Evaluation at = evaluated(x);
    Eigen::MatrixXd columns(residual_count(), static_cast<Eigen::Index>(numbers.size()) + (clamp_mass ? 1 : 0));
    run_in_parallel(numbers.size(), [&](std::size_t k) {
      const Change change{numbers[k].path, numbers[k].value(kDifferenceStep)};
      columns.col(static_cast<Eigen::Index>(k)) = (evaluate(x, &at, &change).residuals - at.residuals) / kDifferenceStep;
    });
    if (clamp_mass) columns.col(columns.cols() - 1) = clamp_mass_column(at);
    return columns;
  }

  /// The model's points (with the clamp mass) at x; converged() false where it did not converge.
  std::vector<damper::ImpedancePoint> points(const Eigen::VectorXd& x) const {
    const damper::DamperDescription description =
        variables_.damper(x, std::max(0.0, variables_.clamp_mass(x)), max_sections_);
    const Evaluation* warm = best_recent();
    return solve_points(damper::Damper(description), measurement_, options_.solver, warm ? &warm->solutions : nullptr,
                        nullptr);
  }

  int evaluations() const { return evaluations_.load(); }

 private:
  /// A number of the damper set apart from the variables' (a fixed number's column).
  struct Change {
    std::string path;
    double value = 0.0;
  };

  /// The model with the clamp mass left out (it is added as i W m_c, which may then
  /// be negative), with `change` made to the damper if given.
  Evaluation evaluate(const Eigen::VectorXd& x, const Evaluation* warm, const Change* change = nullptr) {
    ++evaluations_;
    const std::size_t n = measurement_.points.size();
    Evaluation e{x, Eigen::VectorXd(2 * n), std::vector<bool>(n, false), {}};
    std::vector<damper::ImpedancePoint> arms;
    if (x.cwiseAbs().maxCoeff() <= fit_core::Search::variable_limit) {
      try {
        damper::DamperDescription description = variables_.damper(x, 0.0, max_sections_);
        if (change) design::set_damper_number(description, change->path, change->value);
        arms = solve_points(damper::Damper(description), measurement_, options_.solver,
                            warm ? &warm->solutions : nullptr, &e.solutions);
      } catch (const InvalidParameter&) {
        arms.clear();  // parameters the model does not accept (overflowed)
      }
    }
    if (arms.empty()) {
      e.residuals.setConstant(kRejected);
      return e;
    }
    const double clamp_mass = variables_.clamp_mass(x);
    for (std::size_t i = 0; i < n; ++i) {
      const MeasuredImpedance& m = measurement_.points[i];
      std::complex<double> z = 0.0;
      if (arms[i].converged()) {
        z = arms[i].impedance + std::complex<double>(0.0, m.excitation.angular_frequency() * clamp_mass);
        e.converged[i] = true;
      }
      const std::complex<double> r = (z - m.impedance) / std::abs(m.impedance);
      e.residuals(2 * i) = r.real();
      e.residuals(2 * i + 1) = r.imag();
    }
    return e;
  }

  /// dr/dx of the clamp-mass variable: i W (mass scale) / |Z| where the model converged.
  Eigen::VectorXd clamp_mass_column(const Evaluation& at) const {
    Eigen::VectorXd column = Eigen::VectorXd::Zero(residual_count());
    for (std::size_t i = 0; i < measurement_.points.size(); ++i) {
      const MeasuredImpedance& m = measurement_.points[i];
      if (at.converged[i]) {
        column(2 * i + 1) = m.excitation.angular_frequency() * variables_.mass_scale() / std::abs(m.impedance);
      }
    }
    return column;
  }

  /// The evaluation at x: Levenberg-Marquardt asks for the Jacobian at its best point,
  /// which need not be the last one evaluated, so the last few are kept.
  Evaluation evaluated(const Eigen::VectorXd& x) {
    for (const Evaluation& e : recent_) {
      if (e.x == x) return e;
    }
    Evaluation e = evaluate(x, best_recent());
    if (recent_.size() == 4) recent_.erase(recent_.begin());
    recent_.push_back(e);
    return e;
  }

  /// The kept evaluation with the smallest residuals (none at first).
  const Evaluation* best_recent() const {
    const Evaluation* best = nullptr;
    for (const Evaluation& e : recent_) {
      if (!best || e.residuals.squaredNorm() < best->residuals.squaredNorm()) best = &e;
    }
    return best;
  }

  template <class Task>
  void run_in_parallel(std::size_t count, Task task) const {
    parallel_for(count, options_.threads, task);
  }

  const FitVariables& variables_;
  const ImpedanceMeasurement& measurement_;
  const ImpedanceIdentificationOptions& options_;
  int max_sections_;
  std::vector<Evaluation> recent_;
  std::atomic<int> evaluations_{0};
};

/// How a law's numbers scale with the damper: "ei_min and ei_max times s^3, chi0 times s^-2".
std::string scaling_words(const cable::SectionLawDescriptor& law) {
  std::vector<int> powers;
  for (const cable::LawNumber& n : law.numbers()) {
    if (n.scaling_power != 0 && std::find(powers.begin(), powers.end(), n.scaling_power) == powers.end()) {
      powers.push_back(n.scaling_power);
    }
  }
  std::string out;
  for (int p : powers) {
    std::vector<std::string> keys;
    for (const cable::LawNumber& n : law.numbers()) {
      if (n.scaling_power == p) keys.push_back(std::string(n.key));
    }
    out += fmt::format("{}{} times s{}", out.empty() ? "" : ", ", cable::joined_with_and(keys),
                       p == 1 ? "" : fmt::format("^{}", p));
  }
  return out;
}

/// Parameter i outside the null space and resolved within kUndeterminedResolution.
bool determined_on_its_own(const std::vector<ParameterEstimate>& parameters, const least_squares::Statistics& s,
                           std::size_t i) {
  return !s.in_null_space[i] && parameters[i].resolution_at_1_percent <= kUndeterminedResolution;
}

/// The first parameter not determined on its own whose estimate is correlated with
/// parameter i's beyond kTiedCorrelation; -1 if none.
int tied_partner(const std::vector<ParameterEstimate>& parameters, const least_squares::Statistics& s, std::size_t i) {
  for (std::size_t j = 0; j < parameters.size(); ++j) {
    const double r = s.correlation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    if (j != i && !determined_on_its_own(parameters, s, j) && std::abs(r) > kTiedCorrelation) return static_cast<int>(j);
  }
  return -1;
}

/// Each variable's estimate (value, standard error, resolution, sensitivity), in the variables' order.
std::vector<ParameterEstimate> estimates(const FitVariables& variables, const Eigen::VectorXd& x,
                                         const least_squares::Statistics& s) {
  std::vector<ParameterEstimate> out;
  for (int i = 0; i < variables.size(); ++i) {
    ParameterEstimate e;
    e.name = variables.name(i);
    e.unit = variables.unit(i);
    if (variables.fits_clamp_mass() && i == variables.clamp_mass_index()) {
      // A linear variable in units of the damper's mass: its resolution in those units.
      e.value = variables.clamp_mass(x);
      e.geometry = true;
      e.standard_error = variables.mass_scale() * s.standard_error(i);
      e.resolution_at_1_percent = s.resolution(i);
      e.sensitivity = s.sensitivity(i) / variables.mass_scale();
    } else if (const DamperNumber* n = variables.number(i)) {
      e.value = n->value(x(i));
      e.geometry = true;
      // A log variable's errors are relative; an offset's in units of its scale.
      e.standard_error = (n->logarithmic ? e.value : n->scale) * s.standard_error(i);
      e.resolution_at_1_percent = s.resolution(i);
      e.sensitivity = n->logarithmic ? s.sensitivity(i) : s.sensitivity(i) / n->scale;
    } else {
      e.value = variables.cable_value(x, i);
      // A log variable: relative errors; a linear one's in units of its step.
      const double scale = variables.linear_scale(i);
      e.standard_error = (scale > 0.0 ? scale : e.value) * s.standard_error(i);
      e.resolution_at_1_percent = s.resolution(i);
      e.sensitivity = scale > 0.0 ? s.sensitivity(i) / scale : s.sensitivity(i);
    }
    if (s.in_null_space[static_cast<std::size_t>(i)]) e.standard_error = kInfinity;
    out.push_back(e);
  }
  // A parameter tied to an undetermined one moves with it: not determined either.
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].determined = determined_on_its_own(out, s, i) && tied_partner(out, s, i) < 0;
  }
  return out;
}

/// Each type's ei + sum c, a combination the data determine even where nothing slips
/// (none under a law of numbers, such as Bouc-Wen's, whose stick stiffness ei_max is a parameter).
std::vector<ParameterEstimate> stick_stiffnesses(const FitVariables& variables, const Eigen::VectorXd& x,
                                                 const least_squares::Statistics& s) {
  std::vector<ParameterEstimate> out;
  const std::vector<section::MasingParameters> cables = variables.cables(x);
  for (std::size_t t = 0; t < cables.size(); ++t) {
    const section::MasingParameters& p = cables[t];
    const double stiffness = p.max_stiffness();
    Eigen::VectorXd g = Eigen::VectorXd::Zero(variables.size());  // d(ei + sum c) / (ei + sum c) per log variable
    const int o = variables.per_type() * static_cast<int>(t);
    g(o) = p.ei / stiffness;
    for (int j = 0; j < variables.elements(); ++j) g(o + 1 + 2 * j) = p.jenkin[j].c / stiffness;
    ParameterEstimate e;
    e.name = variables.type_prefix(t) + "ei_plus_c";
    e.unit = "N m^2";
    e.value = stiffness;
    e.resolution_at_1_percent = s.resolution_of(g);
    e.standard_error = stiffness * s.standard_error_of(g);
    e.sensitivity = std::numeric_limits<double>::quiet_NaN();
    e.determined = e.resolution_at_1_percent <= kUndeterminedResolution;
    out.push_back(e);
  }
  return out;
}

/// One sentence per null-space direction and per poorly resolved parameter, and
/// one where the fitted model never slips.
std::vector<std::string> determination_notes(const std::vector<ParameterEstimate>& parameters,
                                             const least_squares::Statistics& s,
                                             const std::vector<ParameterEstimate>& stick,
                                             const std::vector<damper::ImpedancePoint>& fitted) {
  std::vector<std::string> notes;
  for (Eigen::Index k = 0; k < s.null_space.cols(); ++k) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      if (std::abs(s.null_space(static_cast<Eigen::Index>(i), k)) > 0.1) names.push_back(parameters[i].name);
    }
    notes.push_back(names.size() == 1 ? fmt::format("Z does not change with {}: the data do not determine it", names[0])
                                      : fmt::format("Z changes only with a combination of {}: the data do not "
                                                    "determine them apart",
                                                    fmt::join(names, ", ")));
  }
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const ParameterEstimate& p = parameters[i];
    if (p.determined || s.in_null_space[i]) continue;
    const int partner = tied_partner(parameters, s, i);
    if (p.resolution_at_1_percent <= kUndeterminedResolution && partner >= 0) {
      notes.push_back(fmt::format("{} is not determined apart from {}: their estimates are correlated at {:.6f}", p.name,
                                  parameters[static_cast<std::size_t>(partner)].name,
                                  s.correlation(static_cast<Eigen::Index>(i), partner)));
      continue;
    }
    notes.push_back(fmt::format("{} is not determined: a 1 % scatter of Z moves it by {:.3g} %", p.name,
                                100.0 * p.resolution_at_1_percent));
  }
  const bool slips = std::any_of(fitted.begin(), fitted.end(),
                                 [](const damper::ImpedancePoint& p) { return p.converged() && p.dissipated_power > 0.0; });
  if (!slips) {
    std::string stiffness;
    for (const ParameterEstimate& e : stick) stiffness += fmt::format(", {} = {:.6g} N m^2", e.name, e.value);
    notes.push_back(fmt::format("the fitted cable never slips at the measured points: they determine only its stick "
                                "stiffness{}; measure at a higher velocity or across the arms' resonances",
                                stiffness));
  }
  return notes;
}

/// The lack-of-fit test of the misfit S at the optimum against the stated `scatter`
/// of Z (m real residuals; the statistics' rank the parameters determined).
LackOfFit lack_of_fit(const least_squares::Statistics& s, double sum_of_squares, double rms, double scatter, bool assumed,
                      int residuals) {
  const double component = scatter / std::sqrt(2.0);
  const least_squares::ChiSquareTest test =
      least_squares::chi_square_test(sum_of_squares / (component * component), residuals - s.rank, lack_of_fit_level);
  LackOfFit out;
  out.scatter = scatter;
  out.assumed = assumed;
  out.ratio = rms / scatter;
  out.statistic = test.statistic;
  out.degrees_of_freedom = test.degrees_of_freedom;
  out.p_value = test.p_value;
  out.critical = test.critical;
  out.level = test.level;
  out.significant = test.significant;
  out.error_inflation = s.error_scatter / component;
  return out;
}

/// The change of parameter i's value (in its unit) for a change dx of its variable at x.
double value_change(const FitVariables& variables, const Eigen::VectorXd& x, int i, double dx) {
  if (variables.fits_clamp_mass() && i == variables.clamp_mass_index()) return variables.mass_scale() * dx;
  if (const DamperNumber* n = variables.number(i)) return n->value(x(i) + dx) - n->value(x(i));
  Eigen::VectorXd moved = x;
  moved(i) += dx;
  return variables.cable_value(moved, i) - variables.cable_value(x, i);
}

/// Marks each parameter (confounded_by, confounded_shift) that a suspect explaining
/// at least explaining_share of the misfit, moved to its suggested value, would move
/// by more than its standard error (the suspect moving it most, in standard errors),
/// and says so: one note per such suspect.
std::vector<std::string> confounding_notes(const FitVariables& variables, const Eigen::VectorXd& x,
                                           const least_squares::Statistics& s,
                                           const std::vector<FixedNumberSuspect>& suspects,
                                           const std::vector<least_squares::ExtraVariable>& steps,
                                           std::vector<ParameterEstimate>& parameters) {
  std::vector<double> worst(parameters.size(), 1.0);  // |shift| in standard errors
  for (std::size_t k = 0; k < suspects.size(); ++k) {
    if (suspects[k].misfit_reduction < explaining_share) break;  // ranked: the rest explain less
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      const double se = s.standard_error(static_cast<Eigen::Index>(i));
      const double shift = steps[k].shift(static_cast<Eigen::Index>(i));
      if (!std::isfinite(se) || !(std::abs(shift) > worst[i] * se)) continue;
      worst[i] = std::abs(shift) / se;
      parameters[i].confounded_by = suspects[k].name;
      parameters[i].confounded_shift = value_change(variables, x, static_cast<int>(i), shift);
    }
  }
  std::vector<std::string> notes;
  for (const FixedNumberSuspect& suspect : suspects) {
    std::vector<std::string> moved;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      const ParameterEstimate& p = parameters[i];
      if (p.confounded_by != suspect.name) continue;
      moved.push_back(fmt::format("{} by {:+.3g} {} ({:.2g} standard errors)", p.name, p.confounded_shift, p.unit, worst[i]));
    }
    if (moved.empty()) continue;
    notes.push_back(fmt::format("were {} {:.4g} {} instead of {:.4g}, as the lack of fit suggests, {} would move beyond "
                                "{} standard error{}: {} (free it, or check it on the drawing)",
                                suspect.name, suspect.suggested_value, suspect.unit, suspect.value,
                                moved.size() == 1 ? "this estimate" : "these estimates", moved.size() == 1 ? "its" : "their",
                                moved.size() == 1 ? "" : "s", fmt::join(moved, ", ")));
  }
  return notes;
}

}  // namespace

void ImpedanceMeasurement::validate() const {
  if (points.empty()) throw InvalidParameter("measurement", ": no points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const MeasuredImpedance& p = points[i];
    const std::string at = fmt::format("point {}: ", i + 1);
    require_plausible(at + "frequency_hz", p.excitation.frequency_hz, "Hz");
    require_positive(at + "displacement_m", p.excitation.displacement_amplitude, "m");
    if (!std::isfinite(p.impedance.real()) || !std::isfinite(p.impedance.imag()) || p.impedance == 0.0) {
      throw InvalidParameter(at + "Z", fmt::format(" = {} + {} i N s/m: expected finite and nonzero",
                                                   format_value(p.impedance.real()), format_value(p.impedance.imag())));
    }
    // The misfit divides by |Z|: a magnitude no damper has (a unit mistake) would
    // overflow it (|Z| = 1e-310 made every residual infinite).
    if (const double magnitude = std::abs(p.impedance); magnitude < smallest_magnitude || magnitude > largest_magnitude) {
      throw InvalidParameter(at + "|Z|", fmt::format(" = {} N s/m: expected a value from {:g} to {:g}; one outside is a "
                                                     "unit mistake",
                                                     format_value(magnitude), smallest_magnitude, largest_magnitude));
    }
  }
}

std::vector<std::vector<std::size_t>> measured_curves(const ImpedanceMeasurement& m) {
  std::vector<std::size_t> order(m.points.size());
  std::iota(order.begin(), order.end(), 0);
  auto amplitude = [&](std::size_t i) { return held_amplitude(m.points[i].excitation, m.held); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return amplitude(a) < amplitude(b); });
  std::vector<std::vector<std::size_t>> curves;
  double smallest = 0.0;
  for (const std::size_t i : order) {
    if (curves.empty() || amplitude(i) > kCurveAmplitudeRatio * smallest) {
      curves.emplace_back();
      smallest = amplitude(i);
    }
    curves.back().push_back(i);
  }
  for (std::vector<std::size_t>& curve : curves) {
    std::stable_sort(curve.begin(), curve.end(), [&](std::size_t a, std::size_t b) {
      return m.points[a].excitation.frequency_hz < m.points[b].excitation.frequency_hz;
    });
  }
  return curves;
}

std::vector<std::size_t> cable_types(const damper::DamperDescription& d) {
  std::vector<std::size_t> type(d.arms.size());
  std::vector<std::size_t> first_of_type;
  for (std::size_t k = 0; k < d.arms.size(); ++k) {
    const cable::CableDescription& c = d.arms[k].cable;
    auto same = [&](std::size_t f) {
      const cable::CableDescription& first = d.arms[f].cable;
      return first.law == c.law && first.ei == c.ei && first.jenkin == c.jenkin && first.numbers == c.numbers;
    };
    const auto found = std::find_if(first_of_type.begin(), first_of_type.end(), same);
    type[k] = static_cast<std::size_t>(found - first_of_type.begin());
    if (found == first_of_type.end()) first_of_type.push_back(k);
  }
  return type;
}

void ImpedanceIdentificationOptions::validate() const {
  require_in_range("elements", elements, 1, 6);
  require_in_range("max_jacobians", max_jacobians, 1, 10000);
  require_in_range("threads", threads, 1, 1024);
  if (!(std::isfinite(rms_limit) && rms_limit > 0.0)) {
    throw_invalid("rms_limit", rms_limit, "a finite fraction > 0 (0.1 for 10 %)");
  }
  if (scatter && !(std::isfinite(*scatter) && *scatter > 0.0 && *scatter < 1.0)) {
    throw_invalid("scatter", *scatter, "a fraction of |Z| > 0 and < 1 (0.01 for 1 %)");
  }
  solver.validate();
}

std::vector<damper::ImpedancePoint> model_impedance(const damper::Damper& damper, const ImpedanceMeasurement& m,
                                                    const damper::SolverOptions& solver) {
  return solve_points(damper, m, solver, nullptr, nullptr);
}

ImpedanceIdentification identify_impedance(const damper::DamperDescription& start, const ImpedanceMeasurement& measurement,
                                           const ImpedanceIdentificationOptions& options) {
  options.validate();
  measurement.validate();
  (void)damper::Damper(start);  // validates the start, naming its fields
  const FitVariables variables(start, options);
  if (2 * measurement.points.size() < static_cast<std::size_t>(variables.size())) {
    throw InvalidParameter("measurement", fmt::format(": {} points for {} parameters: expected at least {}",
                                       measurement.points.size(), variables.size(), (variables.size() + 1) / 2));
  }
  ImpedanceIdentificationOptions converged = options;
  for (damper::HarmonicBalanceOptions* o : {&converged.solver.harmonic_balance, &converged.solver.collocation}) {
    o->tolerance = std::min(o->tolerance, kModelTolerance);
    o->periodicity_tolerance = std::min(o->periodicity_tolerance, kModelTolerance);
  }
  ImpedanceProblem coarse(variables, measurement, converged, kExploreSections);
  ImpedanceProblem problem(variables, measurement, converged);

  // Each start explored briefly on coarse cables, the best polished to convergence.
  // The first start's run is kept whatever its misfit, so that a misfit that is not
  // finite at every start (no run better than another) still polishes a start rather
  // than an empty point.
  least_squares::Run best;
  int starts = 0;
  for (const Eigen::VectorXd& x : variables.starts()) {
    least_squares::Run run = least_squares::levenberg_marquardt(coarse, x, std::min(kExploreJacobians, options.max_jacobians));
    ++starts;
    if (starts == 1 || run.sum_of_squares < best.sum_of_squares) best = std::move(run);
    if (std::sqrt(best.sum_of_squares / measurement.points.size()) < kReproducedError) break;
  }
  best = least_squares::levenberg_marquardt(problem, best.x, options.max_jacobians);

  const Eigen::VectorXd x = variables.sorted(best.x);
  const double sum_of_squares = problem.residuals(x).squaredNorm();
  // The damper's exact scalings (FitVariables::scalings) are null directions of the
  // Jacobian, which its forward differences would blur into a small but finite
  // singular value: they are projected out, so that the statistics see them exactly.
  Eigen::MatrixXd jacobian = problem.jacobian(x);
  const std::vector<Eigen::VectorXd> scalings = variables.scalings(x);
  for (const Eigen::VectorXd& g : scalings) jacobian -= (jacobian * g) * g.transpose();  // disjoint supports: orthogonal
  // The standard errors at the stated scatter per real residual (s / sqrt(2)), or at
  // the residuals' own where larger (a lack of fit inflates them).
  const double scatter = options.scatter.value_or(default_scatter);
  const double component_scatter = scatter / std::sqrt(2.0);
  const least_squares::Statistics statistics =
      least_squares::statistics(jacobian, sum_of_squares, kStatedScatter, component_scatter);

  ImpedanceIdentification result;
  result.cable_type = variables.type_of_arm();
  result.law = variables.law();
  result.cables = variables.cables(x);
  result.law_cables = variables.law_cables(x);
  result.clamp_mass = variables.clamp_mass(x);
  result.damper = variables.damper(x, std::max(0.0, result.clamp_mass));
  result.misfit = sum_of_squares;
  result.rms_relative_error = std::sqrt(sum_of_squares / static_cast<double>(measurement.points.size()));
  result.rms_limit = options.rms_limit;
  result.poor_fit = result.rms_relative_error > options.rms_limit;
  result.parameters = estimates(variables, x, statistics);
  result.lack_of_fit = lack_of_fit(statistics, sum_of_squares, result.rms_relative_error, scatter, !options.scatter.has_value(),
                                   static_cast<int>(jacobian.rows()));
  result.correlation = statistics.correlation;
  result.stick_stiffness = stick_stiffnesses(variables, x, statistics);
  result.fitted = problem.points(x);
  result.not_converged = static_cast<int>(
      std::count_if(result.fitted.begin(), result.fitted.end(), [](const damper::ImpedancePoint& p) { return !p.converged(); }));
  result.notes = determination_notes(result.parameters, statistics, result.stick_stiffness, result.fitted);
  if (!scalings.empty()) {
    result.notes.push_back(fmt::format(
        "a damper scaled by any s (cable lengths and offsets times s, inertias times s^2, {}) has the same impedance: "
        "the data do not determine its size; fix one arm's inertia, cable length or (nonzero) offset at the drawing's "
        "value (leave it out of free)",
        variables.numbered() ? scaling_words(*variables.law()) : "ei and c times s^3, h times s"));
  }
  if (result.lack_of_fit.significant) {
    const Eigen::VectorXd residuals = problem.residuals(x);
    const std::vector<DamperNumber> fixed = fixed_numbers(start, variables.numbers());
    const bool clamp_mass = !variables.fits_clamp_mass();
    const Eigen::MatrixXd columns = problem.fixed_number_columns(x, fixed, clamp_mass);
    std::vector<least_squares::ExtraVariable> steps;
    for (Eigen::Index k = 0; k < columns.cols(); ++k) {
      least_squares::ExtraVariable step = least_squares::extra_variable(jacobian, residuals, columns.col(k));
      FixedNumberSuspect suspect;
      if (k < static_cast<Eigen::Index>(fixed.size())) {
        const DamperNumber& n = fixed[static_cast<std::size_t>(k)];
        suspect = {n.path, n.unit, n.start, 0.0, n.value(step.step)};
      } else {
        suspect = {"clamp.mass", "kg", start.clamp_mass, 0.0, start.clamp_mass + variables.mass_scale() * step.step};
      }
      suspect.misfit_reduction = sum_of_squares > 0.0 ? std::min(1.0, step.reduction / sum_of_squares) : 0.0;
      result.lack_of_fit.suspects.push_back(suspect);
      steps.push_back(std::move(step));
    }
    std::vector<std::size_t> order(steps.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return result.lack_of_fit.suspects[a].misfit_reduction > result.lack_of_fit.suspects[b].misfit_reduction;
    });
    std::vector<FixedNumberSuspect> ranked;
    std::vector<least_squares::ExtraVariable> ranked_steps;
    for (const std::size_t k : order) {
      ranked.push_back(result.lack_of_fit.suspects[k]);
      ranked_steps.push_back(steps[k]);
    }
    result.lack_of_fit.suspects = std::move(ranked);
    result.lack_of_fit.notes =
        confounding_notes(variables, x, statistics, result.lack_of_fit.suspects, ranked_steps, result.parameters);
  }
  result.fit = best.summary;
  if (!best.summary.converged()) {
    result.notes.push_back(fmt::format("the fit stopped short of its tolerance after {} iterations ({}): the estimates are "
                                       "the best point reached",
                                       best.jacobians, termination_name(best.summary.termination)));
  }
  result.model_evaluations = coarse.evaluations() + problem.evaluations() + 1;
  result.starts = starts;
  return result;
}

}  // namespace stockbridge::identification
