#pragma once
// One frequency of a span's balance (balance.hpp): the taut string there, the wind
// and self-damping powers, and the ends' dampers at any antinode amplitude with
// their impedances from the tables (each end's clamp velocities found by
// end_fixed_point.hpp) or held fixed at directly solved values (the polish's
// trials, polish.hpp). Library-internal.

#include <complex>
#include <optional>
#include <vector>

#include "stockbridge/damper/impedance.hpp"
#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/end_fixed_point.hpp"
#include "stockbridge/span/travelling_wave.hpp"

namespace stockbridge::span {

/// The chain of one end (MODEL.md section 15): its dampers (positions ascending, and
/// which of the span's dampers each is), and the masses and sub-span bounds on its
/// half of the span, all measured from its own clamp.
struct EndLayout {
  int end = 1;  ///< the span end (1 or 2) whose clamp the chain starts from
  std::vector<double> positions;
  std::vector<std::size_t> damper;
  EndAttachments attachments;
  std::vector<std::size_t> mass;  ///< which of the span's masses each of attachments.masses is

  /// The other end's chain is this one's mirror image (the same velocities by symmetry).
  bool mirrors(const EndLayout& other) const {
    return positions == other.positions && damper == other.damper && attachments == other.attachments;
  }
};

/// End 1 holds the dampers at one or both ends; end 2 those at both ends; each end
/// the masses and dampers placed along the span on its half (the nearer clamp's;
/// mid-span goes to end 1). Ends with nothing on them are left out.
std::vector<EndLayout> end_layouts(const Span& span);

/// A stretch of the span between attachments (the clamps, masses, dampers placed
/// along the span; a clamp's dampers count with the stretch past them, as the energy
/// balance takes the end zones), at its own antinode amplitude.
struct SubSpan {
  double from = 0.0;       ///< m from end 1
  double to = 0.0;         ///< m from end 1
  double amplitude = 0.0;  ///< |A| + |B| there, m

  double length() const { return to - from; }
};

/// What the dampers of all ends do at one amplitude.
struct EndsAtAmplitude {
  std::vector<EndSolution> ends;
  double absorbed = 0.0;  ///< P_d of all ends, W
  std::vector<SubSpan> subspans;  ///< the span's stretches, by position; the free span's at the amplitude asked
  /// converged, or the first end that is not (`where` names it, with its report).
  SolverSummary summary;
};

class FrequencyBalance {
 public:
  /// The span's frequency tables.frequencies[index]; `span`, `tables` and `options` must outlive it.
  FrequencyBalance(const Span& span, const SpanTables& tables, std::size_t index, const BalanceOptions& options);

  double frequency() const { return frequency_; }
  const StringWave& wave() const { return wave_; }
  const std::vector<EndLayout>& layouts() const { return layouts_; }
  /// P_w and P_s summed over the stretches at their own amplitudes times `scale`, W.
  double wind(const std::vector<SubSpan>& subspans, double scale = 1.0) const;
  double self_damping(const std::vector<SubSpan>& subspans, double scale = 1.0) const;
  /// d(P_w - P_s)/dY at y (a central difference: the laws are smooth or piecewise
  /// linear); the stretches' amplitudes in proportion to y as the fixed impedances
  /// make them (the polish's trials), the whole span at y otherwise.
  double net_power_slope(double y);

  /// The ends' dampers at antinode amplitude y (each end's fixed point on the tables
  /// from the last one solved, or the fixed impedances' response).
  EndsAtAmplitude dampers(double y);
  /// The smallest stable amplitude of P_w - P_s - P_d with the dampers' current
  /// impedances; where an end's fixed point fails on the way: inner_failure with it.
  StableRoot balanced_amplitude();

  /// Z of span damper `damper` at clamp velocity v from its table at this frequency.
  std::optional<std::complex<double>> table_impedance(std::size_t damper, double v) const;
  /// Makes damper j of end e's impedance the directly solved one `direct`, whatever
  /// its clamp velocity (the polish's trial: the balance with these impedances).
  void fix(std::size_t e, std::size_t j, const damper::ImpedancePoint& direct);
  /// Back to the tables' impedances (the polish's fixed ones dropped).
  void release();
  /// P_d / y^2 while every damper's impedance is fixed (the polish's trials): the
  /// string is linear then, the dampers absorb in proportion to y^2. None otherwise.
  std::optional<double> absorbed_per_square();
  /// End e's response at antinode amplitude 1 to a change `direction` (per damper,
  /// N s/m) of its impedances `z` (end_response_tangent; the weak form's own).
  EndResponseTangent end_tangent(std::size_t e, const std::vector<std::complex<double>>& z,
                                 const std::vector<std::complex<double>>& direction) const;
  /// Damper j of end e's messenger curvature from its last direct solve (NaN: none).
  double messenger_curvature(std::size_t e, std::size_t j) const { return curvatures_[e][j]; }

 private:
  EndSolution end(std::size_t e, double y) const;
  bool all_fixed(std::size_t e) const;
  EndSolution fixed_end(std::size_t e, double y) const;
  EndSolution weak_end(const EndLayout& layout, const ClampImpedance& z, double y) const;
  /// The span's stretches given the ends' responses at antinode amplitude y.
  std::vector<SubSpan> subspans(const std::vector<EndSolution>& ends, double y) const;
  /// P_w - P_s with every stretch's amplitude `ratio` times y (unit_subspans_).
  double net_power_in_proportion(double y) const;
  /// After the ends' dampers were solved at y (`at`): where every damper on a table
  /// moves slower than the table's lowest node, its Z is held there and the ends are
  /// linear up to the amplitude where the fastest reaches it: then the balance's
  /// powers below it follow from these in proportion (held_).
  void note_held(const EndsAtAmplitude& at, double y);

  /// The ends while every impedance is held at its table's lowest node: up to
  /// `until` (m) they absorb `per_square` y^2 and the stretches stand at `unit` y.
  struct Held {
    double until = 0.0;
    double per_square = 0.0;
    std::vector<SubSpan> unit;
  };

  const Span& span_;
  const SpanTables& tables_;
  std::size_t index_;
  double frequency_;
  const BalanceOptions& options_;
  std::vector<EndLayout> layouts_;
  StringWave wave_;
  std::vector<EndChain> chains_;  ///< per end: its chain at this frequency
  bool mirrored_ = false;         ///< end 2's chain is end 1's mirror image
  std::vector<std::vector<double>> last_velocities_;  ///< per end: where its next fixed point starts
  std::vector<double> last_amplitude_;  ///< per end: the antinode amplitude last_velocities_ were solved at
  /// Per end and damper: the impedance fixed by the polish (none: the table's at v).
  std::vector<std::vector<std::optional<std::complex<double>>>> fixed_;
  std::vector<std::vector<double>> curvatures_;  ///< per end and damper: the last direct solve's messenger curvature
  std::optional<double> absorbed_per_square_;    ///< cached by absorbed_per_square()
  std::vector<SubSpan> unit_subspans_;           ///< with it: the stretches at amplitude 1
  std::vector<std::vector<double>> lowest_node_;  ///< per end and damper: its table's lowest velocity here (m/s; 0: none)
  Held held_;                                    ///< of the current balanced_amplitude()
};

}  // namespace stockbridge::span
