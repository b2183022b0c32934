#pragma once
// The text of a JSON document as feran writes it.

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "feran/core/types.hpp"

namespace feran::detail {

/// @p j as text with @p indent spaces per level and a final newline. A string that
/// is not valid UTF-8 (a model path from the command line can hold any bytes) has
/// each invalid byte replaced by U+FFFD, so the document is always valid JSON
/// (nlohmann::json would otherwise throw after the whole analysis had run).
inline std::string json_text(const nlohmann::json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

/// @p x as a JSON number; NaN and infinities have no JSON spelling and become null.
inline nlohmann::json json_number(Real x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

/// The names of a node's six degrees of freedom (the keys of displacements) and of
/// the six directions of forces and moments, in the order of the model's DOFs.
inline constexpr const char* dof_names[dofs_per_node] = {"u", "v", "w", "rx", "ry", "rz"};
inline constexpr const char* direction_names[dofs_per_node] = {"x", "y", "z", "rx", "ry", "rz"};

}  // namespace feran::detail
