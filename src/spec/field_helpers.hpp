#pragma once
// What the field tables share (spec/fields.cpp and each family's under entries/):
// bounds, the words of the choice fields, the name, node and to fields.

#include <cstdint>
#include <string_view>

#include <feran/spec/fields.hpp>

namespace feran::spec::field_helpers {

using K = FieldKind;
using Q = Quantity;

inline constexpr Bound positive{Bound::Kind::positive};
inline constexpr Bound non_negative{Bound::Kind::non_negative};
inline constexpr Bound at_least(std::int64_t minimum, std::int64_t maximum = 1'000'000'000) {
  return Bound{Bound::Kind::at_least, minimum, maximum};
}

// The words of the choice fields.
inline constexpr std::string_view gyroscopic_forms[] = {"consistent", "lumped"};
inline constexpr std::string_view free_motion_names[] = {"axial", "torsion", "lateral"};
inline constexpr std::string_view shear_formulas[] = {"cowper", "hutchinson"};
inline constexpr std::string_view dof_names[] = {"u",  "v",   "w",       "rx",           "ry",
                                                 "rz", "all", "lateral", "translations", "rotations"};
inline constexpr std::string_view force_kinds[] = {"fixed", "rotating_force", "rotating_moment"};
inline constexpr std::string_view force_directions[] = {"x", "y", "z", "rx", "ry", "rz"};
inline constexpr std::string_view motor_kinds[] = {"dc", "induction", "table"};
inline constexpr std::string_view film_theories[] = {"short", "long", "finite"};
inline constexpr std::string_view cavitation_conditions[] = {"reynolds", "gumbel"};
inline constexpr std::string_view film_evaluations[] = {"auto", "table", "exact"};
inline constexpr std::string_view rolling_types[] = {"ball", "roller"};

inline constexpr std::string_view default_hint = "leave it out for the analysis's default";

/// Largest number of elements per section: guards against a typo such as 1e9 elements.
inline constexpr std::int64_t max_elements_per_section = 100000;

/// The name of an entry, used in messages and to name it in parameter paths.
template <class S>
Field<S> name_field(std::string_view doc, std::string_view default_text = {}) {
  return {.key = "name", .kind = K::text, .member = &S::name, .doc = doc, .default_text = default_text};
}

/// The node an entry sits at.
template <class S>
Field<S> node_field(std::string_view doc) {
  return {.key = "node", .kind = K::node, .member = &S::node, .doc = doc, .required = true};
}

template <class S>
Field<S> to_field(std::string_view special, std::string_view doc, std::string_view default_text) {
  return {.key = "to", .kind = K::node, .member = &S::to, .doc = doc, .special = special, .default_text = default_text};
}

}  // namespace feran::spec::field_helpers
