#include <feran/spec/fields.hpp>

namespace feran::spec {

namespace {

using K = FieldKind;
using Q = Quantity;

constexpr Bound positive{Bound::Kind::positive};
constexpr Bound non_negative{Bound::Kind::non_negative};
constexpr Bound at_least(std::int64_t minimum, std::int64_t maximum = 1'000'000'000) {
  return Bound{Bound::Kind::at_least, minimum, maximum};
}

// The words of the choice fields.
constexpr std::string_view gyroscopic_forms[] = {"consistent", "lumped"};
constexpr std::string_view free_motion_names[] = {"axial", "torsion", "lateral"};
constexpr std::string_view dof_names[] = {"u", "v", "w", "rx", "ry", "rz", "all", "lateral", "translations",
                   "rotations"};
constexpr std::string_view force_kinds[] = {"fixed", "rotating_force", "rotating_moment"};
constexpr std::string_view force_directions[] = {"x", "y", "z", "rx", "ry", "rz"};
constexpr std::string_view gravity_directions[] = {"+x", "-x", "+y", "-y", "+z", "-z", "none"};
constexpr std::string_view integrator_names[] = {"trapezoidal", "rk3", "wolfbrandt", "ros34pw2"};

constexpr std::string_view default_hint = "leave it out for the analysis's default";

/// Largest number of elements per section: guards against a typo such as 1e9 elements.
constexpr std::int64_t max_elements_per_section = 100000;

/// The name of an entry, used in messages and to name it in parameter paths.
template <class S>
Field<S> name_field(std::string_view doc) {
  return {.key = "name", .kind = K::text, .member = &S::name, .doc = doc};
}

/// The node an entry sits at.
template <class S>
Field<S> node_field(std::string_view doc) {
  return {.key = "node", .kind = K::node, .member = &S::node, .doc = doc, .required = true};
}

template <class S>
Field<S> to_field(std::string_view special, std::string_view doc) {
  return {.key = "to", .kind = K::node, .member = &S::to, .doc = doc, .special = special};
}

}  // namespace

template <>
const FieldTable<ModelSpec>& fields_of<ModelSpec>() {
  static const FieldTable<ModelSpec> table = {
      {.key = "title", .kind = K::text, .member = &ModelSpec::title,
       .doc = "name of the model, shown in reports"},
  };
  return table;
}

template <>
const FieldTable<OptionsSpec>& fields_of<OptionsSpec>() {
  using S = OptionsSpec;
  static const FieldTable<S> table = {
      {.key = "shear_deformation", .kind = K::flag, .member = &S::shear_deformation,
       .doc = "Timoshenko shaft elements (true) or Euler–Bernoulli (false); default true"},
      {.key = "gyroscopic", .kind = K::choice, .member = &S::gyroscopic,
       .doc = "gyroscopic matrix of shaft elements: consistent (default) or lumped at the nodes",
       .choices = gyroscopic_forms},
      {.key = "shaft_damping", .kind = K::quantity, .member = &S::shaft_damping,
       .doc = "stiffness-proportional material damping β of rotating shafts, C_i = β·K",
       .quantity = Q::time, .bound = non_negative},
      {.key = "free_motions", .kind = K::choice_list, .member = &S::free_motions,
       .doc = "rigid-body motions that may stay free (singular stiffness) without an error",
       .choices = free_motion_names},
  };
  return table;
}

template <>
const FieldTable<MaterialSpec>& fields_of<MaterialSpec>() {
  using S = MaterialSpec;
  static const FieldTable<S> table = {
      {.key = "name", .kind = K::text, .member = &S::name,
       .doc = "the material's name, referred to by shafts and disks", .required = true},
      {.key = "E", .kind = K::quantity, .member = &S::E, .doc = "Young's modulus",
       .quantity = Q::pressure, .bound = positive, .required = true, .unit = "GPa"},
      {.key = "G", .kind = K::quantity, .member = &S::G,
       .doc = "shear modulus (give G or nu, not both)", .quantity = Q::pressure,
       .bound = positive, .unit = "GPa"},
      {.key = "nu", .kind = K::number, .member = &S::nu,
       .doc = "Poisson's ratio, -1 < nu < 0.5 (give G or nu, not both)"},
      {.key = "rho", .kind = K::quantity, .member = &S::rho, .doc = "density",
       .quantity = Q::density, .bound = non_negative, .required = true},
      {.key = "loss_factor", .kind = K::number, .member = &S::loss_factor,
       .doc = "hysteretic loss factor η of shafts of this material (harmonic analyses)",
       .bound = non_negative},
  };
  return table;
}

template <>
const FieldTable<ShaftSpec>& fields_of<ShaftSpec>() {
  using S = ShaftSpec;
  static const FieldTable<S> table = {
      name_field<S>("the shaft's name, used in element labels"),
      {.key = "x", .kind = K::quantity, .member = &S::x,
       .doc = "axial position of the shaft's first node; default 0", .unit = "mm"},
      {.key = "rotating", .kind = K::flag, .member = &S::rotating,
       .doc = "whether the shaft rotates; default true"},
      {.key = "material", .kind = K::text, .member = &S::material,
       .doc = "default material of the sections"},
      {.key = "start_node", .kind = K::text, .member = &S::start_node,
       .doc = "name of the shaft's first node"},
  };
  return table;
}

template <>
const FieldTable<SectionSpec>& fields_of<SectionSpec>() {
  using S = SectionSpec;
  static const FieldTable<S> table = {
      {.key = "length", .kind = K::quantity, .member = &S::length, .doc = "length of the section",
       .bound = positive, .required = true, .unit = "mm"},
      {.key = "outer_diameter", .kind = K::quantity, .member = &S::outer_diameter,
       .doc = "outer diameter", .bound = positive, .required = true, .unit = "mm"},
      {.key = "inner_diameter", .kind = K::quantity, .member = &S::inner_diameter,
       .doc = "bore diameter, smaller than outer_diameter; default 0 (solid)",
       .bound = non_negative, .unit = "mm"},
      {.key = "material", .kind = K::text, .member = &S::material,
       .doc = "material of the section; default the shaft's"},
      {.key = "elements", .kind = K::integer, .member = &S::elements,
       .doc = "number of equal shaft elements; default 1",
       .bound = at_least(1, max_elements_per_section)},
      {.key = "end_node", .kind = K::text, .member = &S::end_node,
       .doc = "name of the section's last node"},
  };
  return table;
}

template <>
const FieldTable<NodeSpec>& fields_of<NodeSpec>() {
  using S = NodeSpec;
  static const FieldTable<S> table = {
      {.key = "x", .kind = K::quantity, .member = &S::x, .doc = "axial position",
       .required = true, .unit = "mm"},
      {.key = "name", .kind = K::text, .member = &S::name, .doc = "the node's name"},
      {.key = "number", .kind = K::integer, .member = &S::number,
       .doc = "the node's number; default the next free number",
       .bound = at_least(1, 2147483646)},
      {.key = "rotating", .kind = K::flag, .member = &S::rotating,
       .doc = "whether the node rotates; default false"},
  };
  return table;
}

template <>
const FieldTable<RigidBodySpec>& fields_of<RigidBodySpec>() {
  using S = RigidBodySpec;
  static const FieldTable<S> table = {
      name_field<S>("the body's name, in messages and reports"),
      node_field<S>("node the body sits at"),
      {.key = "mass", .kind = K::quantity, .member = &S::mass, .doc = "mass",
       .quantity = Q::mass, .bound = non_negative},
      {.key = "Ja", .kind = K::quantity, .member = &S::Ja,
       .doc = "moment of inertia about a transverse axis through the node",
       .quantity = Q::inertia, .bound = non_negative},
      {.key = "Jp", .kind = K::quantity, .member = &S::Jp, .doc = "polar moment of inertia",
       .quantity = Q::inertia, .bound = non_negative},
      {.key = "outer_diameter", .kind = K::quantity, .member = &S::outer_diameter,
       .doc = "disk form: outer diameter", .bound = positive, .unit = "mm"},
      {.key = "inner_diameter", .kind = K::quantity, .member = &S::inner_diameter,
       .doc = "disk form: bore diameter; default 0", .bound = non_negative, .unit = "mm"},
      {.key = "width", .kind = K::quantity, .member = &S::width, .doc = "disk form: axial width",
       .bound = positive, .unit = "mm"},
      {.key = "material", .kind = K::text, .member = &S::material,
       .doc = "disk form: material whose density is used"},
      {.key = "offset", .kind = K::quantity, .member = &S::offset,
       .doc = "axial offset of the centre of mass from the node; default 0", .unit = "mm"},
      {.key = "rotating", .kind = K::flag, .member = &S::rotating,
       .doc = "whether the body rotates; default as its node"},
  };
  return table;
}

template <>
const FieldTable<SpringSpec>& fields_of<SpringSpec>() {
  using S = SpringSpec;
  const auto coefficient = [](std::string_view key, std::optional<SpeedCoefficient> S::*member,
                              Quantity q, bool direct, std::string_view doc) {
    return Field<S>{.key = key, .kind = K::coefficient, .member = member, .doc = doc,
                    .quantity = q, .bound = direct ? non_negative : Bound{}, .direct = direct};
  };
  static const FieldTable<S> table = {
      name_field<S>("the spring's name, referred to by [runup] springs"),
      node_field<S>("first node"),
      to_field<S>("ground", "second node, or \"ground\" (default)"),
      coefficient("kx", &S::kx, Q::stiffness, true, "axial stiffness"),
      coefficient("ky", &S::ky, Q::stiffness, true, "stiffness along y"),
      coefficient("kz", &S::kz, Q::stiffness, true, "stiffness along z"),
      coefficient("krx", &S::krx, Q::rotational_stiffness, true, "torsional stiffness"),
      coefficient("kry", &S::kry, Q::rotational_stiffness, true, "tilt stiffness about y"),
      coefficient("krz", &S::krz, Q::rotational_stiffness, true, "tilt stiffness about z"),
      coefficient("kyz", &S::kyz, Q::stiffness, false, "cross-coupled stiffness, y force from z"),
      coefficient("kzy", &S::kzy, Q::stiffness, false, "cross-coupled stiffness, z force from y"),
      coefficient("cx", &S::cx, Q::damping, true, "axial damping"),
      coefficient("cy", &S::cy, Q::damping, true, "damping along y"),
      coefficient("cz", &S::cz, Q::damping, true, "damping along z"),
      coefficient("crx", &S::crx, Q::rotational_damping, true, "torsional damping"),
      coefficient("cry", &S::cry, Q::rotational_damping, true, "tilt damping about y"),
      coefficient("crz", &S::crz, Q::rotational_damping, true, "tilt damping about z"),
      coefficient("cyz", &S::cyz, Q::damping, false, "cross-coupled damping, y force from z"),
      coefficient("czy", &S::czy, Q::damping, false, "cross-coupled damping, z force from y"),
      {.key = "loss_factor", .kind = K::number, .member = &S::loss_factor,
       .doc = "hysteretic loss factor η of the stiffness (harmonic analyses)",
       .bound = non_negative},
  };
  return table;
}

template <>
const FieldTable<RotatingDamperSpec>& fields_of<RotatingDamperSpec>() {
  using S = RotatingDamperSpec;
  static const FieldTable<S> table = {
      name_field<S>("the damper's name"),
      node_field<S>("first node (rotating)"),
      to_field<S>("axis", "second node (rotating), or \"axis\" (default): the rotating frame"),
      {.key = "ct", .kind = K::quantity, .member = &S::ct, .doc = "lateral damping",
       .quantity = Q::damping, .bound = non_negative},
      {.key = "cr", .kind = K::quantity, .member = &S::cr, .doc = "tilt damping",
       .quantity = Q::rotational_damping, .bound = non_negative},
      {.key = "cx", .kind = K::quantity, .member = &S::cx, .doc = "axial damping",
       .quantity = Q::damping, .bound = non_negative},
      {.key = "crx", .kind = K::quantity, .member = &S::crx, .doc = "torsional damping",
       .quantity = Q::rotational_damping, .bound = non_negative},
  };
  return table;
}

template <>
const FieldTable<FrictionSpec>& fields_of<FrictionSpec>() {
  using S = FrictionSpec;
  static const FieldTable<S> table = {
      name_field<S>("the contact's name"),
      node_field<S>("first node (rotating)"),
      to_field<S>("axis", "second node (rotating), or \"axis\" (default): the rotating frame"),
      {.key = "force", .kind = K::quantity, .member = &S::force,
       .doc = "friction force F_ct0 of the translational part", .quantity = Q::force,
       .bound = non_negative},
      {.key = "moment", .kind = K::quantity, .member = &S::moment,
       .doc = "friction moment F_cr0 of the rotational part", .quantity = Q::moment,
       .bound = non_negative},
      {.key = "epsilon_t", .kind = K::quantity, .member = &S::epsilon_t,
       .doc = "regularisation velocity of the translational part; default 0.1 mm/s",
       .quantity = Q::velocity, .bound = positive},
      {.key = "epsilon_r", .kind = K::quantity, .member = &S::epsilon_r,
       .doc = "regularisation angular velocity of the rotational part; default 0.001 rad/s",
       .quantity = Q::angular_velocity, .bound = positive},
  };
  return table;
}

template <>
const FieldTable<RigidLinkSpec>& fields_of<RigidLinkSpec>() {
  using S = RigidLinkSpec;
  static const FieldTable<S> table = {
      {.key = "nodes", .kind = K::node_list, .member = &S::nodes,
       .doc = "at least two nodes; the first leads, the others follow it rigidly",
       .required = true},
  };
  return table;
}

template <>
const FieldTable<FixedSpec>& fields_of<FixedSpec>() {
  using S = FixedSpec;
  static const FieldTable<S> table = {
      node_field<S>("node whose DOFs are held"),
      {.key = "dofs", .kind = K::choice_list, .member = &S::dofs,
       .doc = "DOFs held at zero; default all",
       .choices = dof_names,
       .if_empty = "leave it out to fix all DOFs"},
  };
  return table;
}

template <>
const FieldTable<UnbalanceSpec>& fields_of<UnbalanceSpec>() {
  using S = UnbalanceSpec;
  static const FieldTable<S> table = {
      name_field<S>("the unbalance's name"),
      node_field<S>("node the unbalance acts at"),
      {.key = "mass", .kind = K::quantity, .member = &S::mass, .doc = "unbalance mass m_U",
       .quantity = Q::mass, .bound = positive, .required = true},
      {.key = "radius", .kind = K::quantity, .member = &S::radius, .doc = "radius r_U",
       .bound = positive, .required = true, .unit = "mm"},
      {.key = "phase", .kind = K::quantity, .member = &S::phase,
       .doc = "angle from +y towards +z at t = 0; default 0", .quantity = Q::angle,
       .unit = "deg"},
      {.key = "lever", .kind = K::quantity, .member = &S::lever,
       .doc = "axial distance from the node to the unbalance plane; default 0", .unit = "mm"},
  };
  return table;
}

namespace {
Quantity force_amplitude_quantity(const ForceSpec& f) {
  const bool moment = f.kind == "rotating_moment" ||
                      (f.kind == "fixed" && (f.direction == "rx" || f.direction == "ry" ||
                                             f.direction == "rz"));
  return moment ? Quantity::moment : Quantity::force;
}
}  // namespace

Quantity amplitude_quantity(const ForceSpec& force) { return force_amplitude_quantity(force); }

template <>
const FieldTable<ForceSpec>& fields_of<ForceSpec>() {
  using S = ForceSpec;
  static const FieldTable<S> table = {
      name_field<S>("the force's name"),
      node_field<S>("node the force acts at"),
      {.key = "kind", .kind = K::choice, .member = &S::kind,
       .doc = "fixed (default), rotating_force or rotating_moment",
       .choices = force_kinds},
      {.key = "direction", .kind = K::choice, .member = &S::direction,
       .doc = "direction of a fixed force or moment", .choices = force_directions},
      {.key = "amplitude", .kind = K::quantity, .member = &S::amplitude,
       .doc = "amplitude: a force, or a moment for rotating_moment and directions rx, ry, rz",
       .quantity = Q::force, .bound = positive, .required = true},
      {.key = "phase", .kind = K::quantity, .member = &S::phase, .doc = "phase; default 0",
       .quantity = Q::angle, .unit = "deg"},
  };
  return table;
}

template <>
const FieldTable<StaticLoadSpec>& fields_of<StaticLoadSpec>() {
  using S = StaticLoadSpec;
  static const FieldTable<S> table = {
      name_field<S>("the load's name"),
      node_field<S>("node the load acts at"),
      {.key = "fx", .kind = K::quantity, .member = &S::fx, .doc = "force along x",
       .quantity = Q::force},
      {.key = "fy", .kind = K::quantity, .member = &S::fy, .doc = "force along y",
       .quantity = Q::force},
      {.key = "fz", .kind = K::quantity, .member = &S::fz, .doc = "force along z",
       .quantity = Q::force},
      {.key = "mx", .kind = K::quantity, .member = &S::mx, .doc = "moment about x",
       .quantity = Q::moment},
      {.key = "my", .kind = K::quantity, .member = &S::my, .doc = "moment about y",
       .quantity = Q::moment},
      {.key = "mz", .kind = K::quantity, .member = &S::mz, .doc = "moment about z",
       .quantity = Q::moment},
  };
  return table;
}

template <>
const FieldTable<ModalSpec>& fields_of<ModalSpec>() {
  using S = ModalSpec;
  static const FieldTable<S> table = {
      {.key = "speed", .kind = K::quantity, .member = &S::speed, .doc = "rotor speed",
       .quantity = Q::speed, .unit = "Hz"},
      {.key = "modes", .kind = K::integer, .member = &S::modes, .doc = "number of modes",
       .bound = at_least(1)},
  };
  return table;
}

template <>
const FieldTable<CampbellSpec>& fields_of<CampbellSpec>() {
  using S = CampbellSpec;
  static const FieldTable<S> table = {
      {.key = "start", .kind = K::quantity, .member = &S::start, .doc = "first speed",
       .quantity = Q::speed, .unit = "Hz"},
      {.key = "stop", .kind = K::quantity, .member = &S::stop,
       .doc = "last speed, greater than start", .quantity = Q::speed, .unit = "Hz"},
      {.key = "points", .kind = K::integer, .member = &S::points,
       .doc = "number of evenly spaced speeds", .bound = at_least(2)},
      {.key = "modes", .kind = K::integer, .member = &S::modes, .doc = "number of modes tracked",
       .bound = at_least(1)},
      {.key = "orders", .kind = K::integer_list, .member = &S::orders,
       .doc = "excitation orders k of the lines f = k·speed", .bound = at_least(1)},
  };
  return table;
}

template <>
const FieldTable<ResponseSpec>& fields_of<ResponseSpec>() {
  using S = ResponseSpec;
  static const FieldTable<S> table = {
      {.key = "start", .kind = K::quantity, .member = &S::start,
       .doc = "first speed (or frequency) of the sweep", .quantity = Q::speed, .unit = "Hz"},
      {.key = "stop", .kind = K::quantity, .member = &S::stop,
       .doc = "last speed, greater than start", .quantity = Q::speed, .unit = "Hz"},
      {.key = "points", .kind = K::integer, .member = &S::points,
       .doc = "number of sweep points", .bound = at_least(2)},
      {.key = "probes", .kind = K::node_list, .member = &S::probes,
       .doc = "nodes whose response is reported", .if_empty = default_hint},
      {.key = "loss_factor", .kind = K::number, .member = &S::loss_factor,
       .doc = "global hysteretic loss factor η", .bound = non_negative},
  };
  return table;
}

template <>
const FieldTable<StaticSpec>& fields_of<StaticSpec>() {
  using S = StaticSpec;
  static const FieldTable<S> table = {
      {.key = "gravity", .kind = K::choice, .member = &S::gravity,
       .doc = "direction in which gravity pulls, or none",
       .choices = gravity_directions},
      {.key = "g", .kind = K::quantity, .member = &S::g,
       .doc = "gravitational acceleration; default 9.81 m/s^2", .quantity = Q::acceleration,
       .bound = positive},
      {.key = "speed", .kind = K::quantity, .member = &S::speed,
       .doc = "speed at which speed-dependent coefficients are evaluated", .quantity = Q::speed,
       .unit = "Hz"},
  };
  return table;
}

template <>
const FieldTable<RunupSpec>& fields_of<RunupSpec>() {
  using S = RunupSpec;
  static const FieldTable<S> table = {
      {.key = "speed", .kind = K::quantity, .member = &S::speed,
       .doc = "constant speed (one form of the speed profile)", .quantity = Q::speed,
       .bound = non_negative, .unit = "Hz"},
      {.key = "from", .kind = K::quantity, .member = &S::from,
       .doc = "ramp: initial speed; default 0", .quantity = Q::speed, .bound = non_negative,
       .unit = "Hz"},
      {.key = "to", .kind = K::quantity, .member = &S::to, .doc = "ramp: final speed",
       .quantity = Q::speed, .bound = non_negative, .unit = "Hz"},
      {.key = "ramp_time", .kind = K::quantity, .member = &S::ramp_time,
       .doc = "ramp: its duration", .quantity = Q::time, .bound = positive},
      {.key = "table", .kind = K::speed_table, .member = &S::table,
       .doc = "[time, speed] points from time 0, piecewise linear, held after the last"},
      {.key = "duration", .kind = K::quantity, .member = &S::duration,
       .doc = "length of the run; default the ramp time or the last table time",
       .quantity = Q::time, .bound = positive},
      {.key = "integrator", .kind = K::choice, .member = &S::integrator,
       .doc = "time integrator", .choices = integrator_names},
      {.key = "dt", .kind = K::quantity, .member = &S::dt, .doc = "time step (initial step)",
       .quantity = Q::time, .bound = positive},
      {.key = "rel_tol", .kind = K::number, .member = &S::rel_tol,
       .doc = "relative tolerance of adaptive stepping", .bound = positive},
      {.key = "abs_tol", .kind = K::number, .member = &S::abs_tol,
       .doc = "absolute tolerance of adaptive stepping", .bound = positive},
      {.key = "output_interval", .kind = K::quantity, .member = &S::output_interval,
       .doc = "time between recorded samples", .quantity = Q::time, .bound = positive},
      {.key = "probes", .kind = K::node_list, .member = &S::probes,
       .doc = "nodes whose response is recorded", .if_empty = default_hint},
      {.key = "springs", .kind = K::text_list, .member = &S::springs,
       .doc = "names of springs whose forces are recorded", .if_empty = default_hint},
      {.key = "modes", .kind = K::integer, .member = &S::modes,
       .doc = "integrate in a basis of this many undamped modes", .bound = at_least(1)},
  };
  return table;
}

const std::vector<CoefficientLaw>& coefficient_laws() {
  static const std::vector<CoefficientLaw> laws = {
      {"table", {"law", "speeds", "values", "speed_unit"}},
      {"step", {"law", "below", "above", "at", "speed_unit"}},
      {"arctan", {"law", "value", "f_as", "c0", "c1", "c2"}},
  };
  return laws;
}

}  // namespace feran::spec
