#include "stockbridge/requests/modes_request.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::requests {

namespace {

/// The CSV's name of the whole damper in the arm column.
constexpr const char* kWholeDamper = "damper";

std::vector<double> modes_hz(const damper::ArmModes& arm) { return {arm.frequencies_hz(0), arm.frequencies_hz(1)}; }

std::vector<double> modes_hz(const std::vector<damper::DamperMode>& modes) {
  std::vector<double> hz;
  for (const damper::DamperMode& mode : modes) hz.push_back(mode.frequency_hz);
  return hz;
}

void add_rows(std::vector<ModeRow>& rows, const std::string& arm, damper::CableLimit limit,
              const std::vector<double>& hz) {
  for (std::size_t i = 0; i < hz.size(); ++i) rows.push_back({arm, limit, i + 1, hz[i]});
}

std::vector<io::JsonObject> damper_modes_json(const std::vector<damper::DamperMode>& modes,
                                              const std::vector<std::string>& names) {
  std::vector<io::JsonObject> out;
  for (const damper::DamperMode& mode : modes) {
    std::vector<io::JsonObject> arms;
    for (std::size_t k = 0; k < names.size(); ++k) {
      arms.push_back(io::JsonObject()
                         .add("name", names[k])
                         .add("x", mode.arms[k](0))
                         .add("phi", mode.arms[k](1))
                         .add("energy_share", mode.arm_energy_share[k]));
    }
    out.push_back(io::JsonObject()
                      .add("frequency_hz", mode.frequency_hz)
                      .add("dominant_arm", names[mode.dominant_arm])
                      .add("clamp_x", mode.clamp_deflection)
                      .add("clamp_energy_share", mode.clamp_energy_share)
                      .add("arms", arms));
  }
  return out;
}

}  // namespace

ModesResult run_modes(const damper::Damper& damper) {
  ModesResult out;
  out.modes = damper::damper_modes(damper);
  out.clamp_mass_kg = damper.clamp_mass();
  out.arm_names = arm_column_prefixes(damper);
  out.csv_arm_names = out.arm_names;
  if (std::find(out.arm_names.begin(), out.arm_names.end(), kWholeDamper) != out.arm_names.end()) {
    for (std::size_t k = 0; k < out.csv_arm_names.size(); ++k) out.csv_arm_names[k] = fmt::format("arm{}", k + 1);
  }
  return out;
}

std::vector<ModeRow> mode_rows(const ModesResult& result) {
  std::vector<ModeRow> rows;
  const damper::DamperModes& m = result.modes;
  for (std::size_t k = 0; k < result.csv_arm_names.size(); ++k) {
    for (const damper::LimitModes* limit : {&m.stick, &m.slip}) {
      add_rows(rows, result.csv_arm_names[k], limit->limit, modes_hz(limit->arms[k]));
    }
  }
  for (const damper::LimitModes* limit : {&m.stick, &m.slip}) {
    add_rows(rows, kWholeDamper, limit->limit, modes_hz(limit->damper));
  }
  return rows;
}

Table<ModeRow> modes_table() {
  return Table<ModeRow>({
      {"arm", "", "an arm's name (its modes with the clamp held), or damper (the whole damper's, clamp free)",
       ColumnKind::label, {}, [](const ModeRow& r, std::size_t) { return r.arm; }},
      {"state", "", "stick (every element sticking: ei + sum c) or slip (every element slipping: ei)",
       ColumnKind::label, {}, [](const ModeRow& r, std::size_t) { return std::string(damper::cable_limit_name(r.limit)); }},
      {"mode", "", "the mode's number, from 1 in increasing frequency", ColumnKind::count,
       [](const ModeRow& r, std::size_t) { return static_cast<double>(r.mode); }, {}},
      {"frequency_hz", "Hz", "its natural frequency", ColumnKind::number,
       [](const ModeRow& r, std::size_t) { return r.frequency_hz; }, {}},
  });
}

io::JsonObject modes_summary(const ModesResult& result) {
  const damper::DamperModes& m = result.modes;
  const std::vector<std::string>& names = result.arm_names;
  std::vector<io::JsonObject> arms;
  for (std::size_t k = 0; k < names.size(); ++k) {
    arms.push_back(io::JsonObject()
                       .add("name", names[k])
                       .add("stick_hz", modes_hz(m.stick.arms[k]))
                       .add("slip_hz", modes_hz(m.slip.arms[k])));
  }
  return io::JsonObject()
      .add("arms", arms)
      .add("damper", io::JsonObject()
                         .add("clamp_mass_kg", result.clamp_mass_kg)
                         .add("stick_hz", modes_hz(m.stick.damper))
                         .add("slip_hz", modes_hz(m.slip.damper))
                         .add("stick_modes", damper_modes_json(m.stick.damper, names))
                         .add("slip_modes", damper_modes_json(m.slip.damper, names)));
}

}  // namespace stockbridge::requests
