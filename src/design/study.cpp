#include "stockbridge/design/study.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/damper_numbers.hpp"

namespace stockbridge::design {

// A damper file's numbers by their paths: the damper module's (the identification frees them too).
using damper::ArmPath;
using damper::damper_number;
using damper::set_damper_number;
using damper::split_arm_path;

Objective parse_objective(std::string_view name) {
  if (name == "max_stress") return Objective::max_stress;
  if (name == "life") return Objective::life;
  throw InvalidParameter("objective", fmt::format(" = '{}': expected max_stress or life", printable(name)));
}

std::string_view objective_name(Objective objective) { return objective == Objective::life ? "life" : "max_stress"; }

namespace {

/// The span's first damper at the ends (by `position`), or none: the one a position variable places.
const span::SpanDamper* first_end_damper(const span::Span& span) {
  const auto& d = span.dampers();
  const auto first = std::find_if(d.begin(), d.end(), [](const span::SpanDamper& x) { return !x.in_span(); });
  return first == d.end() ? nullptr : &*first;
}

/// A variable's or tie's path must name a number of the base damper.
void check_path(const std::string& field, const std::string& path, const damper::DamperDescription& base) {
  try {
    damper_number(base, path);
  } catch (const InvalidParameter& error) {
    throw InvalidParameter(field, fmt::format(" = \"{}\"{}", printable(path), error.detail()));
  }
}

void validate_variable(const DesignVariable& v, std::size_t i, const damper::DamperDescription& base,
                       const std::vector<DesignSpan>& spans) {
  const std::string field = fmt::format("variable[{}]", i);
  if (!std::isfinite(v.min)) throw_invalid(field + ".min", v.min, "a finite bound");
  if (!std::isfinite(v.max)) throw_invalid(field + ".max", v.max, "a finite bound");
  if (!(v.min < v.max)) throw_invalid(field + ".max", v.max, fmt::format("a value > min = {}", v.min));
  if (v.name == kPosition || v.name == kPositionLoopFraction) {
    if (!(v.min > 0.0)) throw_invalid(field + ".min", v.min, "a position > 0 m from the span clamp");
    if (v.name == kPositionLoopFraction && !(v.max <= 5.0)) {
      throw_invalid(field + ".max", v.max, "a fraction of the shortest loop up to 5");
    }
    for (const DesignSpan& s : spans) {
      const span::SpanDamper* first = first_end_damper(s.span);
      if (!first) {
        throw InvalidParameter(field + ".name", fmt::format(" = \"{}\": span {} has no [[damper]] at its ends (position) "
                                                            "to move",
                                                            v.name, s.name));
      }
      double last = 0.0;  // the farthest damper at the ends beyond the first, which the position places
      for (const span::SpanDamper& d : s.span.dampers()) {
        if (!d.in_span()) last = std::max(last, d.position - first->position);
      }
      const double farthest = v.name == kPosition ? v.max : v.max * span::shortest_loop(s.span);
      if (!(farthest + last < 0.5 * s.span.length())) {
        throw_invalid(field + ".max", v.max, fmt::format("a position whose dampers stay within half of span {} ({} m)", s.name,
                                                         0.5 * s.span.length()));
      }
    }
    return;
  }
  check_path(field + ".name", v.name, base);
}

}  // namespace

DesignStudy::DesignStudy(damper::DamperDescription base, std::vector<DesignSpan> spans, Objective objective,
                         std::vector<DesignVariable> variables, std::vector<DesignTie> ties,
                         DesignConstraints constraints, int points)
    : base_(std::move(base)),
      spans_(std::move(spans)),
      objective_(objective),
      variables_(std::move(variables)),
      ties_(std::move(ties)),
      constraints_(constraints),
      points_(points) {
  within_field("damper", [&] { damper::Damper{base_}; });
  if (spans_.empty()) throw InvalidParameter("spans", ": expected at least one span file");
  if (variables_.empty()) throw InvalidParameter("variable", ": expected at least one [[variable]]");
  require_in_range("points", points_, 2, 100000);
  for (std::size_t i = 0; i < variables_.size(); ++i) {
    validate_variable(variables_[i], i, base_, spans_);
    for (std::size_t j = 0; j < i; ++j) {
      if (variables_[j].name == variables_[i].name) {
        throw InvalidParameter(fmt::format("variable[{}].name", i),
                               fmt::format(" = \"{}\": already variable[{}]", printable(variables_[i].name), j));
      }
    }
  }
  for (std::size_t i = 0; i < ties_.size(); ++i) {
    const DesignTie& t = ties_[i];
    const std::string field = fmt::format("tie[{}]", i);
    check_path(field + ".name", t.name, base_);
    const auto followed = std::find_if(variables_.begin(), variables_.end(), [&](const auto& v) { return v.name == t.equals; });
    if (followed == variables_.end() || t.equals == kPosition || t.equals == kPositionLoopFraction) {
      throw InvalidParameter(field + ".equals",
                             fmt::format(" = \"{}\": expected the name of a damper [[variable]]", printable(t.equals)));
    }
    for (const DesignVariable& v : variables_) {
      if (v.name == t.name) {
        throw InvalidParameter(field + ".name", fmt::format(" = \"{}\": is a [[variable]] itself", printable(t.name)));
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (ties_[j].name == t.name) {
        throw InvalidParameter(field + ".name", fmt::format(" = \"{}\": already tie[{}]", printable(t.name), j));
      }
    }
  }
  if (constraints_.total_mass_max) require_positive("constraints.total_mass_max", *constraints_.total_mass_max, "kg");
  if (constraints_.messenger_curvature_max) {
    require_positive("constraints.messenger_curvature_max", *constraints_.messenger_curvature_max, "1/m");
  }
  if (objective_ == Objective::life) {
    for (const DesignSpan& s : spans_) {
      if (!s.span.fatigue().life) {
        throw InvalidParameter("objective", fmt::format(" = \"life\": span {} gives no wind climate ([fatigue] wind_weibull)", s.name));
      }
    }
  }
}

std::vector<double> DesignStudy::base_values() const {
  std::vector<double> x;
  for (const DesignVariable& v : variables_) {
    const double first = v.name == kPosition || v.name == kPositionLoopFraction ? first_end_damper(spans_.front().span)->position : 0.0;
    x.push_back(v.name == kPosition               ? first
                : v.name == kPositionLoopFraction ? first / shortest_loop(0)
                                                  : damper_number(base_, v.name));
  }
  return x;
}

damper::DamperDescription DesignStudy::damper_of(const std::vector<double>& x) const {
  if (x.size() != variables_.size()) {
    throw InvalidParameter("x", fmt::format(": {} values for {} variables", x.size(), variables_.size()));
  }
  damper::DamperDescription d = base_;
  std::vector<std::string> set;  // the paths given values
  const auto assign = [&](const std::string& path, double value) {
    set_damper_number(d, path, value);
    set.push_back(path);
  };
  for (std::size_t i = 0; i < variables_.size(); ++i) {
    if (variables_[i].name != kPosition && variables_[i].name != kPositionLoopFraction) assign(variables_[i].name, x[i]);
  }
  for (const DesignTie& t : ties_) {
    const auto k = std::find_if(variables_.begin(), variables_.end(), [&](const auto& v) { return v.name == t.equals; });
    assign(t.name, x[static_cast<std::size_t>(k - variables_.begin())]);
  }
  // Constant radius of gyration where the mass changes and the inertia is not given.
  for (std::size_t a = 0; a < d.arms.size(); ++a) {
    bool mass_set = false, inertia_set = false;
    for (const std::string& path : set) {
      if (path == "clamp.mass") continue;
      const ArmPath p = split_arm_path(d, path);
      if (p.arm != a) continue;
      mass_set = mass_set || p.field == "mass";
      inertia_set = inertia_set || p.field == "inertia";
    }
    if (mass_set && !inertia_set) d.arms[a].inertia = base_.arms[a].inertia * d.arms[a].mass / base_.arms[a].mass;
  }
  return d;
}

double DesignStudy::shortest_loop(std::size_t k) const { return span::shortest_loop(spans_.at(k).span); }

std::optional<double> DesignStudy::position_on(std::size_t k, const std::vector<double>& x) const {
  for (std::size_t i = 0; i < variables_.size(); ++i) {
    if (variables_[i].name == kPosition) return x.at(i);
    if (variables_[i].name == kPositionLoopFraction) return x.at(i) * shortest_loop(k);
  }
  return std::nullopt;
}

std::optional<double> DesignStudy::position_of(const std::vector<double>& x) const {
  for (std::size_t i = 0; i < variables_.size(); ++i) {
    if (variables_[i].name == kPosition) return x.at(i);
  }
  return std::nullopt;
}

span::Span DesignStudy::span_with(std::size_t k, const damper::Damper& damper, std::optional<double> position) const {
  const span::Span& s = spans_.at(k).span;
  std::vector<span::SpanDamper> dampers = s.dampers();
  for (span::SpanDamper& d : dampers) {
    d.damper = damper;
    d.sheet.reset();  // a span's measured damper is replaced by the candidate too
  }
  const span::Span with = s.with_dampers(std::move(dampers));
  return position ? with.with_dampers_at(*position) : with;
}

namespace {

/// What a candidate needs of a span's points, taken as they are balanced (none held):
/// the first that did not converge, and the largest messenger curvature.
struct PointFigures {
  std::optional<span::BalancePoint> first_failure;
  double messenger_curvature = 0.0;

  void take(span::BalancePoint&& p) {
    if (!p.converged()) {
      if (!first_failure) first_failure = std::move(p);
      return;
    }
    for (const span::DamperAtBalance& d : p.dampers) {
      messenger_curvature = std::max(messenger_curvature, d.messenger_curvature_max);
    }
  }
};

/// The constraint a converged candidate breaks, if any.
std::string broken_constraint(const DesignConstraints& c, const Evaluation& e) {
  if (c.total_mass_max && e.total_mass > *c.total_mass_max) {
    return fmt::format("total mass {:.4g} kg > total_mass_max {:.4g} kg", e.total_mass, *c.total_mass_max);
  }
  if (c.messenger_curvature_max && !(e.messenger_curvature_max <= *c.messenger_curvature_max)) {
    return fmt::format("messenger curvature {:.4g} 1/m > messenger_curvature_max {:.4g} 1/m", e.messenger_curvature_max,
                       *c.messenger_curvature_max);
  }
  return {};
}

}  // namespace

Evaluation evaluate(const DesignStudy& study, const std::vector<double>& x, TableCache* cache) {
  Evaluation e;
  e.x = x;
  std::optional<damper::Damper> damper;
  try {
    damper.emplace(study.damper_of(x));
  } catch (const InvalidParameter& error) {
    e.infeasibility = fmt::format("the candidate damper is not valid: {}", error.what());
    return e;
  }
  e.total_mass = damper->total_mass();
  std::vector<double> damper_key;  // the damper variables' values: what the tables depend on
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::string& name = study.variables()[i].name;
    if (name != kPosition && name != kPositionLoopFraction) damper_key.push_back(x[i]);
  }
  double ratio = 0.0, curvature = 0.0, life = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < study.spans().size(); ++k) {
    const DesignSpan& design_span = study.spans()[k];
    std::optional<span::Span> s;
    try {
      s.emplace(study.span_with(k, *damper, study.position_on(k, x)));
    } catch (const InvalidParameter& error) {
      e.infeasibility = fmt::format("span {}: {}", design_span.name, error.what());
      return e;
    }
    span::AnalysisOptions options;
    options.balance = design_span.balance;
    PointFigures figures;
    options.take_point = [&figures](const span::Span&, span::BalancePoint&& p) { figures.take(std::move(p)); };
    const span::TableSource tables = [&](const span::Span& with, const std::vector<double>& f,
                                         const span::ImpedanceTableOptions& table) {
      const auto make = [&] { return std::make_shared<const span::SpanTables>(with, f, table); };
      if (!cache) return make();
      TableCache::Key key{static_cast<double>(k)};
      key.insert(key.end(), damper_key.begin(), damper_key.end());
      return cache->get(key, make);
    };
    const span::SpanAnalysis a = span::analyse_span(*s, span::band_frequencies(*s, study.points()), options, {}, tables);
    const span::BalanceSummary& b = a.balance.summary;
    if (const std::optional<span::BalancePoint>& p = figures.first_failure) {
      e.termination = p->summary.termination;
      e.failure = fmt::format("span {}: {} of {} points did not converge, first at {:.4g} Hz: {}", design_span.name,
                              b.points - b.converged, b.points, p->frequency_hz, brief_report(p->summary));
      return e;
    }
    const double r = b.max_judged_stress / b.endurance_limit;
    e.spans.push_back(SpanFigures{r, b.max_judged_stress, b.undamped_max_judged_stress,
                                  b.life ? b.life->life_years : std::numeric_limits<double>::quiet_NaN(),
                                  b.max_judged_stress_place});
    if (k == 0 || r > ratio) {
      ratio = r;
      e.max_stress = b.max_judged_stress;
      e.frequency_at_max_hz = b.max_judged_stress_frequency_hz;
      e.span_at_max = k;
      e.place_at_max = b.max_judged_stress_place;
    }
    curvature = std::max(curvature, figures.messenger_curvature);
    if (b.life) life = std::min(life, b.life->life_years);
  }
  e.termination = Termination::converged;
  e.max_stress_ratio = ratio;
  e.messenger_curvature_max = curvature;
  if (study.objective() == Objective::life) e.shortest_life_years = life;
  // An infinite life (no damage at all) is capped for the comparison (and the optimiser).
  e.objective = study.objective() == Objective::life ? -std::min(life, 1e12) : ratio;
  e.infeasibility = broken_constraint(study.constraints(), e);
  return e;
}

std::vector<double> rounded_candidate(const DesignStudy& study, const std::vector<double>& x, int digits) {
  if (digits < 1 || digits > 15) {
    throw InvalidParameter(fmt::format("round_digits = {}: expected 1 to 15 significant digits", digits));
  }
  std::vector<double> out = x;
  for (std::size_t d = 0; d < out.size() && d < study.variables().size(); ++d) {
    const DesignVariable& v = study.variables()[d];
    const double value = out[d];
    if (value == 0.0 || !std::isfinite(value)) continue;
    const double unit = std::pow(10.0, std::floor(std::log10(std::abs(value))) - (digits - 1));
    double r = std::round(value / unit) * unit;
    if (r > v.max) r = std::floor(v.max / unit) * unit;
    if (r < v.min) r = std::ceil(v.min / unit) * unit;
    // Printed to `digits` digits, the value reads back as itself.
    out[d] = std::stod(fmt::format("{:.{}g}", r, digits + 1));
  }
  return out;
}

}  // namespace stockbridge::design
