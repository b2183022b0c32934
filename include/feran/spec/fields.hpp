#pragma once
/// @file
/// The keys of every table of a model file, declared once.
///
/// Each spec type S (model_spec.hpp) has one field table, fields_of<S>(): per key its
/// name, what kind of value it holds, its physical quantity and bounds, whether it is
/// required, the unit it is shown in and a one-line description, and which member of
/// S holds it. The TOML reader, the writer, the parameter paths, the builder's bound
/// checks and the key lists of docs/model-format.md are all driven by these tables,
/// so a key is declared in one place. visit_tables() names the tables of a ModelSpec.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <feran/core/units.hpp>
#include <feran/spec/model_spec.hpp>

namespace feran::spec {

/// What a key holds.
enum class FieldKind {
  quantity,      ///< a physical quantity (number in SI or "value unit" text)
  number,        ///< a dimensionless number
  integer,       ///< an integer (counts, node numbers)
  flag,          ///< true or false
  text,          ///< a name
  choice,        ///< one word of Field::choices
  choice_list,   ///< an array of words of Field::choices
  text_list,     ///< an array of names
  node,          ///< a node reference (number or name)
  node_list,     ///< an array of node references
  integer_list,  ///< an array of integers
  coefficient,   ///< a speed-dependent coefficient: a quantity or a law table
  time_table,    ///< an array of [time, value] pairs, the value of the field's quantity
};

/// Bounds on a number (quantities, numbers, integers and coefficient values).
struct Bound {
  enum class Kind { none, positive, non_negative, at_least };
  Kind kind = Kind::none;
  std::int64_t minimum = 0;              ///< for at_least (integers)
  std::int64_t maximum = 1'000'000'000;  ///< integers: the largest allowed value
};

/// Element @p index of an array member of S (a spring's coefficients).
template <class S, class T, std::size_t N>
struct ArrayElement {
  std::array<T, N> S::*array;
  std::size_t index;
};

/// The value a field's member (a pointer to a member of S, or an element of an
/// array member) designates in @p s; every visitor of Field::member reads and
/// writes through these.
template <class S, class T>
constexpr T& member_of(S& s, T S::*m) {
  return s.*m;
}
template <class S, class T>
constexpr const T& member_of(const S& s, T S::*m) {
  return s.*m;
}
template <class S, class T, std::size_t N>
constexpr T& member_of(S& s, const ArrayElement<S, T, N>& m) {
  return (s.*m.array)[m.index];
}
template <class S, class T, std::size_t N>
constexpr const T& member_of(const S& s, const ArrayElement<S, T, N>& m) {
  return (s.*m.array)[m.index];
}

/// The member of S a field is stored in.
template <class S>
using Member = std::variant<Real S::*, std::optional<Real> S::*, int S::*, std::optional<int> S::*,
                            std::optional<std::int64_t> S::*, bool S::*, std::optional<bool> S::*, std::string S::*,
                            std::optional<std::string> S::*, std::vector<std::string> S::*, NodeRef S::*,
                            std::optional<NodeRef> S::*, std::vector<NodeRef> S::*, std::vector<int> S::*,
                            std::optional<SpeedCoefficient> S::*, std::vector<std::pair<Real, Real>> S::*,
                            ArrayElement<S, std::optional<SpeedCoefficient>, spring::count>>;

/// One key of a table.
template <class S>
struct Field {
  std::string_view key;
  FieldKind kind = FieldKind::number;
  Member<S> member;
  std::string_view doc;
  Quantity quantity = Quantity::length;  ///< for quantities and coefficients
  Bound bound = {};
  bool required = false;  ///< the reader reports a missing key
  /// The unit values are written and shown in when no text was given ("mm", "GPa");
  /// empty: the SI unit.
  std::string_view unit = {};
  std::span<const std::string_view> choices = {};  ///< for choice and choice_list
  /// For node references: a word that means "no node" ("ground", "axis"); empty: none.
  std::string_view special = {};
  /// For coefficients: a direct coefficient may not be negative.
  bool direct = false;
  /// The default as the documentation states it, when it is neither "required" nor
  /// the value of a default-constructed S ("the node's flag", "`\"spring <i>\"`").
  std::string_view default_text = {};
  /// For lists: when not empty, an empty list is an error and this says what to do
  /// instead ("leave it out to fix all DOFs").
  std::string_view if_empty = {};
  /// Analysis options (spec/request.hpp): the group of fields this one belongs to
  /// ("profile": a run-up's speed, ramp and table), taken from a request all together.
  std::string_view group = {};
  /// Analysis options: the group this field follows (the magnitude g follows the
  /// direction of gravity): taken from a request alone when it sets that group.
  std::string_view follows = {};
  /// Analysis options: a one-letter name on the command line ("s" for -s,--speed).
  std::string_view short_name = {};
  /// Analysis options: the name the doors give it when not its key ("probe" for the
  /// key probes: --probe on the command line, probe= in Python, one node each).
  std::string_view option = {};
  /// Analysis options: the set of options this one belongs to when a table holds
  /// alternatives (a response's speed sweep, or its fixed speed): a request that sets
  /// an option of one alternative takes none of the others from the file.
  std::string_view alternative = {};
};

template <class S>
using FieldTable = std::vector<Field<S>>;

/// The field table of spec type S. Defined for ModelSpec (top-level keys), OptionsSpec,
/// MaterialSpec, ShaftSpec, SectionSpec, NodeSpec, RigidBodySpec, SpringSpec,
/// RotatingDamperSpec, FrictionSpec, JournalBearingSpec, RollingBearingSpec, AnnularSealSpec, RigidLinkSpec, FixedSpec,
/// UnbalanceSpec, ForceSpec, StaticLoadSpec, ModalSpec, CampbellSpec, ResponseSpec, StaticSpec, RunupSpec, Api684Spec,
/// OrbitsSpec and DriveSpec.
template <class S>
const FieldTable<S>& fields_of();

/// The most points of a sweep (Campbell speeds, response points, frequencies): a
/// million eigen solves or factorisations, hours of work and gigabytes of results;
/// the same limit whether the count comes from a model file or a command line.
inline constexpr std::int64_t max_sweep_points = 1'000'000;

/// The field @p key of spec type S (std::logic_error when S has none: a defect).
template <class S>
const Field<S>& field_of(std::string_view key) {
  for (const Field<S>& f : fields_of<S>())
    if (f.key == key) return f;
  throw std::logic_error("no field " + std::string(key));
}

/// The words field @p key of spec type S takes (empty for a key without choices).
template <class S>
std::span<const std::string_view> choices_of(std::string_view key) {
  for (const Field<S>& f : fields_of<S>())
    if (f.key == key) return f.choices;
  return {};
}

/// How a table appears in a file.
enum class TableForm {
  table,           ///< [key]: one table
  array_of_tables  ///< [[key]]: a list of tables
};

/// Calls f(key, form, doc, member) for each table of a ModelSpec in file order, with
/// member a reference to spec's S (for [key]) or std::vector<S> (for [[key]]).
/// @p spec may be const.
template <class Spec, class F>
void visit_tables(Spec& spec, F&& f) {
  using enum TableForm;
  f("options", table, "model-wide options", spec.options);
  f("materials", array_of_tables, "isotropic materials", spec.materials);
  f("shafts", array_of_tables, "shafts made of shaft elements; they create nodes", spec.shafts);
  f("nodes", array_of_tables, "extra nodes (stator, housing, foundation, a lumped rotor)", spec.nodes);
  f("rigid_bodies", array_of_tables, "rigid bodies (disks, rotors, stators) at nodes", spec.rigid_bodies);
  f("springs", array_of_tables, "spring–dampers to ground or between nodes (bearings, foot springs)", spec.springs);
  f("rotating_dampers", array_of_tables, "viscous dampers between rotating parts (internal damping)",
    spec.rotating_dampers);
  f("friction", array_of_tables, "Coulomb friction between rotating parts", spec.friction);
  f("journal_bearings", array_of_tables, "plain journal bearings on an oil film (nonlinear)", spec.journal_bearings);
  f("rolling_bearings", array_of_tables, "ball and roller bearings in Hertzian contact (nonlinear)",
    spec.rolling_bearings);
  f("annular_seals", array_of_tables, "plain annular liquid seals (short-seal bulk-flow model)", spec.annular_seals);
  f("rigid_links", array_of_tables, "nodes moving together as one rigid body", spec.rigid_links);
  f("fixed", array_of_tables, "DOFs held at zero", spec.fixed);
  f("unbalances", array_of_tables, "point unbalances", spec.unbalances);
  f("forces", array_of_tables, "harmonic forces and moments, or forces given in time (run-ups)", spec.forces);
  f("static_loads", array_of_tables, "constant forces and moments (static analysis)", spec.static_loads);
  f("modal", table, "defaults for a modal analysis", spec.modal);
  f("campbell", table, "defaults for a Campbell diagram", spec.campbell);
  f("response", table, "defaults for a steady-state (harmonic) response", spec.response);
  f("static", table, "gravity and defaults for a static analysis", spec.static_);
  f("runup", table, "speed profile and defaults for a run-up (transient) analysis", spec.runup);
  f("api684", table, "operating range and settings of the API 617 / API 684 analyses", spec.api684);
  f("orbits", table, "speed range and settings of periodic orbits (harmonic balance, continuation, Floquet)",
    spec.orbits);
  f("drive", table, "the motor and load torques of torque-driven run-ups", spec.drive);
}

/// Calls f(key, doc, children) for the arrays of sub-tables of an entry of spec type
/// S ([[shafts.sections]] of a shaft); nothing for other types.
template <class S, class F>
void visit_children(S& entry, F&& f) {
  if constexpr (std::is_same_v<std::remove_const_t<S>, ShaftSpec>)
    f("sections", "sections of uniform circular cross-section, in order along x", entry.sections);
}

/// The quantity of a force's amplitude: a moment for kind "rotating_moment" and the
/// directions rx, ry, rz, else a force.
Quantity amplitude_quantity(const ForceSpec& force);
/// The quantity of field @p f's values in @p entry: the field's own, except for the
/// amplitude and time table of a force, which are moments for the moment directions.
template <class S>
Quantity value_quantity(const S& entry, const Field<S>& f) {
  if constexpr (std::is_same_v<S, ForceSpec>)
    if (f.key == "amplitude" || f.key == "time_table") return amplitude_quantity(entry);
  return f.quantity;
}

/// The keys of a coefficient's law table ({ law = "step", below = …, … }).
struct CoefficientLaw {
  std::string_view law;                ///< "table", "step", "arctan" or "frequency_table"
  std::vector<std::string_view> keys;  ///< its keys, "law" first
};
/// The laws a coefficient may follow, in the order messages name them.
const std::vector<CoefficientLaw>& coefficient_laws();

}  // namespace feran::spec
