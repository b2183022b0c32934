// [[annular_seals]]: plain annular liquid seals (the short-seal bulk-flow model of Black and Childs): the family's
// field table (its keys, bounds, units and help) and its build step (the checks across its keys, and the element it
// adds to the model).
#include <feran/spec/entries/annular_seals.hpp>

#include <feran/elements/annular_seal.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<AnnularSealSpec>& fields_of<AnnularSealSpec>() {
  using S = AnnularSealSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"annular seal <i>\"`"),
      node_field<S>("the rotor's land; must be a rotating node"),
      to_field<S>("ground", "the stator: a non-rotating node, or the ground", "`\"ground\"`"),
      {.key = "diameter",
       .kind = K::quantity,
       .member = &S::diameter,
       .doc = "diameter 2R of the rotor's land",
       .quantity = Q::length,
       .bound = positive,
       .required = true},
      {.key = "length",
       .kind = K::quantity,
       .member = &S::length,
       .doc = "axial length L; the model neglects the circumferential pressure flow, as short seals (L well below 2R) "
              "allow",
       .quantity = Q::length,
       .bound = positive,
       .required = true},
      {.key = "clearance",
       .kind = K::quantity,
       .member = &S::clearance,
       .doc = "radial clearance C; below R",
       .quantity = Q::length,
       .bound = positive,
       .required = true},
      {.key = "pressure_drop",
       .kind = K::quantity,
       .member = &S::pressure_drop,
       .doc = "pressure drop ΔP across the seal, which drives its leakage",
       .quantity = Q::pressure,
       .bound = positive,
       .required = true},
      {.key = "density",
       .kind = K::quantity,
       .member = &S::density,
       .doc = "density ρ of the liquid",
       .quantity = Q::density,
       .bound = positive,
       .required = true},
      {.key = "viscosity",
       .kind = K::quantity,
       .member = &S::viscosity,
       .doc = "dynamic viscosity μ of the liquid",
       .quantity = Q::viscosity,
       .bound = positive,
       .required = true},
      {.key = "entrance_loss",
       .kind = K::number,
       .member = &S::entrance_loss,
       .doc = "entrance loss coefficient ξ: the inlet's pressure drop is (1 + ξ)·ρV²/2",
       .bound = non_negative,
       .default_text = "`0.1`"},
      {.key = "friction_n",
       .kind = K::number,
       .member = &S::friction_n,
       .doc = "n of each wall's Fanning friction factor f = n·Re^m, Re = 2CV/ν (Blasius' law for smooth walls)",
       .bound = positive,
       .default_text = "`0.079`"},
      {.key = "friction_m",
       .kind = K::number,
       .member = &S::friction_m,
       .doc = "m of f = n·Re^m; from −1 (excluded) to 0",
       .default_text = "`-0.25`"},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_annular_seals() {
  for (std::size_t i = 0; i < spec_.annular_seals.size(); ++i) {
    const AnnularSealSpec& s = spec_.annular_seals[i];
    const std::string path = element("annular_seals", i);
    const std::string label = entry_label(s.name, "annular seal", i);
    const auto [a, b] = bearing_nodes(s.node, s.to, path, "annular seal");
    check_bounds(s, path);
    if (!(s.clearance < 0.5 * s.diameter))
      fail(child(path, "clearance"), fmt::format("the radial clearance ({} m) must be smaller than the land's radius "
                                                 "({} m); a seal's is usually about a few thousandths of it",
                                                 s.clearance, 0.5 * s.diameter));
    if (!(s.friction_m > -1 && s.friction_m <= 0))
      fail(child(path, "friction_m"), fmt::format("the friction exponent m must be above −1 and at most 0 (the "
                                                  "friction falls with the Reynolds number, more slowly than "
                                                  "laminar flow's 1/Re), got {}",
                                                  s.friction_m));
    model_.elements.emplace_back(AnnularSeal(a, b,
                                             {.radius = 0.5 * s.diameter,
                                              .length = s.length,
                                              .clearance = s.clearance,
                                              .pressure_drop = s.pressure_drop,
                                              .density = s.density,
                                              .viscosity = s.viscosity,
                                              .entrance_loss = s.entrance_loss,
                                              .friction_n = s.friction_n,
                                              .friction_m = s.friction_m}),
                                 label);
  }
}

}  // namespace builder

}  // namespace feran
