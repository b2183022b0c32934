#include <feran/io/node_reference.hpp>

#include <array>
#include <charconv>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "suggestions.hpp"

namespace feran {

namespace {

using detail::join_list;

/// At most this many node names are listed in a message.
constexpr std::size_t max_listed_names = 8;

constexpr std::array<Dof, dofs_per_node> node_dof_order = {Dof::u, Dof::v, Dof::w, Dof::rx, Dof::ry, Dof::rz};

std::vector<std::string> node_dof_names() {
  std::vector<std::string> names;
  for (const Dof d : node_dof_order) names.emplace_back(dof_name(d));
  return names;
}

/// "the node names are 'a' and 'b', the node numbers 1-9", for a reference that
/// matched nothing and is close to nothing.
std::string node_choices(const Model& model) {
  const std::string numbers = detail::number_ranges(detail::node_numbers(model));
  std::vector<std::string> names = detail::node_names(model);
  if (names.empty()) return fmt::format("no node has a name; the node numbers are {}", numbers);
  if (names.size() <= max_listed_names)
    return fmt::format("the node names are {}, the node numbers {}", join_list(names, "and", '\''), numbers);
  const std::size_t n_names = names.size();
  names.resize(max_listed_names);
  return fmt::format("the node names include {} ({} names in all), the node numbers are {}",
                     join_list(names, "and", '\''), n_names, numbers);
}

/// " (did you mean 'v', the displacement along y?)" and the like, or "".
std::string dof_hint(const std::string& text) {
  struct Axis {
    std::string_view lower, upper, dof;
  };
  constexpr std::array<Axis, 3> axes = {{{"x", "X", "u"}, {"y", "Y", "v"}, {"z", "Z", "w"}}};
  for (const Axis& a : axes)
    if (text == a.lower || text == a.upper)
      return fmt::format(" (did you mean '{}', the displacement along {}?)", a.dof, a.lower);
  // Distance 0: only a match ignoring case; one edit away from "r" lie u, v, w, rx, …
  if (const auto match = detail::closest_match(text, node_dof_names(), 0))
    return fmt::format(" (did you mean '{}'?)", *match);
  return {};
}

}  // namespace

Index find_node_reference(const Model& model, const std::string& text, const std::string& what) {
  if (text.empty()) throw Error(fmt::format("{}: empty node reference; give a node number or a node name", what));
  if (detail::all_digits(text)) {
    int number = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (ec == std::errc{} && ptr == text.data() + text.size())
      if (const Index found = model.find_node(number); found >= 0) return found;
    if (const Index named = model.find_node(text); named >= 0) return named;
    throw Error(fmt::format("{} '{}': no such node; the node numbers are {}", what, text,
                            detail::number_ranges(detail::node_numbers(model))));
  }
  if (const Index found = model.find_node(text); found >= 0) return found;
  if (const auto match = detail::closest_node_name(model, text))
    throw Error(fmt::format("{} '{}': no such node; did you mean '{}'?", what, text, *match));
  throw Error(fmt::format("{} '{}': no such node; {}", what, text, node_choices(model)));
}

std::pair<Index, std::optional<Dof>> parse_probe(const Model& model, const std::string& text) {
  const std::string what = "probe";
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos || model.find_node(text) >= 0)
    return {find_node_reference(model, text, what), std::nullopt};

  const Index node = find_node_reference(model, text.substr(0, colon), what);
  const std::string dof = text.substr(colon + 1);
  for (const Dof d : node_dof_order)
    if (dof == dof_name(d)) return {node, d};
  if (dof.empty())
    throw Error(fmt::format("probe '{}': no DOF after ':'; the DOFs are {}", text, join_list(node_dof_names(), "and")));
  throw Error(fmt::format("probe '{}': unknown DOF '{}'; the DOFs are {}{}", text, dof,
                          join_list(node_dof_names(), "and"), dof_hint(dof)));
}

}  // namespace feran
