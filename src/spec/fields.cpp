#include <feran/spec/fields.hpp>

#include "field_helpers.hpp"

namespace feran::spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<ModelSpec>& fields_of<ModelSpec>() {
  static const FieldTable<ModelSpec> table = {
      {.key = "title", .kind = K::text, .member = &ModelSpec::title, .doc = "name of the model, shown in reports"},
  };
  return table;
}

template <>
const FieldTable<OptionsSpec>& fields_of<OptionsSpec>() {
  using S = OptionsSpec;
  static const FieldTable<S> table = {
      {.key = "shear_deformation",
       .kind = K::flag,
       .member = &S::shear_deformation,
       .doc = "Timoshenko shaft elements (`true`) or Euler–Bernoulli (`false`)"},
      {.key = "gyroscopic",
       .kind = K::choice,
       .member = &S::gyroscopic,
       .doc = "gyroscopic matrix of shaft elements, consistent or lumped at the nodes",
       .choices = gyroscopic_forms},
      {.key = "shaft_damping",
       .kind = K::quantity,
       .member = &S::shaft_damping,
       .doc = "stiffness-proportional material damping β of rotating shafts: C_i = β·K of each rotating shaft element "
              "(non-rotating shafts get none)",
       .quantity = Q::time,
       .bound = non_negative},
      {.key = "free_motions",
       .kind = K::choice_list,
       .member = &S::free_motions,
       .doc = "rigid-body motions that may stay free (section 6)",
       .choices = free_motion_names},
      {.key = "rotary_inertia",
       .kind = K::flag,
       .member = &S::rotary_inertia,
       .doc = "rotary inertia ρI of the shaft sections in the mass matrix (`false`: translational inertia only; the "
              "gyroscopic matrix stays)"},
      {.key = "shear_coefficient",
       .kind = K::choice,
       .member = &S::shear_coefficient,
       .doc = "the formula of the shear coefficient κ of shaft elements: Cowper (1966) or Hutchinson (2001), for a "
              "hollow circle",
       .choices = shear_formulas},
      {.key = "kappa",
       .kind = K::number,
       .member = &S::kappa,
       .doc = "a fixed shear coefficient κ for every shaft element, instead of the formula",
       .bound = positive},
      {.key = "rayleigh_alpha",
       .kind = K::quantity,
       .member = &S::rayleigh_alpha,
       .doc = "non-rotating proportional damping of shafts, C = α·M + β·K (external: no circulatory terms, unlike "
              "`shaft_damping`); α",
       .quantity = Q::inverse_time,
       .bound = non_negative},
      {.key = "rayleigh_beta",
       .kind = K::quantity,
       .member = &S::rayleigh_beta,
       .doc = "β of the non-rotating proportional damping of shafts",
       .quantity = Q::time,
       .bound = non_negative},
  };
  return table;
}

template <>
const FieldTable<MaterialSpec>& fields_of<MaterialSpec>() {
  using S = MaterialSpec;
  static const FieldTable<S> table = {
      {.key = "name", .kind = K::text, .member = &S::name, .doc = "unique among materials", .required = true},
      {.key = "E",
       .kind = K::quantity,
       .member = &S::E,
       .doc = "Young's modulus",
       .quantity = Q::pressure,
       .bound = positive,
       .required = true,
       .unit = "GPa"},
      {.key = "G",
       .kind = K::quantity,
       .member = &S::G,
       .doc = "shear modulus; give `G` or `nu`, not both",
       .quantity = Q::pressure,
       .bound = positive,
       .unit = "GPa"},
      {.key = "nu",
       .kind = K::number,
       .member = &S::nu,
       .doc = "−1 < ν < 0.5, Poisson's ratio; then G = E / (2(1 + ν))"},
      {.key = "rho",
       .kind = K::quantity,
       .member = &S::rho,
       .doc = "density (0 is allowed for a massless-shaft idealisation)",
       .quantity = Q::density,
       .bound = non_negative,
       .required = true},
      {.key = "loss_factor",
       .kind = K::number,
       .member = &S::loss_factor,
       .doc = "hysteretic (structural) loss factor η of the material",
       .bound = non_negative},
  };
  return table;
}

template <>
const FieldTable<ShaftSpec>& fields_of<ShaftSpec>() {
  using S = ShaftSpec;
  static const FieldTable<S> table = {
      name_field<S>("used in element labels; without it the shaft's index (1, 2, …) is used"),
      {.key = "x",
       .kind = K::quantity,
       .member = &S::x,
       .doc = "axial position of the shaft's first node",
       .unit = "mm"},
      {.key = "rotating", .kind = K::flag, .member = &S::rotating, .doc = "whether the shaft and its nodes rotate"},
      {.key = "material",
       .kind = K::text,
       .member = &S::material,
       .doc = "name of the default material of its sections"},
      {.key = "start_node", .kind = K::text, .member = &S::start_node, .doc = "name of the shaft's first node"},
      {.key = "rayleigh_alpha",
       .kind = K::quantity,
       .member = &S::rayleigh_alpha,
       .doc = "this shaft's α of non-rotating proportional damping",
       .quantity = Q::inverse_time,
       .bound = non_negative,
       .default_text = "`[options]` `rayleigh_alpha`"},
      {.key = "rayleigh_beta",
       .kind = K::quantity,
       .member = &S::rayleigh_beta,
       .doc = "this shaft's β of non-rotating proportional damping",
       .quantity = Q::time,
       .bound = non_negative,
       .default_text = "`[options]` `rayleigh_beta`"},
  };
  return table;
}

template <>
const FieldTable<SectionSpec>& fields_of<SectionSpec>() {
  using S = SectionSpec;
  static const FieldTable<S> table = {
      {.key = "length",
       .kind = K::quantity,
       .member = &S::length,
       .doc = "length of the section",
       .bound = positive,
       .required = true,
       .unit = "mm"},
      {.key = "outer_diameter",
       .kind = K::quantity,
       .member = &S::outer_diameter,
       .doc = "outer diameter",
       .bound = positive,
       .required = true,
       .unit = "mm"},
      {.key = "inner_diameter",
       .kind = K::quantity,
       .member = &S::inner_diameter,
       .doc = "bore diameter, < `outer_diameter`",
       .bound = non_negative,
       .unit = "mm"},
      {.key = "outer_diameter_end",
       .kind = K::quantity,
       .member = &S::outer_diameter_end,
       .doc = "outer diameter at the section's end: a tapered (conical) section, both diameters linear along it",
       .bound = positive,
       .unit = "mm",
       .default_text = "`outer_diameter`"},
      {.key = "inner_diameter_end",
       .kind = K::quantity,
       .member = &S::inner_diameter_end,
       .doc = "bore diameter at the section's end, < `outer_diameter_end`",
       .bound = non_negative,
       .unit = "mm",
       .default_text = "`inner_diameter`"},
      {.key = "axial_force",
       .kind = K::quantity,
       .member = &S::axial_force,
       .doc = "constant axial force in the section, tension positive: geometric stiffness of its elements "
              "(tension stiffens, compression softens)",
       .quantity = Q::force},
      {.key = "material",
       .kind = K::text,
       .member = &S::material,
       .doc = "name of a material; required if the shaft gives none",
       .default_text = "the shaft's `material`"},
      {.key = "elements",
       .kind = K::integer,
       .member = &S::elements,
       .doc = "number of equal shaft elements",
       .bound = at_least(1, max_elements_per_section)},
      {.key = "end_node", .kind = K::text, .member = &S::end_node, .doc = "name of the section's last node"},
  };
  return table;
}

template <>
const FieldTable<NodeSpec>& fields_of<NodeSpec>() {
  using S = NodeSpec;
  static const FieldTable<S> table = {
      {.key = "x", .kind = K::quantity, .member = &S::x, .doc = "axial position", .required = true, .unit = "mm"},
      {.key = "name", .kind = K::text, .member = &S::name, .doc = "unique node name"},
      {.key = "number",
       .kind = K::integer,
       .member = &S::number,
       .doc = "unique node number",
       .bound = at_least(1, 2147483646),
       .default_text = "next free number (section 3)"},
      {.key = "rotating",
       .kind = K::flag,
       .member = &S::rotating,
       .doc = "whether the node belongs to a rotating body"},
  };
  return table;
}

template <>
const FieldTable<RigidBodySpec>& fields_of<RigidBodySpec>() {
  using S = RigidBodySpec;
  static const FieldTable<S> table = {
      name_field<S>("label (i counts the entries from 1)", "`\"rigid body <i>\"`"),
      node_field<S>("the node the body sits at"),
      {.key = "mass",
       .kind = K::quantity,
       .member = &S::mass,
       .doc = "mass form: the mass",
       .quantity = Q::mass,
       .bound = non_negative,
       .default_text = "required in the mass form"},
      {.key = "Ja",
       .kind = K::quantity,
       .member = &S::Ja,
       .doc = "mass form: about a transverse axis **through the node**",
       .quantity = Q::inertia,
       .bound = non_negative,
       .default_text = "required in the mass form"},
      {.key = "Jp",
       .kind = K::quantity,
       .member = &S::Jp,
       .doc = "mass form: polar, about the x axis",
       .quantity = Q::inertia,
       .bound = non_negative,
       .default_text = "required in the mass form"},
      {.key = "outer_diameter",
       .kind = K::quantity,
       .member = &S::outer_diameter,
       .doc = "disk form: outer diameter",
       .bound = positive,
       .unit = "mm",
       .default_text = "required in the disk form"},
      {.key = "inner_diameter",
       .kind = K::quantity,
       .member = &S::inner_diameter,
       .doc = "disk form: bore diameter, < `outer_diameter`",
       .bound = non_negative,
       .unit = "mm",
       .default_text = "`0` (disk form)"},
      {.key = "width",
       .kind = K::quantity,
       .member = &S::width,
       .doc = "disk form: axial width",
       .bound = positive,
       .unit = "mm",
       .default_text = "required in the disk form"},
      {.key = "material",
       .kind = K::text,
       .member = &S::material,
       .doc = "disk form: name of a material (its `rho` is used)",
       .default_text = "required in the disk form"},
      {.key = "offset",
       .kind = K::quantity,
       .member = &S::offset,
       .doc = "axial position of the centre of mass relative to the node",
       .unit = "mm",
       .default_text = "`0`"},
      {.key = "rotating",
       .kind = K::flag,
       .member = &S::rotating,
       .doc = "whether the body spins (adds the gyroscopic term of Jp)",
       .default_text = "the node's flag"},
  };
  return table;
}

template <>
const FieldTable<RigidLinkSpec>& fields_of<RigidLinkSpec>() {
  using S = RigidLinkSpec;
  static const FieldTable<S> table = {
      {.key = "nodes",
       .kind = K::node_list,
       .member = &S::nodes,
       .doc = "at least two distinct nodes; the first is the leader",
       .required = true},
  };
  return table;
}

template <>
const FieldTable<FixedSpec>& fields_of<FixedSpec>() {
  using S = FixedSpec;
  static const FieldTable<S> table = {
      node_field<S>("the node whose DOFs are held"),
      {.key = "dofs",
       .kind = K::choice_list,
       .member = &S::dofs,
       .doc = "DOFs and groups of DOFs held at zero (below)",
       .choices = dof_names,
       .default_text = "`[\"all\"]`",
       .if_empty = "leave it out to fix all DOFs"},
  };
  return table;
}

template <>
const FieldTable<UnbalanceSpec>& fields_of<UnbalanceSpec>() {
  using S = UnbalanceSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"unbalance <i>\"`"),
      node_field<S>("the node the unbalance acts at"),
      {.key = "mass",
       .kind = K::quantity,
       .member = &S::mass,
       .doc = "unbalance mass m_U",
       .quantity = Q::mass,
       .bound = positive,
       .required = true},
      {.key = "radius",
       .kind = K::quantity,
       .member = &S::radius,
       .doc = "radius r_U",
       .bound = positive,
       .required = true,
       .unit = "mm"},
      {.key = "phase",
       .kind = K::quantity,
       .member = &S::phase,
       .doc = "angle at t = 0, measured from +y towards +z",
       .quantity = Q::angle,
       .unit = "deg"},
      {.key = "lever",
       .kind = K::quantity,
       .member = &S::lever,
       .doc = "axial distance from the node to the unbalance plane",
       .unit = "mm"},
  };
  return table;
}

namespace {
Quantity force_amplitude_quantity(const ForceSpec& f) {
  const bool moment = f.kind == "rotating_moment" ||
                      (f.kind == "fixed" && (f.direction == "rx" || f.direction == "ry" || f.direction == "rz"));
  return moment ? Quantity::moment : Quantity::force;
}
}  // namespace

Quantity amplitude_quantity(const ForceSpec& force) { return force_amplitude_quantity(force); }

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

template <>
const FieldTable<StaticLoadSpec>& fields_of<StaticLoadSpec>() {
  using S = StaticLoadSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"static load <i>\"`"),
      node_field<S>("the node the load acts at"),
      {.key = "fx", .kind = K::quantity, .member = &S::fx, .doc = "force along x (any sign)", .quantity = Q::force},
      {.key = "fy", .kind = K::quantity, .member = &S::fy, .doc = "force along y (any sign)", .quantity = Q::force},
      {.key = "fz", .kind = K::quantity, .member = &S::fz, .doc = "force along z (any sign)", .quantity = Q::force},
      {.key = "mx",
       .kind = K::quantity,
       .member = &S::mx,
       .doc = "moment about x (any sign, right-hand rule)",
       .quantity = Q::moment},
      {.key = "my",
       .kind = K::quantity,
       .member = &S::my,
       .doc = "moment about y (any sign, right-hand rule)",
       .quantity = Q::moment},
      {.key = "mz",
       .kind = K::quantity,
       .member = &S::mz,
       .doc = "moment about z (any sign, right-hand rule)",
       .quantity = Q::moment},
  };
  return table;
}

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

const std::vector<CoefficientLaw>& coefficient_laws() {
  static const std::vector<CoefficientLaw> laws = {
      {"table", {"law", "speeds", "values", "speed_unit"}},
      {"step", {"law", "below", "above", "at", "speed_unit"}},
      {"arctan", {"law", "value", "f_as", "c0", "c1", "c2"}},
      {"frequency_table", {"law", "frequencies", "values", "speeds", "speed_unit", "frequency_unit"}},
  };
  return laws;
}

}  // namespace feran::spec
