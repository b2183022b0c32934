#pragma once
// The model builder (spec/build_model.hpp's build_model): one ModelSpec into one Model,
// every check a SpecError at the spec path of what is wrong. Internal to the library:
// build_model.cpp holds the shared steps (nodes, materials, shafts, the analyses'
// tables, the structure's checks) and each model-entry family's file under entries/
// holds its field table and its build step (Builder::build_<family>).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <unordered_map>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include <feran/assembly/assembler.hpp>
#include <feran/assembly/checks.hpp>
#include <feran/core/suggestions.hpp>
#include <feran/core/units.hpp>
#include <feran/elements/rigid_body.hpp>
#include <feran/elements/rotating_damper.hpp>
#include <feran/elements/spring_damper.hpp>
#include <feran/elements/timoshenko_beam.hpp>
#include <feran/forces/coulomb_friction.hpp>
#include <feran/forces/fluid_film_bearing.hpp>
#include <feran/forces/harmonic_force.hpp>
#include <feran/forces/rolling_bearing.hpp>
#include <feran/forces/static_load.hpp>
#include <feran/forces/unbalance.hpp>
#include <feran/spec/fields.hpp>

#include <feran/spec/build_model.hpp>
#include <feran/spec/spec_path.hpp>

namespace feran::builder {

using detail::all_digits;
using detail::closest_match;
using detail::join_list;
using detail::number_ranges;
using spec::Bound;
using spec::child;
using spec::element;

inline constexpr std::string_view ground_word = "ground";
inline constexpr std::string_view axis_word = "axis";

/// The label of the @p i-th entry of a list: its name, or "<kind> <i+1>" without one.
inline std::string entry_label(const std::string& name, std::string_view kind, std::size_t i) {
  return name.empty() ? fmt::format("{} {}", kind, i + 1) : name;
}

/// Builds one Model from one spec; every check throws SpecError.
class Builder {
 public:
  Builder(const ModelSpec& spec, const SpecSource* source) : spec_(spec), source_(source) {}

  Model build(BuildInfo* info);

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& message) const { throw SpecError(path, message); }
  /// How messages name the place of @p path: "line 4, column 8", or the path itself.
  std::string place(const std::string& path) const;
  /// A quantity as written at @p path, else formatted in @p unit.
  std::string shown(const std::string& path, Real si, Quantity kind, std::string_view unit = {}) const;
  /// True when the reader saw @p path (always false for specs built in code).
  bool given(const std::string& path) const { return source_ != nullptr && source_->places.count(path) != 0; }
  /// True when @p a was written before @p b (always false without a source).
  bool earlier(const std::string& a, const std::string& b) const;
  std::string missing_key(std::string_view key, std::string_view table, std::string_view expected) const {
    return fmt::format("missing key '{}' in {} (expected {})", key, table, expected);
  }

  template <class S>
  void check_bounds(const S& entry, const std::string& path) const;
  // A quantity's magnitude within physical_range() (and at least its smallest
  // positive value where it must be positive).
  void check_range(Real v, const std::string& at, std::string_view key, Quantity quantity, std::string_view unit,
                   bool positive) const;
  void check_coefficient(const SpeedCoefficient& c, const std::string& path, std::string_view key, Quantity kind,
                         bool direct) const;
  void check_choice(const std::string& value, const std::string& path, std::string_view key,
                    std::span<const std::string_view> choices) const;

  void build_options();
  const Material& material(const std::string& name, const std::string& path) const;
  void build_materials();
  void check_node_name(const std::string& name, const std::string& path) const;
  Index add_node(Node node, const std::string& defined_at, const std::string& name_at);
  void build_shafts();
  void build_nodes();
  Index node(const NodeRef& ref, const std::string& path, std::string_view key, std::string_view special = {}) const;
  std::optional<Index> other_node(const std::optional<NodeRef>& to, const std::string& path, std::string_view special,
                                  Index from) const;
  void require_rotating(Index index, const std::string& path, std::string_view reason) const;
  void build_rigid_bodies();
  void build_springs();
  void build_rotating_dampers();
  void build_friction();
  void build_journal_bearings();
  void build_rolling_bearings();
  void build_annular_seals();
  std::pair<Index, std::optional<Index>> bearing_nodes(const NodeRef& journal, const std::optional<NodeRef>& to,
                                                       const std::string& path, std::string_view what) const;
  void build_rigid_links();
  void build_fixed();
  void build_unbalances();
  void build_forces();
  void build_static_loads();
  void build_drive();
  void check_sweep(std::optional<Real> start, std::optional<Real> stop, const std::string& table) const;
  /// The nodes of a list of references at @p path (key @p key), none twice.
  std::vector<Index> distinct_nodes(const std::vector<NodeRef>& refs, const std::string& path,
                                    std::string_view key) const;
  void check_analysis_tables() const;
  void check_response() const;
  void check_static() const;
  void check_runup() const;
  void build_gravity();
  void check_api684() const;
  void check_orbits() const;
  // Each of @p names is the name of one [[springs]] entry, none twice (at @p key[i]).
  void check_spring_names(const std::vector<std::string>& names, const std::string& key) const;
  void check_structure(BuildInfo* info);

  const ModelSpec& spec_;
  const SpecSource* source_;
  Model model_;
  BeamOptions beam_;  ///< [options] as shaft elements take them
  std::vector<Material> materials_;
  std::vector<std::string> node_paths_;       ///< per node: the table that defines it
  std::vector<std::string> node_name_paths_;  ///< per node: where its name (or it) is
  // The nodes by number and by name (so that registering n nodes is linear in n),
  // and the highest number so far.
  std::unordered_map<int, std::size_t> node_by_number_;
  std::unordered_map<std::string, std::size_t> node_by_name_;
  int highest_number_ = 0;
  std::vector<std::string> unnamed_spring_labels_;
};

template <class S>
void Builder::check_bounds(const S& entry, const std::string& path) const {
  using Kind = Bound::Kind;
  for (const spec::Field<S>& f : spec::fields_of<S>()) {
    const std::string at = child(path, f.key);
    const auto check_real = [&](Real v) {
      const auto text = [&] {
        return f.kind == spec::FieldKind::quantity ? shown(at, v, f.quantity, f.unit) : fmt::format("{}", v);
      };
      if (!std::isfinite(v)) fail(at, fmt::format("'{}' must be a finite number, got {}", f.key, v));
      if (f.bound.kind == Kind::positive && !(v > 0.0))
        fail(at, fmt::format("'{}' must be positive, got {}", f.key, text()));
      if (f.bound.kind == Kind::non_negative && !(v >= 0.0))
        fail(at, fmt::format("'{}' must not be negative, got {}", f.key, text()));
      if (f.kind == spec::FieldKind::quantity)
        check_range(v, at, f.key, f.quantity, f.unit, f.bound.kind == Kind::positive);
    };
    const auto check_integer = [&](std::int64_t v, const std::string& where, std::string_view name) {
      if (f.bound.kind != Kind::at_least) return;
      if (v < f.bound.minimum) fail(where, fmt::format("'{}' must be at least {}, got {}", name, f.bound.minimum, v));
      if (v > f.bound.maximum) fail(where, fmt::format("'{}' must be at most {}, got {}", name, f.bound.maximum, v));
    };
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(spec::member_of(entry, member))>;
          const T& value = spec::member_of(entry, member);
          if constexpr (std::is_same_v<T, Real>) {
            check_real(value);
          } else if constexpr (std::is_same_v<T, std::optional<Real>>) {
            if (value) check_real(*value);
          } else if constexpr (std::is_same_v<T, int>) {
            check_integer(value, at, f.key);
          } else if constexpr (std::is_same_v<T, std::optional<int>> ||
                               std::is_same_v<T, std::optional<std::int64_t>>) {
            if (value) check_integer(*value, at, f.key);
          } else if constexpr (std::is_same_v<T, std::vector<int>>) {
            for (std::size_t i = 0; i < value.size(); ++i)
              check_integer(value[i], element(at, i), fmt::format("{}[{}]", f.key, i));
          } else if constexpr (std::is_same_v<T, std::optional<SpeedCoefficient>>) {
            if (value) check_coefficient(*value, at, f.key, f.quantity, f.direct);
          } else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, std::optional<std::string>>) {
            // A word of a table is checked like its command-line flag: one of the
            // field's choices, listed in the message.
            if (f.kind == spec::FieldKind::choice && !f.choices.empty()) {
              const std::string* word = nullptr;
              if constexpr (std::is_same_v<T, std::string>) {
                if (!value.empty()) word = &value;
              } else if (value) {
                word = &*value;
              }
              if (word) check_choice(*word, at, f.key, f.choices);
            }
          }
        },
        f.member);
  }
}

}  // namespace feran::builder
