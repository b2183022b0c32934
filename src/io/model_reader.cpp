#include <feran/io/model_reader.hpp>
#include <feran/io/option_text.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include "toml.hpp"

#include <feran/assembly/assembler.hpp>
#include <feran/core/suggestions.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/spec/fields.hpp>
#include <feran/spec/parameters.hpp>
#include <feran/spec/request.hpp>
#include <feran/spec/spec_path.hpp>

#include "spec_table.hpp"
#include "table_reader.hpp"

namespace feran {

namespace {

using detail::QuantityValue;
using detail::TableReader;
using detail::type_name;
using spec::child;
using spec::element;
using spec::FieldKind;

/// Reads a parsed TOML document into a ModelSpec, recording in a SpecSource where
/// each path was written and how each quantity was written. It checks only what TOML
/// itself can get wrong — unknown keys, missing keys, types, units, the shape of law
/// tables and profile tables; build_model() checks the values.
class SpecReader {
 public:
  SpecReader(const toml::table& root, const std::string& path) : path_(path), top_(root, "", path) {
    source_.file = path;
    source_.places[""] = SourceLocation{path, 1, 1};
  }

  ModelSpec read();
  SpecSource take_source() { return std::move(source_); }
  /// Reads table @p t (shown as @p context) into @p out by S's field table, keys
  /// @p extra allowed besides.
  template <class S>
  void read_table(const toml::table& t, std::string_view context, S& out, std::span<const std::string_view> extra) {
    read_fields(TableReader(t, std::string(context), path_), out, "", extra);
  }

 private:
  void record(const std::string& path, const toml::node& node) {
    source_.places[path] = detail::location_of(path_, node);
  }
  void record_quantity(const std::string& path, const QuantityValue& q) {
    record(path, *q.node);
    source_.written[path] = q.written;
  }

  /// Reads the keys of @p t into @p out by the field table of S; @p path is the
  /// table's path.
  template <class S>
  void read_fields(const TableReader& t, S& out, const std::string& path, std::span<const std::string_view> extra = {});
  template <class S>
  void read_field(const TableReader& t, const spec::Field<S>& f, const toml::node& n, S& out, const std::string& at);
  template <class S>
  void read_children(const TableReader& t, S& out, const std::string& path);

  NodeRef read_node(const TableReader& t, const toml::node& n, std::string_view name, std::string_view special) const;
  SpeedCoefficient read_coefficient(const TableReader& parent, const toml::node& n, const std::string& key,
                                    Quantity kind, const std::string& at);
  /// A speed (or, with @p unit_key "frequency_unit", a frequency of the motion) of a
  /// coefficient law, in rad/s.
  Real read_speed(const TableReader& t, const toml::node& n, const std::string& name, const std::string& speed_unit,
                  const std::string& at, std::string_view unit_key = "speed_unit");
  std::vector<std::pair<Real, Real>> read_time_table(const TableReader& t, const toml::node& n, std::string_view key,
                                                     Quantity kind, const std::string& at);
  std::vector<std::string> read_words(const TableReader& t, const spec::FieldKind kind, const toml::node& n,
                                      std::string_view key, std::span<const std::string_view> choices,
                                      const std::string& at);

  const std::string& path_;
  TableReader top_;
  SpecSource source_;
};

/// "…" quoted choices joined: "\"a\", \"b\" or \"c\"", or "one of …" for long lists.
std::string choices_phrase(std::span<const std::string_view> choices) {
  const std::vector<std::string> names(choices.begin(), choices.end());
  const std::string list = detail::join_list(names, "or", '"');
  return names.size() <= 3 ? list : "one of " + list;
}

ModelSpec SpecReader::read() {
  ModelSpec spec;
  std::vector<std::string_view> keys = {"title"};
  spec::visit_tables(spec, [&](std::string_view key, auto, std::string_view, auto&) { keys.push_back(key); });
  top_.check_keys(keys);
  if (const auto title = top_.string("title")) spec.title = *title;

  spec::visit_tables(spec, [&](std::string_view key, spec::TableForm form, std::string_view, auto& member) {
    const toml::node* n = top_.find(key);
    if (n == nullptr) return;
    const std::string path(key);
    using M = std::remove_cvref_t<decltype(member)>;
    if constexpr (requires { typename M::value_type; }) {
      const toml::array* array = n->as_array();
      if (array == nullptr || form != spec::TableForm::array_of_tables)
        top_.fail(*n, fmt::format("'{}' must be an array of tables, written [[{}]], got {}", key, key, type_name(*n)));
      const std::string context = fmt::format("[[{}]]", key);
      for (const toml::node& entry : *array) {
        const toml::table* table = entry.as_table();
        if (table == nullptr)
          top_.fail(entry, fmt::format("each entry of '{}' must be a table, got {}", key, type_name(entry)));
        const std::string at = element(path, member.size());
        member.emplace_back();
        read_fields(TableReader(*table, context, path_), member.back(), at);
      }
    } else {
      const toml::table* table = n->as_table();
      if (table == nullptr)
        top_.fail(*n, fmt::format("'{}' must be a table, written [{}], got {}", key, key, type_name(*n)));
      read_fields(TableReader(*table, fmt::format("[{}]", key), path_), member, path);
    }
  });
  return spec;
}

template <class S>
void SpecReader::read_fields(const TableReader& t, S& out, const std::string& path,
                             std::span<const std::string_view> extra) {
  std::vector<std::string_view> keys(extra.begin(), extra.end());
  for (const spec::Field<S>& f : spec::fields_of<S>()) keys.push_back(f.key);
  spec::visit_children(out, [&](std::string_view key, std::string_view, auto&) { keys.push_back(key); });
  t.check_keys(keys);
  record(path, t.table());
  for (const spec::Field<S>& f : spec::fields_of<S>()) {
    const toml::node* n = t.find(f.key);
    if (n == nullptr) {
      if (f.required) {
        const std::string expected = f.kind == FieldKind::quantity ? expected_quantity(f.quantity)
                                     : f.kind == FieldKind::node   ? std::string("a node number or a node name")
                                     : f.kind == FieldKind::node_list
                                         ? std::string("an array of at least two node numbers or names")
                                         : fmt::format("{}, a string such as \"steel\"", f.doc);
        t.require(f.key, expected);
      }
      continue;
    }
    const std::string at = child(path, f.key);
    record(at, *n);
    read_field(t, f, *n, out, at);
  }
  read_children(t, out, path);
}

template <class S>
void SpecReader::read_field(const TableReader& t, const spec::Field<S>& f, const toml::node& n, S& out,
                            const std::string& at) {
  std::visit(
      [&](auto member) {
        using T = std::remove_cvref_t<decltype(spec::member_of(out, member))>;
        T& value = spec::member_of(out, member);
        if constexpr (std::is_same_v<T, Real> || std::is_same_v<T, std::optional<Real>>) {
          if (f.kind == FieldKind::quantity) {
            const QuantityValue q = t.quantity_at(n, f.key, spec::value_quantity(out, f));
            record_quantity(at, q);
            value = q.si;
          } else {
            value = *t.number(f.key);
          }
        } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>) {
          value = t.integer_at(n, f.key, std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
        } else if constexpr (std::is_same_v<T, std::optional<std::int64_t>>) {
          const auto i = n.value_exact<std::int64_t>();
          if (!i) t.fail(n, fmt::format("'{}' must be an integer, got {}", f.key, type_name(n)));
          value = *i;
        } else if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, std::optional<bool>>) {
          value = *t.boolean(f.key);
        } else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, std::optional<std::string>>) {
          value = *t.string(f.key);
        } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
          value = read_words(t, f.kind, n, f.key, f.choices, at);
          if (value.empty() && !f.if_empty.empty())
            t.fail(n, fmt::format("'{}' must not be empty ({})", f.key, f.if_empty));
        } else if constexpr (std::is_same_v<T, NodeRef>) {
          value = read_node(t, n, f.key, f.special);
        } else if constexpr (std::is_same_v<T, std::optional<NodeRef>>) {
          if (const auto text = n.value_exact<std::string>(); text && *text == f.special) return;
          value = read_node(t, n, f.key, f.special);
        } else if constexpr (std::is_same_v<T, std::vector<NodeRef>> || std::is_same_v<T, std::vector<int>>) {
          const toml::array& entries = *t.array(f.key);
          if (entries.empty() && !f.if_empty.empty())
            t.fail(entries, fmt::format("'{}' must not be empty ({})", f.key, f.if_empty));
          for (std::size_t i = 0; i < entries.size(); ++i) {
            const toml::node& entry = *entries.get(i);
            const std::string name = fmt::format("{}[{}]", f.key, i);
            record(element(at, i), entry);
            if constexpr (std::is_same_v<T, std::vector<int>>)
              value.push_back(
                  t.integer_at(entry, name, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
            else
              value.push_back(read_node(t, entry, name, {}));
          }
        } else if constexpr (std::is_same_v<T, std::optional<SpeedCoefficient>>) {
          value = read_coefficient(t, n, std::string(f.key), f.quantity, at);
        } else if constexpr (std::is_same_v<T, std::vector<std::pair<Real, Real>>>) {
          value = read_time_table(t, n, f.key, spec::value_quantity(out, f), at);
        }
      },
      f.member);
}

template <class S>
void SpecReader::read_children(const TableReader& t, S& out, const std::string& path) {
  spec::visit_children(out, [&](std::string_view key, std::string_view, auto& children) {
    const toml::node& n = t.require(key, "at least one section, written [[shafts.sections]]");
    record(child(path, key), n);
    const toml::array* array = n.as_array();
    if (array == nullptr)
      t.fail(n, fmt::format("'{}' must be an array of tables, written [[shafts.{}]], got {}", key, key, type_name(n)));
    for (const toml::node& entry : *array) {
      const toml::table* table = entry.as_table();
      if (table == nullptr)
        t.fail(entry, fmt::format("each entry of '{}' must be a table, got {}", key, type_name(entry)));
      const std::string at = element(child(path, key), children.size());
      children.emplace_back();
      read_fields(TableReader(*table, fmt::format("[[shafts.{}]]", key), path_), children.back(), at);
    }
  });
}

NodeRef SpecReader::read_node(const TableReader& t, const toml::node& n, std::string_view name,
                              std::string_view special) const {
  if (const auto number = n.value_exact<std::int64_t>()) return *number;
  if (const auto text = n.value_exact<std::string>()) return *text;
  if (!special.empty())
    t.fail(n, fmt::format("'{}' must be \"{}\", a node number (an integer) or a node name (a "
                          "string), got {}",
                          name, special, type_name(n)));
  t.fail(n,
         fmt::format("'{}' must be a node number (an integer) or a node name (a string), got {}", name, type_name(n)));
}

std::vector<std::string> SpecReader::read_words(const TableReader& t, FieldKind kind, const toml::node& n,
                                                std::string_view key, std::span<const std::string_view> choices,
                                                const std::string& at) {
  const toml::array& entries = *t.array(key);
  std::vector<std::string> words;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::node& entry = *entries.get(i);
    record(element(at, i), entry);
    const auto s = entry.value_exact<std::string>();
    if (!s) {
      if (kind == FieldKind::choice_list)
        t.fail(entry,
               fmt::format("entries of '{}' must be {}, got {}", key, choices_phrase(choices), type_name(entry)));
      t.fail(entry, fmt::format("'{}[{}]' must be the name of a spring (a string, the 'name' of a "
                                "[[springs]] entry), got {}",
                                key, i, type_name(entry)));
    }
    words.push_back(*s);
  }
  (void)n;
  return words;
}

Real SpecReader::read_speed(const TableReader& t, const toml::node& n, const std::string& name,
                            const std::string& speed_unit, const std::string& at, std::string_view unit_key) {
  QuantityValue q = t.quantity_at(n, name, Quantity::speed);
  const bool bare = n.is_integer() || n.is_floating_point();
  // A bare number would be rad/s, which a table of speeds rarely means: ask for the
  // unit (0 is 0 in every unit).
  if (bare && speed_unit.empty() && q.si != 0.0)
    t.fail(n,
           fmt::format("'{}' is a bare number ({}): a {} of a coefficient law needs its unit, "
                       "e.g. \"50 Hz\", \"3000 rpm\" or \"314 rad/s\", or the law's {} "
                       "({} = \"Hz\")",
                       name, *n.value<double>(), unit_key == "speed_unit" ? "speed" : "frequency", unit_key, unit_key));
  if (!speed_unit.empty() && bare) {
    q.si = *to_si(Quantity::speed, q.si, speed_unit);
    q.written = fmt::format("{} {}", *n.value<double>(), speed_unit);
  }
  record_quantity(at, q);
  return q.si;
}

SpeedCoefficient SpecReader::read_coefficient(const TableReader& parent, const toml::node& n, const std::string& key,
                                              Quantity kind, const std::string& at) {
  const toml::table* table = n.as_table();
  if (table == nullptr) {
    if (n.is_array() || n.is_boolean() || n.is_date() || n.is_time() || n.is_date_time())
      parent.fail(
          n, fmt::format("{}, or an inline table with a 'law', got {}", must_be_quantity(key, kind), type_name(n)));
    const QuantityValue q = parent.quantity_at(n, key, kind);
    record_quantity(at, q);
    return SpeedCoefficient(q.si);
  }

  const TableReader t(*table, fmt::format("coefficient '{}'", key), path_);
  const auto& laws = spec::coefficient_laws();
  std::vector<std::string> law_names;
  for (const auto& l : laws) law_names.emplace_back(l.law);
  const std::string law = t.required_string("law", "\"table\", \"step\", \"arctan\" or \"frequency_table\"");
  const auto it = std::find_if(laws.begin(), laws.end(), [&](const spec::CoefficientLaw& l) { return l.law == law; });
  if (it == laws.end()) {
    std::string message = fmt::format(
        "unknown law '{}' for coefficient '{}'; expected \"table\", \"step\", \"arctan\" or "
        "\"frequency_table\"",
        law, key);
    if (const auto m = detail::closest_match(law, law_names, 2)) message += fmt::format(" (did you mean \"{}\"?)", *m);
    t.fail(*t.find("law"), message);
  }
  t.check_keys(it->keys);

  const auto speed_unit = [&](std::string_view unit_key = "speed_unit") -> std::string {
    const auto unit = t.string(unit_key);
    if (!unit) return {};
    if (!to_si(Quantity::speed, 1.0, *unit))
      t.fail(*t.find(unit_key), fmt::format("'{}' must be \"rad/s\", \"Hz\" or \"rpm\", got \"{}\"", unit_key, *unit));
    return *unit;
  };
  const auto required = [&](std::string_view name, Quantity q) {
    const QuantityValue v = t.required_quantity(name, q);
    record_quantity(child(at, name), v);
    return v.si;
  };
  const auto optional_number = [&](std::string_view name, Real fallback) {
    if (const toml::node* c = t.find(name)) record(child(at, name), *c);
    return t.number(name).value_or(fallback);
  };
  record(child(at, "law"), *t.find("law"));

  if (law == "table") {
    const std::string unit = speed_unit();
    const toml::array& speeds = t.required_array("speeds", "an array of speeds, e.g. [0, \"50 Hz\", \"100 Hz\"]");
    const toml::array& values =
        t.required_array("values", fmt::format("an array of values, each {}", quantity_name(kind)));
    record(child(at, "speeds"), speeds);
    record(child(at, "values"), values);
    SpeedCoefficient::Table law_table;
    for (std::size_t i = 0; i < speeds.size(); ++i)
      law_table.speeds.push_back(
          read_speed(t, *speeds.get(i), fmt::format("{}.speeds[{}]", key, i), unit, element(child(at, "speeds"), i)));
    for (std::size_t i = 0; i < values.size(); ++i) {
      const QuantityValue v = t.quantity_at(*values.get(i), fmt::format("{}.values[{}]", key, i), kind);
      record_quantity(element(child(at, "values"), i), v);
      law_table.values.push_back(v.si);
    }
    return SpeedCoefficient(SpeedCoefficient::Law{law_table});
  }
  if (law == "frequency_table") {
    // Frequencies along each row; one row without speeds, else one row per speed.
    const std::string s_unit = speed_unit(), f_unit = speed_unit("frequency_unit");
    const toml::array& frequencies =
        t.required_array("frequencies", "an array of frequencies of the motion, e.g. [0, \"50 Hz\", \"100 Hz\"]");
    record(child(at, "frequencies"), frequencies);
    SpeedCoefficient::FrequencyTable law_table;
    for (std::size_t i = 0; i < frequencies.size(); ++i)
      law_table.frequencies.push_back(read_speed(t, *frequencies.get(i), fmt::format("{}.frequencies[{}]", key, i),
                                                 f_unit, element(child(at, "frequencies"), i), "frequency_unit"));
    const toml::node* speeds_node = t.find("speeds");
    if (speeds_node != nullptr) {
      const toml::array& speeds = t.required_array("speeds", "an array of speeds, e.g. [0, \"50 Hz\", \"100 Hz\"]");
      record(child(at, "speeds"), speeds);
      for (std::size_t i = 0; i < speeds.size(); ++i)
        law_table.speeds.push_back(read_speed(t, *speeds.get(i), fmt::format("{}.speeds[{}]", key, i), s_unit,
                                              element(child(at, "speeds"), i)));
    }
    const std::string one_value = fmt::format("each {}", quantity_name(kind));
    const toml::array& values = t.required_array(
        "values", speeds_node != nullptr
                      ? fmt::format("an array with one array per speed of one value per frequency, {}", one_value)
                      : fmt::format("an array of one value per frequency, {}", one_value));
    record(child(at, "values"), values);
    const auto read_row = [&](const toml::array& row, const std::string& row_at, const std::string& row_name) {
      if (row.size() != law_table.frequencies.size())
        t.fail(row, fmt::format("'{}' must hold one value per frequency: {} frequencies, got {} values", row_name,
                                law_table.frequencies.size(), row.size()));
      for (std::size_t j = 0; j < row.size(); ++j) {
        const QuantityValue v = t.quantity_at(*row.get(j), fmt::format("{}[{}]", row_name, j), kind);
        record_quantity(element(row_at, j), v);
        law_table.values.push_back(v.si);
      }
    };
    if (speeds_node == nullptr) {
      read_row(values, child(at, "values"), fmt::format("{}.values", key));
    } else {
      if (values.size() != law_table.speeds.size())
        t.fail(values, fmt::format("'{}.values' must hold one array per speed: {} speeds, got {} entries", key,
                                   law_table.speeds.size(), values.size()));
      for (std::size_t i = 0; i < values.size(); ++i) {
        const toml::array* row = values.get(i)->as_array();
        const std::string row_name = fmt::format("{}.values[{}]", key, i);
        if (row == nullptr)
          t.fail(*values.get(i), fmt::format("'{}' must be an array of one value per frequency (the values at "
                                             "speed {}), got {}",
                                             row_name, i, type_name(*values.get(i))));
        read_row(*row, element(child(at, "values"), i), row_name);
      }
    }
    return SpeedCoefficient(SpeedCoefficient::Law{law_table});
  }
  if (law == "step") {
    const std::string unit = speed_unit();
    SpeedCoefficient::Step step;
    step.below = required("below", kind);
    step.above = required("above", kind);
    step.at = read_speed(t, t.require("at", expected_quantity(Quantity::speed)), "at", unit, child(at, "at"));
    return SpeedCoefficient(SpeedCoefficient::Law{step});
  }
  SpeedCoefficient::Arctan a;
  a.value = required("value", kind);
  a.f_as = required("f_as", Quantity::frequency);
  a.c0 = optional_number("c0", a.c0);
  a.c1 = optional_number("c1", a.c1);
  a.c2 = optional_number("c2", a.c2);
  return SpeedCoefficient(SpeedCoefficient::Law{a});
}

std::vector<std::pair<Real, Real>> SpecReader::read_time_table(const TableReader& t, const toml::node& n,
                                                               std::string_view key, Quantity kind,
                                                               const std::string& at) {
  const std::string_view noun = quantity_noun(kind);
  const std::string example = kind == Quantity::speed ? R"(["2 s", "50 Hz"])" : R"(["2 ms", "500 N"])";
  const toml::array* table = n.as_array();
  if (table == nullptr) t.fail(n, fmt::format("'{}' must be an array, got {}", key, type_name(n)));
  if (table->empty())
    t.fail(*table, fmt::format("'{}' needs at least one [time, {}] pair, e.g. [{}]", key, noun,
                               kind == Quantity::speed ? R"(["0 s", "0 Hz"], ["5 s", "80 Hz"])"
                                                       : R"(["0 s", "0 N"], ["2 ms", "500 N"], ["4 ms", "0 N"])"));
  std::vector<std::pair<Real, Real>> points;
  for (std::size_t i = 0; i < table->size(); ++i) {
    const toml::node& entry = *table->get(i);
    const toml::array* pair = entry.as_array();
    if (pair == nullptr || pair->size() != 2)
      t.fail(entry,
             fmt::format("each entry of '{}' must be a [time, {}] pair such as {}, got {}", key, noun, example,
                         pair != nullptr ? fmt::format("an array of {} values", pair->size()) : type_name(entry)));
    record(element(at, i), entry);
    const QuantityValue time = t.quantity_at(*pair->get(0), fmt::format("{}[{}][0]", key, i), Quantity::time);
    const QuantityValue value = t.quantity_at(*pair->get(1), fmt::format("{}[{}][1]", key, i), kind);
    record_quantity(element(element(at, i), 0), time);
    record_quantity(element(element(at, i), 1), value);
    points.emplace_back(time.si, value.si);
  }
  return points;
}

// Keys of more parts than this (dotted keys, table headers) are refused before the
// TOML parser sees them: toml++ descends once per part, and tens of thousands of
// parts on one line overflow its stack. A model file's deepest key has four.
constexpr int max_key_parts = 64;

// How a character outside strings and comments that is not ASCII looks in a message:
// the character itself when it is valid UTF-8, else its bytes as \xNN.
std::string shown_character(std::string_view text, std::size_t at) {
  const auto lead = static_cast<unsigned char>(text[at]);
  const std::size_t length = lead >= 0xf0 ? 4 : lead >= 0xe0 ? 3 : lead >= 0xc2 ? 2 : 1;
  bool valid = length > 1 && lead < 0xf5 && at + length <= text.size();
  for (std::size_t k = 1; valid && k < length; ++k) valid = (static_cast<unsigned char>(text[at + k]) & 0xc0) == 0x80;
  if (valid) return fmt::format("'{}'", text.substr(at, length));
  return fmt::format("the byte \\x{:02x}", lead);
}

// A light scan of the text before the TOML parser sees it, for what toml++ 3.3.0
// does not survive; each is refused as a ModelError at its line and column:
// - a key (of a key–value pair, a table header or an inline table) of more than
//   max_key_parts parts: the dots between two separators (= , { } [ ] and line ends)
//   outside strings — a dotted key has one per part, a number at most one;
// - a character that is not ASCII outside a string or a comment (TOML allows none
//   there). toml++ 3.3.0 asks is_non_ascii_horizontal_whitespace() about it, which
//   reaches __builtin_unreachable() for U+00A1 to U+0499 (Latin-1, Greek, Cyrillic:
//   `length = 5 µm`; found by fuzzing with the two bytes C2 B7, U+00B7): undefined
//   behaviour in the parser (unicode_autogenerated.h, the switch on child_index_0
//   lacks case 0x00);
// - a table header whose name does not start with a bare-key character or a quote:
//   toml++ 3.3.0 calls parse_key() without checking, which assumes one
//   (TOML_ASSERT_ASSUME, undefined behaviour without assertions; found by fuzzing
//   with the two bytes "[@");
// - '}' where an array expects a value (after its '[' or a comma: `a = [1, }`):
//   toml++ 3.3.0 calls parse_value() there, which assumes no value terminator
//   follows (TOML_ASSERT_ASSUME: undefined behaviour where the compiler takes the
//   assumption, as clang does; found by fuzzing).
// The contents of strings (basic, literal, multi-line) and comments are skipped. A
// quote opens a string only where TOML lets one begin (at a line's start, after white
// space, '=', '[', '{' or ',', or after a key's '.'): in `1"µ"` toml++ reads the
// number on through the quote, and meets the 'µ' outside any string (found by
// fuzzing).
void check_before_parsing(std::string_view text, const std::string& path) {
  int line = 1;
  std::size_t line_start = 0;
  const auto fail = [&](std::size_t at, const std::string& message) {
    throw ModelError(SourceLocation{path, line, static_cast<int>(at - line_start + 1)}, message);
  };
  const auto bare_key_character = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  };
  int parts = 1;
  std::vector<char> open;    // arrays ('[') and inline tables ('{') open in a value (they span lines)
  bool in_value = false;     // after the '=' of this line's key–value pair
  bool line_begins = true;   // nothing but spaces and tabs yet on this line
  bool key_position = true;  // where a key, not a value, comes (a '.' there separates a dotted key's parts)
  std::size_t awaiting =
      std::string_view::npos;  // where the innermost open array's '[' or last comma was, while it awaits a value
  int awaiting_line = 0;
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n; ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = i + 1;
      parts = 1;
      in_value = !open.empty();
      line_begins = true;
      key_position = open.empty();
      continue;
    }
    if (line_begins && c != ' ' && c != '\t') {
      line_begins = false;
      if (c == '[' && open.empty()) {
        std::size_t k = i + 1;
        if (k < n && text[k] == '[') ++k;
        while (k < n && (text[k] == ' ' || text[k] == '\t')) ++k;
        if (k < n && !bare_key_character(text[k]) && text[k] != '"' && text[k] != '\'' && text[k] != ']')
          fail(k, fmt::format("a table header must name its table: after '[' comes a key (letters, digits, '_' "
                              "or '-', or a quoted string), not {}",
                              static_cast<unsigned char>(text[k]) < 0x80 ? fmt::format("'{}'", text[k])
                                                                         : shown_character(text, k)));
      }
    }
    if (c != ' ' && c != '\t' && c != '\r' && c != '#' && awaiting != std::string_view::npos) {
      if (c == '}')
        fail(i,
             fmt::format("'}}' where the array opened or continued at line {} expects a value or ']'", awaiting_line));
      awaiting = std::string_view::npos;
    }
    const char before = i > line_start ? text[i - 1] : '\n';
    const bool string_may_begin = before == '\n' || before == ' ' || before == '\t' || before == '=' || before == '[' ||
                                  before == '{' || before == ',' || (before == '.' && key_position);
    if ((c == '"' || c == '\'') && string_may_begin) {
      // A string: skip to its end (a multi-line one may span lines).
      const bool multi = text.substr(i, 3) == std::string_view(c == '"' ? "\"\"\"" : "\'\'\'");
      const std::string_view close = multi ? text.substr(i, 3) : text.substr(i, 1);
      std::size_t k = i + close.size();
      while (k < n) {
        if (c == '"' && text[k] == '\\') {
          k += 2;
          continue;
        }
        if (text.substr(k, close.size()) == close) break;
        if (text[k] == '\n') {
          if (!multi) break;  // an unterminated string: the parser says so
          ++line;
          line_start = k + 1;
        }
        ++k;
      }
      // A multi-line string may end in up to two more quotes of its own.
      if (multi) {
        k += 3;
        for (int extra = 0; extra < 2 && k < n && text[k] == c; ++extra) ++k;
        i = k - 1;
      } else {
        i = k < n && text[k] == c ? k : k - 1;
      }
      continue;
    }
    if (c == '#') {
      while (i + 1 < n && text[i + 1] != '\n') ++i;
      continue;
    }
    if (static_cast<unsigned char>(c) >= 0x80)
      fail(i, fmt::format("{} outside a quoted string or a comment: TOML allows only ASCII there (a value "
                          "with a unit is a string, e.g. length = \"5 mm\")",
                          shown_character(text, i)));
    if (c == '.') {
      if (++parts > max_key_parts)
        fail(i, fmt::format("nesting too deep: a key of more than {} parts (dotted keys or a table header); a "
                            "model file's keys have at most four",
                            max_key_parts));
    } else if (c == '=' || c == ',' || c == '{' || c == '}' || c == '[' || c == ']') {
      parts = 1;
      if (c == '=' && open.empty()) in_value = true;
      if ((c == '[' || c == '{') && (in_value || !open.empty()))
        open.push_back(c);
      else if ((c == ']' || c == '}') && !open.empty())
        open.pop_back();
      key_position = (c == '{' || c == ',') && !open.empty() && open.back() == '{';
      if (open.empty() && !in_value) key_position = true;  // a table header's name
      if ((c == '[' || c == ',') && !open.empty() && open.back() == '[') {
        awaiting = i;
        awaiting_line = line;
      }
    }
  }
}

}  // namespace

namespace detail {

template <class S>
S read_spec_table(const toml::table& table, std::string_view context, const std::string& file,
                  std::span<const std::string_view> extra) {
  SpecReader reader(table, file);
  S out;
  reader.read_table(table, context, out, extra);
  for (const spec::Field<S>& f : spec::fields_of<S>()) {
    const toml::node* n = table.get(f.key);
    if (n == nullptr) continue;
    try {
      spec::check_field(out, f, fmt::format("{} '{}'", context, f.key));
    } catch (const Error& e) {
      throw ModelError(location_of(file, *n), e.what());
    }
  }
  return out;
}

template CampbellSpec read_spec_table<CampbellSpec>(const toml::table&, std::string_view, const std::string&,
                                                    std::span<const std::string_view>);
template ResponseSpec read_spec_table<ResponseSpec>(const toml::table&, std::string_view, const std::string&,
                                                    std::span<const std::string_view>);
template Api684Spec read_spec_table<Api684Spec>(const toml::table&, std::string_view, const std::string&,
                                                std::span<const std::string_view>);
template OrbitsSpec read_spec_table<OrbitsSpec>(const toml::table&, std::string_view, const std::string&,
                                                std::span<const std::string_view>);

}  // namespace detail

ModelSpec read_model_spec(std::string_view toml_text, const std::string& path_for_messages, SpecSource* source) {
  check_before_parsing(detail::utf8_text(toml_text, path_for_messages), path_for_messages);
  const toml::table root = detail::parse_toml(toml_text, path_for_messages);
  SpecReader reader(root, path_for_messages);
  ModelSpec spec = reader.read();
  if (source != nullptr) *source = reader.take_source();
  return spec;
}

namespace {

/// True when @p a names @p b or a part of it, or the other way round.
bool overlaps(std::string_view a, std::string_view b) {
  if (a.size() > b.size()) std::swap(a, b);
  return b.starts_with(a) && (a.size() == b.size() || b[a.size()] == '.' || b[a.size()] == '[');
}

/// Builds file.spec into file.model; @p set are the assignments applied to the spec
/// and the canonical paths they set.
void build(ModelFile& file, const std::vector<std::pair<std::string, std::string>>& set) {
  try {
    BuildInfo info;
    file.model = build_model(file.spec, &file.source, &info);
    // The response's forces are text the model's nodes give meaning to.
    for (std::size_t i = 0; i < file.spec.response.forces.size(); ++i) {
      try {
        (void)parse_force_text(file.model, file.spec.response.forces[i], "force");
      } catch (const Error& e) {
        throw SpecError(fmt::format("response.forces[{}]", i), e.what());
      }
    }
    file.assembler = std::move(info.assembler);
    for (const std::string& path : info.node_paths) file.node_locations.push_back(file.source.locate(path));
  } catch (const SpecError& e) {
    // The latest assignment to the path is the value the spec holds.
    for (auto it = set.rbegin(); it != set.rend(); ++it)
      if (overlaps(it->second, e.path())) throw Error(fmt::format("{}: {}", it->first, e.message()));
    throw file.source.locate(e);
  }
}

}  // namespace

ModelFile read_model_string(std::string_view toml_text, const std::string& path_for_messages) {
  ModelFile file;
  file.path = path_for_messages;
  file.spec = read_model_spec(toml_text, path_for_messages, &file.source);
  file.title = file.spec.title;
  build(file, {});
  return file;
}

std::string read_text_file(const std::string& path) {
  // Only a regular file of bounded size: a FIFO without a writer would block, a
  // device such as /dev/zero never ends.
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec) throw Error(fmt::format("cannot open model file '{}': {}", path, ec.message()));
  if (fs::is_directory(status)) throw Error(fmt::format("'{}' is a directory, not a model file", path));
  if (!fs::is_regular_file(status))
    throw Error(fmt::format("'{}' is not a regular file ({}); a model is read from a regular file", path,
                            fs::is_fifo(status)             ? "a FIFO"
                            : fs::is_character_file(status) ? "a character device"
                            : fs::is_block_file(status)     ? "a block device"
                            : fs::is_socket(status)         ? "a socket"
                                                            : "a special file"));
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > max_model_file_bytes)
    throw Error(fmt::format("model file '{}' is {} bytes; model files are limited to {} bytes ({} MiB)", path, size,
                            max_model_file_bytes, max_model_file_bytes >> 20));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot open model file '{}'", path));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(fmt::format("cannot read model file '{}'", path));
  return text.str();
}

ModelFile read_model_file(const std::string& path) { return read_model_string(read_text_file(path), path); }

ModelFile read_model_file(const std::string& path, const std::vector<std::string>& assignments) {
  SpecSource source;
  ModelSpec spec = read_model_spec(read_text_file(path), path, &source);
  std::vector<std::pair<std::string, std::string>> set;
  for (const std::string& assignment : assignments)
    set.emplace_back(fmt::format("--set '{}'", assignment), apply_assignment(spec, assignment));
  return build_model_file(std::move(spec), std::move(source), path, set);
}

ModelFile build_model_file(ModelSpec spec, SpecSource source, std::string path,
                           const std::vector<std::pair<std::string, std::string>>& changed) {
  ModelFile file;
  file.path = std::move(path);
  file.spec = std::move(spec);
  file.source = std::move(source);
  // The file's text of a value set since is no longer what the spec holds.
  for (const auto& change : changed) {
    const std::string& canonical = change.second;
    std::erase_if(file.source.written, [&](const auto& w) { return overlaps(canonical, w.first); });
  }
  file.title = file.spec.title;
  build(file, changed);
  return file;
}

}  // namespace feran
