#include "stockbridge/requests/sweep_request.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "stockbridge/core/error.hpp"

namespace stockbridge::requests {

namespace {
constexpr const char* kOneAmplitudeKind = "give either velocity (m/s) or displacement (m) amplitudes, one of the two";
}  // namespace

damper::Excitation excitation(double frequency_hz, std::optional<double> velocity, std::optional<double> displacement) {
  if (velocity.has_value() == displacement.has_value()) throw InvalidParameter(kOneAmplitudeKind);
  const damper::Excitation e = velocity ? damper::Excitation::from_velocity(frequency_hz, *velocity)
                                        : damper::Excitation{frequency_hz, *displacement};
  e.validate();
  return e;
}

damper::SweepSpec sweep_spec(const SweepRequest& request) {
  damper::SweepSpec spec;
  if (request.velocities.empty() == request.displacements.empty()) throw InvalidParameter(kOneAmplitudeKind);
  spec.constant_displacement = !request.displacements.empty();
  spec.amplitudes = spec.constant_displacement ? request.displacements : request.velocities;
  spec.frequencies = request.frequencies.empty()
                         ? damper::log_spaced(request.grid.fmin, request.grid.fmax, request.grid.points)
                         : request.frequencies;
  spec.solver = solver_options(request.solver);
  spec.threads = request.threads;
  spec.validate();
  return spec;
}

namespace {

using Point = damper::ImpedancePoint;
using PointQuantity = Quantity<Point>;

/// A value that is round-off of zero relative to `scale` (|value| < 1e-12 scale) as 0.
double without_round_off(double value, double scale) { return std::abs(value) < 1e-12 * scale ? 0.0 : value; }

/// The apparent power V^2 |Z| / 2 of an impedance at the velocity amplitude v.
double apparent_power(double v, std::complex<double> z) { return 0.5 * v * v * std::abs(z); }

/// Z with a real part that is round-off of zero against |Z| (nothing slips) as 0.
std::complex<double> cleaned_impedance(const Point& p) {
  return {without_round_off(p.impedance.real(), std::abs(p.impedance)), p.impedance.imag()};
}

/// A quantity of a converged point (NaN otherwise).
PointQuantity computed(std::string name, std::string unit, std::string meaning, std::function<double(const Point&)> value) {
  return masked_quantity<Point>(std::move(name), std::move(unit), std::move(meaning),
                               [](const Point& p) { return p.converged(); },
                               [value = std::move(value)](const Point& p, std::size_t) { return value(p); });
}

/// A quantity every point has.
PointQuantity given(std::string name, std::string unit, std::string meaning, ColumnKind kind,
                    std::function<double(const Point&)> value) {
  return {std::move(name), std::move(unit), std::move(meaning), kind,
          [value = std::move(value)](const Point& p, std::size_t) { return value(p); }, {}};
}

PointQuantity frequency_quantity() {
  return given("frequency_hz", "Hz", "the excitation frequency f", ColumnKind::number,
               [](const Point& p) { return p.frequency_hz; });
}
PointQuantity velocity_quantity() {
  return given("velocity_m_s", "m/s", "the clamp's velocity amplitude V = W X", ColumnKind::number,
               [](const Point& p) { return p.velocity_amplitude; });
}
PointQuantity displacement_quantity() {
  return given("displacement_m", "m", "the clamp's displacement amplitude X", ColumnKind::number,
               [](const Point& p) { return p.displacement_amplitude; });
}
PointQuantity converged_quantity() {
  return given("converged", "", "1 where every arm converged within the energy tolerance, else 0", ColumnKind::flag,
               [](const Point& p) { return p.converged() ? 1.0 : 0.0; });
}
PointQuantity dissipated_quantity() {
  return computed("dissipated_power_w", "W", "the energy the sliders dissipate per period / T (equal to power_w)",
                  [](const Point& p) { return p.dissipated_power; });
}

}  // namespace

std::vector<PointQuantity> design_figures() {
  return {
      computed("messenger_curvature_max_per_m", "1/m",
               "the largest, over the arms, of the curvature amplitude of the arm's clamp section (<arm>_clamp_curvature_per_m "
               "of response, the integration point nearest the clamp): the damper cable's own fatigue load, where it bends most",
               [](const Point& p) { return p.messenger_curvature_max; }),
      masked_quantity<Point>(
          "<arm>_power_w", "W",
          "the mean power that arm takes from the clamp, V^2 Re(Z_k) / 2 with Z_k = F1_k / V the arm's part of Z; it "
          "equals what the arm's sliders dissipate per period / T, and the arms' powers add up to power_w. An arm that "
          "does not slip shows 0 (round-off), as power_w does",
          [](const Point& p) { return p.converged(); },
          [](const Point& p, std::size_t k) {
            const damper::ArmFigures& arm = p.arms.at(k);
            // An arm that does not slip takes no power but for round-off of its own |Z_k|: 0, as the damper's.
            return without_round_off(arm.power, apparent_power(p.velocity_amplitude, arm.impedance));
          }),
      masked_quantity<Point>(
          "<arm>_mass_amplitude_m", "m",
          "the amplitude of x - b phi: how far the mass's centre of gravity moves relative to the clamp, the clearance "
          "its motion needs",
          [](const Point& p) { return p.converged(); },
          [](const Point& p, std::size_t k) { return p.arms.at(k).mass_amplitude; }),
  };
}

Table<Point> impedance_table(const damper::Damper& damper) {
  std::vector<PointQuantity> q{
      frequency_quantity(),
      velocity_quantity(),
      computed("re_z_n_s_m", "N s/m", "Re Z: the damping part (0 where nothing slips)",
               [](const Point& p) { return cleaned_impedance(p).real(); }),
      computed("im_z_n_s_m", "N s/m", "Im Z: the inertia and stiffness part",
               [](const Point& p) { return cleaned_impedance(p).imag(); }),
      computed("abs_z_n_s_m", "N s/m", "|Z|", [](const Point& p) { return std::abs(cleaned_impedance(p)); }),
      computed("phase_deg", "deg", "arg Z",
               [](const Point& p) { return std::arg(cleaned_impedance(p)) * 180.0 / std::numbers::pi; }),
      computed("power_w", "W", "the mean power the damper takes, V^2 Re Z / 2",
               [](const Point& p) {
                 return without_round_off(p.power, apparent_power(p.velocity_amplitude, p.impedance));
               }),
      converged_quantity(),
      displacement_quantity(),
      dissipated_quantity(),
      computed("energy_error", "", "|P - D / T| relative to the apparent power V^2 |Z| / 2 (the energy check)",
               [](const Point& p) { return p.energy_error; }),
      computed("residual", "", "the solver's final residual, relative to its scale (largest over the arms)",
               [](const Point& p) { return p.residual; }),
      given("iterations", "", "Newton iterations, the largest over the arms (0 for the time method)", ColumnKind::count,
            [](const Point& p) { return static_cast<double>(p.newton_iterations); }),
      given("periods", "", "periods integrated, the largest over the arms (hb and collocation: with the settling periods)",
            ColumnKind::count, [](const Point& p) { return static_cast<double>(p.periods); }),
      given("non_unique", "", "1 where the response curve folds near this frequency: several steady states",
            ColumnKind::flag, [](const Point& p) { return p.non_unique ? 1.0 : 0.0; }),
  };
  for (PointQuantity& f : design_figures()) q.push_back(std::move(f));
  return Table<Point>(std::move(q), {{"<arm>", arm_column_prefixes(damper)}});
}

Table<Point> point_summary_table(const damper::Damper& damper) {
  std::vector<PointQuantity> q{
      frequency_quantity(),
      velocity_quantity(),
      displacement_quantity(),
      converged_quantity(),
      {"termination", "", "how the solve ended (converged, max_iterations, ...)", ColumnKind::label, {},
       [](const Point& p, std::size_t) { return std::string(termination_name(p.termination)); }},
      computed("re_z_n_s_m", "N s/m", "Re Z", [](const Point& p) { return p.impedance.real(); }),
      computed("im_z_n_s_m", "N s/m", "Im Z", [](const Point& p) { return p.impedance.imag(); }),
      computed("power_w", "W", "the mean power the damper takes, V^2 Re Z / 2", [](const Point& p) { return p.power; }),
      dissipated_quantity(),
      given("energy_error", "", "|P - D / T| relative to the apparent power (null unless converged)", ColumnKind::number,
            [](const Point& p) { return p.energy_error; }),
  };
  for (PointQuantity& f : design_figures()) q.push_back(std::move(f));
  return Table<Point>(std::move(q), {{"<arm>", arm_column_prefixes(damper)}});
}

std::vector<std::string> arm_column_prefixes(const damper::Damper& damper) {
  std::vector<std::string> names;
  for (const damper::ArmDescription& arm : damper.description().arms) names.push_back(arm.name);
  // A name that would make one of an arm's columns one of the table's own
  // (dissipated_power_w of the impedance CSV, shaker_force_n of the response CSV).
  return column_prefixes(names, "arm", {"dissipated", "shaker"});
}

void SweepSummary::add(double amplitude, const damper::ImpedancePoint& p) {
  ++tally_.points;
  tally_.non_unique += p.non_unique;
  if (!p.converged()) {
    failures_.push_back({p.frequency_hz, amplitude, p.termination, p.failure});
    return;
  }
  ++tally_.converged;
  tally_.max_energy_error = std::max(tally_.max_energy_error.value_or(0.0), p.energy_error);
}

io::JsonObject SweepSummary::json(std::string_view method, std::optional<double> seconds) const {
  std::vector<io::JsonObject> failed;
  for (const Failure& f : failures_) {
    failed.push_back(io::JsonObject()
                         .add("frequency_hz", f.frequency_hz)
                         .add("amplitude", f.amplitude)
                         .add("termination", std::string(termination_name(f.termination)))
                         .add("reason", f.reason));
  }
  io::JsonObject json;
  json.add("method", std::string(method))
      .add("points", tally_.points)
      .add("converged", tally_.converged)
      .add("non_unique", tally_.non_unique)
      .add("max_energy_error", tally_.max_energy_error.value_or(std::numeric_limits<double>::quiet_NaN()));  // null when none
  if (seconds) json.add("seconds", *seconds);
  json.add("failed", failed);
  return json;
}

namespace {
SweepSummary summary_of(const std::vector<damper::SweepRun>& runs) {
  SweepSummary summary;
  for (const damper::SweepRun& run : runs) {
    for (const damper::ImpedancePoint& p : run.points) summary.add(run.amplitude, p);
  }
  return summary;
}
}  // namespace

SweepTally tally(const std::vector<damper::SweepRun>& runs) { return summary_of(runs).tally(); }

std::vector<const damper::ImpedancePoint*> sweep_points(const std::vector<damper::SweepRun>& runs) {
  std::vector<const damper::ImpedancePoint*> points;
  for (const damper::SweepRun& run : runs) {
    for (const damper::ImpedancePoint& p : run.points) points.push_back(&p);
  }
  return points;
}

Table<damper::ImpedancePoint> impedance_point_notes_table() {
  using P = damper::ImpedancePoint;
  return Table<P>({
      {"termination", "", "how the point's solve ended (converged, or why not)", ColumnKind::label, {},
       [](const P& p, std::size_t) { return std::string(termination_name(p.termination)); }},
      {"messages", "", "why a point did not converge; a converged point's note", ColumnKind::label, {},
       [](const P& p, std::size_t) { return p.converged() ? p.note : p.failure; }},
  });
}

io::JsonObject sweep_summary(const std::vector<damper::SweepRun>& runs, std::string_view method,
                             std::optional<double> seconds) {
  return summary_of(runs).json(method, seconds);
}

}  // namespace stockbridge::requests
