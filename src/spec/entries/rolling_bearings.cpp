// [[rolling_bearings]]: ball and roller bearings (Hertzian contact, clearance): the family's field table (its keys,
// bounds, units and help) and its build step (the checks across its keys, and the element or force it adds to the
// model).
#include <feran/spec/entries/rolling_bearings.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<RollingBearingSpec>& fields_of<RollingBearingSpec>() {
  using S = RollingBearingSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"rolling bearing <i>\"`"),
      node_field<S>("the journal (inner race); must be a rotating node"),
      to_field<S>("ground", "the housing (outer race, at rest): a non-rotating node, or the ground", "`\"ground\"`"),
      {.key = "elements",
       .kind = K::integer,
       .member = &S::elements,
       .doc = "number Z of balls or rollers",
       .bound = at_least(1, 10000),
       .required = true},
      {.key = "element_diameter",
       .kind = K::quantity,
       .member = &S::element_diameter,
       .doc = "diameter d of a ball or roller; below `pitch_diameter`",
       .quantity = Q::length,
       .bound = positive,
       .required = true},
      {.key = "pitch_diameter",
       .kind = K::quantity,
       .member = &S::pitch_diameter,
       .doc = "diameter D_p of the circle through the elements' centres",
       .quantity = Q::length,
       .bound = positive,
       .required = true},
      {.key = "contact_angle",
       .kind = K::quantity,
       .member = &S::contact_angle,
       .doc = "contact angle α; below 90°",
       .quantity = Q::angle,
       .bound = non_negative,
       .default_text = "`0`"},
      {.key = "clearance",
       .kind = K::quantity,
       .member = &S::clearance,
       .doc = "radial clearance c_r between the elements and the races",
       .quantity = Q::length,
       .bound = non_negative,
       .default_text = "`0`"},
      {.key = "hertz_constant",
       .kind = K::number,
       .member = &S::hertz_constant,
       .doc = "K of one element's load–deflection law Q = K·δⁿ, in SI units: N/m^1.5 for balls, N/m^(10/9) for rollers",
       .bound = positive,
       .required = true},
      {.key = "type",
       .kind = K::choice,
       .member = &S::type,
       .doc = "point contact (n = 3/2) or line contact (n = 10/9)",
       .choices = rolling_types,
       .default_text = "`\"ball\"`"},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_rolling_bearings() {
  for (std::size_t i = 0; i < spec_.rolling_bearings.size(); ++i) {
    const RollingBearingSpec& s = spec_.rolling_bearings[i];
    const std::string path = element("rolling_bearings", i);
    const std::string label = entry_label(s.name, "rolling bearing", i);
    RollingBearing b;
    std::tie(b.node_a, b.node_b) = bearing_nodes(s.node, s.to, path, "rolling bearing");
    check_bounds(s, path);
    check_choice(s.type, child(path, "type"), "type", spec::choices_of<RollingBearingSpec>("type"));
    if (!(s.element_diameter < s.pitch_diameter))
      fail(child(path, "element_diameter"),
           fmt::format("the elements' diameter ({} m) must be smaller than the pitch diameter ({} m)",
                       s.element_diameter, s.pitch_diameter));
    if (!(s.contact_angle < 0.5 * pi))
      fail(child(path, "contact_angle"),
           fmt::format("the contact angle must be below 90°, got {:.6g}°", s.contact_angle * 180.0 / pi));
    b.geometry = {.elements = s.elements,
                  .element_diameter = s.element_diameter,
                  .pitch_diameter = s.pitch_diameter,
                  .contact_angle = s.contact_angle,
                  .clearance = s.clearance,
                  .hertz_constant = s.hertz_constant,
                  .roller = s.type == "roller"};
    model_.forces.emplace_back(b, label);
  }
}

}  // namespace builder

}  // namespace feran
