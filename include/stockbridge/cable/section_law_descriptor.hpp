#pragma once
// A section law as one type (docs/architecture.md, "The section law: a seam in the
// cable"): everything the layers above the cable need to know of a law, from one
// place, so that none of them names a law. Its name (the one vocabulary of cable
// files, `loop --law`, `identify --law` and Python), its keys with their units,
// typical ranges and scalings, its validation and zone boundaries, the report's
// words for it, its fitted numbers (packing and starts), its section for `loop`,
// and the factory of its CableLaw.
//
// Every law registers one descriptor: a function `const SectionLawDescriptor&
// <name>_section_law()` defined in its own `src/cable/<name>_cable_law.cpp`, which
// the build finds (src/CMakeLists.txt globs the files and generates the registry).
// A law is then one header and one source under section/ and one under cable/.
//
// Two kinds of laws: the Masing law, whose hysteresis is a list of Jenkin elements
// (CableDescription::jenkin, `--elements` in the fits), and laws of a fixed set of
// numbers (Bouc-Wen: ei_min, ei_max, chi0), each a profile over s, held by key in
// CableDescription (`ei` in CableDescription::ei, the others in `numbers`).

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"

namespace stockbridge::section {
class SectionLaw;
}

namespace stockbridge::cable {

class CableLaw;
class Profile;
struct CableDescription;
struct SectionLawDescriptor;

/// How a fit moves a number: by its logarithm (a number > 0) or by steps of the
/// starting value's size (or 1 where the start is 0), for a number that may be 0 or
/// negative (an exponent).
enum class FitScale { logarithmic, linear };

/// Which factor of identify impedance's starts a number takes: the stiffness's (ei),
/// the slip moment's (h, chi0), or none (kept at its starting value).
enum class StartRole { none, stiffness, slip };

/// One number of a law: a profile over s in cable files.
struct LawNumber {
  std::string_view key;          ///< as cable files, damper paths, Python and `loop` (with - for _) name it
  std::string_view unit;         ///< "N m^2"; "" for a pure number
  std::string_view description;  ///< for `loop --help`: what it is
  TypicalRange typical;          ///< its values' usual range (the unusual-value warnings)
  /// The power of s that a damper scaled by s (lengths times s) multiplies it by,
  /// keeping its impedance: a stiffness 3, a moment 1, a curvature -2, a pure number 0.
  int scaling_power = 0;
  StartRole start_role = StartRole::none;
  FitScale fit_scale = FitScale::logarithmic;
};

/// A law's numbers as constants, in the order of its keys (a fitted cable).
struct LawValues {
  const SectionLawDescriptor* law = nullptr;
  std::vector<double> values;

  double operator[](std::size_t k) const { return values[k]; }
  bool operator==(const LawValues&) const = default;
};

/// What a fit of a law of numbers starts from: the Masing numbers estimated from a
/// record (ei the slipping stiffness, c the stick stiffness above it, h the slip
/// moment of the loop), for the law to turn into its own.
struct MasingEstimate {
  double ei = 0.0;
  double c = 0.0;
  double h = 0.0;
};

/// Which fit asks for starts: `identify local` (moment-curvature) or `identify
/// global` (a cable experiment, from the four steps' Masing cable).
enum class FitKind { local, global };

/// The numbers a `loop` of one section is given: by key (with `ei`), the Masing
/// law's Jenkin elements (c, h), and the name the law was asked by (a law may take
/// variants: the Masing law's "exact" and "regularised").
struct LoopNumbers {
  std::string law;
  std::vector<std::pair<std::string, double>> numbers;
  std::vector<std::pair<double, double>> jenkin;

  const double* find(std::string_view key) const;
};

struct SectionLawDescriptor {
  virtual ~SectionLawDescriptor() = default;

  /// "masing", "bouc-wen", "iwan": cable files' `law`, `loop --law`, `identify --law`, Python.
  virtual std::string_view name() const = 0;
  /// "Masing", "Bouc-Wen": as messages and the report say "the Bouc-Wen law".
  virtual std::string_view title() const = 0;
  /// Where the law sorts among the laws (messages list them in this order); the
  /// first is the default of cable files without `law`.
  virtual int order() const = 0;
  /// Its numbers, "ei" among them where the law has the elastic part (Masing, Iwan).
  virtual std::span<const LawNumber> numbers() const = 0;
  /// Whether the law's hysteresis is CableDescription::jenkin (the Masing law; with
  /// the modified Masing model's k0 and lever_arm_cap), fitted with `--elements`.
  virtual bool jenkin_elements() const { return false; }
  /// What a cable of the law takes, in messages: "ei_min, ei_max and chi0".
  virtual std::string takes() const;

  /// Throws InvalidParameter naming the bad field: the default checks each number
  /// as a plausible (finite, > 0) value in its unit.
  virtual void validate(const CableDescription& description) const;
  /// The profiles whose jumps make zone boundaries: the default, every number's.
  virtual std::vector<const Profile*> profiles(const CableDescription& description) const;
  /// The report's words for the law and its stiffness at the clamp; `number` formats
  /// a value to three significant digits.
  virtual std::string summary(const CableDescription& description, std::string (*number)(double)) const = 0;
  /// The law of a cable at the Gauss points.
  virtual std::shared_ptr<const CableLaw> make(const CableDescription& description, std::span<const double> positions,
                                               std::span<const double> weights) const = 0;

  /// Other names `loop --law` takes for the law (the Masing law's "exact" and "regularised").
  virtual std::vector<std::string_view> loop_variants() const { return {}; }
  /// Keys `loop` takes beyond the law's numbers, optional (the regularised law's "exponent").
  virtual std::vector<LawNumber> loop_extras() const { return {}; }
  /// The section of the law for `loop`, its numbers checked (loop_section()).
  virtual std::unique_ptr<section::SectionLaw> loop_section(const LoopNumbers& numbers) const;
  /// A section with these constant numbers, validated (InvalidParameter naming a key).
  virtual std::unique_ptr<section::SectionLaw> section(const std::vector<double>& values) const = 0;
  /// The moments of a section with these numbers along a path of curvatures from the
  /// virgin state, unvalidated (the local fit's model, its numbers the optimiser's).
  virtual std::vector<double> moments(const std::vector<double>& values, std::span<const double> curvature) const = 0;

  // The fits of a law of numbers (not the Masing law's, which fits Jenkin elements).

  /// The starts of a fit, as numbers in key order.
  virtual std::vector<std::vector<double>> starts(const MasingEstimate& estimate, FitKind kind) const;
  /// The numbers as an optimiser's variables (and back): the default, logarithms
  /// of the numbers scaled logarithmically, the others as they are.
  virtual std::vector<double> pack(const std::vector<double>& values) const;
  virtual std::vector<double> unpack(const std::vector<double>& x) const;
  /// Throws InvalidParameter (naming `prefix` + key) for a start identify impedance
  /// cannot fit from; the default accepts any.
  virtual void check_start(const std::vector<double>& values, const std::string& prefix) const;
};

/// Every law, in order (the first the default).
std::span<const SectionLawDescriptor* const> section_laws();
/// The default law: cable files without `law`.
const SectionLawDescriptor& default_section_law();
/// The law of this name, or nullptr.
const SectionLawDescriptor* find_section_law(std::string_view name);
/// The law of this name: InvalidParameter naming `field` otherwise (" = 'x': expected masing, bouc-wen or iwan").
const SectionLawDescriptor& section_law(std::string_view name, std::string_view field = "law");
/// The names, "masing, bouc-wen or iwan" (`quote`: "\"masing\", \"bouc-wen\" or \"iwan\"").
std::string section_law_names(bool quote = false);
/// "a, b and c".
std::string joined_with_and(const std::vector<std::string>& items);

/// The index of `key` among the law's numbers, or -1.
int number_index(const SectionLawDescriptor& law, std::string_view key);
/// The keys a cable table of the law takes: its numbers (and "jenkin",
/// "lever_arm_cap" under jenkin_elements()).
std::vector<std::string_view> law_keys(const SectionLawDescriptor& law);
/// Why `key` does not belong to a cable of `law`: "is a number of the Masing law:
/// law = \"bouc-wen\" takes ei_min, ei_max and chi0", or under the default law
/// "is a number of the Bouc-Wen law: set law = \"bouc-wen\"".
std::string foreign_key_message(std::string_view key, const SectionLawDescriptor& law);
/// The laws (other than `law`) whose cables take `key`.
std::vector<const SectionLawDescriptor*> owners_of(std::string_view key, const SectionLawDescriptor* law = nullptr);

}  // namespace stockbridge::cable
