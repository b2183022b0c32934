#include <feran/spec/build_model.hpp>

#include "builder.hpp"

namespace feran {

// ---------------------------------------------------------------------------------
// SpecSource

SourceLocation SpecSource::locate(std::string_view path) const {
  std::string p(path);
  while (true) {
    if (const auto it = places.find(p); it != places.end()) return it->second;
    if (p.empty()) break;
    p = spec::parent_path(p);
  }
  return SourceLocation{file, 1, 1};
}

ModelError SpecSource::locate(const SpecError& error) const {
  return ModelError(locate(error.path()), error.message());
}

namespace builder {

std::string Builder::place(const std::string& path) const {
  if (source_ == nullptr) return path;
  const SourceLocation at = source_->locate(path);
  return fmt::format("line {}, column {}", at.line, at.column);
}

std::string Builder::shown(const std::string& path, Real si, Quantity kind, std::string_view unit) const {
  if (source_ != nullptr)
    if (const auto it = source_->written.find(path); it != source_->written.end()) return it->second;
  return format_quantity(si, kind, unit);
}

bool Builder::earlier(const std::string& a, const std::string& b) const {
  // Without a source there is no file order: nothing is earlier, so callers keep
  // declaration order (and a sort by this stays a strict weak ordering).
  if (source_ == nullptr) return false;
  const SourceLocation p = source_->locate(a), q = source_->locate(b);
  return p.line < q.line || (p.line == q.line && p.column < q.column);
}

// ---------------------------------------------------------------------------------
// Bounds declared in the field tables

void Builder::check_range(Real v, const std::string& at, std::string_view key, Quantity quantity, std::string_view unit,
                          bool positive) const {
  const PhysicalRange range = physical_range(quantity);
  // The limit in the unit the value was written in.
  const std::string written = shown(at, v, quantity, unit);
  const auto split = split_quantity(written);
  const std::string user_unit = split && !split->unit.empty() ? std::string(split->unit) : std::string(unit);
  const auto limit = [&](Real si) { return approximate_quantity(si, quantity, user_unit); };
  if (std::abs(v) > range.largest)
    fail(at, fmt::format("'{}' is {}, beyond the physical range of {} (at most {} in magnitude)", key,
                         shown(at, v, quantity, unit), quantity_name(quantity), limit(range.largest)));
  if (positive && v < range.smallest_positive)
    fail(at, fmt::format("'{}' is {}, below the physical range of {} (at least {})", key, shown(at, v, quantity, unit),
                         quantity_name(quantity), limit(range.smallest_positive)));
}

void Builder::check_coefficient(const SpeedCoefficient& c, const std::string& path, std::string_view key, Quantity kind,
                                bool direct) const {
  const std::string note = fmt::format(
      " ('{}' is a direct coefficient; only the cross terms kyz, kzy, cyz, czy may "
      "be negative)",
      key);
  const auto value = [&](Real v, const std::string& at, std::string_view name, bool in_law,
                         bool may_be_negative = false) {
    if (!std::isfinite(v)) fail(at, fmt::format("'{}' must be a finite number, got {}", name, v));
    if (direct && v < 0.0 && !may_be_negative)
      fail(at, fmt::format("'{}' must not be negative, got {}{}", name, shown(at, v, kind), in_law ? note : ""));
    check_range(v, at, name, kind, {}, false);
  };
  const auto speed = [&](Real v, const std::string& at, std::string_view name) {
    if (!std::isfinite(v)) fail(at, fmt::format("'{}' must be a finite number, got {}", name, v));
    check_range(v, at, name, Quantity::speed, "Hz", false);
  };
  std::visit(
      [&](const auto& law) {
        using L = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<L, SpeedCoefficient::Constant>) {
          value(law.value, path, key, false);
        } else if constexpr (std::is_same_v<L, SpeedCoefficient::Table>) {
          if (law.speeds.empty()) fail(child(path, "speeds"), fmt::format("'{}.speeds' must not be empty", key));
          if (law.values.size() != law.speeds.size())
            fail(child(path, "values"), fmt::format("'{0}.speeds' and '{0}.values' must have the same length, got {1} "
                                                    "speeds and {2} values",
                                                    key, law.speeds.size(), law.values.size()));
          for (std::size_t i = 0; i < law.speeds.size(); ++i) {
            const std::string at = element(child(path, "speeds"), i);
            speed(law.speeds[i], at, fmt::format("{}.speeds[{}]", key, i));
            if (i > 0 && !(law.speeds[i] > law.speeds[i - 1]))
              fail(at, fmt::format("'{}.speeds' must be strictly increasing, but entry {} ({} "
                                   "rad/s) does not exceed the one before it ({} rad/s)",
                                   key, i, law.speeds[i], law.speeds[i - 1]));
            const std::string v_at = element(child(path, "values"), i);
            value(law.values[i], v_at, fmt::format("{}.values[{}]", key, i), true);
          }
        } else if constexpr (std::is_same_v<L, SpeedCoefficient::FrequencyTable>) {
          const auto increasing = [&](const std::vector<Real>& grid, std::string_view name) {
            for (std::size_t i = 0; i < grid.size(); ++i) {
              const std::string at = element(child(path, name), i);
              speed(grid[i], at, fmt::format("{}.{}[{}]", key, name, i));
              if (i > 0 && !(grid[i] > grid[i - 1]))
                fail(at, fmt::format("'{}.{}' must be strictly increasing, but entry {} ({} rad/s) does not "
                                     "exceed the one before it ({} rad/s)",
                                     key, name, i, grid[i], grid[i - 1]));
            }
          };
          if (law.frequencies.empty())
            fail(child(path, "frequencies"), fmt::format("'{}.frequencies' must not be empty", key));
          increasing(law.frequencies, "frequencies");
          if (law.frequencies.front() < 0.0)
            fail(element(child(path, "frequencies"), 0),
                 fmt::format("'{}.frequencies' must not be negative (a coefficient at −ω is the one at ω), got {} "
                             "rad/s",
                             key, law.frequencies.front()));
          increasing(law.speeds, "speeds");
          const std::size_t rows = law.speeds.empty() ? 1 : law.speeds.size(), nf = law.frequencies.size();
          if (law.values.size() != rows * nf)
            fail(child(path, "values"),
                 fmt::format("'{}.values' must hold one value per speed and frequency: {} × {}, got {}", key, rows, nf,
                             law.values.size()));
          // A dynamic stiffness turns negative above a support's own resonance (mass-like):
          // a direct stiffness in a frequency table may be negative; a direct damping may not.
          const bool stiffness = kind == Quantity::stiffness || kind == Quantity::rotational_stiffness;
          for (std::size_t i = 0; i < rows; ++i)
            for (std::size_t j = 0; j < nf; ++j) {
              const std::string at = law.speeds.empty() ? element(child(path, "values"), j)
                                                        : element(element(child(path, "values"), i), j);
              const std::string name = law.speeds.empty() ? fmt::format("{}.values[{}]", key, j)
                                                          : fmt::format("{}.values[{}][{}]", key, i, j);
              const Real v = law.values[i * nf + j];
              if (direct && !stiffness && v < 0.0)
                fail(at, fmt::format("'{}' must not be negative, got {} ('{}' is a direct damping: in a frequency "
                                     "table a direct stiffness may turn negative, a damping may not)",
                                     name, shown(at, v, kind), key));
              value(v, at, name, true, true);
            }
        } else if constexpr (std::is_same_v<L, SpeedCoefficient::Step>) {
          value(law.below, child(path, "below"), "below", true);
          value(law.above, child(path, "above"), "above", true);
          speed(law.at, child(path, "at"), "at");
        } else {
          value(law.value, child(path, "value"), "value", true);
          for (const auto& [name, v] :
               {std::pair{"f_as", law.f_as}, std::pair{"c0", law.c0}, std::pair{"c1", law.c1}, std::pair{"c2", law.c2}})
            if (!std::isfinite(v))
              fail(child(path, name), fmt::format("'{}' must be a finite number, got {}", name, v));
          check_range(law.f_as, child(path, "f_as"), "f_as", Quantity::frequency, {}, false);  // in Hz
          // s(f) runs between c0 − |c1|/2 and c0 + |c1|/2; a direct coefficient stays ≥ 0.
          if (direct && law.c0 < 0.5 * std::abs(law.c1))
            fail(given(child(path, "c0")) || source_ == nullptr ? child(path, "c0") : child(path, "c1"),
                 fmt::format("the arctan factor of direct coefficient '{}' would turn negative "
                             "at high or low speed: need c0 ≥ |c1|/2, got c0 = {}, c1 = {}",
                             key, law.c0, law.c1));
        }
      },
      c.law());
}

void Builder::check_choice(const std::string& value, const std::string& path, std::string_view key,
                           std::span<const std::string_view> choices) const {
  std::vector<std::string> names(choices.begin(), choices.end());
  if (std::find(names.begin(), names.end(), value) != names.end()) return;
  std::string message = fmt::format("'{}' must be {}, got \"{}\"", key, join_list(names, "or", '"'), value);
  if (const auto m = closest_match(value, names, 2)) message += fmt::format("; did you mean \"{}\"?", *m);
  fail(path, message);
}

// ---------------------------------------------------------------------------------
// Options, materials, nodes

void Builder::build_options() {
  const OptionsSpec& o = spec_.options;
  check_bounds(o, "options");
  check_choice(o.gyroscopic, "options.gyroscopic", "gyroscopic", spec::choices_of<OptionsSpec>("gyroscopic"));
  beam_.shear_deformation = o.shear_deformation;
  beam_.gyroscopic = o.gyroscopic == "lumped" ? GyroscopicForm::lumped : GyroscopicForm::consistent;
  beam_.damping_beta = o.shaft_damping;
  check_choice(o.shear_coefficient, "options.shear_coefficient", "shear_coefficient",
               spec::choices_of<OptionsSpec>("shear_coefficient"));
  beam_.rotary_inertia = o.rotary_inertia;
  beam_.shear = o.kappa                               ? ShearCoefficient::given
                : o.shear_coefficient == "hutchinson" ? ShearCoefficient::hutchinson
                                                      : ShearCoefficient::cowper;
  beam_.kappa = o.kappa.value_or(0.0);
  beam_.rayleigh_alpha = o.rayleigh_alpha;
  beam_.rayleigh_beta = o.rayleigh_beta;
  const std::vector<std::string> names = {"axial", "torsion", "lateral"};
  for (std::size_t i = 0; i < o.free_motions.size(); ++i) {
    const std::string& s = o.free_motions[i];
    const auto it = std::find(names.begin(), names.end(), s);
    if (it == names.end()) {
      std::string message =
          fmt::format("entries of 'free_motions' must be \"axial\", \"torsion\" or \"lateral\", got \"{}\"", s);
      if (const auto m = closest_match(s, names, 2)) message += fmt::format("; did you mean \"{}\"?", *m);
      fail(element("options.free_motions", i), message);
    }
    const auto motion = static_cast<FreeMotion>(it - names.begin());
    auto& motions = model_.free_motions;
    if (std::find(motions.begin(), motions.end(), motion) == motions.end()) motions.push_back(motion);
  }
}

void Builder::build_materials() {
  for (std::size_t i = 0; i < spec_.materials.size(); ++i) {
    const MaterialSpec& s = spec_.materials[i];
    const std::string path = element("materials", i);
    const std::string name_at = child(path, "name");
    if (s.name.empty()) fail(name_at, "material 'name' must not be empty");
    for (std::size_t j = 0; j < i; ++j)
      if (spec_.materials[j].name == s.name)
        fail(name_at, fmt::format("material '{}' is defined twice; the first definition is at {}", s.name,
                                  place(child(element("materials", j), "name"))));
    check_bounds(s, path);
    Material m;
    m.name = s.name;
    m.E = s.E;
    if (s.G && s.nu) fail(child(path, "nu"), "give either the shear modulus 'G' or Poisson's ratio 'nu', not both");
    if (s.G) {
      m.G = *s.G;
    } else if (s.nu) {
      if (!(*s.nu > -1.0 && *s.nu < 0.5))
        fail(child(path, "nu"),
             fmt::format("'nu' (Poisson's ratio) must lie between -1 and 0.5 (both excluded), got {}", *s.nu));
      m.G = m.E / (2.0 * (1.0 + *s.nu));
    } else {
      fail(path, fmt::format("missing key 'G' or 'nu' in [[materials]] (expected the shear "
                             "modulus G, {}, or Poisson's ratio nu, a number such as 0.3)",
                             expected_quantity(Quantity::pressure)));
    }
    m.rho = s.rho;
    m.loss_factor = s.loss_factor;
    materials_.push_back(m);
  }
}

const Material& Builder::material(const std::string& name, const std::string& path) const {
  std::vector<std::string> names;
  for (const Material& m : materials_) {
    if (m.name == name) return m;
    names.push_back(m.name);
  }
  std::string message = fmt::format("material '{}' is not defined", name);
  if (const auto match = closest_match(name, names, 2))
    message += fmt::format("; did you mean '{}'?", *match);
  else if (names.empty())
    message += "; define it in a [[materials]] table";
  else
    message += fmt::format("; the defined materials are {}", join_list(names, "and", '\''));
  fail(path, message);
}

void Builder::check_node_name(const std::string& name, const std::string& path) const {
  if (name == ground_word || name == axis_word)
    fail(path, fmt::format("'{}' cannot be a node name: it is reserved for references to {}", name,
                           name == ground_word ? "the ground" : "the rotating frame's axis"));
}

Index Builder::add_node(Node node, const std::string& defined_at, const std::string& name_at) {
  if (const auto it = node_by_number_.find(node.number); it != node_by_number_.end())
    fail(defined_at, fmt::format("node number {} is already used by the node defined at {}", node.number,
                                 place(node_paths_[it->second])));
  if (!node.name.empty())
    if (const auto it = node_by_name_.find(node.name); it != node_by_name_.end())
      fail(name_at, fmt::format("node name '{}' is already used by node {}, defined at {}", node.name,
                                model_.nodes[it->second].number, place(node_name_paths_[it->second])));
  node_by_number_.emplace(node.number, model_.nodes.size());
  if (!node.name.empty()) node_by_name_.emplace(node.name, model_.nodes.size());
  highest_number_ = std::max(highest_number_, node.number);
  node_paths_.push_back(defined_at);
  node_name_paths_.push_back(name_at);
  model_.nodes.push_back(std::move(node));
  return model_.n_nodes() - 1;
}

void Builder::build_shafts() {
  int next_number = 1;
  for (std::size_t i = 0; i < spec_.shafts.size(); ++i) {
    const ShaftSpec& shaft = spec_.shafts[i];
    const std::string path = element("shafts", i);
    check_bounds(shaft, path);
    const std::string shaft_label = shaft.name.empty() ? fmt::format("{}", i + 1) : shaft.name;
    const Material* shaft_material =
        shaft.material.empty() ? nullptr : &material(shaft.material, child(path, "material"));
    if (shaft.sections.empty())
      fail(child(path, "sections"), "a shaft needs at least one section ([[shafts.sections]])");

    Node first;
    first.number = next_number++;
    first.x = shaft.x;
    first.rotating = shaft.rotating;
    first.name = shaft.start_node;
    if (!first.name.empty()) check_node_name(first.name, child(path, "start_node"));
    Index node_a = add_node(first, path, first.name.empty() ? path : child(path, "start_node"));

    BeamOptions beam_options = beam_;
    beam_options.rotating = shaft.rotating;
    if (!shaft.rotating) beam_options.damping_beta = 0.0;
    beam_options.rayleigh_alpha = shaft.rayleigh_alpha.value_or(beam_.rayleigh_alpha);
    beam_options.rayleigh_beta = shaft.rayleigh_beta.value_or(beam_.rayleigh_beta);
    Real x_section = shaft.x;
    for (std::size_t j = 0; j < shaft.sections.size(); ++j) {
      const SectionSpec& s = shaft.sections[j];
      const std::string section_path = element(child(path, "sections"), j);
      check_bounds(s, section_path);
      if (!(s.inner_diameter < s.outer_diameter))
        fail(child(section_path, "inner_diameter"),
             fmt::format("inner_diameter ({}) must be smaller than outer_diameter ({})",
                         shown(child(section_path, "inner_diameter"), s.inner_diameter, Quantity::length, "mm"),
                         shown(child(section_path, "outer_diameter"), s.outer_diameter, Quantity::length, "mm")));
      const Material* m = s.material.empty() ? shaft_material : &material(s.material, child(section_path, "material"));
      if (m == nullptr)
        fail(section_path,
             "missing key 'material' in [[shafts.sections]] (expected the name of a material; "
             "or give the shaft a default with 'material' in [[shafts]])");
      BeamOptions options = beam_options;
      options.loss_factor = m->loss_factor;
      if (!s.end_node.empty()) check_node_name(s.end_node, child(section_path, "end_node"));
      const Real outer_end = s.outer_diameter_end.value_or(s.outer_diameter);
      const Real inner_end = s.inner_diameter_end.value_or(s.inner_diameter);
      if (!(inner_end < outer_end))
        fail(child(section_path, s.inner_diameter_end ? "inner_diameter_end" : "outer_diameter_end"),
             fmt::format("the bore at the section's end ({}) must be smaller than its outer diameter there ({})",
                         shown(child(section_path, "inner_diameter_end"), inner_end, Quantity::length, "mm"),
                         shown(child(section_path, "outer_diameter_end"), outer_end, Quantity::length, "mm")));
      options.axial_force = s.axial_force;
      // Element e spans ξ ∈ [(e − 1)/n, e/n] of the section; diameters are linear in ξ.
      const auto section_at = [&](int e) {
        const Real xi = static_cast<Real>(e) / static_cast<Real>(s.elements);
        return CircularSection{s.outer_diameter + xi * (outer_end - s.outer_diameter),
                               s.inner_diameter + xi * (inner_end - s.inner_diameter)};
      };
      const bool tapered = outer_end != s.outer_diameter || inner_end != s.inner_diameter;
      for (int e = 1; e <= s.elements; ++e) {
        Node node;
        node.number = next_number++;
        node.x = x_section + s.length * static_cast<Real>(e) / static_cast<Real>(s.elements);
        node.rotating = shaft.rotating;
        const bool last = e == s.elements;
        if (last) node.name = s.end_node;
        const Index node_b =
            add_node(node, section_path, last && !s.end_node.empty() ? child(section_path, "end_node") : section_path);
        const CircularSection section_a =
            tapered ? section_at(e - 1) : CircularSection{s.outer_diameter, s.inner_diameter};
        const CircularSection section_b = tapered ? section_at(e) : section_a;
        model_.elements.emplace_back(
            TimoshenkoBeam(node_a, node_b, s.length / static_cast<Real>(s.elements), section_a, section_b, *m, options),
            fmt::format("shaft {} section {} element {}", shaft_label, j + 1, e));
        node_a = node_b;
      }
      x_section += s.length;
    }
  }
}

void Builder::build_nodes() {
  // Explicit numbers first, so that default numbers never take a number that a later
  // entry asks for.
  std::set<std::int64_t> claimed;
  for (const NodeSpec& n : spec_.nodes)
    if (n.number) claimed.insert(*n.number);
  for (std::size_t i = 0; i < spec_.nodes.size(); ++i) {
    const NodeSpec& s = spec_.nodes[i];
    const std::string path = element("nodes", i);
    check_bounds(s, path);
    Node node;
    node.x = s.x;
    node.name = s.name;
    if (!s.name.empty()) check_node_name(s.name, child(path, "name"));
    node.rotating = s.rotating;
    if (s.number) {
      node.number = static_cast<int>(*s.number);
    } else {
      // The next number above every one so far that no entry claims.
      std::int64_t next = std::int64_t{highest_number_} + 1;
      while (claimed.count(next) != 0) ++next;
      if (next > std::numeric_limits<int>::max())
        fail(path, fmt::format("no node number is left for this node: the next free number, {}, is above the "
                               "largest, {}; give it a 'number' below the others",
                               next, std::numeric_limits<int>::max()));
      node.number = static_cast<int>(next);
    }
    add_node(node, s.number ? child(path, "number") : path, s.name.empty() ? path : child(path, "name"));
    // Messages about the node (e.g. from check_model) point at its table.
    node_paths_.back() = path;
  }
}

Index Builder::node(const NodeRef& ref, const std::string& path, std::string_view key, std::string_view special) const {
  if (const auto* number = std::get_if<std::int64_t>(&ref)) {
    if (*number >= std::numeric_limits<int>::min() && *number <= std::numeric_limits<int>::max())
      if (const auto it = node_by_number_.find(static_cast<int>(*number)); it != node_by_number_.end())
        return static_cast<Index>(it->second);
    std::vector<int> numbers;
    for (const Node& n : model_.nodes) numbers.push_back(n.number);
    fail(path, fmt::format("node {} does not exist; the node numbers are {}", *number, number_ranges(numbers)));
  }
  const std::string& text = std::get<std::string>(ref);
  if (text == ground_word || text == axis_word)
    fail(path, fmt::format("'{}' cannot be \"{}\" here; expected {}a node number or a node name", key, text,
                           special.empty() ? std::string{} : fmt::format("\"{}\", ", special)));
  if (const auto it = node_by_name_.find(text); it != node_by_name_.end()) return static_cast<Index>(it->second);
  std::vector<std::string> names;
  for (const Node& n : model_.nodes)
    if (!n.name.empty()) names.push_back(n.name);
  std::vector<std::string> candidates = names;
  if (!special.empty()) candidates.emplace_back(special);
  std::string message = fmt::format("node '{}' does not exist", text);
  if (const auto match = closest_match(text, candidates, detail::node_name_distance))
    message += fmt::format("; did you mean '{}'?", *match);
  else if (all_digits(text))
    message += fmt::format(
        "; a quoted reference is a node name: to refer to node number {0}, "
        "write {1} = {0} without quotes",
        text, key);
  else if (names.empty())
    message += fmt::format("; no node has a name, so refer to nodes by number (e.g. {} = 1)", key);
  else if (names.size() <= 10)
    message += fmt::format("; the node names are {}", join_list(names, "and", '\''));
  fail(path, message);
}

std::optional<Index> Builder::other_node(const std::optional<NodeRef>& to, const std::string& path,
                                         std::string_view special, Index from) const {
  if (!to) return std::nullopt;
  const std::string at = child(path, "to");
  if (const auto* text = std::get_if<std::string>(&*to); text && *text == special) return std::nullopt;
  const Index index = node(*to, at, "to", special);
  if (index == from)
    fail(at, fmt::format("'to' must be a node other than 'node' (both are node {})", model_.node_label(index)));
  return index;
}

void Builder::require_rotating(Index index, const std::string& path, std::string_view reason) const {
  if (!model_.nodes[static_cast<std::size_t>(index)].rotating)
    fail(path, fmt::format("{}, but node {} is not rotating (a shaft's nodes rotate unless the "
                           "shaft says rotating = false; [[nodes]] entries need rotating = true)",
                           reason, model_.node_label(index)));
}

// ---------------------------------------------------------------------------------
// Elements

// The journal (a rotating node) and the housing (a non-rotating node, or the ground)
// of a bearing's entry at @p path.
std::pair<Index, std::optional<Index>> Builder::bearing_nodes(const NodeRef& journal, const std::optional<NodeRef>& to,
                                                              const std::string& path, std::string_view what) const {
  const Index a = node(journal, child(path, "node"), "node");
  require_rotating(a, child(path, "node"), fmt::format("the journal of a {} turns", what));
  const std::optional<Index> b = other_node(to, path, ground_word, a);
  if (b && model_.nodes[static_cast<std::size_t>(*b)].rotating)
    fail(child(path, "to"), fmt::format("the housing of a {} must not rotate, but node {} does (a [[nodes]] entry "
                                        "with rotating = false, or the ground)",
                                        what, model_.node_label(*b)));
  return {a, b};
}

// ---------------------------------------------------------------------------------
// Constraints and loads

// ---------------------------------------------------------------------------------
// Analysis tables

void Builder::check_sweep(std::optional<Real> start, std::optional<Real> stop, const std::string& table) const {
  if (start && stop && !(*stop > *start))
    fail(child(table, "stop"), fmt::format("'stop' ({}) must be greater than 'start' ({})",
                                           shown(child(table, "stop"), *stop, Quantity::speed, "Hz"),
                                           shown(child(table, "start"), *start, Quantity::speed, "Hz")));
}

std::vector<Index> Builder::distinct_nodes(const std::vector<NodeRef>& refs, const std::string& path,
                                           std::string_view key) const {
  std::vector<Index> nodes;
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const std::string at = element(path, i);
    const Index n = node(refs[i], at, fmt::format("{}[{}]", key, i));
    if (std::find(nodes.begin(), nodes.end(), n) != nodes.end())
      fail(at, fmt::format("node {} appears twice in '{}'", model_.node_label(n), key));
    nodes.push_back(n);
  }
  return nodes;
}

void Builder::check_analysis_tables() const {
  check_bounds(spec_.modal, "modal");
  check_bounds(spec_.campbell, "campbell");
  check_sweep(spec_.campbell.start, spec_.campbell.stop, "campbell");
  check_bounds(spec_.response, "response");
  check_response();
  check_static();
  check_runup();
  check_api684();
  check_orbits();
}

void Builder::check_response() const {
  const ResponseSpec& r = spec_.response;
  check_sweep(r.start, r.stop, "response");
  distinct_nodes(r.probes, "response.probes", "probes");
  // A speed sweep, or a fixed speed (alone, or with a frequency sweep): not both.
  const bool frequencies = r.freq_start || r.freq_stop || r.freq_points;
  if ((r.start || r.stop || r.points) && (r.speed || frequencies))
    fail(r.speed ? "response.speed" : "response.freq_start",
         "give either a speed sweep ('start', 'stop', 'points') or a fixed speed ('speed', with 'freq_start', "
         "'freq_stop' and 'freq_points' for a frequency sweep), not both");
  if (frequencies && !(r.freq_start && r.freq_stop))
    fail(r.freq_start  ? "response.freq_start"
         : r.freq_stop ? "response.freq_stop"
                       : "response.freq_points",
         "a frequency sweep needs both 'freq_start' and 'freq_stop'");
  if (r.freq_start && r.freq_stop && !(*r.freq_stop > *r.freq_start))
    fail("response.freq_stop", fmt::format("'freq_stop' ({}) must be greater than 'freq_start' ({})",
                                           shown("response.freq_stop", *r.freq_stop, Quantity::speed, "Hz"),
                                           shown("response.freq_start", *r.freq_start, Quantity::speed, "Hz")));
}

void Builder::check_static() const {
  const StaticSpec& s = spec_.static_;
  const std::vector<std::string> choices = {"+x", "-x", "+y", "-y", "+z", "-z", "none"};
  if (s.gravity) {
    const std::string& gravity = *s.gravity;
    if (gravity == "none") {
      if (s.g)
        fail("static.g",
             "'g' cannot be given with gravity = \"none\"; give a direction such as "
             "gravity = \"-z\", or leave 'g' out");
    } else if (std::find(choices.begin(), choices.end(), gravity) == choices.end()) {
      std::string message = fmt::format("'gravity' must be {} (the direction in which gravity pulls), got \"{}\"",
                                        join_list(choices, "or", '"'), gravity);
      if (gravity == "x" || gravity == "y" || gravity == "z")
        message += fmt::format("; give its sign: \"-{0}\" or \"+{0}\"", gravity);
      else if (const auto m = closest_match(gravity, choices, 0))
        message += fmt::format("; did you mean \"{}\"?", *m);
      fail("static.gravity", message);
    }
  } else if (s.g) {
    fail("static.g", "'g' needs a direction: give 'gravity' as well, e.g. gravity = \"-z\"");
  }
  check_bounds(s, "static");
}

// The gravity the machine runs under: [static] gravity and g (checked above), by
// default 9.81 m/s² along −y, as for a static analysis.
void Builder::build_gravity() {
  const StaticSpec& s = spec_.static_;
  const std::string direction = s.gravity.value_or("-y");
  model_.gravity.setZero();
  if (direction == "none") return;
  model_.gravity(direction.back() - 'x') = (direction.front() == '-' ? -1.0 : 1.0) * s.g.value_or(standard_gravity);
}

void Builder::check_runup() const {
  const RunupSpec& r = spec_.runup;
  if (r.start) check_choice(*r.start, "runup.start", "start", spec::choices_of<RunupSpec>("start"));
  // The speed profile's three forms, each named by its first key given.
  std::vector<std::string> forms;
  for (const auto& keys :
       {std::vector<std::pair<std::string, bool>>{{"speed", r.speed.has_value()}},
        std::vector<std::pair<std::string, bool>>{
            {"from", r.from.has_value()}, {"to", r.to.has_value()}, {"ramp_time", r.ramp_time.has_value()}},
        std::vector<std::pair<std::string, bool>>{{"table", !r.table.empty()}}}) {
    std::string first;
    for (const auto& [key, present] : keys)
      if (present && (first.empty() || earlier("runup." + key, "runup." + first))) first = key;
    if (!first.empty()) forms.push_back(first);
  }
  std::sort(forms.begin(), forms.end(),
            [&](const std::string& a, const std::string& b) { return a != b && earlier("runup." + a, "runup." + b); });
  if (forms.size() > 1)
    fail("runup." + forms[1], fmt::format("the speed profile is given either by 'speed' (a constant speed), by "
                                          "'from', 'to' and 'ramp_time' (a linear ramp) or by 'table' (time and speed "
                                          "points); this [runup] mixes '{}' and '{}'",
                                          forms[0], forms[1]));
  check_bounds(r, "runup");
  for (std::size_t i = 0; i < r.table.size(); ++i) {
    const std::string time_at = element(element("runup.table", i), 0);
    const std::string speed_at = element(element("runup.table", i), 1);
    const auto [time, speed] = r.table[i];
    if (!std::isfinite(time) || !std::isfinite(speed))
      fail(element("runup.table", i), "'table' entries must be finite numbers");
    if (i == 0 && time != 0.0)
      fail(time_at, fmt::format("'table' must start at time 0, where the run-up starts, but its "
                                "first time is {}",
                                shown(time_at, time, Quantity::time)));
    if (i > 0 && !(time > r.table[i - 1].first)) {
      const std::string before_at = element(element("runup.table", i - 1), 0);
      fail(time_at, fmt::format("the times in 'table' must be strictly increasing, but "
                                "table[{}] ({}) does not come after table[{}] ({})",
                                i, shown(time_at, time, Quantity::time), i - 1,
                                shown(before_at, r.table[i - 1].first, Quantity::time)));
    }
    if (!(speed >= 0.0))
      fail(speed_at, fmt::format("'table[{}][1]' must not be negative, got {}", i,
                                 shown(speed_at, speed, Quantity::speed, "Hz")));
  }
  if (!forms.empty() && (forms[0] == "from" || forms[0] == "to" || forms[0] == "ramp_time")) {
    if (!r.to)
      fail("runup",
           missing_key("to", "[runup]", fmt::format("the ramp's final speed, {}", expected_quantity(Quantity::speed))));
    if (!r.ramp_time)
      fail("runup", missing_key("ramp_time", "[runup]",
                                fmt::format("the ramp's duration, {}", expected_quantity(Quantity::time))));
  }
  distinct_nodes(r.probes, "runup.probes", "probes");

  check_spring_names(r.springs, "runup.springs");
}

void Builder::check_spring_names(const std::vector<std::string>& names, const std::string& key) const {
  std::vector<std::string> named;
  for (const SpringSpec& s : spec_.springs)
    if (!s.name.empty() && std::find(named.begin(), named.end(), s.name) == named.end()) named.push_back(s.name);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& name = names[i];
    const std::string at = element(key, i);
    const auto count =
        std::count_if(spec_.springs.begin(), spec_.springs.end(), [&](const SpringSpec& s) { return s.name == name; });
    if (count > 1)
      fail(at, fmt::format("spring name '{}' is ambiguous: {} [[springs]] entries have it; give "
                           "them different names",
                           name, count));
    if (count == 0) {
      std::string message = fmt::format("spring '{}' does not exist", name);
      if (std::find(unnamed_spring_labels_.begin(), unnamed_spring_labels_.end(), name) != unnamed_spring_labels_.end())
        message += fmt::format(
            "; '{}' is the label of a [[springs]] entry without a 'name', and "
            "only named springs can be referenced: give that entry a 'name'",
            name);
      else if (const auto match = closest_match(name, named, 2))
        message += fmt::format("; did you mean '{}'?", *match);
      else if (named.empty())
        message += "; no [[springs]] entry has a 'name', and only named springs can be referenced";
      else if (named.size() == 1)
        message += fmt::format("; the only named spring is '{}'", named.front());
      else if (named.size() <= 10)
        message += fmt::format("; the named springs are {}", join_list(named, "and", '\''));
      fail(at, message);
    }
    if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i), name) !=
        names.begin() + static_cast<std::ptrdiff_t>(i))
      fail(at, fmt::format("spring '{}' appears twice in '{}'", name, key.substr(key.rfind('.') + 1)));
  }
}

void Builder::check_orbits() const {
  const OrbitsSpec& o = spec_.orbits;
  check_bounds(o, "orbits");
  for (const char* key : {"branch", "direction"}) {
    const std::optional<std::string>& value = std::string_view(key) == "branch" ? o.branch : o.direction;
    if (value) check_choice(*value, child("orbits", key), key, spec::choices_of<OrbitsSpec>(key));
  }
  if (o.from && o.to && !(*o.to > *o.from))
    fail("orbits.to",
         fmt::format("'to' ({}) must be above 'from' ({})", shown("orbits.to", *o.to, Quantity::speed, "Hz"),
                     shown("orbits.from", *o.from, Quantity::speed, "Hz")));
  if (o.harmonics && o.samples && *o.samples < 2 * *o.harmonics + 1)
    fail("orbits.samples", fmt::format("'samples' ({}) must be at least 2·harmonics + 1 = {}: fewer samples alias "
                                       "the harmonics",
                                       *o.samples, 2 * *o.harmonics + 1));
  distinct_nodes(o.probes, "orbits.probes", "probes");
}

void Builder::check_api684() const {
  const Api684Spec& a = spec_.api684;
  check_bounds(a, "api684");
  if (a.min_speed && a.max_speed && *a.max_speed < *a.min_speed)
    fail("api684.max_speed", fmt::format("'max_speed' ({}) must not be below 'min_speed' ({})",
                                         shown("api684.max_speed", *a.max_speed, Quantity::speed, "rpm"),
                                         shown("api684.min_speed", *a.min_speed, Quantity::speed, "rpm")));
  if (a.map_low && a.map_high && !(*a.map_high > *a.map_low))
    fail("api684.map_high", fmt::format("'map_high' ({}) must be above 'map_low' ({})",
                                        shown("api684.map_high", *a.map_high, Quantity::stiffness),
                                        shown("api684.map_low", *a.map_low, Quantity::stiffness)));
  distinct_nodes(a.probes, "api684.probes", "probes");
  check_spring_names(a.bearings, "api684.bearings");
  if (a.stability_node) node(*a.stability_node, "api684.stability_node", "stability_node", {});
}

void Builder::check_structure(BuildInfo* info) {
  try {
    auto built = std::make_shared<const Assembler>(model_);
    // Located at the constraints that took the last DOF away.
    if (built->dof_map().n_reduced() == 0)
      fail(spec_.fixed.empty() ? std::string{} : element("fixed", 0), std::string(no_free_dof_message));
    check_model(model_, *built);
    if (info != nullptr) info->assembler = std::move(built);
  } catch (const ModelStructureError& e) {
    const long n = e.node();
    fail(n >= 0 && n < static_cast<long>(node_paths_.size()) ? node_paths_[static_cast<std::size_t>(n)] : std::string{},
         e.what());
  }
}

Model Builder::build(BuildInfo* info) {
  model_.name = spec_.title;
  build_options();
  build_materials();
  build_shafts();
  build_nodes();
  if (model_.nodes.empty()) fail("", "the model has no nodes; define a shaft with [[shafts]] or a node with [[nodes]]");
  build_rigid_bodies();
  build_springs();
  build_rotating_dampers();
  build_friction();
  build_journal_bearings();
  build_rolling_bearings();
  build_annular_seals();
  build_rigid_links();
  build_fixed();
  build_unbalances();
  build_forces();
  build_static_loads();
  build_drive();
  check_analysis_tables();
  build_gravity();
  check_structure(info);
  if (info != nullptr) info->node_paths = node_paths_;
  return std::move(model_);
}

}  // namespace builder

Model build_model(const ModelSpec& spec, const SpecSource* source, BuildInfo* info) {
  return builder::Builder(spec, source).build(info);
}

}  // namespace feran
