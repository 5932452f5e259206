#pragma once
// A span as a span file describes it (MODEL.md section 9; docs/span.md): the
// conductor and its tension, the span's length, the wind, the conductor's
// self-damping, the dampers at one or both ends, and the fatigue criterion. A
// constant description, valid by construction; the balance (balance.hpp) and the
// analysis (analysis.hpp) take it as it is.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/damper/damper.hpp"
#include "stockbridge/span/conductor.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/impedance_sheet.hpp"
#include "stockbridge/span/life.hpp"
#include "stockbridge/span/self_damping.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {

/// A damper on the span: at `position` (m from the span end's clamp) at one end, or
/// at both ends (mirrored); known by its model, or by a measured impedance sheet
/// (impedance_sheet.hpp) where there is no model.
struct SpanDamper {
  std::optional<damper::Damper> damper;  ///< the model (none: the sheet)
  double position = 0.0;
  bool both_ends = true;
  std::string name;  ///< how tables and messages call it ("damper 1" or the file's stem)
  std::shared_ptr<const ImpedanceSheet> sheet;  ///< the measured sheet, where there is no model

  bool measured() const { return sheet != nullptr; }
};

/// Where the fatigue verdict's endurance limit comes from: the Safe Border Line at
/// `cycles`, or a given limit (Pa); and the climate for the life.
struct FatigueSpec {
  std::optional<double> cycles;
  std::optional<double> endurance_limit;
  std::optional<LifeModel> life;
  /// x_b of the bending amplitude Yb and the Poffenberger-Swart stress, m from the
  /// clamp's last point of contact (IEEE 1966: 89 mm).
  double yb_distance = poffenberger_swart_distance;

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
  Span(Conductor conductor, double length, double tension, WindModel wind, SelfDampingModel self_damping,
       std::vector<SpanDamper> dampers, FatigueSpec fatigue, std::optional<int> terrain = std::nullopt);

  const Conductor& conductor() const { return conductor_; }
  double length() const { return length_; }
  double tension() const { return tension_; }
  const WindModel& wind() const { return wind_; }
  const SelfDampingModel& self_damping() const { return self_damping_; }
  const std::vector<SpanDamper>& dampers() const { return dampers_; }
  const FatigueSpec& fatigue() const { return fatigue_; }
  /// CIGRE TB 273's terrain category (1..4, tension_figures.hpp), if given.
  std::optional<int> terrain() const { return terrain_; }
  /// The endurance limit the verdict uses, Pa.
  double endurance_limit() const;
  /// The same span with every damper moved to `position` + (its position - the first's).
  Span with_dampers_at(double position) const;
  /// The same span without dampers.
  Span without_dampers() const;
  /// The same span with other dampers (validated as the constructor does).
  Span with_dampers(std::vector<SpanDamper> dampers) const;

 private:
  Conductor conductor_;
  double length_;
  double tension_;
  WindModel wind_;
  SelfDampingModel self_damping_;
  std::vector<SpanDamper> dampers_;
  FatigueSpec fatigue_;
  std::optional<int> terrain_;
};

}  // namespace stockbridge::span
