#pragma once
/// @file
/// Parameter paths: get and set any number of a ModelSpec by a path with units.
///
/// A path names a table, an entry, a key and, for coefficient laws and tables, a part:
///
///     materials[steel].E                  entry by its name
///     shafts[0].sections[2].outer_diameter  entry by its index (from 0)
///     springs[bearing 1].ky               a constant coefficient (or an arctan's value)
///     springs[mount].ky.f_as              a part of a coefficient law
///     springs[mount].ky.values[2]         an entry of a coefficient table
///     rigid_bodies[rotor].mass            an entry without a name, by its node's name
///     campbell.stop                       a key of a single table
///     runup.table[1][1]                   the speed of a run-up table's second point
///
/// An entry is found by its index, its name, or — for entries that sit at a node and
/// have no such name — the name of its node, when that picks exactly one entry. Every
/// number a field table declares (quantities, dimensionless numbers, counts, the
/// parts of coefficient laws) can be set; names, choices and node references cannot.
/// Values are set with their unit ("2e7 N/m", "30 Hz"); a bare number is in the SI
/// unit of the key, as in a model file. Setting does not check the value: build_model()
/// does, as it does for a file.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <feran/core/error.hpp>
#include <feran/core/units.hpp>
#include <feran/spec/model_spec.hpp>

namespace feran {

/// A bad parameter path or value: what() says which part is wrong and, where a name
/// was misspelt, what was probably meant.
class ParameterError : public Error {
 public:
  using Error::Error;
};

/// One settable number of a spec.
struct Parameter {
  std::string path;                  ///< e.g. "springs[bearing 1].ky"
  Real value = 0.0;                  ///< in SI units (speeds in rad/s, frequencies in Hz)
  std::optional<Quantity> quantity;  ///< empty for dimensionless numbers and counts
  bool integer = false;              ///< a count (set with an integer)
  std::string unit;                  ///< the unit it is shown in ("mm"); empty: SI
  std::string doc;                   ///< what the key means
  /// The value with its unit, as written back to a file ("68 mm", "0.3", "4").
  std::string text() const;
};

/// Every number of @p spec that a path can set and that has a value, in file order.
/// Entries are named by their name when it is unique in their table, else by index.
std::vector<Parameter> list_parameters(const ModelSpec& spec);

/// The parameter at @p path, with its value; throws ParameterError when @p path names
/// nothing settable or a key that has no value.
Parameter get_parameter(const ModelSpec& spec, std::string_view path);

/// Sets the number at @p path to @p value, written with a unit or as a bare number in
/// the SI unit ("2e7 N/m", "30 Hz", "0.3", "4"). An absent optional key (such as
/// campbell.stop, or a spring coefficient) is created. Throws ParameterError for a bad
/// path, a unit of the wrong kind or a count that is not an integer. Returns the
/// canonical path of what was set, entries by index ("springs[0].ky"), as SpecError
/// paths name it.
std::string set_parameter(ModelSpec& spec, std::string_view path, std::string_view value);

/// Sets the number at @p path to @p si (SI units); returns the canonical path.
std::string set_parameter(ModelSpec& spec, std::string_view path, Real si);

/// Splits "PATH=VALUE" (as --set takes it) and sets it; throws ParameterError naming
/// @p assignment when it has no '=' or setting fails. Returns the canonical path.
std::string apply_assignment(ModelSpec& spec, std::string_view assignment);

}  // namespace feran
