#pragma once
// The text of a JSON document as feran writes it.

#include <string>

#include <nlohmann/json.hpp>

namespace feran::detail {

/// @p j as text with @p indent spaces per level and a final newline. A string that
/// is not valid UTF-8 (a model path from the command line can hold any bytes) has
/// each invalid byte replaced by U+FFFD, so the document is always valid JSON
/// (nlohmann::json would otherwise throw after the whole analysis had run).
inline std::string json_text(const nlohmann::json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace feran::detail
