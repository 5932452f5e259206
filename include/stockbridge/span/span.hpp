#pragma once
// A span as a span file describes it (MODEL.md section 9; docs/span.md): the
// conductor and its tension, the span's length, the wind, the conductor's
// self-damping, the dampers at one or both ends, and the fatigue criterion. A
// constant description, valid by construction; the balance (balance.hpp) and the
// analysis (analysis.hpp) take it as it is.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/damper/damper.hpp"
#include "stockbridge/span/conductor.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/impedance_sheet.hpp"
#include "stockbridge/span/life.hpp"
#include "stockbridge/span/self_damping.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {

/// A damper model fitted to a measured sheet from the damper's drawing (a span
/// file's fit_from, docs/span.md): where it comes from and how well it follows.
struct SheetFit {
  std::string sheet;                ///< the measured sheet's path, as the file gives it
  std::string start;                ///< the damper file it started from (the drawing)
  std::vector<std::string> free;    ///< the damper's numbers fitted with the cable
  double rms_relative_error = 0.0;  ///< of Z over the sheet's points
  int points = 0;                   ///< the sheet's points
  bool poor_fit = false;            ///< above identify impedance's rms_limit
  bool lack_of_fit = false;         ///< significant against the sheet's assumed 1 % scatter
  bool cached = false;              ///< read from the fit cache, not fitted in this run

  /// "fitted to one.csv from drawing.toml (free: arm.long.mass, ...), RMS 0.083 % of |Z| over 16 points"
  std::string summary() const;
};

/// A damper on the span: at `position` (m from the span end's clamp) at one end, or
/// at both ends (mirrored), or at each of `along` (m from end 1: anywhere along the
/// span, MODEL.md section 15); known by its model, or by a measured impedance sheet
/// (impedance_sheet.hpp) where there is no model.
struct SpanDamper {
  std::optional<damper::Damper> damper;  ///< the model (none: the sheet)
  double position = 0.0;
  bool both_ends = true;
  std::string name;  ///< how tables and messages call it ("damper 1" or the file's stem)
  std::shared_ptr<const ImpedanceSheet> sheet;  ///< the measured sheet, where there is no model
  std::optional<SheetFit> fit;  ///< the model is fitted to a measured sheet (fit_from)
  /// Positions measured from end 1 (a span file's `positions = [..]`); empty: at
  /// `position` from the clamp of one or both ends. Its {} keeps the initialisers
  /// that leave it out (damper, position, both_ends, name, sheet, fit) free of
  /// -Wmissing-field-initializers.
  std::vector<double> along{};

  bool measured() const { return sheet != nullptr; }
  /// Placed along the span (`along`), not at `position` from the ends.
  bool in_span() const { return !along.empty(); }
  /// Each of its positions, m from end 1, on a span of `span_length` m: `along`, or
  /// `position` from end 1's clamp and (both_ends) from end 2's, end 1's first.
  std::vector<double> positions_from_end1(double span_length) const {
    if (in_span()) return along;
    if (both_ends) return {position, span_length - position};
    return {position};
  }
};

/// A rigid mass clamped on the conductor (an aircraft warning sphere, a marker): a
/// point load of impedance Z = j w M at each of its positions (MODEL.md section 15).
struct SpanMass {
  std::string name;              ///< how tables and reports call it ("sphere", or "mass 1")
  double mass = 0.0;             ///< kg
  std::vector<double> positions; ///< m from end 1, each in (0, L)
  /// The clamp's own factor on the conductor's stress at it (the point-force formula's
  /// stress times this; 1 for a clamp that bends the conductor as a point force does).
  double stress_factor = 1.0;
};

/// The criterion a span's verdict judges by (docs/span.md, "Criteria"):
///  * safe_border_line: the fymax stress against the S-N curve at `cycles`: CIGRE's
///    Safe Border Line, or the span's own `curve` where one is given;
///  * microstrain: the peak-to-peak bending strain of the Poffenberger-Swart stress
///    (from Yb, as a recorder measures it) against `limit_pp_microstrain` (the IEEE
///    committee's 150 by default);
///  * stress: the fymax stress against a given endurance limit (EPRI's by the
///    conductor's construction, a utility's own).
enum class FatigueCriterion { safe_border_line, microstrain, stress };
/// "safe-border-line", "microstrain" or "stress"; InvalidParameter naming "criterion" otherwise.
FatigueCriterion parse_fatigue_criterion(std::string_view name);
std::string_view fatigue_criterion_name(FatigueCriterion criterion);
/// The IEEE committee's peak-to-peak bending strain limit (IEEE 1966 report; EPRI "Orange Book").
inline constexpr double ieee_limit_pp_microstrain = 150.0;

/// The fatigue verdict's criterion and limit, and the climate for the life.
struct FatigueSpec {
  FatigueCriterion criterion = FatigueCriterion::safe_border_line;
  std::optional<double> cycles;           ///< safe_border_line: the cycles of the endurance limit
  std::optional<double> endurance_limit;  ///< stress: the endurance limit, Pa (zero-to-peak)
  std::optional<double> limit_pp_microstrain;  ///< microstrain: the limit (none: the IEEE's 150)
  std::optional<LifeModel> life;
  /// The S-N curve in the Safe Border Line's place (the endurance limit at `cycles`,
  /// N(sigma) in the life), e.g. one fitted to the conductor's own fatigue tests.
  std::optional<SnCurve> curve;
  /// x_b of the bending amplitude Yb and the Poffenberger-Swart stress, m from the
  /// clamp's last point of contact (IEEE 1966: 89 mm).
  double yb_distance = poffenberger_swart_distance;

  /// The criterion's own number and no other's: InvalidParameter naming the field.
  void validate() const;
};

/// A span as a span file describes it, valid by construction.
class Span {
 public:
  /// Throws InvalidParameter naming the field as the span file spells it
  /// ("span.length", "damper[1].position", "fatigue.cycles", "span.terrain"). A
  /// damper position past half the span names span.length where the position is a
  /// usual one (typical_ranges.hpp) and the span is what is short. Each damper has
  /// its model or its sheet, not both ("damper[0]").
  /// Masses name "mass[0].positions[1]"; a damper along the span "damper[0].positions[1]".
  /// Where the outer wires are not aluminium (steel, aluminium-clad steel: earth wires,
  /// OPGW) and no `curve` is given, the Safe Border Line does not apply: criterion
  /// safe_border_line is refused naming "fatigue.endurance_limit_mpa" (the limit to give
  /// instead), a life estimate naming "fatigue.curve".
  Span(Conductor conductor, double length, double tension, WindModel wind, SelfDampingModel self_damping,
       std::vector<SpanDamper> dampers, FatigueSpec fatigue, std::optional<int> terrain = std::nullopt,
       std::vector<SpanMass> masses = {});

  const Conductor& conductor() const { return conductor_; }
  double length() const { return length_; }
  double tension() const { return tension_; }
  const WindModel& wind() const { return wind_; }
  const SelfDampingModel& self_damping() const { return self_damping_; }
  const std::vector<SpanDamper>& dampers() const { return dampers_; }
  /// The masses along the span (warning spheres, markers), in the file's order.
  const std::vector<SpanMass>& masses() const { return masses_; }
  /// Whether anything hangs along the span besides the dampers at the ends: a mass
  /// or a damper placed by `along` (the balance then runs through the sub-spans).
  bool has_attachments() const;
  const FatigueSpec& fatigue() const { return fatigue_; }
  /// CIGRE TB 273's terrain category (1..4, tension_figures.hpp), if given.
  std::optional<int> terrain() const { return terrain_; }
  /// The endurance limit the verdict uses, as a zero-to-peak stress, Pa (under the
  /// microstrain criterion the Poffenberger-Swart stress of that strain, E_a eps / 2).
  double endurance_limit() const;
  /// The S-N curve in force: the fatigue's `curve`, or the Safe Border Line of the
  /// conductor's aluminium layers; InvalidParameter naming "fatigue.curve" where the
  /// outer wires are not aluminium and no curve is given.
  SnCurve sn_curve() const;
  /// Whether the verdict judges the Poffenberger-Swart stress (the microstrain
  /// criterion: Yb as measured) rather than the fymax stress.
  bool judges_poffenberger_swart() const { return fatigue_.criterion == FatigueCriterion::microstrain; }
  /// The criterion in words, as reports name it ("the CIGRE Safe Border Line at 5e+08
  /// cycles", "the S-N curve 'Drake tests' (curve.toml) at 5e+08 cycles", "150 microstrain peak-to-peak (the IEEE committee's limit)", "a given
  /// endurance limit").
  std::string criterion_description() const;
  /// The same span with every damper at the ends moved to `position` + (its position -
  /// the first's); dampers along the span stay where they are.
  Span with_dampers_at(double position) const;
  /// The same span without dampers (its masses kept).
  Span without_dampers() const;
  /// The same span with other dampers (validated as the constructor does; its masses kept).
  Span with_dampers(std::vector<SpanDamper> dampers) const;
  /// The same span with other masses.
  Span with_masses(std::vector<SpanMass> masses) const;

 private:
  Conductor conductor_;
  double length_;
  double tension_;
  WindModel wind_;
  SelfDampingModel self_damping_;
  std::vector<SpanDamper> dampers_;
  FatigueSpec fatigue_;
  std::optional<int> terrain_;
  std::vector<SpanMass> masses_;
};

}  // namespace stockbridge::span
