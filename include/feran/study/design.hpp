#pragma once
/// @file
/// The design variables of a study: numbers of a model, set by parameter path.
///
/// A variable spans a range (linear or logarithmic) or a list of discrete values,
/// and sets one or more parameter paths to the same value (variables tied
/// together, such as the stiffness of both bearings in both directions). Samplers
/// and optimisers work in the unit cube: coordinate t ∈ [0, 1] of each variable,
/// mapped to its value here, so that a log-scaled stiffness from 1e6 to 1e9 N/m is
/// explored evenly in its decades.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/core/units.hpp>
#include <feran/spec/model_spec.hpp>

namespace feran {

enum class VariableScale { linear, log };

struct DesignVariable {
  std::string name;
  std::vector<std::string> paths;  ///< parameter paths, all set to the variable's value
  /// Per path (both empty: 1 and 0 for all): path k is set to offsets[k] +
  /// factors[k]·value, for paths tied by a linear relation instead of equal (an
  /// arctan law's c0 and c1 from one remaining stiffness fraction).
  std::vector<Real> factors, offsets;
  Real lower = 0.0, upper = 0.0;  ///< bounds in SI units (continuous variables)
  VariableScale scale = VariableScale::linear;
  std::vector<Real> values;          ///< discrete values in SI units; empty: continuous
  std::optional<Quantity> quantity;  ///< the kind of the paths' values (none: a number)
  std::string unit;                  ///< the unit values are shown in (e.g. "N/m"); empty: SI

  bool discrete() const { return !values.empty(); }
  /// The value path @p k takes when the variable is @p value.
  Real path_value(std::size_t k, Real value) const { return factors.empty() ? value : offsets[k] + factors[k] * value; }
  /// Number of distinct values (discrete), 0 for a continuous variable.
  Index levels() const { return static_cast<Index>(values.size()); }
};

/// The value of @p v at unit coordinate @p t (clamped to [0, 1]): linear or
/// geometric interpolation between the bounds, or the discrete value of the bin
/// ⌊t·n⌋ (the last bin includes t = 1), so that every value has an equal share.
Real value_at(const DesignVariable& v, Real t);

/// The values of all variables at unit coordinates @p t (one per variable).
std::vector<Real> design_values(std::span<const DesignVariable> variables, std::span<const Real> t);

/// @p base with every variable's paths set to its value (path_value()). Throws ParameterError for a
/// path that names nothing settable (checked when the study is read, so that this is
/// found before any analysis runs).
ModelSpec apply_design(const ModelSpec& base, std::span<const DesignVariable> variables, std::span<const Real> values);

/// Throws SpecError (path "variables[i]…") for an inconsistent variable: no path,
/// bounds not finite or lower ≥ upper, a log scale with lower ≤ 0, duplicate names.
void check_variables(std::span<const DesignVariable> variables);

}  // namespace feran
