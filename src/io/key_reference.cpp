#include <feran/io/key_reference.hpp>

#include <optional>

#include <feran/analyses/list.hpp>

#include <type_traits>

#include <fmt/format.h>

#include <feran/integrators/integrator.hpp>
#include <feran/core/error.hpp>
#include <feran/core/units.hpp>
#include <feran/spec/fields.hpp>

namespace feran {

namespace {

using spec::Field;
using spec::FieldKind;

/// "length" from "a length", "angle" from "an angle".
std::string noun(Quantity q) {
  std::string name(quantity_name(q));
  if (name.starts_with("an ")) return name.substr(3);
  if (name.starts_with("a ")) return name.substr(2);
  return name;
}

std::string quoted_choices(std::span<const std::string_view> choices) {
  std::string out;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (i > 0) out += i + 1 == choices.size() ? " or " : ", ";
    out += fmt::format("`\"{}\"`", choices[i]);
  }
  return out;
}

template <class S>
std::string kind_of(const Field<S>& f) {
  switch (f.kind) {
    case FieldKind::quantity:
      if constexpr (std::is_same_v<S, ForceSpec>)
        if (f.key == "amplitude") return "force or moment";
      return noun(f.quantity);
    case FieldKind::number:
      return "number";
    case FieldKind::integer:
      return "integer";
    case FieldKind::flag:
      return "boolean";
    case FieldKind::text:
    case FieldKind::choice:
      return "string";
    case FieldKind::choice_list:
    case FieldKind::text_list:
      return "array of strings";
    case FieldKind::node:
      return f.special.empty() ? "node reference" : fmt::format("`\"{}\"` or node reference", f.special);
    case FieldKind::node_list:
      return "array of node references";
    case FieldKind::integer_list:
      return "array of integers";
    case FieldKind::coefficient:
      return noun(f.quantity) + " or law";
    case FieldKind::time_table:
      if constexpr (std::is_same_v<S, ForceSpec>) return "array of `[time, force or moment]` pairs";
      return fmt::format("array of `[time, {}]` pairs", noun(f.quantity));
  }
  return {};
}

template <class S>
std::string default_of(const Field<S>& f) {
  if (f.required) return "required";
  if (!f.default_text.empty()) return std::string(f.default_text);
  // An analysis's options: the analysis's own defaults (analyses/list.hpp).
  std::optional<std::string> analysis_default;
  Analyses::for_each([&]<class A>() {
    if constexpr (std::is_same_v<typename A::Spec, S>) {
      const std::string text = spec::value_text(A::defaults(), f);
      const bool word = f.kind == FieldKind::choice || f.kind == FieldKind::text;
      analysis_default = text.empty() ? "—" : word ? fmt::format("`\"{}\"`", text) : fmt::format("`{}`", text);
    }
  });
  if (analysis_default) return *analysis_default;
  static const S defaults{};
  return std::visit(
      [&](auto member) -> std::string {
        using T = std::remove_cvref_t<decltype(spec::member_of(defaults, member))>;
        const T& v = spec::member_of(defaults, member);
        if constexpr (std::is_same_v<T, Real>) {
          if (v == 0.0) return "`0`";
          return f.kind == FieldKind::quantity ? fmt::format("`{}`", format_quantity(v, f.quantity, f.unit))
                                               : fmt::format("`{}`", v);
        } else if constexpr (std::is_same_v<T, int>) {
          return fmt::format("`{}`", v);
        } else if constexpr (std::is_same_v<T, bool>) {
          return v ? "`true`" : "`false`";
        } else if constexpr (std::is_same_v<T, std::string>) {
          return v.empty() ? "—" : fmt::format("`\"{}\"`", v);
        } else {
          return "—";
        }
      },
      f.member);
}

/// Words a key takes that an analysis defines rather than the field table (the
/// registry of integrators), for the documentation.
std::vector<std::string> analysis_choices(std::string_view table, std::string_view key) {
  if (table == "runup" && key == "integrator") return integrator_names();
  return {};
}

template <class S>
std::string constraints_of(const Field<S>& f, std::string_view table) {
  std::vector<std::string> parts;
  const bool list = f.kind == FieldKind::integer_list;
  switch (f.bound.kind) {
    case spec::Bound::Kind::positive:
      parts.emplace_back("> 0");
      break;
    case spec::Bound::Kind::non_negative:
      parts.emplace_back("≥ 0");
      break;
    case spec::Bound::Kind::at_least:
      parts.push_back(f.bound.maximum < 1'000'000'000
                          ? fmt::format("{}{} to {}", list ? "each " : "", f.bound.minimum, f.bound.maximum)
                          : fmt::format("{}≥ {}", list ? "each " : "", f.bound.minimum));
      break;
    case spec::Bound::Kind::none:
      break;
  }
  if (!f.choices.empty()) parts.push_back(quoted_choices(f.choices));
  const std::vector<std::string> names = analysis_choices(table, f.key);
  const std::vector<std::string_view> views(names.begin(), names.end());
  if (!views.empty()) parts.push_back(quoted_choices(views));
  if (!f.doc.empty()) parts.emplace_back(f.doc);
  return fmt::format("{}", fmt::join(parts, "; "));
}

template <class S>
std::string table_of(std::string_view table, std::string_view child_key = {}, std::string_view child_doc = {}) {
  std::string out = "| key | kind | default | constraints / meaning |\n| --- | --- | --- | --- |\n";
  for (const Field<S>& f : spec::fields_of<S>())
    out += fmt::format("| `{}` | {} | {} | {} |\n", f.key, kind_of(f), default_of(f), constraints_of(f, table));
  if (!child_key.empty()) out += fmt::format("| `{}` | array of tables | required | {} |\n", child_key, child_doc);
  return out;
}

}  // namespace

std::vector<std::string> documented_tables() {
  std::vector<std::string> out;
  const ModelSpec spec;
  spec::visit_tables(spec, [&](std::string_view key, spec::TableForm, std::string_view, const auto& member) {
    out.emplace_back(key);
    using M = std::remove_cvref_t<decltype(member)>;
    if constexpr (requires { typename M::value_type; }) {
      const typename M::value_type entry{};
      spec::visit_children(entry, [&](std::string_view child, std::string_view, const auto&) {
        out.push_back(fmt::format("{}.{}", key, child));
      });
    }
  });
  return out;
}

std::string key_table_markdown(std::string_view table) {
  std::string out;
  const ModelSpec spec;
  spec::visit_tables(spec, [&](std::string_view key, spec::TableForm, std::string_view, const auto& member) {
    using M = std::remove_cvref_t<decltype(member)>;
    if constexpr (requires { typename M::value_type; }) {
      using S = typename M::value_type;
      const S entry{};
      std::string child_key, child_doc;
      spec::visit_children(entry, [&](std::string_view child, std::string_view doc, const auto& children) {
        child_key = child;
        child_doc = doc;
        using C = typename std::remove_cvref_t<decltype(children)>::value_type;
        if (table == fmt::format("{}.{}", key, child)) out = table_of<C>(table);
      });
      if (table == key) out = table_of<S>(table, child_key, child_doc);
    } else {
      if (table == key) out = table_of<M>(table);
    }
  });
  if (out.empty()) throw Error(fmt::format("no table '{}' in a model file", table));
  return out;
}

}  // namespace feran
