#pragma once
// Fields of the CSV files feran writes (RFC 4180).

#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include <feran/model/model.hpp>

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

/// @p x as a CSV number with ten significant digits; an empty field when not finite.
inline std::string csv_number(Real x) { return std::isfinite(x) ? fmt::format("{:.10g}", x) : ""; }

/// The name a node's columns start with: its name, or node<number> when it has none.
inline std::string csv_node_tag(const Model& model, Index node) {
  const Node& n = model.nodes[static_cast<std::size_t>(node)];
  return n.name.empty() ? fmt::format("node{}", n.number) : n.name;
}

/// The name an element's columns start with: its label, or element<position from 1>.
inline std::string csv_element_tag(const Model& model, Index element) {
  const std::string& label = model.elements[static_cast<std::size_t>(element)].label();
  return label.empty() ? fmt::format("element{}", element + 1) : label;
}

}  // namespace feran::detail
