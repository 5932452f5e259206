#pragma once
// How a span is stepped in time (span/conductor_in_time.hpp; `stockbridge
// simulate` and `span --check-time`), as the span file gives it: the clamps' hold
// on the conductor ([span] ends) and the mesh, step and length of the run ([time]).
// The energy balance does not use them. The wake oscillator's parameters ([wake])
// hold where a run takes the wake's wind.

#include <string_view>

namespace stockbridge::span {

/// How the conductor is held at the span's two clamps.
enum class BeamEnds {
  pinned,   ///< no displacement, the slope free
  clamped,  ///< no displacement, no slope (the suspension clamps)
};
/// "pinned" or "clamped".
std::string_view beam_ends_name(BeamEnds ends);
/// "pinned" or "clamped"; InvalidParameter naming "ends" otherwise.
BeamEnds parse_beam_ends(std::string_view name);

/// The wind on the span in time: (a) the EBM's own input as a force on the
/// velocity's component at the drive; (b) a wake oscillator per element.
enum class WindInTime { ebm, wake };
/// "ebm" or "wake".
std::string_view wind_in_time_name(WindInTime wind);
/// "ebm" or "wake"; InvalidParameter naming "wind" otherwise.
WindInTime parse_wind_in_time(std::string_view name);

/// Facchinetti, de Langre & Biolley (2004)'s wake oscillator, MODEL.md 16 (b): per
/// length of the conductor a wake variable q,
///
///     q_tt + epsilon w_s (q^2 - 1) q_t + w_s^2 q = (coupling / D) y_tt,
///
/// and the lift (1/4) rho U^2 D C_L0 q on the conductor, w_s = 2 pi St U / D the
/// shedding frequency (the span file's Strouhal number). Alone (y_tt = 0), q is a van
/// der Pol oscillator whose limit cycle has the amplitude 2 at w_s.
struct WakeParameters {
  double epsilon = 0.3;           ///< the wake's van der Pol parameter, > 0
  double coupling = 12.0;         ///< A, the acceleration coupling, > 0
  double lift_coefficient = 0.3;  ///< C_L0, the fixed cylinder's lift amplitude, > 0
  double air_density = 1.225;     ///< rho, kg/m^3, > 0

  /// InvalidParameter naming the field ("epsilon", "coupling", "lift_coefficient", "air_density").
  void validate() const;
};

/// A run in time's settings, the defaults fine enough that the dampers' third and
/// fifth harmonics are resolved too (10 elements a wavelength at 3 f;
/// docs/time-domain.md).
struct TimeSettings {
  BeamEnds ends = BeamEnds::clamped;  ///< [span] ends
  int elements_per_wavelength = 30;   ///< at the drive frequency, 4 to 1000
  int steps_per_period = 160;         ///< of the drive, 8 to 100000
  double duration_s = 60.0;           ///< simulated at most, > 0
  WakeParameters wake;                ///< [wake]: the wake oscillator's, where the wind is "wake"
};

}  // namespace stockbridge::span
