#include "stockbridge/span/span_modes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/linear_impedance.hpp"

namespace stockbridge::span {

namespace {

constexpr double kChainPi = std::numbers::pi;
/// Attachments closer than this fraction of the span act at one point.
constexpr double kSameChainPoint = 1e-12;
/// A uniform sample of the shapes this close (a fraction of the span) to an
/// attachment gives way to the attachment's own.
constexpr double kSampleClearance = 1e-6;
/// A chain whose end condition misses by more than this (relative to the largest |Y|)
/// is not a mode of the conductor: a damper's clamp stands still at its pole.
constexpr double kClampStillResidual = 1e-6;

/// The attachments at one point of the conductor.
struct ChainNode {
  double x = 0.0;
  double mass = 0.0;                  ///< rigid masses, kg
  std::vector<std::size_t> dampers;   ///< indices into the string's linear impedances
};

/// Y and Y' at a point of the chain.
struct ChainState {
  double deflection = 0.0;
  double slope = 0.0;
};

/// The state carried over a distance d of bare string.
ChainState carry_state(ChainState s, double k, double d) {
  const double c = std::cos(k * d), sn = std::sin(k * d);
  return {s.deflection * c + s.slope * sn / k, -s.deflection * k * sn + s.slope * c};
}

/// The largest |Y| over a segment of length d starting at `s`: the antinode's
/// amplitude where the segment holds one, else the larger end.
double segment_peak_deflection(ChainState s, double k, double d) {
  const double amplitude = std::hypot(s.deflection, s.slope / k);
  if (k * d >= kChainPi) return amplitude;
  const double phase = std::atan2(s.deflection, s.slope / k);  // Y = R sin(k t + phase)
  const double to_antinode = std::fmod(std::fmod(0.5 * kChainPi - phase, kChainPi) + kChainPi, kChainPi) / k;
  if (to_antinode <= d) return amplitude;
  return std::max(std::abs(s.deflection), std::abs(carry_state(s, k, d).deflection));
}

/// The conductor with its attachments at one tension: the count of its natural
/// frequencies and the chain (span_modes.hpp).
class AttachedString {
 public:
  AttachedString(double length, double tension, double wave_speed, std::vector<ChainNode> nodes,
                 std::vector<damper::LinearImpedance> impedances)
      : length_(length), tension_(tension), wave_speed_(wave_speed), nodes_(std::move(nodes)),
        impedances_(std::move(impedances)) {}

  const std::vector<ChainNode>& nodes() const { return nodes_; }

  /// J(w): the natural frequencies below w (Wittrick-Williams).
  int modes_below(double w) const {
    for (int nudge = 0; nudge < 8; ++nudge) {  // w on a pole or a segment's resonance: move off it
      if (const std::optional<int> count = count_at(w)) return *count;
      w = std::nextafter(w, std::numeric_limits<double>::infinity());
    }
    throw NumericalError(fmt::format("span modes: the count at {} rad/s is not defined", format_value(w)));
  }

  /// The n-th natural frequency (rad/s) in (lo, hi], where J(lo) < n <= J(hi): J
  /// bisected to round-off.
  double root(int n, double& lo, double hi) const {
    while (true) {
      const double mid = 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi)) return hi;
      if (modes_below(mid) >= n) {
        hi = mid;
      } else {
        lo = mid;
      }
    }
  }

  /// M_i(w) at node i: its rigid masses and its dampers' effective masses, kg.
  double effective_mass(const ChainNode& node, double w) const {
    double mass = node.mass;
    for (const std::size_t d : node.dampers) mass += impedances_[d].effective_mass(w);
    return mass;
  }

  /// (Y, Y'(x+)) just past each node, from Y(0) = 0, Y'(0) = 1.
  std::vector<ChainState> chain(double w) const {
    const double k = w / wave_speed_;
    std::vector<ChainState> past;
    ChainState s{0.0, 1.0};
    double x = 0.0;
    for (const ChainNode& node : nodes_) {
      s = carry_state(s, k, node.x - x);
      x = node.x;
      s.slope -= w * w * effective_mass(node, w) * s.deflection / tension_;
      past.push_back(s);
    }
    return past;
  }

  /// The state at which the segment holding x starts, and where.
  std::pair<ChainState, double> segment_start(const std::vector<ChainState>& past, double x) const {
    std::size_t i = 0;
    while (i < nodes_.size() && nodes_[i].x <= x) ++i;
    return i == 0 ? std::pair{ChainState{0.0, 1.0}, 0.0} : std::pair{past[i - 1], nodes_[i - 1].x};
  }

  double deflection(const std::vector<ChainState>& past, double w, double x) const {
    const auto [start, from] = segment_start(past, x);
    return carry_state(start, w / wave_speed_, x - from).deflection;
  }

  /// The largest |Y| along the span.
  double peak(const std::vector<ChainState>& past, double w) const {
    const double k = w / wave_speed_;
    double largest = segment_peak_deflection({0.0, 1.0}, k, nodes_.empty() ? length_ : nodes_.front().x);
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const double end = i + 1 < nodes_.size() ? nodes_[i + 1].x : length_;
      largest = std::max(largest, segment_peak_deflection(past[i], k, end - nodes_[i].x));
    }
    return largest;
  }

 private:
  /// J(w), or none where a pivot or a damper's mass is not a number (w on a pole).
  std::optional<int> count_at(double w) const {
    const double k = w / wave_speed_;
    const double tk = tension_ * k;
    int count = 0;
    double previous_x = 0.0;
    double previous_pivot = 0.0, previous_coupling = 0.0;  // the last node's pivot and its coupling to this one
    double cot_left = 0.0;
    for (std::size_t i = 0; i <= nodes_.size(); ++i) {
      const double x = i < nodes_.size() ? nodes_[i].x : length_;
      const double kd = k * (x - previous_x);
      count += static_cast<int>(std::floor(kd / kChainPi));  // the segment's own modes, pinned at both ends
      const double sn = std::sin(kd);
      if (sn == 0.0) return std::nullopt;
      const double cot_right = std::cos(kd) / sn;
      if (i > 0) {  // the pivot of node i - 1, whose segments are now both known
        const ChainNode& node = nodes_[i - 1];
        for (const std::size_t d : node.dampers) count += impedances_[d].held_modes_below(w);
        const double diagonal = tk * (cot_left + cot_right) - w * w * effective_mass(node, w);
        double pivot = diagonal - (i > 1 ? previous_coupling * previous_coupling / previous_pivot : 0.0);
        if (std::isnan(pivot)) return std::nullopt;
        if (pivot == 0.0) pivot = std::numeric_limits<double>::min();
        if (pivot < 0.0) ++count;
        previous_pivot = pivot;
      }
      previous_coupling = -tk / sn;
      cot_left = cot_right;
      previous_x = x;
    }
    return count;
  }

  double length_;
  double tension_;
  double wave_speed_;
  std::vector<ChainNode> nodes_;
  std::vector<damper::LinearImpedance> impedances_;
};

/// One attachment with the damper impedance it acts by (none: a rigid mass).
struct PlacedAttachment {
  ModeAttachment attachment;
  std::optional<std::size_t> impedance;
};

void place_mode_masses(const Span& span, std::vector<PlacedAttachment>& placed) {
  for (const SpanMass& mass : span.masses()) {
    for (const double x : mass.positions) placed.push_back({{AttachmentKind::mass, mass.name, x, mass.mass}, {}});
  }
}

void place_mode_dampers(const Span& span, std::vector<PlacedAttachment>& placed, std::vector<damper::LinearImpedance>& impedances) {
  for (std::size_t j = 0; j < span.dampers().size(); ++j) {
    const SpanDamper& d = span.dampers()[j];
    if (!d.damper) {
      throw InvalidParameter("dampers", fmt::format(" = linear: damper[{}] ('{}') is known by its measured sheet only, "
                                                    "which holds no linear impedance (its lowest curve still slips "
                                                    "and dissipates): expected removed",
                                                    j, printable(d.name)));
    }
    impedances.emplace_back(*d.damper, damper::CableLimit::stick);
    for (const double x : d.positions_from_end1(span.length())) {
      placed.push_back({{AttachmentKind::damper, d.name, x, d.damper->total_mass()}, impedances.size() - 1});
    }
  }
}

/// The string of the span's conductor with its attachments, and the attachments by
/// position with the node each acts at.
struct ModesAssembly {
  std::optional<AttachedString> string;
  std::vector<ModeAttachment> attachments;
  std::vector<std::size_t> node_of;  ///< per attachment
};

ModesAssembly assemble_modes(const Span& span, ModeDampers dampers) {
  std::vector<PlacedAttachment> placed;
  std::vector<damper::LinearImpedance> impedances;
  place_mode_masses(span, placed);
  if (dampers == ModeDampers::linear) place_mode_dampers(span, placed, impedances);
  std::stable_sort(placed.begin(), placed.end(),
                   [](const PlacedAttachment& a, const PlacedAttachment& b) { return a.attachment.position < b.attachment.position; });
  ModesAssembly out;
  std::vector<ChainNode> nodes;
  for (const PlacedAttachment& p : placed) {
    const double x = p.attachment.position;
    if (nodes.empty() || x - nodes.back().x > kSameChainPoint * span.length()) nodes.push_back(ChainNode{x, 0.0, {}});
    if (p.impedance) {
      nodes.back().dampers.push_back(*p.impedance);
    } else {
      nodes.back().mass += p.attachment.mass;
    }
    out.attachments.push_back(p.attachment);
    out.node_of.push_back(nodes.size() - 1);
  }
  const Conductor& c = span.conductor();
  out.string.emplace(span.length(), span.tension(), wave_speed(c, span.tension()), std::move(nodes),
                     std::move(impedances));
  return out;
}

/// The shapes' samples: uniform, at least `per_wavelength` a wavelength of the
/// highest mode, and every attachment's position.
std::vector<double> shape_sample_positions(const Span& span, const SpanModesOptions& options, double top_frequency_hz,
                                     const std::vector<ModeAttachment>& attachments) {
  const double wavelength = wave_speed(span.conductor(), span.tension()) / top_frequency_hz;
  const double wanted = std::ceil(options.samples_per_wavelength * span.length() / wavelength) + 1.0;
  const std::size_t n = static_cast<std::size_t>(std::max<double>(options.min_samples, wanted));
  std::vector<double> at;  // the attachments' positions, ascending
  for (const ModeAttachment& a : attachments) at.push_back(a.position);
  const auto near_attachment = [&](double x) {  // a sample this close would only crowd it
    const auto next = std::lower_bound(at.begin(), at.end(), x);
    const double close = kSampleClearance * span.length();
    return (next != at.end() && *next - x <= close) || (next != at.begin() && x - *(next - 1) <= close);
  };
  std::vector<double> x = at;
  for (std::size_t i = 0; i < n; ++i) {
    const double uniform = span.length() * static_cast<double>(i) / static_cast<double>(n - 1);
    if (!near_attachment(uniform)) x.push_back(uniform);
  }
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  return x;
}

/// The chain at one natural frequency: its states past each node, the largest |Y|
/// and the end condition's residual.
struct ModeChain {
  double w = 0.0;
  std::vector<ChainState> past;
  double peak = 0.0;
  double residual = 0.0;
};

/// Every natural frequency below max_frequency_hz (rad/s, ascending), by the count
/// bisected; InvalidParameter naming max_frequency_hz above max_span_modes of them.
std::vector<double> natural_angular_frequencies(const AttachedString& string, double max_frequency_hz) {
  const double w_max = 2.0 * kChainPi * max_frequency_hz;
  const int total = string.modes_below(w_max);
  if (total > max_span_modes) {
    throw_invalid("max_frequency_hz", max_frequency_hz,
                  fmt::format("a frequency with at most {} modes below it ({} lie below this one)", max_span_modes, total));
  }
  std::vector<double> roots;
  double lo = 0.0;  // J(lo) < n for the next n
  for (int n = 1; n <= total; ++n) roots.push_back(string.root(n, lo, w_max));
  return roots;
}

/// The chain at w, or none where it misses its end condition: a clamp-still mode.
std::optional<ModeChain> conductor_mode(const AttachedString& string, double w, double length) {
  ModeChain c{w, string.chain(w), 0.0, 0.0};
  c.peak = string.peak(c.past, w);
  c.residual = std::abs(string.deflection(c.past, w, length)) / c.peak;
  if (!(std::isfinite(c.peak) && c.residual <= kClampStillResidual)) return std::nullopt;
  return c;
}

SpanMode span_mode(const ModeChain& chain, int number, double wave_speed_m_s, const std::vector<std::size_t>& node_of) {
  SpanMode mode;
  mode.number = number;
  mode.frequency_hz = chain.w / (2.0 * kChainPi);
  mode.wavelength_m = wave_speed_m_s / mode.frequency_hz;
  mode.end_residual = chain.residual;
  for (const std::size_t node : node_of) mode.attachment_deflection.push_back(chain.past[node].deflection / chain.peak);
  return mode;
}

}  // namespace

std::string_view mode_dampers_name(ModeDampers dampers) {
  return dampers == ModeDampers::removed ? "removed" : "linear";
}

ModeDampers parse_mode_dampers(std::string_view name) {
  if (name == "removed") return ModeDampers::removed;
  if (name == "linear") return ModeDampers::linear;
  throw InvalidParameter("dampers", fmt::format(" = '{}': expected removed (the span without its dampers) or linear "
                                                "(each damper at its linear impedance, every element sticking)",
                                                printable(name)));
}

std::string_view attachment_kind_name(AttachmentKind kind) { return kind == AttachmentKind::mass ? "mass" : "damper"; }

void SpanModesOptions::validate() const {
  require_plausible("max_frequency_hz", max_frequency_hz, "Hz");
  if (!(std::isfinite(samples_per_wavelength) && samples_per_wavelength >= 4.0 && samples_per_wavelength <= 1000.0)) {
    throw_invalid("samples_per_wavelength", samples_per_wavelength, "from 4 to 1000 samples a wavelength");
  }
  require_in_range("min_samples", min_samples, 2, 1000000);
}

int span_modes_below(const Span& span, ModeDampers dampers, double frequency_hz) {
  require_plausible("frequency_hz", frequency_hz, "Hz");
  return assemble_modes(span, dampers).string->modes_below(2.0 * kChainPi * frequency_hz);
}

SpanModes span_modes(const Span& span, const SpanModesOptions& options) {
  options.validate();
  const ModesAssembly assembly = assemble_modes(span, options.dampers);
  const AttachedString& string = *assembly.string;
  SpanModes out;
  out.length = span.length();
  out.wave_speed = wave_speed(span.conductor(), span.tension());
  out.max_frequency_hz = options.max_frequency_hz;
  out.dampers = options.dampers;
  out.attachments = assembly.attachments;
  std::vector<ModeChain> chains;  // of each mode kept
  for (const double w : natural_angular_frequencies(string, options.max_frequency_hz)) {
    std::optional<ModeChain> chain = conductor_mode(string, w, span.length());
    if (!chain) {
      ++out.clamp_still_modes;
      continue;
    }
    out.modes.push_back(span_mode(*chain, static_cast<int>(out.modes.size()) + 1, out.wave_speed, assembly.node_of));
    out.max_end_residual = std::max(out.max_end_residual, chain->residual);
    chains.push_back(std::move(*chain));
  }
  if (!options.shapes) return out;
  const double top = out.modes.empty() ? options.max_frequency_hz : out.modes.back().frequency_hz;
  out.x = shape_sample_positions(span, options, top, out.attachments);
  for (std::size_t i = 0; i < out.modes.size(); ++i) {
    const ModeChain& c = chains[i];
    for (const double x : out.x) out.modes[i].shape.push_back(string.deflection(c.past, c.w, x) / c.peak);
  }
  return out;
}

}  // namespace stockbridge::span
