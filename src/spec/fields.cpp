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
