// [[journal_bearings]]: plain journal bearings on an oil film (short, long or finite-length theory): the family's field
// table (its keys, bounds, units and help) and its build step (the checks across its keys, and the element or force it
// adds to the model).
#include <feran/spec/entries/journal_bearings.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<JournalBearingSpec>& fields_of<JournalBearingSpec>() {
  using S = JournalBearingSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"journal bearing <i>\"`"),
      node_field<S>("the journal; must be a rotating node"),
      to_field<S>("ground", "the housing: a non-rotating node, or the ground", "`\"ground\"`"),
      {.key = "diameter",
       .kind = K::quantity,
       .member = &S::diameter,
       .doc = "journal diameter D",
       .quantity = Q::length,
       .bound = positive,
       .required = true},
      {.key = "length",
       .kind = K::quantity,
       .member = &S::length,
       .doc = "axial length L of the film",
       .quantity = Q::length,
       .bound = positive,
       .required = true},
      {.key = "clearance",
       .kind = K::quantity,
       .member = &S::clearance,
       .doc = "radial clearance c; below D/2",
       .quantity = Q::length,
       .bound = positive,
       .required = true},
      {.key = "viscosity",
       .kind = K::quantity,
       .member = &S::viscosity,
       .doc = "dynamic viscosity μ of the oil at its working temperature",
       .quantity = Q::viscosity,
       .bound = positive,
       .required = true},
      {.key = "theory",
       .kind = K::choice,
       .member = &S::theory,
       .doc = "the film's solution: short = Ocvirk's with the π film, long = Sommerfeld's with Gümbel's condition, "
              "finite = the Reynolds equation solved by finite differences over the bearing",
       .choices = film_theories,
       .default_text = "`\"short\"`"},
      {.key = "cavitation",
       .kind = K::choice,
       .member = &S::cavitation,
       .doc = "only with `theory = \"finite\"`: where the film cavitates — Reynolds' (Swift–Stieber) condition, or "
              "Gümbel's (the uncavitated pressure kept where positive)",
       .choices = cavitation_conditions,
       .default_text = "`\"reynolds\"`"},
      {.key = "circumferential_cells",
       .kind = K::integer,
       .member = &S::circumferential_cells,
       .doc = "only with `theory = \"finite\"`: grid cells around the circumference",
       .bound = at_least(8, 100000),
       .default_text = "`72`"},
      {.key = "axial_cells",
       .kind = K::integer,
       .member = &S::axial_cells,
       .doc = "only with `theory = \"finite\"`: grid cells from the bearing's mid-plane to one end; "
              "`circumferential_cells` × `axial_cells` at most 250000",
       .bound = at_least(1, 10000),
       .default_text = "`8`"},
      {.key = "evaluation",
       .kind = K::choice,
       .member = &S::evaluation,
       .doc = "only with `theory = \"finite\"`: how the film force is evaluated — table = interpolated in a table of "
              "the solver's solutions built once per bearing shape (about 1 µs an evaluation, within 1 % of the "
              "solver, else the solver is used), exact = the solver at every evaluation (about 0.3 ms on the "
              "default grid), auto = the table in run-ups and the solver in the other analyses",
       .choices = film_evaluations,
       .default_text = "`\"auto\"`"},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_journal_bearings() {
  for (std::size_t i = 0; i < spec_.journal_bearings.size(); ++i) {
    const JournalBearingSpec& s = spec_.journal_bearings[i];
    const std::string path = element("journal_bearings", i);
    const std::string label = entry_label(s.name, "journal bearing", i);
    FluidFilmBearing b;
    std::tie(b.node_a, b.node_b) = bearing_nodes(s.node, s.to, path, "journal bearing");
    check_bounds(s, path);
    if (!(s.clearance < 0.5 * s.diameter))
      fail(child(path, "clearance"), fmt::format("the radial clearance ({} m) must be smaller than the journal's "
                                                 "radius ({} m); it is usually about a thousandth of it",
                                                 s.clearance, 0.5 * s.diameter));
    b.geometry = {.diameter = s.diameter, .length = s.length, .clearance = s.clearance, .viscosity = s.viscosity};
    check_choice(s.theory, child(path, "theory"), "theory", spec::choices_of<JournalBearingSpec>("theory"));
    b.theory = s.theory == "long"     ? FilmTheory::long_bearing
               : s.theory == "finite" ? FilmTheory::finite_length
                                      : FilmTheory::short_bearing;
    if (b.theory != FilmTheory::finite_length) {
      for (const auto& [key, given] :
           {std::pair{"cavitation", s.cavitation.has_value()},
            std::pair{"circumferential_cells", s.circumferential_cells.has_value()},
            std::pair{"axial_cells", s.axial_cells.has_value()}, std::pair{"evaluation", s.evaluation.has_value()}})
        if (given)
          fail(child(path, key), fmt::format("'{}' applies only to theory = \"finite\" (the {} bearing's closed "
                                             "form has its own cavitation condition and no grid)",
                                             key, s.theory));
    }
    if (s.cavitation) {
      check_choice(*s.cavitation, child(path, "cavitation"), "cavitation",
                   spec::choices_of<JournalBearingSpec>("cavitation"));
      b.grid.cavitation = *s.cavitation == "gumbel" ? Cavitation::gumbel : Cavitation::reynolds;
    }
    if (s.circumferential_cells) b.grid.circumferential = *s.circumferential_cells;
    if (s.axial_cells) b.grid.axial = *s.axial_cells;
    if (s.evaluation) {
      check_choice(*s.evaluation, child(path, "evaluation"), "evaluation",
                   spec::choices_of<JournalBearingSpec>("evaluation"));
      b.grid.evaluation = *s.evaluation == "exact"   ? FilmEvaluation::exact
                          : *s.evaluation == "table" ? FilmEvaluation::table
                                                     : FilmEvaluation::automatic;
    }
    // Each count within its bounds, their product bounded too: every force evaluation
    // factorises the Reynolds equation on the whole grid.
    constexpr long long max_cells = 250000;
    const long long cells = static_cast<long long>(b.grid.circumferential) * b.grid.axial;
    if (cells > max_cells)
      fail(child(path, s.axial_cells ? "axial_cells" : "circumferential_cells"),
           fmt::format("the film's grid of {} × {} = {} cells is too large: at most {} (each force evaluation "
                       "solves the Reynolds equation on the whole grid; its time and memory grow faster than the "
                       "count)",
                       b.grid.circumferential, b.grid.axial, cells, max_cells));
    model_.forces.emplace_back(b, label);
  }
}

}  // namespace builder

}  // namespace feran
