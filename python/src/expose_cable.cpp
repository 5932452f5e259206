// Cables and dampers: the Cable and Damper classes, their files, a section's loop, a cable's cycle, strands and the conductor catalogue.
#include "binding_support.hpp"

#include <algorithm>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include "stockbridge/cable/cable.hpp"
#include "stockbridge/damper/damper.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/strand_file.hpp"
#include "stockbridge/requests/conductor_request.hpp"
#include "stockbridge/requests/cycle_request.hpp"
#include "stockbridge/requests/section_loop.hpp"
#include "stockbridge/requests/strand_request.hpp"
#include "stockbridge/strand/strand_bounds.hpp"

namespace stockbridge::python {

namespace {

py::dict cycle(const cable::Cable& cable, const std::string& experiment, double amplitude, int cycles, int points) {
  const requests::CycleRequest request{experiment, amplitude, cycles, points};
  std::optional<requests::CycleResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_cycle(cable, request));
  }
  warn(warning_messages(result->warnings));
  py::dict out = table_arrays(requests::cycle_table().values(requests::cycle_samples(*result)),
                              {result->record.samples.size()});
  out["last_cycle_dissipation_j"] = result->record.summary.slider_dissipation;
  out["last_cycle_loop_work_j"] = result->record.summary.loop_work;
  return out;
}

py::dict loop(std::optional<double> ei, const std::vector<std::pair<double, double>>& jenkin, double amplitude,
              int cycles, int points, const std::string& law, std::optional<double> exponent, const py::kwargs& numbers) {
  const section::SinusoidalDrive drive{amplitude, cycles, points};
  cable::LoopNumbers given{law, {}, jenkin};
  if (ei) given.numbers.emplace_back("ei", *ei);
  if (exponent) given.numbers.emplace_back("exponent", *exponent);
  for (const auto& [key, value] : numbers) {
    if (!value.is_none()) given.numbers.emplace_back(py::cast<std::string>(key), py::cast<double>(value));
  }
  const requests::LoopSpelling spelling{[](std::string_view key) { return std::string(key); },
                                        [](std::string_view name) { return "law = '" + std::string(name) + "'"; }};
  section::LoopRecord record;
  {
    py::gil_scoped_release release;
    record = requests::section_loop(given, drive, spelling);
  }
  py::dict out = table_arrays(requests::loop_table().values(requests::loop_samples(record)), {record.curvature.size()});
  out["last_cycle_dissipation_j_per_m"] = record.last_cycle_dissipation();
  return out;
}

}  // namespace

void expose_cable(py::module_& m) {
  py::class_<cable::Cable> cable_class(m, "Cable",
                                       "A cable (length, sections, section law and its numbers), validated and discretised");
  cable_class.def_property_readonly("length", &cable::Cable::length, "m")
      .def_property_readonly("sections", [](const cable::Cable& c) { return c.description().sections; })
      .def_property_readonly("law", [](const cable::Cable& c) { return std::string(c.description().law->name()); },
                             ("the section law: " + cable::section_law_names(true)).c_str());
  // Every law's numbers as properties, each key once: its value at the clamp, None
  // under a law without it.
  std::vector<std::string> number_keys;
  for (const cable::SectionLawDescriptor* law : cable::section_laws()) {
    for (const cable::LawNumber& n : law->numbers()) {
      const std::string key(n.key);
      if (std::find(number_keys.begin(), number_keys.end(), key) != number_keys.end()) continue;
      number_keys.push_back(key);
      std::vector<std::string> owners;
      for (const cable::SectionLawDescriptor* o : cable::section_laws()) {
        if (cable::number_index(*o, key) >= 0) owners.push_back(std::string(o->title()));
      }
      cable_class.def_property_readonly(
          key.c_str(),
          [key](const cable::Cable& c) -> std::optional<double> {
            if (cable::number_index(*c.description().law, key) < 0) return std::nullopt;
            return c.description().number(key).at(0.0);
          },
          fmt::format("{}{}{} (at the clamp; None under a law without it: the {} law{} take{} it)", n.unit,
                      n.unit.empty() ? "" : ", ", n.description, cable::joined_with_and(owners),
                      owners.size() > 1 ? "s" : "", owners.size() > 1 ? "" : "s")
              .c_str());
    }
  }
  cable_class
      .def_property_readonly(
          "jenkin",
          [](const cable::Cable& c) {
            std::vector<std::pair<double, double>> c_h;
            for (const auto& e : c.description().jenkin) c_h.emplace_back(e.c.at(0.0), e.h.at(0.0));
            return jenkin_list(c_h);
          },
          "[{'c': N m^2, 'h': N m}, ...] (at the clamp)")
      .def("toml", [](const cable::Cable& c) { return io::cable_table_toml(c.description()); },
           "The keys of a [cable] table for this cable (what cable and damper files accept).")
      .def(
          "with_length",
          [](const cable::Cable& c, double length) {
            cable::CableDescription d = c.description();
            d.length = length;
            return cable::Cable(std::move(d));
          },
          py::arg("length"), "A copy of this cable cut to another length, m (its parameters and sections kept).")
      .def(
          "save",
          [](const cable::Cable& c, const std::string& path, const std::string& comment) {
            io::write_file_atomically(path, io::cable_file_toml(c.description(), comment));
          },
          py::arg("path"), py::arg("comment") = "",
          "Write this cable as a cable file (TOML) that load_cable, the cycle command and damper files' "
          "[arm.cable] file = ... read; `comment` goes on top as TOML comments.");
  py::class_<damper::Damper>(m, "Damper", "A damper (clamp mass and arms), validated")
      .def_property_readonly("clamp_mass", &damper::Damper::clamp_mass, "kg")
      .def_property_readonly("arms", [](const damper::Damper& d) {
        py::list names;
        for (std::size_t k = 0; k < d.arms().size(); ++k) names.append(d.arm_name(k));
        return names;
      });

  m.def(
      "load_cable",
      [](const std::string& path, bool allow_unusual) {
        return warned(io::load_cable_file(path, slip_policy(allow_unusual)));
      },
      py::arg("path"), py::arg("allow_unusual") = false,
      "Read a cable TOML file (an UnusualValueWarning for each value outside the typical ranges; UnusualValueError "
      "for one a unit slip explains, unless allow_unusual).");
  m.def(
      "load_damper",
      [](const std::string& path, bool allow_unusual) {
        return warned(io::load_damper_file(path, slip_policy(allow_unusual)));
      },
      py::arg("path"), py::arg("allow_unusual") = false,
      "Read a damper TOML file (an UnusualValueWarning for each value outside the typical ranges; UnusualValueError "
      "for one a unit slip explains, unless allow_unusual).");
  m.def(
      "_cable_from_toml",
      [](std::string_view text, std::string_view source, bool allow_unusual) {
        return warned(io::load_cable_text(text, source, slip_policy(allow_unusual)));
      },
      py::arg("text"), py::arg("source"), py::arg("allow_unusual") = false,
      "A cable from TOML text (make_cable builds it): the cable file reader's keys, checks, messages and warnings.");
  m.def(
      "_damper_from_toml",
      [](std::string_view text, std::string_view source, bool allow_unusual) {
        return warned(io::load_damper_text(text, source, slip_policy(allow_unusual)));
      },
      py::arg("text"), py::arg("source"), py::arg("allow_unusual") = false,
        "A damper from TOML text (make_damper builds it): the damper file reader's keys, checks, messages and warnings.");
  m.def("cycle", &cycle, py::arg("cable"), py::arg("experiment"), py::arg("amplitude"),
        py::arg("cycles") = requests::CycleRequest{}.cycles, py::arg("points") = requests::CycleRequest{}.points,
        "Experiment 'a' (tip force) or 'b' (tip rotation) on a cable.");
  m.def("loop", &loop, py::arg("ei") = py::none(), py::arg("jenkin") = std::vector<std::pair<double, double>>{},
        py::arg("amplitude"), py::arg("cycles") = section::SinusoidalDrive{}.cycles,
        py::arg("points") = section::SinusoidalDrive{}.points, py::arg("law") = std::string(requests::default_loop_law),
        py::arg("exponent") = py::none(),
        "One section driven by kappa = amplitude sin(2 pi k / points), as the loop command: the law's numbers by key "
        "(Cable's properties; ei and jenkin = [(c, h), ...] in N m^2 and N m for law 'masing', its variants 'exact' "
        "and 'regularised' (with exponent, default 10); ei_min, ei_max (N m^2) and chi0 (1/m) for law 'bouc-wen').");
  m.def(
      "load_strand",
      [](const std::string& path) {
        const strand::Strand s = io::read_strand_file(path);
        return from_json(requests::strand_summary(strand::strand_bounds(s)));
      },
      py::arg("path"), "A strand file's bending-stiffness bounds, as the strand command: {ei_min_n_m2, ei_max_n_m2}.");
  m.def(
      "strand_bounds",
      [](double core_radius, const std::vector<std::tuple<int, double, double, double>>& layers, double youngs_modulus) {
        strand::Strand s;
        s.core_radius = core_radius;
        s.youngs_modulus = youngs_modulus;
        for (const auto& [count, r, pitch, lay] : layers) s.layers.push_back({count, r, pitch, lay});
        strand::validate(s);
        const strand::StrandBounds b = strand::strand_bounds(s);
        return std::make_pair(b.ei_min, b.ei_max);
      },
      py::arg("core_radius"), py::arg("layers"), py::arg("youngs_modulus") = strand::Strand{}.youngs_modulus,
      "(EI_min, EI_max) in N m^2; layers = [(count, wire_radius, pitch_radius, lay_length), ...] in m.");
  m.def(
      "conductor",
      [](const std::string& type) { return from_json(requests::conductor_summary(io::catalogue_conductor(type))); },
      py::arg("type"),
      "A conductor of the catalogue (case, spaces and hyphens aside, e.g. 'acsr-drake'), as `stockbridge conductors "
      "TYPE --json`: a dict of type, stranding, source and the span file's [conductor] values with units "
      "(mass_per_length_kg_m, diameter_m, rated_tensile_strength_n, ei_min_n_m2, ei_max_n_m2, outer_wire_diameter_m, "
      "outer_wire_modulus_pa, aluminium_layers), EI_min and the rest derived from the stranding.");
  m.def(
      "conductors",
      [] {
        py::list out;
        for (const span::StrandedConductor& c : io::conductor_catalogue()) out.append(from_json(requests::conductor_summary(c)));
        return out;
      },
      "The catalogue: one dict per conductor, as conductor() gives it.");
  m.def(
      "load_conductor",
      [](const std::string& path) { return from_json(requests::conductor_summary(io::read_conductor_file(path))); },
      py::arg("path"), "A conductor file (the catalogue's format, docs/file-formats.md), as conductor() gives an entry.");
}

}  // namespace stockbridge::python
