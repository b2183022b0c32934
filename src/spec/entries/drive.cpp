// [drive]: the motor that drives a torque-driven run-up (DC, induction or tabulated torque): the family's field table
// (its keys, bounds, units and help) and its build step (the checks across its keys, and what it adds to the model).
#include <feran/spec/entries/drive.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<DriveSpec>& fields_of<DriveSpec>() {
  using S = DriveSpec;
  static const FieldTable<S> table = {
      {.key = "motor",
       .kind = K::choice,
       .member = &S::motor,
       .doc = "the motor's torque law (below)",
       .choices = motor_kinds,
       .default_text = "required in `[drive]`"},
      {.key = "inertia",
       .kind = K::quantity,
       .member = &S::inertia,
       .doc = "polar inertia the drive adds to the rotor's (motor rotor, couplings)",
       .quantity = Q::inertia,
       .bound = non_negative},
      {.key = "stall_torque",
       .kind = K::quantity,
       .member = &S::stall_torque,
       .doc = "`\"dc\"`: T_s, the torque at rest",
       .quantity = Q::moment,
       .bound = positive,
       .default_text = "required for `\"dc\"`"},
      {.key = "no_load_speed",
       .kind = K::quantity,
       .member = &S::no_load_speed,
       .doc = "`\"dc\"`: Ω₀, where the torque falls to 0",
       .quantity = Q::speed,
       .bound = positive,
       .unit = "Hz",
       .default_text = "required for `\"dc\"`"},
      {.key = "synchronous_speed",
       .kind = K::quantity,
       .member = &S::synchronous_speed,
       .doc = "`\"induction\"`: Ω_s, the field's speed (2π·f_supply/pole pairs)",
       .quantity = Q::speed,
       .bound = positive,
       .unit = "Hz",
       .default_text = "required for `\"induction\"`"},
      {.key = "breakdown_torque",
       .kind = K::quantity,
       .member = &S::breakdown_torque,
       .doc = "`\"induction\"`: T_b, the largest torque",
       .quantity = Q::moment,
       .bound = positive,
       .default_text = "required for `\"induction\"`"},
      {.key = "breakdown_slip",
       .kind = K::number,
       .member = &S::breakdown_slip,
       .doc = "`\"induction\"`: s_b, the slip of the breakdown torque, 0 < s_b < 1",
       .bound = positive,
       .default_text = "required for `\"induction\"`"},
      {.key = "torque",
       .kind = K::coefficient,
       .member = &S::torque,
       .doc = "`\"table\"`: the motor torque over speed, a `table` law",
       .quantity = Q::moment,
       .default_text = "required for `\"table\"`"},
      {.key = "friction_torque",
       .kind = K::quantity,
       .member = &S::friction_torque,
       .doc = "T_f: a constant torque resisting the rotation (seals, brushes)",
       .quantity = Q::moment,
       .bound = non_negative},
      {.key = "viscous_torque",
       .kind = K::quantity,
       .member = &S::viscous_torque,
       .doc = "c₁: a resisting torque c₁Ω (windage, viscous drag)",
       .quantity = Q::rotational_damping,
       .bound = non_negative},
      {.key = "quadratic_torque",
       .kind = K::number,
       .member = &S::quadratic_torque,
       .doc = "c₂ [N m s²/rad²]: a resisting torque c₂Ω² (fan, pump)",
       .bound = non_negative},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_drive() {
  const DriveSpec& s = spec_.drive;
  if (s.motor.empty()) {
    if (!(s == DriveSpec{})) fail("drive", missing_key("motor", "[drive]", "\"dc\", \"induction\" or \"table\""));
    return;
  }
  check_bounds(s, "drive");
  const auto at = [](std::string_view key) { return child("drive", key); };
  // The law first: the keys that belong to it are judged by it.
  check_choice(s.motor, at("motor"), "motor", spec::choices_of<DriveSpec>("motor"));
  Drive d;
  d.inertia = s.inertia;
  d.friction_torque = s.friction_torque;
  d.viscous_torque = s.viscous_torque;
  d.quadratic_torque = s.quadratic_torque;
  // The keys of each law, and those that belong to another.
  const std::vector<std::pair<std::string_view, bool>> keys = {
      {"stall_torque", s.stall_torque.has_value()},           {"no_load_speed", s.no_load_speed.has_value()},
      {"synchronous_speed", s.synchronous_speed.has_value()}, {"breakdown_torque", s.breakdown_torque.has_value()},
      {"breakdown_slip", s.breakdown_slip.has_value()},       {"torque", s.torque.has_value()}};
  const auto own = [&](std::string_view key) {
    if (s.motor == "dc") return key == "stall_torque" || key == "no_load_speed";
    if (s.motor == "induction")
      return key == "synchronous_speed" || key == "breakdown_torque" || key == "breakdown_slip";
    return key == "torque";
  };
  for (const auto& [key, given] : keys) {
    if (given && !own(key)) fail(at(key), fmt::format("'{}' is not a key of motor = \"{}\"", key, s.motor));
    if (!given && own(key))
      fail("drive", missing_key(key, "[drive]", fmt::format("a value of motor = \"{}\"", s.motor)));
  }
  if (s.motor == "dc") {
    d.motor.kind = MotorLaw::Kind::dc;
    d.motor.stall_torque = *s.stall_torque;
    d.motor.no_load_speed = *s.no_load_speed;
  } else if (s.motor == "induction") {
    d.motor.kind = MotorLaw::Kind::induction;
    if (!(*s.breakdown_slip < 1.0))
      fail(at("breakdown_slip"),
           fmt::format("'breakdown_slip' must be below 1 (a slip of 1 is standstill), got {}", *s.breakdown_slip));
    d.motor.synchronous_speed = *s.synchronous_speed;
    d.motor.breakdown_torque = *s.breakdown_torque;
    d.motor.breakdown_slip = *s.breakdown_slip;
  } else {
    d.motor.kind = MotorLaw::Kind::table;
    const auto* table = std::get_if<SpeedCoefficient::Table>(&s.torque->law());
    if (table == nullptr || table->speeds.size() < 2)
      fail(at("torque"),
           "'torque' of motor = \"table\" must be a table law of at least two points, e.g. "
           "{ law = \"table\", speeds = [0, \"50 Hz\"], values = [\"20 N*m\", 0] }");
    check_coefficient(*s.torque, "drive", "torque", Quantity::moment, false);
    for (std::size_t i = 0; i < table->speeds.size(); ++i)
      d.motor.table.emplace_back(table->speeds[i], table->values[i]);
  }
  model_.drive = d;
}

}  // namespace builder

}  // namespace feran
