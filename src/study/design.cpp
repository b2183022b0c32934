#include <feran/study/design.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/spec/parameters.hpp>

namespace feran {

Real value_at(const DesignVariable& v, Real t) {
  t = std::clamp(t, Real(0), Real(1));
  if (v.discrete()) {
    const auto n = v.values.size();
    const auto bin = std::min(n - 1, static_cast<std::size_t>(t * static_cast<Real>(n)));
    return v.values[bin];
  }
  if (t == 0) return v.lower;
  if (t == 1) return v.upper;
  if (v.scale == VariableScale::log) return v.lower * std::pow(v.upper / v.lower, t);
  return v.lower + t * (v.upper - v.lower);
}

std::vector<Real> design_values(std::span<const DesignVariable> variables, std::span<const Real> t) {
  std::vector<Real> out(variables.size());
  for (std::size_t i = 0; i < variables.size(); ++i) out[i] = value_at(variables[i], t[i]);
  return out;
}

ModelSpec apply_design(const ModelSpec& base, std::span<const DesignVariable> variables, std::span<const Real> values) {
  ModelSpec spec = base;
  for (std::size_t i = 0; i < variables.size(); ++i)
    for (std::size_t k = 0; k < variables[i].paths.size(); ++k)
      set_parameter(spec, variables[i].paths[k], variables[i].path_value(k, values[i]));
  return spec;
}

void check_variables(std::span<const DesignVariable> variables) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const auto& v = variables[i];
    const auto here = fmt::format("variables[{}]", i);
    if (!names.insert(v.name).second)
      throw SpecError(here + ".name", fmt::format("the name '{}' is used by another variable", v.name));
    if (v.paths.empty()) throw SpecError(here + ".paths", "a variable needs at least one parameter path");
    if ((!v.factors.empty() || !v.offsets.empty()) &&
        (v.factors.size() != v.paths.size() || v.offsets.size() != v.paths.size()))
      throw SpecError(here + ".paths", "a factor and an offset for each path, or none");
    if (v.discrete()) {
      if (std::any_of(v.values.begin(), v.values.end(), [](Real x) { return !std::isfinite(x); }))
        throw SpecError(here + ".values", "every value must be finite");
      continue;
    }
    if (!std::isfinite(v.lower) || !std::isfinite(v.upper) || !(v.lower < v.upper))
      throw SpecError(here, fmt::format("'lower' must be below 'upper', got {} and {}", v.lower, v.upper));
    if (v.scale == VariableScale::log && !(v.lower > 0))
      throw SpecError(here + ".lower", fmt::format("a log scale needs lower > 0, got {}", v.lower));
  }
}

}  // namespace feran
