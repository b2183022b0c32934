#include <feran/io/model_reader.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <utility>

#include <fmt/format.h>
#include <toml++/toml.h>

#include <feran/assembly/assembler.hpp>
#include <feran/assembly/checks.hpp>
#include <feran/elements/rigid_body.hpp>
#include <feran/elements/rotating_damper.hpp>
#include <feran/elements/spring_damper.hpp>
#include <feran/elements/timoshenko_beam.hpp>

#include "suggestions.hpp"
#include "table_reader.hpp"

namespace feran {

namespace {

using detail::all_digits;
using detail::closest_match;
using detail::expected_quantity;
using detail::join_list;
using detail::number_ranges;
using detail::QuantityValue;
using detail::TableReader;
using detail::type_name;

/// A node reference may also be one of these words, depending on the table.
constexpr std::string_view ground_word = "ground";
constexpr std::string_view axis_word = "axis";

/// Gravitational acceleration used when [static] gives a direction but no 'g' [m/s²].
constexpr Real default_gravity = 9.81;

/// Upper bound on elements per section: guards against a typo such as 1e9 elements.
constexpr int max_elements_per_section = 100000;

/// The integrators [runup] may name: the names the transient analysis registers
/// (make_integrator() in analyses/transient/integrator.hpp).
const std::vector<std::string> runup_integrators = {"trapezoidal", "rk3", "wolfbrandt",
                                                    "ros34pw2"};

/// True when @p a is written before @p b in the file.
bool written_before(const toml::node& a, const toml::node& b) {
  const auto p = a.source().begin, q = b.source().begin;
  return p.line < q.line || (p.line == q.line && p.column < q.column);
}

std::string format_location(const SourceLocation& at) {
  return fmt::format("line {}, column {}", at.line, at.column);
}

/// Builds a ModelFile from a parsed TOML document.
class ModelBuilder {
 public:
  ModelBuilder(const toml::table& root, const std::string& path)
      : path_(path), top_(root, "", path) {
    out_.path = path;
  }

  ModelFile build();

 private:
  /// A name that a special word or a digit string would make ambiguous.
  void check_node_name(const toml::node& at, const std::string& name, const TableReader& t) const;
  /// Adds a node; @p defined_at is where it was defined, @p name_at where its name was
  /// given (or nullptr).
  Index add_node(Node node, const toml::node& defined_at, const toml::node* name_at,
                 const TableReader& t);

  void read_options();
  void read_materials();
  void read_shafts();
  void read_extra_nodes();
  void read_rigid_bodies();
  void read_springs();
  void read_rotating_dampers();
  void read_friction();
  void read_rigid_links();
  void read_fixed();
  void read_unbalances();
  void read_forces();
  void read_static_loads();
  void read_modal();
  void read_campbell();
  void read_response();
  void read_static();
  void read_runup();
  void check_structure();

  /// `probes`: node references, non-empty, no node twice (as in [response]).
  void read_probes(const TableReader& t, std::vector<Index>& probes) const;
  /// The spring–damper element named by the string @p name written at @p n.
  Index resolve_spring(const toml::node& n, const std::string& name, const TableReader& t) const;

  /// Calls f(reader, index) for each table of the array of tables @p key (1-based index).
  template <class F>
  void for_each_table(std::string_view key, F f) const;
  /// The table @p key (written [key]), or nullptr.
  const toml::table* sub_table(std::string_view key) const;

  /// The node a reference (number or name) at @p n denotes. @p special, if not
  /// empty, is a word ("ground", "axis") the caller has already handled; it is
  /// offered in suggestions.
  Index resolve_node(const toml::node& n, std::string_view name, const TableReader& t,
                     std::string_view special = {}) const;
  /// `node` key (required).
  Index required_node(const TableReader& t, std::string_view key = "node") const;
  /// `to` key: std::nullopt for @p special (also the default), else a node ≠ @p from.
  std::optional<Index> other_node(const TableReader& t, std::string_view special,
                                  Index from) const;
  /// The material named by the string at @p n.
  const Material& resolve_material(const toml::node& n, const TableReader& t) const;
  /// Throws "<reason>, but node … is not rotating (…)" unless node @p index is rotating;
  /// @p reason reads e.g. "a rotating damper acts between rotating parts".
  void require_rotating(Index index, const toml::node& at, std::string_view reason,
                        const TableReader& t) const;

  SpeedCoefficient read_coefficient(const toml::node& n, const std::string& key, Quantity kind,
                                    bool direct, const TableReader& parent) const;
  /// A speed that may be a bare number in @p speed_unit (rad/s when empty).
  Real read_speed(const toml::node& n, std::string_view name, const std::string& speed_unit,
                  const TableReader& t) const;

  const std::string& path_;
  TableReader top_;
  ModelFile out_;
  Model& model_ = out_.model;
  std::vector<const toml::node*> material_nodes_;     ///< where each material's name is
  std::vector<SourceLocation> name_locations_;        ///< where each node's name is
  std::set<int> claimed_numbers_;                     ///< explicit [[nodes]] numbers
  std::vector<int> fixed_index_;                      ///< node → index in model_.fixed
  /// [[springs]] entries with a 'name' (references from [runup]): name, element index.
  std::vector<std::pair<std::string, Index>> named_springs_;
  std::vector<std::string> unnamed_spring_labels_;    ///< default labels, for hints
};

template <class F>
void ModelBuilder::for_each_table(std::string_view key, F f) const {
  const toml::node* n = top_.find(key);
  if (n == nullptr) return;
  const toml::array* array = n->as_array();
  if (array == nullptr)
    top_.fail(*n, fmt::format("'{}' must be an array of tables, written [[{}]], got {}", key, key,
                              type_name(*n)));
  const std::string context = fmt::format("[[{}]]", key);
  int index = 0;
  for (const toml::node& entry : *array) {
    ++index;
    const toml::table* table = entry.as_table();
    if (table == nullptr)
      top_.fail(entry, fmt::format("each entry of '{}' must be a table, got {}", key,
                                   type_name(entry)));
    f(TableReader(*table, context, path_), index);
  }
}

const toml::table* ModelBuilder::sub_table(std::string_view key) const {
  const toml::node* n = top_.find(key);
  if (n == nullptr) return nullptr;
  if (const toml::table* t = n->as_table()) return t;
  top_.fail(*n, fmt::format("'{}' must be a table, written [{}], got {}", key, key, type_name(*n)));
}

ModelFile ModelBuilder::build() {
  top_.check_keys({"title", "options", "materials", "shafts", "nodes", "rigid_bodies", "springs",
                   "rotating_dampers", "friction", "rigid_links", "fixed", "unbalances", "forces",
                   "static_loads", "modal", "campbell", "response", "static", "runup"});
  if (const auto title = top_.string("title")) out_.title = *title;
  model_.name = out_.title;

  read_options();
  read_materials();
  read_shafts();
  read_extra_nodes();
  if (model_.nodes.empty())
    throw ModelError(SourceLocation{path_, 1, 1},
                     "the model has no nodes; define a shaft with [[shafts]] or a node with "
                     "[[nodes]]");
  fixed_index_.assign(model_.nodes.size(), -1);
  read_rigid_bodies();
  read_springs();
  read_rotating_dampers();
  read_friction();
  read_rigid_links();
  read_fixed();
  read_unbalances();
  read_forces();
  read_static_loads();
  read_modal();
  read_campbell();
  read_response();
  read_static();
  read_runup();
  check_structure();
  return std::move(out_);
}

// ---------------------------------------------------------------------------------
// Options and materials

void ModelBuilder::read_options() {
  const toml::table* table = sub_table("options");
  if (table == nullptr) return;
  const TableReader t(*table, "[options]", path_);
  t.check_keys({"shear_deformation", "gyroscopic", "shaft_damping", "free_motions"});
  ModelOptions& o = model_.options;
  o.shear_deformation = t.boolean("shear_deformation").value_or(true);
  if (const auto g = t.string("gyroscopic")) {
    if (*g == "consistent") {
      o.gyroscopic = GyroscopicForm::consistent;
    } else if (*g == "lumped") {
      o.gyroscopic = GyroscopicForm::lumped;
    } else {
      std::string message =
          fmt::format("'gyroscopic' must be \"consistent\" or \"lumped\", got \"{}\"", *g);
      if (const auto m = closest_match(*g, {"consistent", "lumped"}, 2))
        message += fmt::format("; did you mean \"{}\"?", *m);
      t.fail(*t.find("gyroscopic"), message);
    }
  }
  if (const auto beta = t.quantity("shaft_damping", Quantity::time)) {
    t.require_non_negative(*beta, "shaft_damping");
    o.shaft_damping = beta->si;
  }
  if (const toml::array* motions = t.array("free_motions")) {
    const std::vector<std::string> names = {"axial", "torsion", "lateral"};
    for (const toml::node& entry : *motions) {
      const auto s = entry.value_exact<std::string>();
      const auto it = s ? std::find(names.begin(), names.end(), *s) : names.end();
      if (it == names.end()) {
        std::string message = fmt::format(
            "entries of 'free_motions' must be \"axial\", \"torsion\" or \"lateral\", got {}",
            s ? fmt::format("\"{}\"", *s) : type_name(entry));
        if (s)
          if (const auto m = closest_match(*s, names, 2))
            message += fmt::format("; did you mean \"{}\"?", *m);
        t.fail(entry, message);
      }
      const auto motion = static_cast<FreeMotion>(it - names.begin());
      if (std::find(o.free_motions.begin(), o.free_motions.end(), motion) == o.free_motions.end())
        o.free_motions.push_back(motion);
    }
  }
}

void ModelBuilder::read_materials() {
  for_each_table("materials", [&](const TableReader& t, int /*index*/) {
    t.check_keys({"name", "E", "G", "nu", "rho", "loss_factor"});
    Material m;
    m.name = t.required_string("name", "the material's name, a string such as \"steel\"");
    const toml::node& name_node = *t.find("name");
    if (m.name.empty()) t.fail(name_node, "material 'name' must not be empty");
    for (std::size_t i = 0; i < model_.materials.size(); ++i)
      if (model_.materials[i].name == m.name)
        t.fail(name_node, fmt::format("material '{}' is defined twice; the first definition is at {}",
                                      m.name,
                                      format_location(detail::location_of(path_, *material_nodes_[i]))));

    const QuantityValue E = t.required_quantity("E", Quantity::pressure);
    t.require_positive(E, "E");
    m.E = E.si;

    const auto G = t.quantity("G", Quantity::pressure);
    const auto nu = t.number("nu");
    if (G && nu)
      t.fail(*t.find("nu"), "give either the shear modulus 'G' or Poisson's ratio 'nu', not both");
    if (G) {
      t.require_positive(*G, "G");
      m.G = G->si;
    } else if (nu) {
      if (!(*nu > -1.0 && *nu < 0.5))
        t.fail(*t.find("nu"),
               fmt::format("'nu' (Poisson's ratio) must lie between -1 and 0.5 (both excluded), got {}",
                           *nu));
      m.G = m.E / (2.0 * (1.0 + *nu));
    } else {
      t.fail_here(fmt::format("missing key 'G' or 'nu' in [[materials]] (expected the shear "
                              "modulus G, {}, or Poisson's ratio nu, a number such as 0.3)",
                              expected_quantity(Quantity::pressure)));
    }

    const QuantityValue rho = t.required_quantity("rho", Quantity::density);
    t.require_non_negative(rho, "rho");
    m.rho = rho.si;
    m.loss_factor = t.non_negative_number("loss_factor").value_or(0.0);

    model_.materials.push_back(m);
    material_nodes_.push_back(&name_node);
  });
}

const Material& ModelBuilder::resolve_material(const toml::node& n, const TableReader& t) const {
  const auto name = n.value_exact<std::string>();
  if (!name)
    t.fail(n, fmt::format("'material' must be the name of a material (a string), got {}",
                          type_name(n)));
  std::vector<std::string> names;
  for (const Material& m : model_.materials) {
    if (m.name == *name) return m;
    names.push_back(m.name);
  }
  std::string message = fmt::format("material '{}' is not defined", *name);
  if (const auto match = closest_match(*name, names, 2))
    message += fmt::format("; did you mean '{}'?", *match);
  else if (names.empty())
    message += "; define it in a [[materials]] table";
  else
    message += fmt::format("; the defined materials are {}", join_list(names, "and", '\''));
  t.fail(n, message);
}

// ---------------------------------------------------------------------------------
// Nodes

void ModelBuilder::check_node_name(const toml::node& at, const std::string& name,
                                   const TableReader& t) const {
  if (name.empty()) t.fail(at, "a node name must not be empty");
  if (name == ground_word || name == axis_word)
    t.fail(at, fmt::format("'{}' cannot be a node name: it is reserved for references to {}",
                           name, name == ground_word ? "the ground" : "the rotating frame's axis"));
}

Index ModelBuilder::add_node(Node node, const toml::node& defined_at, const toml::node* name_at,
                             const TableReader& t) {
  for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
    const Node& other = model_.nodes[i];
    if (other.number == node.number)
      t.fail(defined_at,
             fmt::format("node number {} is already used by the node defined at {}", node.number,
                         format_location(out_.node_locations[i])));
    if (!node.name.empty() && other.name == node.name)
      t.fail(name_at != nullptr ? *name_at : defined_at,
             fmt::format("node name '{}' is already used by node {}, defined at {}", node.name,
                         other.number, format_location(name_locations_[i])));
  }
  out_.node_locations.push_back(detail::location_of(path_, defined_at));
  name_locations_.push_back(detail::location_of(path_, name_at != nullptr ? *name_at : defined_at));
  model_.nodes.push_back(std::move(node));
  return model_.n_nodes() - 1;
}

void ModelBuilder::read_shafts() {
  int next_number = 1;
  for_each_table("shafts", [&](const TableReader& t, int shaft_index) {
    t.check_keys({"name", "x", "rotating", "material", "start_node", "sections"});
    const auto name = t.string("name");
    const std::string shaft_label = name ? *name : fmt::format("{}", shaft_index);
    const Real x0 = t.quantity("x", Quantity::length).value_or(QuantityValue{}).si;
    const bool rotating = t.boolean("rotating").value_or(true);
    const Material* shaft_material = nullptr;
    if (const toml::node* m = t.find("material")) shaft_material = &resolve_material(*m, t);

    const toml::node& sections_node =
        t.require("sections", "at least one section, written [[shafts.sections]]");
    const toml::array* sections = sections_node.as_array();
    if (sections == nullptr)
      t.fail(sections_node, fmt::format("'sections' must be an array of tables, written "
                                        "[[shafts.sections]], got {}",
                                        type_name(sections_node)));
    if (sections->empty())
      t.fail(sections_node, "a shaft needs at least one section ([[shafts.sections]])");

    // First node of the shaft, at x0.
    Node first;
    first.number = next_number++;
    first.x = x0;
    first.rotating = rotating;
    const toml::node* first_name_at = nullptr;
    if (const auto start = t.string("start_node")) {
      first_name_at = t.find("start_node");
      check_node_name(*first_name_at, *start, t);
      first.name = *start;
    }
    Index node_a = add_node(first, t.table(), first_name_at, t);

    const BeamOptions beam_options{model_.options.shear_deformation, model_.options.gyroscopic,
                                   rotating, rotating ? model_.options.shaft_damping : 0.0};
    Real x_section = x0;
    int section_index = 0;
    for (const toml::node& entry : *sections) {
      ++section_index;
      const toml::table* table = entry.as_table();
      if (table == nullptr)
        t.fail(entry, fmt::format("each entry of 'sections' must be a table, got {}",
                                  type_name(entry)));
      const TableReader s(*table, "[[shafts.sections]]", path_);
      s.check_keys({"length", "outer_diameter", "inner_diameter", "material", "elements",
                    "end_node"});
      const QuantityValue length = s.required_quantity("length", Quantity::length);
      s.require_positive(length, "length");
      const QuantityValue outer = s.required_quantity("outer_diameter", Quantity::length);
      s.require_positive(outer, "outer_diameter");
      CircularSection section{outer.si, 0.0};
      if (const auto inner = s.quantity("inner_diameter", Quantity::length)) {
        s.require_non_negative(*inner, "inner_diameter");
        if (!(inner->si < outer.si))
          s.fail(*inner->node,
                 fmt::format("inner_diameter ({}) must be smaller than outer_diameter ({})",
                             inner->written, outer.written));
        section.inner_diameter = inner->si;
      }
      const Material* material = shaft_material;
      if (const toml::node* m = s.find("material")) material = &resolve_material(*m, s);
      if (material == nullptr)
        s.fail_here(
            "missing key 'material' in [[shafts.sections]] (expected the name of a material; "
            "or give the shaft a default with 'material' in [[shafts]])");
      BeamOptions section_options = beam_options;
      section_options.loss_factor = material->loss_factor;
      const int n_elements = s.integer("elements", 1, max_elements_per_section).value_or(1);
      const toml::node* end_name_at = nullptr;
      std::string end_name;
      if (const auto end = s.string("end_node")) {
        end_name_at = s.find("end_node");
        check_node_name(*end_name_at, *end, s);
        end_name = *end;
      }

      for (int j = 1; j <= n_elements; ++j) {
        Node node;
        node.number = next_number++;
        node.x = x_section + length.si * static_cast<Real>(j) / static_cast<Real>(n_elements);
        node.rotating = rotating;
        if (j == n_elements) node.name = end_name;
        const Index node_b =
            add_node(node, *table, j == n_elements ? end_name_at : nullptr, s);
        model_.elements.emplace_back(
            TimoshenkoBeam(node_a, node_b, length.si / static_cast<Real>(n_elements), section,
                           *material, section_options),
            fmt::format("shaft {} section {} element {}", shaft_label, section_index, j));
        node_a = node_b;
      }
      x_section += length.si;
    }
  });
}

void ModelBuilder::read_extra_nodes() {
  // Explicit numbers first, so that default numbers never take a number that a
  // later entry asks for.
  if (const toml::node* n = top_.find("nodes"))
    if (const toml::array* a = n->as_array())
      for (const toml::node& entry : *a)
        if (const toml::table* t = entry.as_table())
          if (const auto number = t->get("number") ? t->get("number")->value_exact<std::int64_t>()
                                                   : std::nullopt)
            if (*number >= 1 && *number <= std::numeric_limits<int>::max())
              claimed_numbers_.insert(static_cast<int>(*number));

  for_each_table("nodes", [&](const TableReader& t, int /*index*/) {
    t.check_keys({"x", "name", "number", "rotating"});
    Node node;
    node.x = t.required_quantity("x", Quantity::length).si;
    const toml::node* name_at = nullptr;
    if (const auto name = t.string("name")) {
      name_at = t.find("name");
      check_node_name(*name_at, *name, t);
      node.name = *name;
    }
    node.rotating = t.boolean("rotating").value_or(false);
    const toml::node* defined_at = &t.table();
    if (const auto number = t.integer("number", 1, std::numeric_limits<int>::max() - 1)) {
      node.number = *number;
      defined_at = t.find("number");
    } else {
      int highest = 0;
      for (const Node& other : model_.nodes) highest = std::max(highest, other.number);
      node.number = highest + 1;
      while (claimed_numbers_.count(node.number) != 0) ++node.number;
    }
    add_node(node, *defined_at, name_at, t);
    // Locate messages about the node (e.g. from check_model) at its table.
    out_.node_locations.back() = detail::location_of(path_, t.table());
  });
}

Index ModelBuilder::resolve_node(const toml::node& n, std::string_view name, const TableReader& t,
                                 std::string_view special) const {
  if (const auto number = n.value_exact<std::int64_t>()) {
    for (Index i = 0; i < model_.n_nodes(); ++i)
      if (model_.nodes[static_cast<std::size_t>(i)].number == *number) return i;
    t.fail(n, fmt::format("node {} does not exist; the node numbers are {}", *number,
                          number_ranges(detail::node_numbers(model_))));
  }
  if (const auto text = n.value_exact<std::string>()) {
    // "ground" and "axis" are reserved, so they never name a node.
    if (*text == ground_word || *text == axis_word)
      t.fail(n, fmt::format("'{}' cannot be \"{}\" here; expected {}a node number or a node name",
                            name, *text,
                            special.empty() ? std::string{} : fmt::format("\"{}\", ", special)));
    const Index found = model_.find_node(*text);
    if (found >= 0) return found;
    const std::vector<std::string> names = detail::node_names(model_);
    std::vector<std::string> extra;
    if (!special.empty()) extra.emplace_back(special);
    std::string message = fmt::format("node '{}' does not exist", *text);
    if (const auto match = detail::closest_node_name(model_, *text, extra))
      message += fmt::format("; did you mean '{}'?", *match);
    else if (all_digits(*text))
      message += fmt::format("; a quoted reference is a node name: to refer to node number {0}, "
                             "write {1} = {0} without quotes",
                             *text, name);
    else if (names.empty())
      message += fmt::format("; no node has a name, so refer to nodes by number (e.g. {} = 1)",
                             name);
    else if (names.size() <= 10)
      message += fmt::format("; the node names are {}", join_list(names, "and", '\''));
    t.fail(n, message);
  }
  if (!special.empty())
    t.fail(n, fmt::format("'{}' must be \"{}\", a node number (an integer) or a node name (a "
                          "string), got {}",
                          name, special, type_name(n)));
  t.fail(n, fmt::format("'{}' must be a node number (an integer) or a node name (a string), got {}",
                        name, type_name(n)));
}

Index ModelBuilder::required_node(const TableReader& t, std::string_view key) const {
  return resolve_node(t.require(key, "a node number or a node name"), key, t);
}

std::optional<Index> ModelBuilder::other_node(const TableReader& t, std::string_view special,
                                              Index from) const {
  const toml::node* n = t.find("to");
  if (n == nullptr) return std::nullopt;
  if (const auto text = n->value_exact<std::string>(); text && *text == special)
    return std::nullopt;
  const Index to = resolve_node(*n, "to", t, special);
  if (to == from)
    t.fail(*n, fmt::format("'to' must be a node other than 'node' (both are node {})",
                           model_.node_label(to)));
  return to;
}

void ModelBuilder::require_rotating(Index index, const toml::node& at, std::string_view reason,
                                    const TableReader& t) const {
  if (!model_.nodes[static_cast<std::size_t>(index)].rotating)
    t.fail(at, fmt::format("{}, but node {} is not rotating (a shaft's nodes rotate unless the "
                           "shaft says rotating = false; [[nodes]] entries need rotating = true)",
                           reason, model_.node_label(index)));
}

// ---------------------------------------------------------------------------------
// Elements

void ModelBuilder::read_rigid_bodies() {
  for_each_table("rigid_bodies", [&](const TableReader& t, int index) {
    t.check_keys({"name", "node", "mass", "Ja", "Jp", "outer_diameter", "inner_diameter", "width",
                  "material", "offset", "rotating"});
    const std::string label =
        t.string("name").value_or(fmt::format("rigid body {}", index));
    const Index node = required_node(t);

    const std::array<std::string_view, 3> mass_keys = {"mass", "Ja", "Jp"};
    const std::array<std::string_view, 4> disk_keys = {"outer_diameter", "inner_diameter", "width",
                                                       "material"};
    const toml::node* mass_key_node = nullptr;
    std::string_view mass_key;
    for (const auto k : mass_keys)
      if (const toml::node* n = t.find(k); n != nullptr && mass_key_node == nullptr) {
        mass_key_node = n;
        mass_key = k;
      }
    const toml::node* disk_key_node = nullptr;
    std::string_view disk_key;
    for (const auto k : disk_keys)
      if (const toml::node* n = t.find(k); n != nullptr && disk_key_node == nullptr) {
        disk_key_node = n;
        disk_key = k;
      }
    if (mass_key_node != nullptr && disk_key_node != nullptr) {
      // Point at whichever of the two keys comes later in the file.
      const auto a = mass_key_node->source().begin, b = disk_key_node->source().begin;
      const bool disk_later = a.line < b.line || (a.line == b.line && a.column < b.column);
      t.fail(disk_later ? *disk_key_node : *mass_key_node,
             fmt::format("a rigid body is given either by mass, Ja and Jp or as a disk by "
                         "outer_diameter, width, inner_diameter and material; this one mixes "
                         "the two forms ('{}' and '{}')",
                         mass_key, disk_key));
    }
    if (mass_key_node == nullptr && disk_key_node == nullptr)
      t.fail_here("a rigid body needs either mass, Ja and Jp, or the disk form outer_diameter, "
                  "width and material (inner_diameter optional)");

    RigidBodyProperties props;
    if (mass_key_node != nullptr) {
      const QuantityValue mass = t.required_quantity("mass", Quantity::mass);
      t.require_non_negative(mass, "mass");
      const QuantityValue ja = t.required_quantity("Ja", Quantity::inertia);
      t.require_non_negative(ja, "Ja");
      const QuantityValue jp = t.required_quantity("Jp", Quantity::inertia);
      t.require_non_negative(jp, "Jp");
      props.mass = mass.si;
      props.transverse_inertia = ja.si;
      props.polar_inertia = jp.si;
    } else {
      const QuantityValue outer = t.required_quantity("outer_diameter", Quantity::length);
      t.require_positive(outer, "outer_diameter");
      const QuantityValue width = t.required_quantity("width", Quantity::length);
      t.require_positive(width, "width");
      Real inner = 0.0;
      if (const auto q = t.quantity("inner_diameter", Quantity::length)) {
        t.require_non_negative(*q, "inner_diameter");
        if (!(q->si < outer.si))
          t.fail(*q->node,
                 fmt::format("inner_diameter ({}) must be smaller than outer_diameter ({})",
                             q->written, outer.written));
        inner = q->si;
      }
      const Material& material = resolve_material(
          t.require("material", "the name of a material, whose density the disk form uses"), t);
      props = RigidBody::disk(material.rho, outer.si, inner, width.si);
    }

    if (const auto offset = t.quantity("offset", Quantity::length)) {
      props.offset = offset->si;
      const Real parallel_axis = props.mass * offset->si * offset->si;
      if (disk_key_node != nullptr) {
        // The disk's inertia is about its centre; Ja is about the node.
        props.transverse_inertia += parallel_axis;
      } else if (props.transverse_inertia < parallel_axis) {
        t.fail(*t.find("Ja"),
               fmt::format("'Ja' ({} kg*m^2) is about a transverse axis through the node, so it "
                           "must be at least mass·offset² = {} kg*m^2",
                           props.transverse_inertia, parallel_axis));
      }
    }
    const bool rotating =
        t.boolean("rotating").value_or(model_.nodes[static_cast<std::size_t>(node)].rotating);
    model_.elements.emplace_back(RigidBody(node, props, rotating), label);
  });
}

Real ModelBuilder::read_speed(const toml::node& n, std::string_view name,
                              const std::string& speed_unit, const TableReader& t) const {
  if (!speed_unit.empty() && (n.is_integer() || n.is_floating_point())) {
    const QuantityValue bare = t.quantity_at(n, name, Quantity::speed);
    return *to_si(Quantity::speed, bare.si, speed_unit);
  }
  return t.quantity_at(n, name, Quantity::speed).si;
}

SpeedCoefficient ModelBuilder::read_coefficient(const toml::node& n, const std::string& key,
                                                Quantity kind, bool direct,
                                                const TableReader& parent) const {
  const toml::table* table = n.as_table();
  if (table == nullptr) {
    if (n.is_array() || n.is_boolean() || n.is_date() || n.is_time() || n.is_date_time())
      parent.fail(n, fmt::format("{}, or an inline table with a 'law', got {}",
                                 detail::must_be_quantity(key, kind), type_name(n)));
    const QuantityValue q = parent.quantity_at(n, key, kind);
    if (direct) parent.require_non_negative(q, key);
    return SpeedCoefficient(q.si);
  }

  const TableReader t(*table, fmt::format("coefficient '{}'", key), path_);
  const std::vector<std::string> laws = {"table", "step", "arctan"};
  const std::string law = t.required_string("law", "\"table\", \"step\" or \"arctan\"");
  if (std::find(laws.begin(), laws.end(), law) == laws.end()) {
    std::string message =
        fmt::format("unknown law '{}' for coefficient '{}'; expected \"table\", \"step\" or "
                    "\"arctan\"",
                    law, key);
    if (const auto m = closest_match(law, laws, 2))
      message += fmt::format(" (did you mean \"{}\"?)", *m);
    t.fail(*t.find("law"), message);
  }

  const auto check_direct = [&](const QuantityValue& q, std::string_view name) {
    if (direct && q.si < 0.0)
      t.fail(*q.node, fmt::format("'{}' must not be negative, got {} ('{}' is a direct "
                                  "coefficient; only the cross terms kyz, kzy, cyz, czy may be "
                                  "negative)",
                                  name, q.written, key));
  };
  const auto speed_unit = [&]() -> std::string {
    const auto unit = t.string("speed_unit");
    if (!unit) return {};
    if (!to_si(Quantity::speed, 1.0, *unit))
      t.fail(*t.find("speed_unit"),
             fmt::format("'speed_unit' must be \"rad/s\", \"Hz\" or \"rpm\", got \"{}\"", *unit));
    return *unit;
  };

  if (law == "table") {
    t.check_keys({"law", "speeds", "values", "speed_unit"});
    const std::string unit = speed_unit();
    const toml::array& speeds =
        t.required_array("speeds", "an array of speeds, e.g. [0, \"50 Hz\", \"100 Hz\"]");
    const toml::array& values = t.required_array(
        "values", fmt::format("an array of values, each {}", quantity_name(kind)));
    if (speeds.empty()) t.fail(speeds, fmt::format("'{}.speeds' must not be empty", key));
    if (values.size() != speeds.size())
      t.fail(*t.find("values"),
             fmt::format("'{0}.speeds' and '{0}.values' must have the same length, got {1} speeds "
                         "and {2} values",
                         key, speeds.size(), values.size()));
    SpeedCoefficient::Table law_table;
    for (std::size_t i = 0; i < speeds.size(); ++i) {
      const toml::node& s = *speeds.get(i);
      const Real speed = read_speed(s, fmt::format("{}.speeds[{}]", key, i), unit, t);
      if (!law_table.speeds.empty() && !(speed > law_table.speeds.back()))
        t.fail(s, fmt::format("'{}.speeds' must be strictly increasing, but entry {} ({} rad/s) "
                              "does not exceed the one before it ({} rad/s)",
                              key, i, speed, law_table.speeds.back()));
      law_table.speeds.push_back(speed);
      const QuantityValue v = t.quantity_at(*values.get(i), fmt::format("{}.values[{}]", key, i), kind);
      check_direct(v, fmt::format("{}.values[{}]", key, i));
      law_table.values.push_back(v.si);
    }
    return SpeedCoefficient(SpeedCoefficient::Law{law_table});
  }
  if (law == "step") {
    t.check_keys({"law", "below", "above", "at", "speed_unit"});
    const std::string unit = speed_unit();
    SpeedCoefficient::Step step;
    const QuantityValue below = t.required_quantity("below", kind);
    check_direct(below, "below");
    const QuantityValue above = t.required_quantity("above", kind);
    check_direct(above, "above");
    step.below = below.si;
    step.above = above.si;
    step.at = read_speed(t.require("at", expected_quantity(Quantity::speed)), "at", unit, t);
    return SpeedCoefficient(SpeedCoefficient::Law{step});
  }
  t.check_keys({"law", "value", "f_as", "c0", "c1", "c2"});
  SpeedCoefficient::Arctan a;
  const QuantityValue value = t.required_quantity("value", kind);
  check_direct(value, "value");
  a.value = value.si;
  a.f_as = t.required_quantity("f_as", Quantity::frequency).si;
  a.c0 = t.number("c0").value_or(a.c0);
  a.c1 = t.number("c1").value_or(a.c1);
  a.c2 = t.number("c2").value_or(a.c2);
  // s(f) runs between c0 − |c1|/2 and c0 + |c1|/2; a direct coefficient must stay ≥ 0.
  if (direct && a.c0 < 0.5 * std::abs(a.c1))
    t.fail(t.has("c0") ? *t.find("c0") : *t.find("c1"),
           fmt::format("the arctan factor of direct coefficient '{}' would turn negative at "
                       "high or low speed: need c0 ≥ |c1|/2, got c0 = {}, c1 = {}",
                       key, a.c0, a.c1));
  return SpeedCoefficient(SpeedCoefficient::Law{a});
}

void ModelBuilder::read_springs() {
  for_each_table("springs", [&](const TableReader& t, int index) {
    t.check_keys({"name", "node", "to", "kx", "ky", "kz", "krx", "kry", "krz", "kyz", "kzy", "cx",
                  "cy", "cz", "crx", "cry", "crz", "cyz", "czy", "loss_factor"});
    const auto name = t.string("name");
    const std::string label = name.value_or(fmt::format("spring {}", index));
    const Index node = required_node(t);
    const std::optional<Index> to = other_node(t, ground_word, node);

    SpringDamperCoefficients c;
    bool any = false;
    const auto read = [&](std::string_view key, Quantity kind, bool direct, SpeedCoefficient& out) {
      if (const toml::node* n = t.find(key)) {
        out = read_coefficient(*n, std::string(key), kind, direct, t);
        any = true;
      }
    };
    const std::array<std::string_view, dofs_per_node> k_keys = {"kx", "ky", "kz", "krx", "kry", "krz"};
    const std::array<std::string_view, dofs_per_node> c_keys = {"cx", "cy", "cz", "crx", "cry", "crz"};
    for (std::size_t d = 0; d < dofs_per_node; ++d) {
      const bool rotational = d >= 3;
      read(k_keys[d], rotational ? Quantity::rotational_stiffness : Quantity::stiffness, true, c.k[d]);
      read(c_keys[d], rotational ? Quantity::rotational_damping : Quantity::damping, true, c.c[d]);
    }
    read("kyz", Quantity::stiffness, false, c.kyz);
    read("kzy", Quantity::stiffness, false, c.kzy);
    read("cyz", Quantity::damping, false, c.cyz);
    read("czy", Quantity::damping, false, c.czy);
    c.loss_factor = t.non_negative_number("loss_factor").value_or(0.0);
    if (!any)
      t.fail_here(fmt::format("a spring needs at least one coefficient: kx, ky, kz, krx, kry, krz, "
                              "kyz, kzy, cx, cy, cz, crx, cry, crz, cyz or czy{}",
                              t.has("loss_factor") ? " ('loss_factor' only scales the stiffness "
                                                     "coefficients, it is not one)"
                                                   : ""));
    if (name)
      named_springs_.emplace_back(*name, static_cast<Index>(model_.elements.size()));
    else
      unnamed_spring_labels_.push_back(label);
    model_.elements.emplace_back(SpringDamper(node, to, c), label);
  });
}

void ModelBuilder::read_rotating_dampers() {
  for_each_table("rotating_dampers", [&](const TableReader& t, int index) {
    t.check_keys({"name", "node", "to", "ct", "cr", "cx", "crx"});
    const std::string label = t.string("name").value_or(fmt::format("rotating damper {}", index));
    const Index node = required_node(t);
    require_rotating(node, *t.find("node"), "a rotating damper acts between rotating parts", t);
    const std::optional<Index> to = other_node(t, axis_word, node);
    if (to)
      require_rotating(*to, *t.find("to"), "a rotating damper acts between rotating parts", t);

    RotatingDamperCoefficients c;
    const auto read = [&](std::string_view key, Quantity kind) {
      const auto q = t.quantity(key, kind);
      if (!q) return 0.0;
      t.require_non_negative(*q, key);
      return q->si;
    };
    c.translational = read("ct", Quantity::damping);
    c.rotational = read("cr", Quantity::rotational_damping);
    c.axial = read("cx", Quantity::damping);
    c.torsional = read("crx", Quantity::rotational_damping);
    if (c.translational == 0.0 && c.rotational == 0.0 && c.axial == 0.0 && c.torsional == 0.0)
      t.fail_here("a rotating damper needs at least one positive coefficient: ct, cr, cx or crx");
    model_.elements.emplace_back(RotatingDamper(node, to, c), label);
  });
}

void ModelBuilder::read_friction() {
  for_each_table("friction", [&](const TableReader& t, int index) {
    t.check_keys({"name", "node", "to", "force", "moment", "epsilon_t", "epsilon_r"});
    CoulombFriction f;
    f.label = t.string("name").value_or(fmt::format("friction {}", index));
    f.node_a = required_node(t);
    require_rotating(f.node_a, *t.find("node"), "Coulomb friction acts between rotating parts", t);
    f.node_b = other_node(t, axis_word, f.node_a);
    if (f.node_b)
      require_rotating(*f.node_b, *t.find("to"), "Coulomb friction acts between rotating parts", t);
    if (const auto q = t.quantity("force", Quantity::force)) {
      t.require_non_negative(*q, "force");
      f.force = q->si;
    }
    if (const auto q = t.quantity("moment", Quantity::moment)) {
      t.require_non_negative(*q, "moment");
      f.moment = q->si;
    }
    if (f.force == 0.0 && f.moment == 0.0)
      t.fail_here("Coulomb friction needs a positive 'force' or 'moment'");
    if (const auto q = t.quantity("epsilon_t", Quantity::velocity)) {
      t.require_positive(*q, "epsilon_t");
      f.epsilon_t = q->si;
    }
    if (const auto q = t.quantity("epsilon_r", Quantity::angular_velocity)) {
      t.require_positive(*q, "epsilon_r");
      f.epsilon_r = q->si;
    }
    model_.friction.push_back(f);
  });
}

// ---------------------------------------------------------------------------------
// Constraints, loads, analysis defaults

void ModelBuilder::read_rigid_links() {
  for_each_table("rigid_links", [&](const TableReader& t, int /*index*/) {
    t.check_keys({"nodes"});
    const toml::array& nodes =
        t.required_array("nodes", "an array of at least two node numbers or names");
    if (nodes.size() < 2)
      t.fail(nodes,
             fmt::format("'nodes' of a rigid link needs at least two nodes, got {}", nodes.size()));
    RigidLink link;
    std::vector<Index> seen;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const toml::node& entry = *nodes.get(i);
      const Index node = resolve_node(entry, fmt::format("nodes[{}]", i), t);
      if (std::find(seen.begin(), seen.end(), node) != seen.end())
        t.fail(entry, fmt::format("node {} appears twice in 'nodes'", model_.node_label(node)));
      seen.push_back(node);
      if (i == 0)
        link.leader = node;
      else
        link.followers.push_back(node);
    }
    model_.links.push_back(link);
  });
}

void ModelBuilder::read_fixed() {
  for_each_table("fixed", [&](const TableReader& t, int /*index*/) {
    t.check_keys({"node", "dofs"});
    const Index node = required_node(t);
    std::array<bool, dofs_per_node> dofs{};
    const auto set = [&](std::initializer_list<Dof> list) {
      for (const Dof d : list) dofs[static_cast<std::size_t>(d)] = true;
    };
    const toml::array* names = t.array("dofs");
    if (names == nullptr) {
      dofs.fill(true);
    } else {
      if (names->empty())
        t.fail(*t.find("dofs"), "'dofs' must not be empty (leave it out to fix all DOFs)");
      const std::vector<std::string> valid = {"u",   "v",   "w",           "rx",     "ry",      "rz",
                                              "all", "lateral", "translations", "rotations"};
      for (const toml::node& entry : *names) {
        const auto s = entry.value_exact<std::string>();
        if (s == "u") set({Dof::u});
        else if (s == "v") set({Dof::v});
        else if (s == "w") set({Dof::w});
        else if (s == "rx") set({Dof::rx});
        else if (s == "ry") set({Dof::ry});
        else if (s == "rz") set({Dof::rz});
        else if (s == "all") set({Dof::u, Dof::v, Dof::w, Dof::rx, Dof::ry, Dof::rz});
        else if (s == "lateral") set({Dof::v, Dof::w, Dof::ry, Dof::rz});
        else if (s == "translations") set({Dof::u, Dof::v, Dof::w});
        else if (s == "rotations") set({Dof::rx, Dof::ry, Dof::rz});
        else {
          std::string message = fmt::format(
              "entries of 'dofs' must be one of {}, got {}", join_list(valid, "or", '"'),
              s ? fmt::format("\"{}\"", *s) : type_name(entry));
          if (s)
            if (const auto m = closest_match(*s, valid, 2))
              message += fmt::format("; did you mean \"{}\"?", *m);
          t.fail(entry, message);
        }
      }
    }
    // Several [[fixed]] entries for one node add up.
    int& slot = fixed_index_[static_cast<std::size_t>(node)];
    if (slot < 0) {
      slot = static_cast<int>(model_.fixed.size());
      model_.fixed.push_back(FixedDofs{node, {}});
    }
    auto& target = model_.fixed[static_cast<std::size_t>(slot)].dofs;
    for (std::size_t d = 0; d < target.size(); ++d) target[d] = target[d] || dofs[d];
  });
}

void ModelBuilder::read_unbalances() {
  for_each_table("unbalances", [&](const TableReader& t, int index) {
    t.check_keys({"name", "node", "mass", "radius", "phase", "lever"});
    Unbalance u;
    u.label = t.string("name").value_or(fmt::format("unbalance {}", index));
    u.node = required_node(t);
    const QuantityValue mass = t.required_quantity("mass", Quantity::mass);
    t.require_positive(mass, "mass");
    u.mass = mass.si;
    const QuantityValue radius = t.required_quantity("radius", Quantity::length);
    t.require_positive(radius, "radius");
    u.radius = radius.si;
    if (const auto phase = t.quantity("phase", Quantity::angle)) u.phase = phase->si;
    if (const auto lever = t.quantity("lever", Quantity::length)) u.lever = lever->si;
    model_.unbalances.push_back(u);
  });
}

void ModelBuilder::read_forces() {
  using Kind = HarmonicForce::Kind;
  struct KindName {
    std::string_view name;
    Kind kind;
  };
  constexpr std::array<KindName, 3> kinds = {{{"fixed", Kind::fixed},
                                              {"rotating_force", Kind::rotating_force},
                                              {"rotating_moment", Kind::rotating_moment}}};
  // Directions name axes; Dof gives the storage order u, v, w, rx, ry, rz.
  constexpr std::array<std::string_view, dofs_per_node> directions = {"x",  "y",  "z",
                                                                      "rx", "ry", "rz"};
  const std::vector<std::string> direction_list(directions.begin(), directions.end());

  for_each_table("forces", [&](const TableReader& t, int index) {
    t.check_keys({"name", "node", "kind", "direction", "amplitude", "phase"});
    HarmonicForce f;
    f.label = t.string("name").value_or(fmt::format("force {}", index));
    f.node = required_node(t);

    std::string kind_name = "fixed";
    if (const auto kind = t.string("kind")) {
      const auto it = std::find_if(kinds.begin(), kinds.end(),
                                    [&](const KindName& k) { return k.name == *kind; });
      if (it == kinds.end()) {
        const std::vector<std::string> names = {"fixed", "rotating_force", "rotating_moment"};
        std::string message = fmt::format("'kind' must be {}, got \"{}\"",
                                          join_list(names, "or", '"'), *kind);
        std::vector<std::string> extending;
        for (const std::string& n : names)
          if (!kind->empty() && n.starts_with(*kind)) extending.push_back(n);
        if (const auto m = closest_match(*kind, names, 3))
          message += fmt::format("; did you mean \"{}\"?", *m);
        else if (!extending.empty())
          message += fmt::format("; did you mean {}?", join_list(extending, "or", '"'));
        t.fail(*t.find("kind"), message);
      }
      f.kind = it->kind;
      kind_name = *kind;
    }

    bool moment = f.kind == Kind::rotating_moment;
    if (f.kind == Kind::fixed) {
      const std::string direction = t.required_string(
          "direction", fmt::format("{} for a force of kind \"fixed\"",
                                   join_list(direction_list, "or", '"')));
      const auto it = std::find(directions.begin(), directions.end(), direction);
      if (it == directions.end()) {
        std::string message =
            fmt::format("'direction' must be {}, got \"{}\"", join_list(direction_list, "or", '"'),
                        direction);
        const std::string unsigned_direction =
            !direction.empty() && (direction.front() == '+' || direction.front() == '-')
                ? direction.substr(1)
                : std::string{};
        if (direction == "u" || direction == "v" || direction == "w")
          message += fmt::format("; did you mean \"{}\"? (directions name axes, not DOFs)",
                                 direction == "u" ? "x" : direction == "v" ? "y" : "z");
        else if (std::find(directions.begin(), directions.end(), unsigned_direction) !=
                 directions.end())
          message += fmt::format("; did you mean \"{}\"? (a direction has no sign: the force "
                                 "acts along +{}; phase = \"180 deg\" reverses it)",
                                 unsigned_direction, unsigned_direction);
        else if (const auto m = closest_match(direction, direction_list, 0))
          message += fmt::format("; did you mean \"{}\"?", *m);
        t.fail(*t.find("direction"), message);
      }
      f.direction = static_cast<Dof>(it - directions.begin());
      moment = f.direction == Dof::rx || f.direction == Dof::ry || f.direction == Dof::rz;
    } else {
      if (const toml::node* direction = t.find("direction"))
        t.fail(*direction,
               fmt::format("'direction' is only for a force of kind \"fixed\"; a {} turns with "
                           "the shaft in the y-z plane, so leave 'direction' out",
                           f.kind == Kind::rotating_force ? "rotating force" : "rotating moment"));
      require_rotating(f.node, *t.find("node"),
                       fmt::format("a force of kind \"{}\" turns with the shaft", kind_name), t);
    }

    const QuantityValue amplitude =
        t.required_quantity("amplitude", moment ? Quantity::moment : Quantity::force);
    t.require_positive(amplitude, "amplitude");
    f.amplitude = amplitude.si;
    if (const auto phase = t.quantity("phase", Quantity::angle)) f.phase = phase->si;
    model_.forces.push_back(f);
  });
}

void ModelBuilder::read_static_loads() {
  constexpr std::array<std::string_view, dofs_per_node> keys = {"fx", "fy", "fz",
                                                                "mx", "my", "mz"};
  for_each_table("static_loads", [&](const TableReader& t, int index) {
    t.check_keys({"name", "node", "fx", "fy", "fz", "mx", "my", "mz"});
    StaticLoad load;
    load.label = t.string("name").value_or(fmt::format("static load {}", index));
    load.node = required_node(t);
    bool any = false;
    for (std::size_t d = 0; d < keys.size(); ++d)
      if (const auto q = t.quantity(keys[d], d < 3 ? Quantity::force : Quantity::moment)) {
        load.load[d] = q->si;
        any = any || q->si != 0.0;
      }
    if (!any)
      t.fail_here("a static load needs at least one non-zero component: the forces fx, fy, fz "
                  "or the moments mx, my, mz");
    model_.static_loads.push_back(load);
  });
}

void ModelBuilder::read_modal() {
  const toml::table* table = sub_table("modal");
  if (table == nullptr) return;
  const TableReader t(*table, "[modal]", path_);
  t.check_keys({"speed", "modes"});
  if (const auto speed = t.quantity("speed", Quantity::speed)) out_.modal.speed = speed->si;
  out_.modal.modes = t.integer("modes", 1);
}

void ModelBuilder::read_campbell() {
  const toml::table* table = sub_table("campbell");
  if (table == nullptr) return;
  const TableReader t(*table, "[campbell]", path_);
  t.check_keys({"start", "stop", "points", "modes", "orders"});
  CampbellDefaults& c = out_.campbell;
  const auto start = t.quantity("start", Quantity::speed);
  const auto stop = t.quantity("stop", Quantity::speed);
  if (start) c.start = start->si;
  if (stop) c.stop = stop->si;
  if (start && stop && !(stop->si > start->si))
    t.fail(*stop->node, fmt::format("'stop' ({}) must be greater than 'start' ({})", stop->written,
                                    start->written));
  c.points = t.integer("points", 2);
  c.modes = t.integer("modes", 1);
  if (const toml::array* orders = t.array("orders")) {
    for (std::size_t i = 0; i < orders->size(); ++i)
      c.orders.push_back(t.integer_at(*orders->get(i), fmt::format("orders[{}]", i), 1));
  }
}

void ModelBuilder::read_response() {
  const toml::table* table = sub_table("response");
  if (table == nullptr) return;
  const TableReader t(*table, "[response]", path_);
  t.check_keys({"start", "stop", "points", "probes", "loss_factor"});
  ResponseDefaults& r = out_.response;
  const auto start = t.quantity("start", Quantity::speed);
  const auto stop = t.quantity("stop", Quantity::speed);
  if (start) r.start = start->si;
  if (stop) r.stop = stop->si;
  if (start && stop && !(stop->si > start->si))
    t.fail(*stop->node, fmt::format("'stop' ({}) must be greater than 'start' ({})", stop->written,
                                    start->written));
  r.points = t.integer("points", 2);
  read_probes(t, r.probes);
  r.loss_factor = t.non_negative_number("loss_factor");
}

void ModelBuilder::read_probes(const TableReader& t, std::vector<Index>& probes) const {
  const toml::array* entries = t.array("probes");
  if (entries == nullptr) return;
  if (entries->empty())
    t.fail(*entries, "'probes' must not be empty (leave it out for the analysis's default)");
  for (std::size_t i = 0; i < entries->size(); ++i) {
    const toml::node& entry = *entries->get(i);
    const Index node = resolve_node(entry, fmt::format("probes[{}]", i), t);
    if (std::find(probes.begin(), probes.end(), node) != probes.end())
      t.fail(entry, fmt::format("node {} appears twice in 'probes'", model_.node_label(node)));
    probes.push_back(node);
  }
}

void ModelBuilder::read_static() {
  const toml::table* table = sub_table("static");
  if (table == nullptr) return;
  const TableReader t(*table, "[static]", path_);
  t.check_keys({"gravity", "g", "speed"});
  StaticDefaults& s = out_.static_;
  const auto g = t.quantity("g", Quantity::acceleration);
  const std::vector<std::string> choices = {"+x", "-x", "+y", "-y", "+z", "-z", "none"};
  const std::string expected =
      fmt::format("'gravity' must be {} (the direction in which gravity pulls)",
                  join_list(choices, "or", '"'));
  if (const toml::node* n = t.find("gravity")) {
    const auto gravity = n->value_exact<std::string>();
    if (!gravity) t.fail(*n, fmt::format("{}, got {}", expected, type_name(*n)));
    if (*gravity == "none") {
      if (g)
        t.fail(*g->node, "'g' cannot be given with gravity = \"none\"; give a direction such as "
                         "gravity = \"-z\", or leave 'g' out");
      s.gravity = Eigen::Vector3d::Zero();
    } else {
      const auto it = std::find(choices.begin(), choices.end(), *gravity);
      if (it == choices.end()) {
        std::string message = fmt::format("{}, got \"{}\"", expected, *gravity);
        if (*gravity == "x" || *gravity == "y" || *gravity == "z")
          message += fmt::format("; give its sign: \"-{0}\" or \"+{0}\"", *gravity);
        else if (const auto m = closest_match(*gravity, choices, 0))
          message += fmt::format("; did you mean \"{}\"?", *m);
        t.fail(*n, message);
      }
      Real magnitude = default_gravity;
      if (g) {
        t.require_positive(*g, "g");
        magnitude = g->si;
      }
      const auto axis = static_cast<Eigen::Index>((it - choices.begin()) / 2);
      const Real sign = (it - choices.begin()) % 2 == 0 ? 1.0 : -1.0;
      Eigen::Vector3d vector = Eigen::Vector3d::Zero();
      vector[axis] = sign * magnitude;
      s.gravity = vector;
    }
  } else if (g) {
    t.fail(*g->node, "'g' needs a direction: give 'gravity' as well, e.g. gravity = \"-z\"");
  }
  if (const auto speed = t.quantity("speed", Quantity::speed)) s.speed = speed->si;
}

/// Reads the speed profile of [runup] into @p profile, in whichever of its three
/// forms is given. Returns the run's default duration: the ramp time or the last
/// table time (when > 0).
std::optional<Real> read_speed_profile(const TableReader& t,
                                       std::vector<std::pair<Real, Real>>& profile) {
  // The first key of each form that is present, to name two of them if they are mixed.
  struct FormKey {
    std::string_view key;
    const toml::node* node;
  };
  std::vector<FormKey> forms;
  for (const auto& keys : {std::vector<std::string_view>{"speed"},
                           std::vector<std::string_view>{"from", "to", "ramp_time"},
                           std::vector<std::string_view>{"table"}}) {
    std::optional<FormKey> first;
    for (const std::string_view key : keys)
      if (const toml::node* n = t.find(key);
          n != nullptr && (!first || written_before(*n, *first->node)))
        first = FormKey{key, n};
    if (first) forms.push_back(*first);
  }
  if (forms.empty()) return std::nullopt;
  std::sort(forms.begin(), forms.end(),
            [](const FormKey& a, const FormKey& b) { return written_before(*a.node, *b.node); });
  if (forms.size() > 1)
    t.fail(*forms[1].node,
           fmt::format("the speed profile is given either by 'speed' (a constant speed), by "
                       "'from', 'to' and 'ramp_time' (a linear ramp) or by 'table' (time and "
                       "speed points); this [runup] mixes '{}' and '{}'",
                       forms[0].key, forms[1].key));

  if (const auto speed = t.quantity("speed", Quantity::speed)) {
    t.require_non_negative(*speed, "speed");
    profile = {{0.0, speed->si}};
    return std::nullopt;
  }

  if (const toml::array* table = t.array("table")) {
    if (table->empty())
      t.fail(*table, "'table' needs at least one [time, speed] pair, e.g. "
                     "[[\"0 s\", \"0 Hz\"], [\"5 s\", \"80 Hz\"]]");
    std::string previous_time;
    for (std::size_t i = 0; i < table->size(); ++i) {
      const toml::node& entry = *table->get(i);
      const toml::array* pair = entry.as_array();
      if (pair == nullptr || pair->size() != 2)
        t.fail(entry, fmt::format("each entry of 'table' must be a [time, speed] pair such as "
                                  "[\"2 s\", \"50 Hz\"], got {}",
                                  pair != nullptr ? fmt::format("an array of {} values", pair->size())
                                                  : type_name(entry)));
      const QuantityValue time =
          t.quantity_at(*pair->get(0), fmt::format("table[{}][0]", i), Quantity::time);
      const QuantityValue speed =
          t.quantity_at(*pair->get(1), fmt::format("table[{}][1]", i), Quantity::speed);
      if (i == 0 && time.si != 0.0)
        t.fail(*time.node, fmt::format("'table' must start at time 0, where the run-up starts, "
                                       "but its first time is {}",
                                       time.written));
      if (i > 0 && !(time.si > profile.back().first))
        t.fail(*time.node,
               fmt::format("the times in 'table' must be strictly increasing, but table[{}] ({}) "
                           "does not come after table[{}] ({})",
                           i, time.written, i - 1, previous_time));
      t.require_non_negative(speed, fmt::format("table[{}][1]", i));
      profile.emplace_back(time.si, speed.si);
      previous_time = time.written;
    }
    if (profile.back().first > 0.0) return profile.back().first;
    return std::nullopt;
  }

  // The ramp: 'to' and 'ramp_time' are required, 'from' defaults to rest.
  const QuantityValue to = t.quantity_at(
      t.require("to", fmt::format("the ramp's final speed, {}", expected_quantity(Quantity::speed))),
      "to", Quantity::speed);
  t.require_non_negative(to, "to");
  const QuantityValue ramp_time =
      t.quantity_at(t.require("ramp_time", fmt::format("the ramp's duration, {}",
                                                       expected_quantity(Quantity::time))),
                    "ramp_time", Quantity::time);
  t.require_positive(ramp_time, "ramp_time");
  Real from = 0.0;
  if (const auto q = t.quantity("from", Quantity::speed)) {
    t.require_non_negative(*q, "from");
    from = q->si;
  }
  profile = {{0.0, from}, {ramp_time.si, to.si}};
  return ramp_time.si;
}

void ModelBuilder::read_runup() {
  const toml::table* table = sub_table("runup");
  if (table == nullptr) return;
  const TableReader t(*table, "[runup]", path_);
  t.check_keys({"speed", "from", "to", "ramp_time", "table", "duration", "integrator", "dt",
                "rel_tol", "abs_tol", "output_interval", "probes", "springs", "modes"});
  RunupDefaults& r = out_.runup;
  const std::optional<Real> profile_duration = read_speed_profile(t, r.profile);

  const auto positive_time = [&](std::string_view key) -> std::optional<Real> {
    const auto q = t.quantity(key, Quantity::time);
    if (!q) return std::nullopt;
    t.require_positive(*q, key);
    return q->si;
  };
  r.duration = positive_time("duration");
  if (!r.duration) r.duration = profile_duration;

  if (const auto integrator = t.string("integrator")) {
    if (std::find(runup_integrators.begin(), runup_integrators.end(), *integrator) ==
        runup_integrators.end()) {
      std::string message = fmt::format("'integrator' must be {}, got \"{}\"",
                                        join_list(runup_integrators, "or", '"'), *integrator);
      if (const auto m = closest_match(*integrator, runup_integrators, 2))
        message += fmt::format("; did you mean \"{}\"?", *m);
      t.fail(*t.find("integrator"), message);
    }
    r.integrator = *integrator;
  }
  r.dt = positive_time("dt");
  r.rel_tol = t.positive_number("rel_tol");
  r.abs_tol = t.positive_number("abs_tol");
  r.output_interval = positive_time("output_interval");
  r.modes = t.integer("modes", 1);
  read_probes(t, r.probes);

  if (const toml::array* springs = t.array("springs")) {
    if (springs->empty())
      t.fail(*springs, "'springs' must not be empty (leave it out for the analysis's default)");
    for (std::size_t i = 0; i < springs->size(); ++i) {
      const toml::node& entry = *springs->get(i);
      const auto name = entry.value_exact<std::string>();
      if (!name)
        t.fail(entry, fmt::format("'springs[{}]' must be the name of a spring (a string, the "
                                  "'name' of a [[springs]] entry), got {}",
                                  i, type_name(entry)));
      const Index element = resolve_spring(entry, *name, t);
      if (std::find(r.springs.begin(), r.springs.end(), element) != r.springs.end())
        t.fail(entry, fmt::format("spring '{}' appears twice in 'springs'", *name));
      r.springs.push_back(element);
    }
  }
}

Index ModelBuilder::resolve_spring(const toml::node& n, const std::string& name,
                                   const TableReader& t) const {
  std::vector<Index> found;
  std::vector<std::string> names;
  for (const auto& [spring_name, element] : named_springs_) {
    if (spring_name == name) found.push_back(element);
    if (std::find(names.begin(), names.end(), spring_name) == names.end())
      names.push_back(spring_name);
  }
  if (found.size() == 1) return found.front();
  if (found.size() > 1)
    t.fail(n, fmt::format("spring name '{}' is ambiguous: {} [[springs]] entries have it; give "
                          "them different names",
                          name, found.size()));
  std::string message = fmt::format("spring '{}' does not exist", name);
  if (std::find(unnamed_spring_labels_.begin(), unnamed_spring_labels_.end(), name) !=
      unnamed_spring_labels_.end())
    message += fmt::format("; '{}' is the label of a [[springs]] entry without a 'name', and "
                           "only named springs can be referenced: give that entry a 'name'",
                           name);
  else if (const auto match = closest_match(name, names, 2))
    message += fmt::format("; did you mean '{}'?", *match);
  else if (names.empty())
    message += "; no [[springs]] entry has a 'name', and only named springs can be referenced";
  else if (names.size() == 1)
    message += fmt::format("; the only named spring is '{}'", names.front());
  else if (names.size() <= 10)
    message += fmt::format("; the named springs are {}", join_list(names, "and", '\''));
  t.fail(n, message);
}

void ModelBuilder::check_structure() {
  try {
    auto assembler = std::make_shared<const Assembler>(model_);
    check_model(model_, *assembler);
    out_.assembler = std::move(assembler);
  } catch (const ModelStructureError& e) {
    const long node = e.node();
    const SourceLocation at = node >= 0 && node < static_cast<long>(out_.node_locations.size())
                                  ? out_.node_locations[static_cast<std::size_t>(node)]
                                  : SourceLocation{path_, 1, 1};
    throw ModelError(at, e.what());
  }
}

}  // namespace

ModelFile read_model_string(std::string_view toml_text, const std::string& path_for_messages) {
  toml::table root;
  try {
    root = toml::parse(toml_text, std::string_view{path_for_messages});
  } catch (const toml::parse_error& e) {
    throw ModelError(SourceLocation{path_for_messages, static_cast<int>(e.source().begin.line),
                                    static_cast<int>(e.source().begin.column)},
                     fmt::format("TOML syntax error: {}", e.description()));
  }
  return ModelBuilder(root, path_for_messages).build();
}

ModelFile read_model_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot open model file '{}'", path));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(fmt::format("cannot read model file '{}'", path));
  return read_model_string(text.str(), path);
}

}  // namespace feran
