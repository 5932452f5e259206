#include "stockbridge/span/wind.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

// The measured reduced-power curves by their published points (y = Y / D, fnc in
// W / (m Hz^3 m^4)), as tabulated with their authors' names in RTE's dohl package
// (rte-france/pallas-dohl, src/dohl/wind_power_data.yaml). Sources in docs/span.md.
constexpr std::array<WindPoint, 10> wind_diana_falco_1971{{{0.03, 0.23},
                                                           {0.06, 0.70},
                                                           {0.10, 1.80},
                                                           {0.20, 5.00},
                                                           {0.30, 9.00},
                                                           {0.40, 14.00},
                                                           {0.50, 18.00},
                                                           {0.60, 20.00},
                                                           {0.70, 21.00},
                                                           {0.80, 20.00}}};
constexpr std::array<WindPoint, 9> wind_rawlins_1983{{{0.03, 0.18},
                                                      {0.06, 0.60},
                                                      {0.10, 1.60},
                                                      {0.20, 4.00},
                                                      {0.30, 6.50},
                                                      {0.40, 9.00},
                                                      {0.50, 10.10},
                                                      {0.60, 10.70},
                                                      {0.70, 10.80}}};
constexpr std::array<WindPoint, 7> wind_brika_laneville_1995{
    {{0.01, 0.03}, {0.03, 0.17}, {0.06, 0.49}, {0.10, 1.10}, {0.20, 3.20}, {0.30, 5.50}, {0.40, 6.00}}};

/// Checks the user's table: at least two points, y_over_d >= 0 strictly increasing, fnc finite.
void check_wind_table(const std::vector<WindPoint>& table) {
  if (table.size() < 2) {
    throw InvalidParameter("table", fmt::format(": {} point(s); expected at least 2 (y_over_d, fnc) points", table.size()));
  }
  for (std::size_t i = 0; i < table.size(); ++i) {
    const std::string at = fmt::format("table[{}]", i);
    require_non_negative(at + ".y_over_d", table[i].y_over_d, "");
    require_finite(at + ".fnc", table[i].fnc, "W/(m Hz^3 m^4)");
    if (i > 0 && !(table[i].y_over_d > table[i - 1].y_over_d)) {
      throw_invalid(at + ".y_over_d", table[i].y_over_d,
                    fmt::format("more than the point before ({}): y_over_d strictly increasing",
                                format_value(table[i - 1].y_over_d)));
    }
  }
}

}  // namespace

WindLaw parse_wind_law(std::string_view name) {
  if (name == "cigre") return WindLaw::cigre;
  if (name == "foti") return WindLaw::foti;
  if (name == "diana-falco") return WindLaw::diana_falco_1971;
  if (name == "rawlins-1983") return WindLaw::rawlins_1983;
  if (name == "brika-laneville") return WindLaw::brika_laneville_1995;
  if (name == "table") return WindLaw::table;
  throw InvalidParameter("law", fmt::format(" = '{}': expected cigre, foti, diana-falco, rawlins-1983, brika-laneville or table",
                                            printable(name)));
}

std::string_view wind_law_name(WindLaw law) {
  switch (law) {
    case WindLaw::cigre: return "cigre";
    case WindLaw::foti: return "foti";
    case WindLaw::diana_falco_1971: return "diana-falco";
    case WindLaw::rawlins_1983: return "rawlins-1983";
    case WindLaw::brika_laneville_1995: return "brika-laneville";
    case WindLaw::table: return "table";
  }
  return "?";
}

std::span<const WindPoint> published_points(WindLaw law) {
  switch (law) {
    case WindLaw::diana_falco_1971: return wind_diana_falco_1971;
    case WindLaw::rawlins_1983: return wind_rawlins_1983;
    case WindLaw::brika_laneville_1995: return wind_brika_laneville_1995;
    default: return {};
  }
}

double cigre_fnc(double y) { return 0.2256 + y * (0.1627 + y * (101.62 - 99.73 * y)); }

double foti_turbulence_factor(double turbulence_intensity) {
  const double ratio = turbulence_intensity / 0.09;
  return 1.0 / std::sqrt(1.0 + ratio * ratio);
}

double interpolate_fnc(std::span<const WindPoint> points, double y) {
  const WindPoint& first = points.front();
  if (y <= first.y_over_d) {
    return first.y_over_d > 0.0 ? first.fnc * y / first.y_over_d : first.fnc;  // the line to fnc(0) = 0
  }
  if (y >= points.back().y_over_d) return points.back().fnc;  // held
  const auto above = std::upper_bound(points.begin(), points.end(), y,
                                      [](double value, const WindPoint& point) { return value < point.y_over_d; });
  const WindPoint& a = *(above - 1);
  const WindPoint& b = *above;
  return a.fnc + (b.fnc - a.fnc) * (y - a.y_over_d) / (b.y_over_d - a.y_over_d);
}

void WindModel::validate() const {
  require_positive("strouhal", strouhal, "");
  if (!(strouhal < 1.0)) throw_invalid("strouhal", strouhal, "a Strouhal number below 1 (conductors: 0.185 to 0.2)");
  require_plausible("speed_min", speed_min, "m/s");
  require_plausible("speed_max", speed_max, "m/s");
  if (!(speed_max > speed_min)) {
    throw_invalid("speed_max", speed_max, fmt::format("more than speed_min = {} m/s", format_value(speed_min)));
  }
  require_positive("power_scale", power_scale, "");
  if (!(power_scale <= 100.0)) throw_invalid("power_scale", power_scale, "a factor on the wind's power, > 0 and <= 100");
  require_non_negative("turbulence_intensity", turbulence_intensity, "");
  if (!(turbulence_intensity <= 1.0)) throw_invalid("turbulence_intensity", turbulence_intensity, "a fraction from 0 to 1");
  if (turbulence_intensity != 0.0 && law != WindLaw::foti) {
    throw_invalid("turbulence_intensity", turbulence_intensity,
                  fmt::format("0: only law = 'foti' uses it (law is '{}')", wind_law_name(law)));
  }
  if (law == WindLaw::table) {
    check_wind_table(table);
  } else if (!table.empty()) {
    throw InvalidParameter("table", fmt::format(": only law = 'table' uses points (law is '{}')", wind_law_name(law)));
  }
}

std::span<const WindPoint> WindModel::points() const {
  return law == WindLaw::table ? std::span<const WindPoint>(table) : published_points(law);
}

double WindModel::fnc(double y_over_d) const {
  switch (law) {
    case WindLaw::cigre: return cigre_fnc(y_over_d);
    case WindLaw::foti: return foti_turbulence_factor(turbulence_intensity) * cigre_fnc(y_over_d);
    default: return interpolate_fnc(points(), y_over_d);
  }
}

double WindModel::power(double amplitude, double frequency, double diameter, double span_length) const {
  const double d2 = diameter * diameter;
  return power_scale * span_length * frequency * frequency * frequency * d2 * d2 * fnc(amplitude / diameter);
}

Interval WindModel::frequency_band(double diameter) const {
  return {strouhal * speed_min / diameter, strouhal * speed_max / diameter};
}

double WindModel::wind_speed(double frequency, double diameter) const { return frequency * diameter / strouhal; }

std::optional<Interval> WindModel::measured_range() const {
  if (law == WindLaw::cigre || law == WindLaw::foti) return std::nullopt;
  const std::span<const WindPoint> p = points();
  return Interval{p.front().y_over_d, p.back().y_over_d};
}

}  // namespace stockbridge::span
