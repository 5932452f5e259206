#include "stockbridge/span/position_search.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <numeric>
#include <optional>

#include <fmt/format.h>
#include <nlopt.hpp>

#include "balance_summary.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

std::string_view position_objective_name(PositionObjective objective) {
  return objective == PositionObjective::life ? "life" : "max_stress";
}

void PositionRules::validate() const {
  require_positive("position_min", position_min, "m");
  if (!(position_max > position_min && std::isfinite(position_max))) {
    throw_invalid("position_max", position_max, "a value > position_min (m)");
  }
  require_non_negative("spacing_min", spacing_min, "m");
  require_in_range("scan_points", scan_points, 3, 10000);
  require_in_range("max_evaluations", max_evaluations, 4, 100000);
  require_in_range("local_searches", local_searches, 1, 5);
}

double position_objective(const SpanBalance& balance, PositionObjective objective) {
  const BalanceSummary& s = balance.summary;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!s.all_converged()) return kInf;
  if (objective == PositionObjective::max_stress) return s.max_judged_stress / s.endurance_limit;
  if (!s.life) return kInf;
  // Damage 0 (no stress at all) is the best there is: a floor keeps the log finite.
  return std::log10(std::max(s.life->damage_per_year, 1e-300));
}

double shortest_loop(const Span& span) {
  const double f_max = band_frequencies(span, 2).back();
  return std::sqrt(span.tension() / span.conductor().mass_per_length) / (2.0 * f_max);
}

std::vector<double> usual_positions(const Span& span, double f_max, int count, double fraction, const PositionRules& rules) {
  const double speed = std::sqrt(span.tension() / span.conductor().mass_per_length);
  const double loop = speed / (2.0 * f_max);
  std::vector<double> x(static_cast<std::size_t>(count));
  double spacing = std::max(rules.spacing_min, fraction * loop);
  x[0] = std::clamp(fraction * loop, rules.position_min, rules.position_max);
  for (std::size_t k = 1; k < x.size(); ++k) {
    spacing = std::max(rules.spacing_min, 1.3 * spacing);
    x[k] = x[k - 1] + spacing;
  }
  // Pushed back inside the range from its far end, the spacings kept where they fit.
  for (std::size_t k = x.size(); k-- > 0;) {
    const double room = rules.position_max - static_cast<double>(x.size() - 1 - k) * rules.spacing_min;
    x[k] = std::min(x[k], room);
    if (k + 1 < x.size()) x[k] = std::min(x[k], x[k + 1] - rules.spacing_min);
  }
  return x;
}

namespace {

/// The dampers a search places: those at the ends (`position`), by their positions;
/// dampers along the span stay where the span has them.
std::vector<std::size_t> placed_dampers(const Span& span) {
  std::vector<std::size_t> order;
  for (std::size_t j = 0; j < span.dampers().size(); ++j) {
    if (!span.dampers()[j].in_span()) order.push_back(j);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return span.dampers()[a].position < span.dampers()[b].position;
  });
  return order;
}

BalanceOptions with_polish_off(BalanceOptions options) {
  options.polish = false;  // on the tables alone
  return options;
}

/// One search: the dampers' order (by their positions in the span), the balances
/// made and the best arrangement seen.
class PositionObjectiveRun {
 public:
  PositionObjectiveRun(const Span& span, const SpanTables& tables, const BalanceOptions& options,
                       const PositionRules& rules, const std::function<bool()>& stop)
      : span_(span),
        tables_(tables),
        options_(with_polish_off(options)),
        rules_(rules),
        stop_(stop),
        order_(placed_dampers(span)),
        undamped_(span, tables, options_),
        frequency_order_(tables.frequencies().size()) {
    std::iota(frequency_order_.begin(), frequency_order_.end(), std::size_t{0});
    options_.validate();
    if (tables.tables().size() != span.dampers().size()) {
      throw std::invalid_argument(fmt::format("optimise_positions: {} impedance tables for {} dampers",
                                              tables.tables().size(), span.dampers().size()));
    }
    best_.objective = std::numeric_limits<double>::infinity();
    best_.criterion = rules.objective;
  }

  /// The objective with the dampers at `sorted` (increasing, m); the best kept.
  /// `bound`: the caller needs the value only where it is at most this (a scan's or
  /// a ranking's best so far). With the max_stress objective the frequencies are
  /// balanced in the order of the best arrangement's stresses, largest first, and an
  /// arrangement stops at the first point that shows its value above `bound` (a
  /// stress, or a point not converged: +inf): what it returns then is that point's
  /// value, above `bound` and at most its own, never the best.
  double operator()(const std::vector<double>& sorted, double bound = std::numeric_limits<double>::infinity()) {
    if (stop_ && stop_()) throw Interrupted("the position search was stopped");
    std::vector<SpanDamper> dampers = span_.dampers();
    for (std::size_t k = 0; k < order_.size(); ++k) dampers[order_[k]].position = sorted[k];
    ++best_.balances;
    const Span arranged = span_.with_dampers(std::move(dampers));
    std::optional<SpanBalance> b = balance_within(arranged, bound);
    if (!b) return shown_;
    const double value = position_objective(*b, rules_.objective);
    // COBYLA may try arrangements a little inside the spacing on its way: never the answer.
    bool spaced = true;
    for (std::size_t k = 1; k < sorted.size(); ++k) spaced = spaced && sorted[k] - sorted[k - 1] >= rules_.spacing_min - 1e-9;
    if (spaced && value < best_.objective) {
      best_.objective = value;
      best_.max_stress_fymax = b->summary.max_stress_fymax;
      best_sorted_ = sorted;
      order_by_stress(arranged, *b);
    }
    if (spaced && value < basin_.first) basin_ = {value, sorted};
    return value;
  }

  /// A local search begins: its best is kept apart from the others'.
  void begin_basin(const std::vector<double>& start, double value) { basin_ = {value, start}; }
  /// The best of the local search that just ended.
  void end_basin() {
    if (std::isfinite(basin_.first)) basins_.push_back(basin_);
  }

  PositionSearch result() const {
    PositionSearch out = best_;
    for (const SpanDamper& d : span_.dampers()) out.positions.push_back(d.position);
    if (best_sorted_.empty()) return out;  // no arrangement converged: the span's own
    const auto placed = [&](const std::vector<double>& sorted) {
      std::vector<double> positions = out.positions;
      for (std::size_t k = 0; k < order_.size(); ++k) positions[order_[k]] = sorted[k];
      return positions;
    };
    std::vector<std::pair<double, std::vector<double>>> others = basins_;
    std::stable_sort(others.begin(), others.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [value, sorted] : others) {
      if (sorted != best_sorted_) out.runners_up.push_back(placed(sorted));
    }
    out.positions = placed(best_sorted_);
    return out;
  }
  const std::vector<double>& best_sorted() const { return best_sorted_; }
  double best_objective() const { return best_.objective; }

 private:
  /// The balance of `arranged` at every frequency, in frequency_order_; none where a
  /// point showed the value above `bound` (shown_: what it showed).
  std::optional<SpanBalance> balance_within(const Span& arranged, double bound) {
    const bool bounded = rules_.objective == PositionObjective::max_stress;
    const double limit = arranged.endurance_limit();
    std::vector<BalancePoint> points(tables_.frequencies().size());
    double largest = 0.0;  // the judged stress over the points so far, Pa (summarise's Largest)
    for (const std::size_t i : frequency_order_) {
      ++best_.points;
      points[i] = balance_on_tables(arranged, tables_, i, options_, undamped_);
      if (!points[i].converged()) {
        shown_ = std::numeric_limits<double>::infinity();  // position_objective's for a point not converged
        return std::nullopt;
      }
      if (const double s = judged_stress(arranged, points[i]); std::isfinite(s) && s > largest) largest = s;
      if (bounded && largest / limit > bound) {
        shown_ = largest / limit;
        return std::nullopt;
      }
    }
    SpanBalance b;
    b.points = std::move(points);
    b.summary = summarise(arranged, b.points);
    return b;
  }

  /// The frequencies from the largest judged stress of `best` to the smallest: where
  /// another arrangement most likely shows itself worse first.
  void order_by_stress(const Span& arranged, const SpanBalance& best) {
    std::vector<double> stress(best.points.size());
    for (std::size_t i = 0; i < stress.size(); ++i) stress[i] = judged_stress(arranged, best.points[i]);
    std::stable_sort(frequency_order_.begin(), frequency_order_.end(),
                     [&](std::size_t a, std::size_t b) { return stress[a] > stress[b]; });
  }

  const Span& span_;
  const SpanTables& tables_;
  BalanceOptions options_;
  const PositionRules& rules_;
  const std::function<bool()>& stop_;
  std::vector<std::size_t> order_;
  UndampedFigures undamped_;  ///< the same for every arrangement
  std::vector<std::size_t> frequency_order_;  ///< the order the tables' frequencies are balanced in
  double shown_ = 0.0;                        ///< what the last arrangement stopped early showed
  PositionSearch best_;
  std::vector<double> best_sorted_;
  std::pair<double, std::vector<double>> basin_{std::numeric_limits<double>::infinity(), {}};  ///< this local search's best
  std::vector<std::pair<double, std::vector<double>>> basins_;  ///< each finished local search's best
};

/// One damper: a scan for the best basin (the objective over the position has a
/// local minimum near every node of the shortest waves), then golden sections in it.
void search_one(PositionObjectiveRun& run, const PositionRules& rules) {
  const double lo0 = rules.position_min, step = (rules.position_max - lo0) / (rules.scan_points - 1);
  std::size_t k_best = 0;
  double f_best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < rules.scan_points; ++k) {
    const double f = run({lo0 + k * step}, f_best);  // only a value below the best so far matters
    if (f < f_best) f_best = f, k_best = static_cast<std::size_t>(k);
  }
  double lo = std::max(lo0, lo0 + (static_cast<double>(k_best) - 1.0) * step);
  double hi = std::min(rules.position_max, lo0 + (static_cast<double>(k_best) + 1.0) * step);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  // Each new point is compared with the one kept: where it shows itself above that,
  // it is the one dropped, and its exact value is not needed.
  double f1 = run({x1}), f2 = run({x2}, f1);
  while (hi - lo > 1e-3 * step) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = run({x1}, f2);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = run({x2}, f1);
    }
  }
}

struct LocalSearch {
  PositionObjectiveRun* run;
  double spacing_min;
  std::size_t k;  // the constraint's pair (k, k + 1)
};

struct LocalObjective {
  PositionObjectiveRun* run;
  std::exception_ptr failure;  ///< what the balance threw (NLopt only stops): rethrown after it
};

double local_objective(unsigned n, const double* x, double*, void* data) {
  auto* local = static_cast<LocalObjective*>(data);
  try {
    const double value = (*local->run)(std::vector<double>(x, x + n));
    return std::isfinite(value) ? value : 1e10;  // COBYLA wants numbers: a failed arrangement is merely very bad
  } catch (...) {
    local->failure = std::current_exception();
    throw nlopt::forced_stop();
  }
}

double spacing_constraint(unsigned, const double* x, double*, void* data) {
  const auto* c = static_cast<const LocalSearch*>(data);
  return c->spacing_min - (x[c->k + 1] - x[c->k]);
}

/// COBYLA from `start` (increasing, feasible) within the range and the spacings.
void search_locally(PositionObjectiveRun& run, const PositionRules& rules, std::vector<double> start) {
  const std::size_t n = start.size();
  nlopt::opt opt(nlopt::LN_COBYLA, static_cast<unsigned>(n));
  opt.set_lower_bounds(std::vector<double>(n, rules.position_min));
  opt.set_upper_bounds(std::vector<double>(n, rules.position_max));
  LocalObjective local{&run, nullptr};
  opt.set_min_objective(&local_objective, &local);
  std::vector<LocalSearch> constraints;
  constraints.reserve(n);
  for (std::size_t k = 0; k + 1 < n; ++k) constraints.push_back({&run, rules.spacing_min, k});
  for (LocalSearch& c : constraints) opt.add_inequality_constraint(&spacing_constraint, &c, 1e-9);
  opt.set_maxeval(rules.max_evaluations);
  opt.set_xtol_abs(1e-3);
  opt.set_initial_step(std::min(0.5, 0.1 * (rules.position_max - rules.position_min)));
  double value = 0.0;
  try {
    opt.optimize(start, value);
  } catch (const std::exception&) {
    // Round-off or NLopt's own limits: the arrangements evaluated stand, the best kept.
  }
  if (local.failure) std::rethrow_exception(local.failure);
}

/// The radical inverse of i in `base` (the Halton sequence's coordinate).
double radical_inverse(int i, int base) {
  double inverse = 0.0, digit = 1.0 / base;
  for (; i > 0; i /= base, digit /= base) inverse += digit * (i % base);
  return inverse;
}

/// `count` arrangements of `n` dampers spread evenly over every arrangement the rules
/// allow (Halton points, each sorted and mapped onto increasing positions at least
/// spacing_min apart): the objective's basins are too many for starts alone.
std::vector<std::vector<double>> spread_arrangements(std::size_t n, int count, const PositionRules& rules) {
  static constexpr int kBases[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29};
  const double room = rules.position_max - rules.position_min - static_cast<double>(n - 1) * rules.spacing_min;
  std::vector<std::vector<double>> out;
  for (int i = 1; i <= count; ++i) {
    std::vector<double> u(n);
    for (std::size_t k = 0; k < n; ++k) u[k] = radical_inverse(i, kBases[k % 10]);
    std::sort(u.begin(), u.end());
    for (std::size_t k = 0; k < n; ++k) u[k] = rules.position_min + static_cast<double>(k) * rules.spacing_min + room * u[k];
    out.push_back(std::move(u));
  }
  return out;
}

}  // namespace

PositionSearch optimise_positions(const Span& span, const SpanTables& tables, const BalanceOptions& options,
                                  const PositionRules& rules, const std::function<bool()>& stop) {
  rules.validate();
  const std::vector<std::size_t> placed = placed_dampers(span);
  const std::size_t n = placed.size();
  if (n == 0) throw InvalidParameter("damper", ": a position search needs at least one [[damper]] at the ends (position)");
  const double room = rules.position_max - rules.position_min;
  if (static_cast<double>(n - 1) * rules.spacing_min > room) {
    throw InvalidParameter("spacing_min", fmt::format(" = {}: {} dampers at least that far apart do not fit between "
                                                      "position_min = {} and position_max = {} m",
                                                      format_value(rules.spacing_min), n, format_value(rules.position_min),
                                                      format_value(rules.position_max)));
  }
  if (rules.objective == PositionObjective::life && !span.fatigue().life) {
    throw InvalidParameter("objective", " = \"life\": the span gives no climate ([fatigue] wind_weibull and "
                                        "aeolian_fraction) to compute a life with");
  }
  PositionObjectiveRun run(span, tables, options, rules, stop);
  if (n == 1) {
    search_one(run, rules);
    return run.result();
  }
  // The starts: the span's own arrangement (made feasible) and the usual ones; the
  // local searches from the best two.
  const int count = static_cast<int>(n);
  const double f_max = tables.frequencies().back();
  std::vector<std::pair<double, std::vector<double>>> starts;
  std::vector<double> own;
  for (const std::size_t j : placed) own.push_back(span.dampers()[j].position);
  PositionRules fit = rules;
  for (std::size_t k = 0; k < n; ++k) {
    own[k] = std::clamp(own[k], rules.position_min + static_cast<double>(k) * rules.spacing_min,
                        rules.position_max - static_cast<double>(n - 1 - k) * rules.spacing_min);
    if (k > 0) own[k] = std::max(own[k], own[k - 1] + rules.spacing_min);
  }
  // Only the best `local_searches` starts are searched from: a start shown worse than
  // all of them stops early.
  const auto kept_worst = [&] {
    std::vector<double> values;
    for (const auto& start : starts) values.push_back(start.first);
    const std::size_t k = static_cast<std::size_t>(rules.local_searches);
    if (values.size() < k) return std::numeric_limits<double>::infinity();
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k - 1), values.end());
    return values[k - 1];
  };
  starts.emplace_back(run(own, kept_worst()), own);
  for (const double fraction : {0.3, 0.5, 0.7, 0.9}) {
    std::vector<double> x = usual_positions(span, f_max, count, fraction, fit);
    starts.emplace_back(run(x, kept_worst()), std::move(x));
  }
  // The objective has a basin near every node of the shortest waves: a local search
  // stays in its start's. Arrangements spread over all that are allowed find the
  // best basins; the local searches start from the best of everything tried.
  for (std::vector<double>& x : spread_arrangements(n, rules.scan_points * static_cast<int>(n) / 2, rules)) {
    const double value = run(x, kept_worst());
    starts.emplace_back(value, std::move(x));
  }
  std::stable_sort(starts.begin(), starts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t s = 0; s < static_cast<std::size_t>(rules.local_searches) && s < starts.size(); ++s) {
    if (!std::isfinite(starts[s].first)) break;
    run.begin_basin(starts[s].second, starts[s].first);
    search_locally(run, rules, starts[s].second);
    run.end_basin();
  }
  return run.result();
}

}  // namespace stockbridge::span
