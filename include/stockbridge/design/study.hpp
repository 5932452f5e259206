#pragma once
// A damper design study (MODEL.md section 10): a base damper, the spans it serves,
// the numbers varied (by their damper-file paths, or the dampers' position on the
// spans), numbers tied to them, constraints and an objective. A candidate is one
// value per variable; its evaluation is the span balance of every span over its
// band, exactly as `stockbridge span` computes it, with the candidate replacing the
// spans' dampers.

#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <functional>
#include <vector>

#include "stockbridge/span/balance.hpp"

namespace stockbridge::design {

/// What a study minimises: the largest fymax stress over the spans and their bands
/// relative to each span's endurance limit, or (maximises) the shortest life.
enum class Objective { max_stress, life };
Objective parse_objective(std::string_view name);
std::string_view objective_name(Objective objective);

/// The name of the variable that moves the spans' dampers (m from the span clamp).
inline constexpr std::string_view kPosition = "position";

struct DesignVariable {
  std::string name;  ///< a damper number's path (damper_numbers.hpp) or "position"
  double min = 0.0;
  double max = 0.0;
};

/// A damper number that follows a variable (symmetric designs).
struct DesignTie {
  std::string name;    ///< a damper number's path
  std::string equals;  ///< a variable's name
};

struct DesignConstraints {
  std::optional<double> total_mass_max;           ///< kg, the clamp and the arms' masses
  std::optional<double> messenger_curvature_max;  ///< 1/m, every arm, span and frequency
};

/// A span the candidates serve, and the name the results give it.
struct DesignSpan {
  span::Span span;
  std::string name;
};

class DesignStudy {
 public:
  /// Throws InvalidParameter naming the field: a variable or tie that names no
  /// number of the base damper, min >= max, a tie to something that is not a
  /// variable, a position variable for spans without dampers, a non-positive budget.
  DesignStudy(damper::DamperDescription base, std::vector<DesignSpan> spans, Objective objective,
              std::vector<DesignVariable> variables, std::vector<DesignTie> ties, DesignConstraints constraints,
              int points = 100);

  const damper::DamperDescription& base() const { return base_; }
  const std::vector<DesignSpan>& spans() const { return spans_; }
  Objective objective() const { return objective_; }
  const std::vector<DesignVariable>& variables() const { return variables_; }
  const std::vector<DesignTie>& ties() const { return ties_; }
  const DesignConstraints& constraints() const { return constraints_; }
  /// Frequencies of each span's band (as `stockbridge span --points`).
  int points() const { return points_; }

  /// The base design's values of the variables (the position: the spans' first damper's).
  std::vector<double> base_values() const;
  /// The damper of a candidate: the variables and ties set; an arm whose mass
  /// changes while its inertia is neither a variable nor tied keeps its radius of
  /// gyration (the inertia scales with the mass). Validated (InvalidParameter).
  damper::DamperDescription damper_of(const std::vector<double>& x) const;
  /// The dampers' position of a candidate: the position variable, none if not varied.
  std::optional<double> position_of(const std::vector<double>& x) const;
  /// Span k with the candidate's damper in place of every damper of its file, at the
  /// candidate's position (every damper moved together) or the file's.
  span::Span span_with(std::size_t k, const damper::Damper& damper, std::optional<double> position) const;

 private:
  damper::DamperDescription base_;
  std::vector<DesignSpan> spans_;
  Objective objective_;
  std::vector<DesignVariable> variables_;
  std::vector<DesignTie> ties_;
  DesignConstraints constraints_;
  int points_;
};

/// A candidate's figures. `objective` is what the study compares (smaller is better
/// for both objectives: the stress ratio, or minus the shortest life in years).
struct Evaluation {
  std::vector<double> x;
  bool converged = false;      ///< every span's every point balanced (else `failure`)
  bool feasible = false;       ///< converged and within every constraint
  double objective = std::numeric_limits<double>::infinity();
  double max_stress_ratio = std::numeric_limits<double>::quiet_NaN();  ///< largest fymax stress / endurance limit
  double max_stress = std::numeric_limits<double>::quiet_NaN();        ///< Pa, where the ratio is largest
  double frequency_at_max_hz = std::numeric_limits<double>::quiet_NaN();
  std::size_t span_at_max = 0;
  double total_mass = std::numeric_limits<double>::quiet_NaN();        ///< kg
  double messenger_curvature_max = std::numeric_limits<double>::quiet_NaN();  ///< 1/m
  double shortest_life_years = std::numeric_limits<double>::quiet_NaN();     ///< with objective life
  std::string failure;         ///< why not converged, or which constraint is broken
};

/// The dampers' impedance tables of the candidates evaluated so far, by the values
/// of their damper variables and the span: candidates that differ only in the
/// position share them (a table depends on the damper and the span's band alone,
/// so sharing changes no result). Safe to use from several threads.
class TableCache {
 public:
  using Tables = std::vector<span::ImpedanceTable>;
  /// The tables of span k for a damper made by `key`, made by `make` if not there yet.
  std::shared_ptr<const Tables> get(std::size_t k, const std::vector<double>& key, const std::function<Tables()>& make);

 private:
  std::mutex mutex_;
  std::map<std::pair<std::size_t, std::vector<double>>, std::shared_ptr<const Tables>> tables_;
};

/// Evaluates a candidate (one thread), with tables from `cache` where given. A
/// candidate whose damper is invalid (an arm mass below zero, a cable too short)
/// is not converged, with the reason.
Evaluation evaluate(const DesignStudy& study, const std::vector<double>& x, TableCache* cache = nullptr);

}  // namespace stockbridge::design
