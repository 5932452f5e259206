#include "stockbridge/line/schedule.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <iterator>
#include <memory>

#include <fmt/format.h>

#include "race.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/span/tension_figures.hpp"

namespace stockbridge::line {

namespace {

/// `steps` whole steps as the decimal number the schedule prints (0.01 * 113 = 1.13).
double steps_of(long long steps, double step) {
  const int digits = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  return std::stod(fmt::format("{:.{}f}", static_cast<double>(steps) * step, digits));
}

/// Positions (increasing) rounded to the rules' step, their range and spacing kept
/// (in whole steps), as the decimal numbers the schedule prints.
std::vector<double> rounded_positions(std::vector<double> x, const ScheduleRules& rules) {
  std::sort(x.begin(), x.end());
  const double step = rules.position_step;
  const span::PositionRules& p = rules.positions;
  const auto lo = static_cast<long long>(std::ceil(p.position_min / step - 1e-9));
  const auto hi = static_cast<long long>(std::floor(p.position_max / step + 1e-9));
  const auto spacing = static_cast<long long>(std::ceil(p.spacing_min / step - 1e-9));
  const auto n = static_cast<long long>(x.size());
  std::vector<long long> steps(x.size());
  for (long long k = 0; k < n; ++k) {
    long long i = std::llround(x[static_cast<std::size_t>(k)] / step);
    i = std::max(lo + k * spacing, std::min(i, hi - (n - 1 - k) * spacing));  // the range wins where they cannot both fit
    if (k > 0) i = std::max(i, steps[static_cast<std::size_t>(k - 1)] + spacing);
    steps[static_cast<std::size_t>(k)] = i;
  }
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = steps_of(steps[k], step);
  return x;
}

/// A further damper beyond an arrangement: 1.3 times its last spacing (or its first
/// position) further on, within the range.
std::vector<double> extended(std::vector<double> x, const ScheduleRules& rules) {
  const span::PositionRules& p = rules.positions;
  const double last_spacing = x.size() > 1 ? x.back() - x[x.size() - 2] : x.front();
  x.push_back(x.back() + std::max(p.spacing_min, 1.3 * last_spacing));
  for (std::size_t k = x.size(); k-- > 0;) {
    x[k] = std::min(x[k], p.position_max - static_cast<double>(x.size() - 1 - k) * p.spacing_min);
    if (k + 1 < x.size()) x[k] = std::min(x[k], x[k + 1] - p.spacing_min);
    x[k] = std::max(x[k], p.position_min + static_cast<double>(k) * p.spacing_min);
  }
  return x;
}

/// Safe by the rules: the verdict safe (uncertain too where the rules accept it).
bool safe_by(span::Verdict verdict, const ScheduleRules& rules) {
  return verdict == span::Verdict::safe || (rules.accept_uncertain && verdict == span::Verdict::uncertain);
}

span::Verdict verdict_of(const span::BalanceSummary& s, const ScheduleRules& rules, bool undamped) {
  if (!rules.life_target) return undamped ? s.undamped_verdict : s.verdict;
  const std::optional<span::LifeEstimate>& life = undamped ? s.undamped_life : s.life;
  if (life) return life->life_years >= *rules.life_target ? span::Verdict::safe : span::Verdict::unsafe;
  return span::Verdict::unknown;
}

double life_years_of(const std::optional<span::LifeEstimate>& life) {
  return life ? life->life_years : std::numeric_limits<double>::quiet_NaN();
}

/// The tables of `count` dampers of one type at `frequencies`, from the cache.
std::shared_ptr<const span::SpanTables> type_tables(const Line& line, std::size_t type, std::size_t count,
                                                     const std::vector<double>& frequencies,
                                                     const span::ImpedanceTableOptions& options, TableCache& cache) {
  const auto table = type_table(line, type, frequencies, options, cache);
  return std::make_shared<const span::SpanTables>(frequencies, std::vector<span::ImpedanceTable>(count, *table));
}

std::size_t type_index(const Line& line, const std::string& name) {
  for (std::size_t t = 0; t < line.types().size(); ++t) {
    if (line.types()[t].name == name) return t;
  }
  throw InvalidParameter("damper_type", fmt::format(" = \"{}\": not a damper type of the line", printable(name)));
}

/// The span's dampers of an arrangement: one a position at the ends, and the one
/// placed beside the masses (a SpanDamper with all its positions along the span).
std::size_t damper_count(const Arrangement& a) { return a.positions.size() + (a.sphere_distance ? 1 : 0); }

/// The span's balance with an arrangement (its analysis as `stockbridge span` makes
/// it), to be advanced a frequency at a time.
std::unique_ptr<span::SpanAnalysisRun> analysis_run(const Line& line, std::size_t index, std::size_t type,
                                                    const Arrangement& arrangement, TableCache& cache) {
  const LineSpan& s = line.spans()[index];
  span::AnalysisOptions options;
  options.balance = s.balance;
  const std::vector<double> f = span::band_frequencies(s.span, line.rules().points);
  if (arrangement.positions.empty()) return std::make_unique<span::SpanAnalysisRun>(s.span, f, options);
  const span::TableSource tables = [&](const span::Span&, const std::vector<double>& frequencies,
                                       const span::ImpedanceTableOptions& table) {
    return type_tables(line, type, damper_count(arrangement), frequencies, table, cache);
  };
  return std::make_unique<span::SpanAnalysisRun>(with_arrangement(s.span, line.types()[type], arrangement), f, options,
                                                 damper::SweepProgress{}, tables);
}

/// The span's balance with an arrangement, every frequency.
span::SpanAnalysis analyse_with(const Line& line, std::size_t index, std::size_t type, const Arrangement& arrangement,
                                TableCache& cache) {
  const std::unique_ptr<span::SpanAnalysisRun> run = analysis_run(line, index, type, arrangement, cache);
  while (!run->done()) run->next();
  return run->finish();
}

/// The distances the dampers beside the masses are tried at: sphere_distance_min, the
/// middle and sphere_distance_max, on the position step (one where the two are equal).
/// Each is searched and balanced with the polish: on the tables alone the largest
/// stress can be off by tens of percent where dampers sit close to a mass, enough to
/// rank the distances wrongly (docs/line.md, "Masses along a span").
constexpr int kSphereDistances = 3;

std::vector<double> sphere_distances(const ScheduleRules& rules) {
  const double step = rules.position_step;
  const auto lo = static_cast<long long>(std::ceil(rules.sphere_distance_min / step - 1e-9));
  const auto hi = std::max(lo, static_cast<long long>(std::floor(rules.sphere_distance_max / step + 1e-9)));
  std::vector<double> d;
  for (int k = 0; k < kSphereDistances; ++k) {
    const long long at = lo + std::llround(static_cast<double>(hi - lo) * k / (kSphereDistances - 1));
    const double x = steps_of(at, step);
    if (d.empty() || x != d.back()) d.push_back(x);
  }
  return d;
}

/// One damper type, `per_end` dampers (and those beside the masses at one distance):
/// the end positions searched on the tables, rounded, and the polished balance there.
struct Candidate {
  std::size_t type = 0;
  Arrangement arrangement;
  /// The polished balance; none where it was left early (polished_best: proven
  /// unsafe, or unable to beat another).
  std::optional<span::SpanAnalysis> analysis;
  int balances = 0;
  double objective = std::numeric_limits<double>::infinity();  ///< of the polished balance
  bool safe = false;
};

/// Safe first, then the objective.
bool judged_better(const Candidate& a, const Candidate& b) {
  return a.safe != b.safe ? a.safe : a.objective < b.objective;
}

/// The largest judged stress an arrangement must stay below to beat `rival` (safe
/// first, then the objective max_stress), Pa; none where no such bound holds (no
/// rival or not balanced to the end, another objective or a life target, a rival
/// neither safe nor unsafe: a point not converged, or only uncertain).
std::optional<double> stress_to_beat(const Candidate* rival, const ScheduleRules& rules) {
  const bool by_stress = !rules.life_target && rules.positions.objective == span::PositionObjective::max_stress;
  if (!rival || !rival->analysis || !by_stress) return std::nullopt;
  const span::BalanceSummary& s = rival->analysis->balance.summary;
  if (!rival->safe && s.verdict != span::Verdict::unsafe) return std::nullopt;
  if (!s.all_converged()) return std::nullopt;
  return s.max_judged_stress;
}

/// The polished balances of `arrangements`, the best kept (safe first, then the
/// objective; the earlier where they tie), judged by the rules. They are raced
/// frequency by frequency from the lowest (race.hpp), and each is left where a
/// converged point shows that it cannot be chosen (no analysis, not safe, the
/// objective infinite):
/// * with `prove_unsafe`, a judged stress above the endurance limit: that point is in
///   the band's balance whatever the other frequencies give, so the arrangement is
///   unsafe (not under a life target: a life is the whole band's);
/// * a judged stress at or above the largest of an arrangement balanced to the end
///   (stress_to_beat): its objective cannot then be below that one's, nor can it be
///   safe where that one is not.
/// What is kept is what polishing every arrangement to the end would keep.
Candidate polished_best(const Line& line, std::size_t index, std::size_t type, std::vector<Arrangement> arrangements,
                        bool prove_unsafe, TableCache& cache) {
  const ScheduleRules& rules = line.rules();
  const span::Span& plain = line.spans()[index].span;
  std::vector<Candidate> candidates;
  std::vector<std::unique_ptr<span::SpanAnalysisRun>> runs;
  std::vector<RaceRunner> runners;
  for (Arrangement& a : arrangements) {
    candidates.push_back({type, std::move(a), std::nullopt});
    runs.push_back(analysis_run(line, index, type, candidates.back().arrangement, cache));
  }
  for (std::size_t k = 0; k < runs.size(); ++k) {
    span::SpanAnalysisRun& run = *runs[k];
    const auto next = [&run, &plain]() -> std::optional<double> {
      const span::BalancePoint& p = run.next();
      if (!p.converged()) return std::nullopt;
      return span::judged_stress(plain, p);
    };
    const auto finish = [&, k] {
      Candidate& c = candidates[k];
      c.analysis = run.finish();
      c.objective = span::position_objective(c.analysis->balance, rules.positions.objective);
      c.safe = safe_by(verdict_of(c.analysis->balance.summary, rules, false), rules);
      return stress_to_beat(&c, rules);
    };
    runners.push_back({[&run] { return run.done(); }, next, finish});
  }
  const std::optional<double> limit =
      prove_unsafe && !rules.life_target ? std::optional<double>(plain.endurance_limit()) : std::nullopt;
  race(runners, limit);
  // A runner left early has no analysis: it cannot be chosen.
  Candidate best = std::move(candidates.front());
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    if (judged_better(candidates[k], best)) best = std::move(candidates[k]);
  }
  return best;
}

/// What a position search hands the polish: the best arrangement of each local search,
/// rounded (the tables' best first), and the search's balances.
struct Searched {
  std::vector<Arrangement> arrangements;
  int balances = 0;
};

/// The end dampers searched on the tables with the rest of `arrangement` in place.
/// The other local searches' bests are polished too: the tables' error can rank two
/// basins otherwise than their polished balances do.
Searched searched_arrangements(const Line& line, std::size_t index, std::size_t type, const Arrangement& arrangement,
                               TableCache& cache, const std::function<bool()>& stop) {
  const LineSpan& s = line.spans()[index];
  const ScheduleRules& rules = line.rules();
  const std::vector<double> f = span::band_frequencies(s.span, rules.search_points);
  const span::Span trial = with_arrangement(s.span, line.types()[type], arrangement);
  const auto tables = type_tables(line, type, damper_count(arrangement), f, s.balance.table.for_position_search(), cache);
  const span::PositionSearch found = span::optimise_positions(trial, *tables, s.balance, rules.positions, stop);
  if (stop && stop()) throw Interrupted("the schedule was stopped");
  // The search gives every damper's position, the ends' first (with_arrangement's order).
  const auto end_positions = [&](const std::vector<double>& positions) {
    const auto ends = positions.begin() + static_cast<std::ptrdiff_t>(arrangement.positions.size());
    return rounded_positions({positions.begin(), ends}, rules);
  };
  Searched out{{arrangement}, found.balances};
  out.arrangements.front().positions = end_positions(found.positions);
  for (const std::vector<double>& other : found.runners_up) {
    Arrangement next = arrangement;
    next.positions = end_positions(other);
    const auto same = [&](const Arrangement& a) { return a.positions == next.positions; };
    if (std::none_of(out.arrangements.begin(), out.arrangements.end(), same)) out.arrangements.push_back(std::move(next));
  }
  return out;
}

/// `per_end` dampers of one type at the ends, from the usual arrangement or from the
/// one of one damper fewer: searched (searched_arrangements), and the local searches'
/// bests polished (polished_best). Where the span gets dampers beside its masses, the
/// search once for each of their distances, and all their arrangements polished
/// together: the best (safe before not, then by the objective; the smaller distance
/// where they tie), the searches' balances added up. `prove_unsafe`: as polished_best.
Candidate search_candidate(const Line& line, std::size_t index, std::size_t type, int per_end,
                           const std::vector<double>& previous, bool prove_unsafe, TableCache& cache,
                           const std::function<bool()>& stop) {
  const LineSpan& s = line.spans()[index];
  const ScheduleRules& rules = line.rules();
  const double f_max = span::band_frequencies(s.span, rules.search_points).back();
  const Arrangement start{previous.empty() ? span::usual_positions(s.span, f_max, per_end, 0.5, rules.positions)
                                           : extended(previous, rules),
                          std::nullopt};
  std::vector<Arrangement> polished;
  int balances = 0;
  const auto search_from = [&](const Arrangement& from) {
    Searched found = searched_arrangements(line, index, type, from, cache, stop);
    balances += found.balances;
    std::move(found.arrangements.begin(), found.arrangements.end(), std::back_inserter(polished));
  };
  if (!gets_sphere_dampers(s.span, rules)) {
    search_from(start);
  } else {
    for (const double d : sphere_distances(rules)) {
      Arrangement beside = start;
      beside.sphere_distance = d;
      search_from(beside);
    }
  }
  Candidate best = polished_best(line, index, type, std::move(polished), prove_unsafe, cache);
  best.balances = balances;
  return best;
}

std::string megapascal(double pascal) { return fmt::format("{:.3g} MPa", pascal / 1e6); }

/// What the type choice compares among the types safe with the fewest dampers: a
/// damper's mass, its price, or nothing (0: the objective decides).
double type_cost(const DamperType& type, TypeChoice choice) {
  constexpr double kUnknown = std::numeric_limits<double>::infinity();
  switch (choice) {
    case TypeChoice::fewest_then_lightest: return type.mass.value_or(kUnknown);
    case TypeChoice::fewest_then_cheapest: return type.price.value_or(kUnknown);
    case TypeChoice::lowest_stress: return 0.0;
  }
  return 0.0;
}

/// Which of two damper types' candidates of one count the schedule takes: of two
/// safe ones the cheaper by rules.choose (a damper's mass or price), else as
/// judged_better (safe first, then the objective).
bool type_preferred(const Candidate& a, const Candidate& b, const Line& line) {
  if (a.safe && b.safe) {
    const double cost_a = type_cost(line.types()[a.type], line.rules().choose);
    const double cost_b = type_cost(line.types()[b.type], line.rules().choose);
    if (cost_a != cost_b) return cost_a < cost_b;
  }
  return judged_better(a, b);
}

void fill_undamped(ScheduleRow& row, const LineSpan& s, const span::BalanceSummary& u, const ScheduleRules& rules) {
  const span::TensionFigures t = span::tension_figures(s.span);
  row.id = s.id;
  row.length = s.span.length();
  row.tension = t.tension;
  row.tension_fraction = t.fraction_of_rts;
  row.catenary_parameter = t.catenary_parameter;
  row.span_parameter = t.span_parameter;
  row.conductor = s.span.conductor().name;
  if (const std::optional<span::SafeDesignTension> safe = span::safe_design_tension(s.span)) {
    row.terrain = safe->terrain.category;
    row.terrain_within = safe->within ? 1 : 0;
  }
  row.endurance_limit = u.endurance_limit;
  row.undamped_max_stress = u.undamped_max_judged_stress;
  row.undamped_life_years = life_years_of(u.undamped_life);
  row.undamped_verdict = verdict_of(u, rules, true);
}

void fill_arrangement(ScheduleRow& row, const Line& line, const Candidate* c, const span::SpanAnalysis& a) {
  const span::BalanceSummary& s = a.balance.summary;
  if (c) {
    row.damper_type = line.types()[c->type].name;
    row.per_end = static_cast<int>(c->arrangement.positions.size());
    row.positions = c->arrangement.positions;
    if (c->arrangement.sphere_distance) {
      row.sphere_distance = *c->arrangement.sphere_distance;
      row.sphere_dampers = static_cast<int>(sphere_damper_positions(a.span, row.sphere_distance).size());
    }
  }
  row.governing_place = s.converged > 0 ? s.max_judged_stress_place : std::string();
  row.max_stress = s.converged > 0 ? s.max_judged_stress : std::numeric_limits<double>::quiet_NaN();
  row.max_stress_high = s.converged > 0 ? s.max_judged_stress_high : std::numeric_limits<double>::quiet_NaN();
  row.max_stress_frequency = s.converged > 0 ? s.max_judged_stress_frequency_hz : std::numeric_limits<double>::quiet_NaN();
  row.life_years = life_years_of(s.life);
  row.verdict = verdict_of(s, line.rules(), false);
  row.converged = s.converged;
  row.points = s.points;
  if (!s.all_converged()) {
    const auto failed = std::find_if(a.balance.points.begin(), a.balance.points.end(),
                                     [](const span::BalancePoint& p) { return !p.converged(); });
    row.warnings.push_back(fmt::format("{} of {} frequencies did not converge, first at {:.4g} Hz: {}; the largest "
                                       "stress is of the others and the verdict unknown unless they exceed the limit",
                                       s.points - s.converged, s.points, failed->frequency_hz,
                                       brief_report(failed->summary)));
  }
  if (c && s.converged > 0 && s.max_judged_stress > s.undamped_max_judged_stress) {
    row.warnings.push_back(fmt::format("the dampers raise the largest stress above the undamped span's ({} against {})",
                                       megapascal(s.max_judged_stress), megapascal(s.undamped_max_judged_stress)));
  }
  row.warnings.insert(row.warnings.end(), a.warnings.begin(), a.warnings.end());
}

}  // namespace

std::shared_ptr<const span::ImpedanceTable> type_table(const Line& line, std::size_t type,
                                                     const std::vector<double>& frequencies,
                                                     const span::ImpedanceTableOptions& options, TableCache& cache) {
  TableCache::Key key{static_cast<double>(type), static_cast<double>(options.velocities), options.velocity_min,
                      options.velocity_max, options.column_ratio};
  key.insert(key.end(), frequencies.begin(), frequencies.end());
  return cache.get(key, [&] {
    const span::SpanDamper& d = line.types().at(type).damper;
    return d.measured() ? std::make_shared<const span::ImpedanceTable>(*d.sheet, frequencies)
                        : std::make_shared<const span::ImpedanceTable>(*d.damper, frequencies, options);
  });
}

SpanSchedule schedule_span(const Line& line, std::size_t index, TableCache& cache, const std::function<bool()>& stop) {
  const LineSpan& s = line.spans().at(index);
  const ScheduleRules& rules = line.rules();
  SpanSchedule out{ScheduleRow{}, analyse_with(line, index, 0, {}, cache)};
  out.row.index = index;
  fill_undamped(out.row, s, out.analysis.balance.summary, rules);
  if (rules.min_per_end == 0 && safe_by(out.row.undamped_verdict, rules)) {
    fill_arrangement(out.row, line, nullptr, out.analysis);
    out.row.no_damper_basis = "balance";
    return out;
  }
  if (rules.min_per_end == 0 && rules.undamped_rule == UndampedRule::tb273 && out.row.terrain_within == 1) {
    fill_arrangement(out.row, line, nullptr, out.analysis);
    out.row.verdict = span::Verdict::safe;
    out.row.no_damper_basis = "tb273";
    out.row.warnings.insert(
        out.row.warnings.begin(),
        fmt::format("no dampers by CIGRE TB 273: H/w {:.4g} m is within the {:.4g} m of terrain category {}; the "
                    "energy balance without dampers judges it {} (largest stress {})",
                    out.row.catenary_parameter, span::terrain_category(out.row.terrain).catenary_parameter_limit,
                    out.row.terrain, span::verdict_name(out.row.undamped_verdict), megapascal(out.row.undamped_max_stress)));
    return out;
  }
  std::vector<std::vector<double>> previous(line.types().size());
  std::optional<Candidate> chosen;
  for (int per_end = std::max(1, rules.min_per_end); per_end <= rules.max_per_end && !(chosen && chosen->safe); ++per_end) {
    // Below the last count an arrangement proven unsafe early is not balanced to the end.
    const bool prove_unsafe = per_end < rules.max_per_end;
    std::optional<Candidate> best;
    for (std::size_t t = 0; t < line.types().size(); ++t) {
      Candidate c = search_candidate(line, index, t, per_end, previous[t], prove_unsafe, cache, stop);
      out.row.balances += c.balances;
      previous[t] = c.arrangement.positions;
      if (!best || type_preferred(c, *best, line)) best = std::move(c);
    }
    chosen = std::move(best);
  }
  // The last count's kept candidate was balanced to the end: nothing is proven unsafe
  // there, and one left early never beats the candidate it was compared with.
  out.analysis = std::move(*chosen->analysis);
  fill_arrangement(out.row, line, &*chosen, out.analysis);
  if (!chosen->safe) {
    out.row.warnings.insert(out.row.warnings.begin(),
                            fmt::format("no arrangement of up to {} dampers per end makes the span safe: the best "
                                        "found is given",
                                        rules.max_per_end));
  }
  return out;
}

span::SpanAnalysis analyse_arrangement(const Line& line, const ScheduleRow& row, TableCache& cache) {
  if (row.positions.empty()) return analyse_with(line, row.index, 0, {}, cache);
  Arrangement arrangement{row.positions, std::nullopt};
  if (row.sphere_dampers > 0) arrangement.sphere_distance = row.sphere_distance;
  return analyse_with(line, row.index, type_index(line, row.damper_type), arrangement, cache);
}

std::vector<BillLine> bill_of_materials(const Line& line, const std::vector<ScheduleRow>& rows) {
  std::vector<BillLine> bill;
  for (const DamperType& type : line.types()) {
    BillLine b{type.name, 0, 0, std::nullopt, std::nullopt};
    for (const ScheduleRow& row : rows) {
      if (row.damper_type != type.name) continue;
      b.dampers += 2 * row.per_end + row.sphere_dampers;
      ++b.spans;
    }
    if (type.mass) b.mass = *type.mass * b.dampers;
    if (type.price) b.price = *type.price * b.dampers;
    bill.push_back(std::move(b));
  }
  return bill;
}

namespace {

/// A warning's kind: its text with every number (digits, and the '.', sign and
/// exponent within them: 12.5, 1.23e+03, 4.5e-05) as '#'.
std::string warning_kind(const std::string& text) {
  const auto at = [&text](std::size_t k) { return k < text.size() ? text[k] : '\0'; };
  const auto digit = [&at](std::size_t k) { return std::isdigit(static_cast<unsigned char>(at(k))) != 0; };
  const auto sign = [&at](std::size_t k) { return at(k) == '+' || at(k) == '-'; };
  const auto exponent = [&at](std::size_t k) { return at(k) == 'e' || at(k) == 'E'; };
  std::string kind;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (!digit(i)) {
      kind += text[i];
      continue;
    }
    while (true) {
      if (digit(i + 1) || at(i + 1) == '.' || (sign(i + 1) && digit(i + 2))) {
        ++i;
      } else if (exponent(i + 1) && digit(i + 2)) {
        i += 2;
      } else if (exponent(i + 1) && sign(i + 2) && digit(i + 3)) {
        i += 3;  // e+03, as fmt writes an exponent
      } else {
        break;
      }
    }
    kind += '#';
  }
  return kind;
}

}  // namespace

std::vector<std::string> grouped_warnings(const std::vector<ScheduleRow>& rows) {
  struct Group {
    std::string kind, first;
    std::vector<std::string> ids;
  };
  std::vector<Group> groups;
  for (const ScheduleRow& r : rows) {
    for (const std::string& w : r.warnings) {
      const std::string kind = warning_kind(w);
      auto g = std::find_if(groups.begin(), groups.end(), [&](const Group& x) { return x.kind == kind; });
      if (g == groups.end()) {
        groups.push_back({kind, w, {}});
        g = groups.end() - 1;
      }
      if (g->ids.empty() || g->ids.back() != r.id) g->ids.push_back(r.id);
    }
  }
  std::vector<std::string> out;
  for (const Group& g : groups) {
    if (g.ids.size() == 1) {
      out.push_back(fmt::format("{}: {}", g.ids.front(), g.first));
      continue;
    }
    std::string ids;
    for (std::size_t k = 0; k < g.ids.size() && k < 12; ++k) ids += fmt::format("{}{}", k == 0 ? "" : ", ", g.ids[k]);
    if (g.ids.size() > 12) ids += fmt::format(" and {} more", g.ids.size() - 12);
    out.push_back(fmt::format("{} ({} spans: {}; the figures are {}'s, each span's are in its row)", g.first,
                              g.ids.size(), ids, g.ids.front()));
  }
  return out;
}

ScheduleCounts schedule_counts(const std::vector<ScheduleRow>& rows) {
  ScheduleCounts c;
  for (const ScheduleRow& r : rows) {
    c.safe += r.verdict == span::Verdict::safe;
    c.unsafe += r.verdict == span::Verdict::unsafe;
    c.unknown += r.verdict == span::Verdict::unknown;
    c.uncertain += r.verdict == span::Verdict::uncertain;
    const bool converged = r.converged == r.points;
    c.not_converged += !converged;
    c.worse_than_undamped += converged && r.per_end > 0 && r.max_stress > r.undamped_max_stress;
    ++c.per_end[r.per_end];
    // A span TB 273's rule spares dampers keeps its undamped balance's stress beside
    // it: it is not what governs the schedule's margin.
    const bool judged = converged && r.no_damper_basis != "tb273";
    if (judged && (!c.governing || r.stress_ratio() > c.governing->stress_ratio())) c.governing = &r;
  }
  return c;
}

}  // namespace stockbridge::line
