// [[forces]]: harmonic and time-table forces and moments, fixed or rotating with the rotor: the family's field table
// (its keys, bounds, units and help) and its build step (the checks across its keys, and what it adds to the model).
#include <feran/spec/entries/forces.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

Quantity amplitude_quantity(const ForceSpec& f) {
  const bool moment = f.kind == "rotating_moment" ||
                      (f.kind == "fixed" && (f.direction == "rx" || f.direction == "ry" || f.direction == "rz"));
  return moment ? Quantity::moment : Quantity::force;
}

template <>
const FieldTable<ForceSpec>& fields_of<ForceSpec>() {
  using S = ForceSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"force <i>\"`"),
      node_field<S>("a rotating node for the rotating kinds"),
      {.key = "kind", .kind = K::choice, .member = &S::kind, .doc = "(below)", .choices = force_kinds},
      {.key = "direction",
       .kind = K::choice,
       .member = &S::direction,
       .doc = "forces along the axes x, y, z (DOF u, v, w) or moments about them rx, ry, rz; not allowed for the "
              "rotating kinds",
       .choices = force_directions,
       .default_text = "required for `\"fixed\"`"},
      {.key = "amplitude",
       .kind = K::quantity,
       .member = &S::amplitude,
       .doc = "A; a force for `\"x\"`, `\"y\"`, `\"z\"` and `\"rotating_force\"`, a moment for `\"rx\"`, `\"ry\"`, "
              "`\"rz\"` and `\"rotating_moment\"`",
       .quantity = Q::force,
       .bound = positive,
       .default_text = "required unless `time_table`"},
      {.key = "phase", .kind = K::quantity, .member = &S::phase, .doc = "φ", .quantity = Q::angle, .unit = "deg"},
      {.key = "frequency",
       .kind = K::quantity,
       .member = &S::frequency,
       .doc = "only for `\"fixed\"`: a frequency of its own, at which the force acts in run-ups, A·cos(ωt + φ), "
              "whatever the speed; such a force takes no part in the steady-state response",
       .quantity = Q::frequency,
       .bound = positive,
       .unit = "Hz",
       .default_text = "— (synchronous)"},
      {.key = "time_table",
       .kind = K::time_table,
       .member = &S::time_table,
       .doc = "only for `\"fixed\"`, instead of `amplitude`, `phase` and `frequency`: the force (or moment) as a "
              "function of time in run-ups, linear between the pairs and held beyond the first and last; times "
              "strictly increase; such a force takes no part in the steady-state response",
       .quantity = Q::force},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_forces() {
  using Kind = HarmonicForce::Kind;
  const std::vector<std::string> kinds = {"fixed", "rotating_force", "rotating_moment"};
  const std::vector<std::string> directions = {"x", "y", "z", "rx", "ry", "rz"};
  for (std::size_t i = 0; i < spec_.forces.size(); ++i) {
    const ForceSpec& s = spec_.forces[i];
    const std::string path = element("forces", i);
    const auto at = [&](std::string_view key) { return child(path, key); };
    HarmonicForce f;
    const std::string label = entry_label(s.name, "force", i);
    f.node = node(s.node, at("node"), "node");

    const auto kind = std::find(kinds.begin(), kinds.end(), s.kind);
    if (kind == kinds.end()) {
      std::string message = fmt::format("'kind' must be {}, got \"{}\"", join_list(kinds, "or", '"'), s.kind);
      std::vector<std::string> extending;
      for (const std::string& n : kinds)
        if (!s.kind.empty() && n.starts_with(s.kind)) extending.push_back(n);
      if (const auto m = closest_match(s.kind, kinds, 3))
        message += fmt::format("; did you mean \"{}\"?", *m);
      else if (!extending.empty())
        message += fmt::format("; did you mean {}?", join_list(extending, "or", '"'));
      fail(at("kind"), message);
    }
    f.type = static_cast<Kind>(kind - kinds.begin());

    if (f.type == Kind::fixed) {
      if (s.direction.empty())
        fail(path, missing_key("direction", "[[forces]]",
                               fmt::format("{} for a force of kind \"fixed\"", join_list(directions, "or", '"'))));
      const auto it = std::find(directions.begin(), directions.end(), s.direction);
      if (it == directions.end()) {
        const std::string& d = s.direction;
        std::string message = fmt::format("'direction' must be {}, got \"{}\"", join_list(directions, "or", '"'), d);
        const std::string unsigned_direction =
            !d.empty() && (d.front() == '+' || d.front() == '-') ? d.substr(1) : std::string{};
        if (d == "u" || d == "v" || d == "w")
          message += fmt::format("; did you mean \"{}\"? (directions name axes, not DOFs)", d == "u"   ? "x"
                                                                                            : d == "v" ? "y"
                                                                                                       : "z");
        else if (std::find(directions.begin(), directions.end(), unsigned_direction) != directions.end())
          message += fmt::format(
              "; did you mean \"{}\"? (a direction has no sign: the force "
              "acts along +{}; phase = \"180 deg\" reverses it)",
              unsigned_direction, unsigned_direction);
        else if (const auto m = closest_match(d, directions, 0))
          message += fmt::format("; did you mean \"{}\"?", *m);
        fail(at("direction"), message);
      }
      f.direction = static_cast<Dof>(it - directions.begin());
    } else {
      if (!s.direction.empty())
        fail(at("direction"), fmt::format("'direction' is only for a force of kind \"fixed\"; a {} turns with "
                                          "the shaft in the y-z plane, so leave 'direction' out",
                                          f.type == Kind::rotating_force ? "rotating force" : "rotating moment"));
      require_rotating(f.node, at("node"), fmt::format("a force of kind \"{}\" turns with the shaft", s.kind));
    }
    check_bounds(s, path);
    if (s.frequency && f.type != Kind::fixed)
      fail(at("frequency"), fmt::format("'frequency' is only for a force of kind \"fixed\"; a {} turns with the "
                                        "shaft, at its speed",
                                        f.type == Kind::rotating_force ? "rotating force" : "rotating moment"));
    if (!s.time_table.empty()) {
      const char* other = s.amplitude ? "amplitude" : s.frequency ? "frequency" : s.phase != 0.0 ? "phase" : nullptr;
      if (other != nullptr)
        fail(at(other), fmt::format("'{}' and 'time_table' exclude each other: a force given in time has its "
                                    "values in the table",
                                    other));
      if (f.type != Kind::fixed)
        fail(at("time_table"), fmt::format("'time_table' is only for a force of kind \"fixed\"; a {} turns with "
                                           "the shaft, at its speed",
                                           f.type == Kind::rotating_force ? "rotating force" : "rotating moment"));
      const Quantity q = spec::amplitude_quantity(s);
      for (std::size_t k = 0; k < s.time_table.size(); ++k) {
        const auto [time, value] = s.time_table[k];
        const std::string point = element(at("time_table"), k);
        check_range(time, element(point, 0), "time_table", Quantity::time, "", false);
        check_range(value, element(point, 1), "time_table", q, "", false);
        if (k > 0 && !(time > s.time_table[k - 1].first))
          fail(element(point, 0), fmt::format("the times of 'time_table' must strictly increase: {} follows {}",
                                              shown(element(point, 0), time, Quantity::time, ""),
                                              shown(element(element(at("time_table"), k - 1), 0),
                                                    s.time_table[k - 1].first, Quantity::time, "")));
      }
      f.time_table = s.time_table;
    } else {
      if (!s.amplitude)
        fail(path, missing_key("amplitude", "[[forces]]",
                               fmt::format("{}; or a 'time_table' for a force given in time",
                                           expected_quantity(spec::amplitude_quantity(s)))));
      f.amplitude = *s.amplitude;
    }
    f.phase = s.phase;
    if (s.frequency) f.frequency = hz_to_rad(*s.frequency);
    model_.forces.emplace_back(f, label);
  }
}

}  // namespace builder

}  // namespace feran
