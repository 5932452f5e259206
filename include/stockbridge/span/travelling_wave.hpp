#pragma once
// Dampers on a span end, by travelling waves (MODEL.md section 9): the conductor
// is a taut string of wave impedance Z0 = sqrt(T m) and wavenumber k = w / c. From
// the fixed end (x = 0) the deflection is Y = S sin(k x) up to the first damper;
// at a damper at x = a with clamp impedance Z the slope jumps,
//     T (Y'(a+) - Y'(a-)) = j w Z Y(a),   i.e.  Y'(a+) = Y'(a-) + j k (Z / Z0) Y(a),
// and past the last damper the wave is A e^{-jkx} + B e^{jkx}: B comes in from
// the span, A goes back out. The span's antinode amplitude is Y = |A| + |B|; the
// end absorbs P_d = Z0 w^2 (|B|^2 - |A|^2) / 2, which equals the dampers' own
// sum Re Z_j w^2 |Y_j|^2 / 2 (an identity the balance checks at every point).

#include <complex>
#include <vector>

namespace stockbridge::span {

/// The taut string at one frequency.
struct StringWave {
  double angular_frequency = 0.0;  ///< w, rad/s
  double wavenumber = 0.0;         ///< k = w / c, 1/m
  double wave_impedance = 0.0;     ///< Z0 = sqrt(T m), N s/m
};

/// What an end's chain carries besides its dampers (MODEL.md section 15): rigid
/// masses, each a point load of impedance Z = j w M, and the places where the wind's
/// sub-spans part (the masses and the dampers placed along the span).
struct EndAttachments {
  std::vector<double> mass_positions;  ///< m from the end, ascending
  std::vector<double> masses;          ///< kg, one per position
  std::vector<double> splits;          ///< m from the end, ascending: each sub-span's bound toward the middle

  bool empty() const { return mass_positions.empty() && splits.empty(); }
  bool operator==(const EndAttachments&) const = default;
};

/// One span end at antinode amplitude Y, its dampers at `positions` (m from the end, ascending).
struct EndResponse {
  double loop_amplitude = 0.0;  ///< S: the loop between the end's clamp and its first damper, m
  std::vector<std::complex<double>> damper_displacement;  ///< Y_j, complex amplitude at each damper, m
  double outgoing = 0.0;        ///< |A|, m
  double incoming = 0.0;        ///< |B|, m
  double absorbed_power = 0.0;  ///< P_d = Z0 w^2 (|B|^2 - |A|^2) / 2, W
  double damper_power = 0.0;    ///< sum Re Z_j w^2 |Y_j|^2 / 2, W (the same, an identity)
  std::vector<std::complex<double>> mass_displacement;  ///< complex amplitude at each mass, m
  /// Per split: the antinode amplitude |A| + |B| of the wave just before it (the
  /// sub-span from the split before it, or the clamp, up to it), m.
  std::vector<double> segment_amplitude;

  /// The clamp velocity amplitude w |Y_j| of each damper, m/s.
  std::vector<double> damper_velocities(double angular_frequency) const;
};

/// The end's standing wave scaled to antinode amplitude `antinode` past its last
/// attachment, with the dampers' impedances `impedances` (N s/m, one per position)
/// and the end's masses. Without attachments S = Y.
EndResponse end_response(const StringWave& wave, const std::vector<double>& positions,
                         const std::vector<std::complex<double>>& impedances, double antinode,
                         const EndAttachments& attachments = {});

/// The end's wave of end_response(wave, positions, impedances, antinode, attachments)
/// at `distances` (m from the end, ascending): |Y| and the local antinode amplitude
/// |A| + |B| of the stretch each lies in.
struct EndSamples {
  std::vector<double> displacement;
  std::vector<double> antinode;
};
EndSamples sample_end(const StringWave& wave, const std::vector<double>& positions,
                      const std::vector<std::complex<double>>& impedances, double antinode,
                      const EndAttachments& attachments, const std::vector<double>& distances);

/// The first-order change of end_response(wave, positions, impedances, antinode)
/// when the impedances move by dZ_j = `direction`[j] (N s/m): the response's
/// recursion is linear in each Z_j, so this is exact (forward mode through it).
struct EndResponseTangent {
  std::vector<double> log_displacement;  ///< d log|Y_j| per damper (0 for a damper at a node, Y_j = 0)
  double absorbed_power = 0.0;           ///< d P_d, W
};
/// The masses' impedances are fixed (no direction); the sub-spans' amplitudes have no tangent here.
EndResponseTangent end_response_tangent(const StringWave& wave, const std::vector<double>& positions,
                                        const std::vector<std::complex<double>>& impedances,
                                        const std::vector<std::complex<double>>& direction, double antinode,
                                        const EndAttachments& attachments = {});

/// One end's chain at one frequency with its stretches' transfers (cos k d, sin k d)
/// worked out once: a balance asks for the same end's response at hundreds of
/// impedances and amplitudes. response() and tangent() are end_response and
/// end_response_tangent; displacements() and log_displacement_jacobian() are the
/// fixed point's hot path, into the caller's buffers, without allocating.
class EndChain {
 public:
  EndChain(const StringWave& wave, const std::vector<double>& positions, const EndAttachments& attachments = {});

  const StringWave& wave() const { return wave_; }
  std::size_t dampers() const { return positions_.size(); }
  const std::vector<double>& positions() const { return positions_; }

  EndResponse response(const std::vector<std::complex<double>>& impedances, double antinode) const;
  EndResponseTangent tangent(const std::vector<std::complex<double>>& impedances,
                             const std::vector<std::complex<double>>& direction, double antinode) const;
  /// Y_j at every damper (`out`, dampers() of them) at antinode amplitude `antinode`.
  void displacements(const std::complex<double>* impedances, double antinode, std::complex<double>* out) const;
  /// d ln|Y_j| / d s_m for a change dZ_m = `slopes`[m] ds_m of damper m's impedance
  /// alone, every j and m: `out`[j * n + m] (n = dampers(); 0 for a damper at a node).
  /// It does not depend on the antinode amplitude.
  void log_displacement_jacobian(const std::complex<double>* impedances, const std::complex<double>* slopes,
                                 double* out) const;

 private:
  enum class Kind { split, mass, damper };
  struct Step {
    Kind kind;
    std::size_t index;        ///< the split's, mass's or damper's
    double cos_kd, sin_kd;    ///< the transfer over the stretch before it
    std::complex<double> jk_ratio;  ///< j k Z / Z0 of a mass (a damper's comes with its Z)
  };
  /// The wave of unit slope at the clamp: Y_j at every damper into `at`, and (y, slope)
  /// past the last attachment.
  void unit_wave(const std::complex<double>* impedances, std::complex<double>* at, std::complex<double>& y,
                 std::complex<double>& slope) const;
  /// (y, slope) carried over the stretch before `step`.
  void propagate(const Step& step, std::complex<double>& y, std::complex<double>& slope) const;

  StringWave wave_;
  std::vector<double> positions_;  ///< the dampers', m from the end
  std::vector<Step> steps_;
};

}  // namespace stockbridge::span
