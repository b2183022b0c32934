#pragma once
// Fields of the CSV files feran writes (RFC 4180).

#include <string>
#include <string_view>

namespace feran::detail {

/// @p text as one CSV field (RFC 4180): as it is, or, when it holds a comma, a
/// double quote, a carriage return or a line feed, in double quotes with each
/// double quote doubled; so a name like `bearing "A", left` keeps the columns.
inline std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

/// A column name made of a model's name (a node's, a spring's, a mode's label) and
/// @p suffix: spaces of the name become underscores ("bearing 1" + "_fx" is
/// bearing_1_fx), and the whole is one CSV field.
inline std::string csv_column(std::string name, std::string_view suffix) {
  for (char& c : name)
    if (c == ' ') c = '_';
  name += suffix;
  return csv_field(name);
}

}  // namespace feran::detail
