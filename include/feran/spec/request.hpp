#pragma once
/// @file
/// An analysis's request as one generic step over its field table.
///
/// An analysis's options are the keys of its model-file table ([static], [runup], …),
/// declared once in that table's field table (fields.hpp). A caller — the command line,
/// the Python module, a C++ program — fills a spec of the same type with what it asks
/// for, each value set and checked here by the rule its field declares; overlay() lays
/// the request over the file's table and that over the analysis's built-in defaults
/// (a spec of the same type), so that every option is taken in one place:
///
///     resolved = overlay(overlay(request, file.spec.static_), static_defaults())
///
/// Fields that belong together are taken together: setting a field of a group (a
/// run-up's speed profile) takes every field of that group from the request alone, and
/// a field that follows a group (the magnitude g follows the direction of gravity) is
/// taken from the request alone when the request sets a field of that group. Where a
/// table holds alternatives (Field::alternative: a response's speed sweep or its fixed
/// speed), a request that sets an option of one takes none of the others from below.

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <feran/spec/fields.hpp>

namespace feran::spec {

/// True when @p s gives field @p f a value: an optional holding one, a list that is
/// not empty. A plain member (not optional) always has one.
template <class S>
bool has_value(const S& s, const Field<S>& f) {
  return std::visit(
      [&](auto member) {
        using T = std::remove_cvref_t<decltype(member_of(s, member))>;
        if constexpr (requires(const T& t) { t.has_value(); })
          return (member_of(s, member)).has_value();
        else if constexpr (requires(const T& t) { t.empty(); } && !std::is_same_v<T, std::string>)
          return !(member_of(s, member)).empty();
        else
          return true;
      },
      f.member);
}

/// True when @p s sets a field of group @p group.
template <class S>
bool sets_group(const S& s, std::string_view group) {
  for (const Field<S>& f : fields_of<S>())
    if (f.group == group && has_value(s, f)) return true;
  return false;
}

/// True when @p s sets a field of an alternative other than @p alternative.
template <class S>
bool sets_other_alternative(const S& s, std::string_view alternative) {
  for (const Field<S>& f : fields_of<S>())
    if (!f.alternative.empty() && f.alternative != alternative && has_value(s, f)) return true;
  return false;
}

/// @p top laid over @p bottom, field by field: a field @p top gives a value wins; any
/// other is @p bottom's, except that a field of a group (Field::group) or one that
/// follows it (Field::follows) is @p top's whenever @p top sets a field of that group,
/// and a field of an alternative (Field::alternative) is @p top's whenever @p top sets a
/// field of another alternative.
template <class S>
S overlay(const S& top, const S& bottom) {
  S out = bottom;
  for (const Field<S>& f : fields_of<S>()) {
    const std::string_view group = !f.group.empty() ? f.group : f.follows;
    const bool from_top = has_value(top, f) || (!group.empty() && sets_group(top, group)) ||
                          (!f.alternative.empty() && sets_other_alternative(top, f.alternative));
    if (from_top) std::visit([&](auto member) { member_of(out, member) = member_of(top, member); }, f.member);
  }
  return out;
}

/// The field of S named @p key, or nullptr.
template <class S>
const Field<S>* find_field(std::string_view key) {
  for (const Field<S>& f : fields_of<S>())
    if (f.key == key) return &f;
  return nullptr;
}

/// The name the doors give field @p f: its option name (Field::option), else its key.
template <class S>
std::string_view option_name(const Field<S>& f) {
  return f.option.empty() ? f.key : f.option;
}

/// The name the doors give the field of S keyed @p key (the key when S has none).
template <class S>
std::string_view option_name(std::string_view key) {
  const Field<S>* f = find_field<S>(key);
  return f != nullptr ? option_name(*f) : key;
}

/// The field of S the doors name @p name (option_name()), or nullptr.
template <class S>
const Field<S>* find_option(std::string_view name) {
  for (const Field<S>& f : fields_of<S>())
    if (option_name(f) == name) return &f;
  return nullptr;
}

namespace detail {
/// A number written as text ("2.5", "1e-3"); throws Error naming @p option otherwise.
Real number_text(std::string_view text, std::string_view option);
/// An integer written as text; throws Error naming @p option otherwise.
std::int64_t integer_text(std::string_view text, std::string_view option);
/// A quantity of kind @p kind written as text: a speed needs its unit ("30Hz",
/// "1800rpm"), any other may be a bare number in its SI unit. Throws Error naming
/// @p option.
Real quantity_text(std::string_view text, Quantity kind, std::string_view option);
/// Time and value points "TIME:VALUE,TIME:VALUE,…" ("0s:0Hz,2s:50Hz"), the values of
/// kind @p kind; throws Error naming @p option.
std::vector<std::pair<Real, Real>> time_table_text(std::string_view text, Quantity kind, std::string_view option);
/// true or false as written ("true", "false").
bool flag_text(std::string_view text, std::string_view option);
/// Checks a number asked for against bound @p bound and, for a quantity (@p kind not
/// empty), its physical range; the message names @p option and shows the value in
/// @p unit ("--speed: must not be negative, got -1 Hz").
void check_number(Real v, const Bound& bound, std::optional<Quantity> kind, std::string_view unit,
                  std::string_view option);
void check_integer(std::int64_t v, const Bound& bound, std::string_view option);
/// @p word is one of @p choices; else Error "OPTION must be a, b or c, got 'w'".
void check_choice(std::string_view word, std::span<const std::string_view> choices, std::string_view option);
}  // namespace detail

/// Checks the value of field @p f of @p s, as a caller set it, by the rule the field
/// declares (bounds, physical range, choices); throws Error naming @p option.
template <class S>
void check_field(const S& s, const Field<S>& f, std::string_view option) {
  const std::optional<Quantity> kind =
      f.kind == FieldKind::quantity ? std::optional<Quantity>(f.quantity) : std::nullopt;
  std::visit(
      [&](auto member) {
        using T = std::remove_cvref_t<decltype(member_of(s, member))>;
        const T& v = member_of(s, member);
        if constexpr (std::is_same_v<T, std::optional<Real>>) {
          if (v) detail::check_number(*v, f.bound, kind, f.unit, option);
        } else if constexpr (std::is_same_v<T, std::optional<int>> || std::is_same_v<T, std::optional<std::int64_t>>) {
          if (v) detail::check_integer(*v, f.bound, option);
        } else if constexpr (std::is_same_v<T, std::vector<int>>) {
          for (const int i : v) detail::check_integer(i, f.bound, option);
        } else if constexpr (std::is_same_v<T, std::optional<std::string>>) {
          if (v && !f.choices.empty()) detail::check_choice(*v, f.choices, option);
        } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
          if (!f.choices.empty())
            for (const std::string& w : v) detail::check_choice(w, f.choices, option);
        }
      },
      f.member);
}

/// Sets field @p f of @p s from @p text as a command line gives it (a list field gains
/// one entry), and checks it (check_field()); throws Error naming @p option.
template <class S>
void set_text(S& s, const Field<S>& f, std::string_view text, std::string_view option) {
  std::visit(
      [&](auto member) {
        using T = std::remove_cvref_t<decltype(member_of(s, member))>;
        T& v = member_of(s, member);
        if constexpr (std::is_same_v<T, std::optional<Real>>) {
          v = f.kind == FieldKind::quantity ? detail::quantity_text(text, f.quantity, option)
                                            : detail::number_text(text, option);
        } else if constexpr (std::is_same_v<T, std::optional<int>>) {
          const std::int64_t i = detail::integer_text(text, option);
          detail::check_integer(i, f.bound, option);
          v = static_cast<int>(i);
        } else if constexpr (std::is_same_v<T, std::optional<std::int64_t>>) {
          v = detail::integer_text(text, option);
        } else if constexpr (std::is_same_v<T, std::vector<int>>) {
          const std::int64_t i = detail::integer_text(text, option);
          detail::check_integer(i, f.bound, option);
          v.push_back(static_cast<int>(i));
        } else if constexpr (std::is_same_v<T, std::optional<bool>>) {
          v = detail::flag_text(text, option);
        } else if constexpr (std::is_same_v<T, std::optional<std::string>>) {
          v = std::string(text);
        } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
          v.emplace_back(text);
        } else if constexpr (std::is_same_v<T, std::vector<std::pair<Real, Real>>>) {
          v = detail::time_table_text(text, f.quantity, option);
        } else if constexpr (std::is_same_v<T, std::optional<NodeRef>> || std::is_same_v<T, std::vector<NodeRef>>) {
          NodeRef ref = std::string(text);
          if (!text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos)
            ref = detail::integer_text(text, option);
          if constexpr (std::is_same_v<T, std::optional<NodeRef>>)
            v = std::move(ref);
          else
            v.push_back(std::move(ref));
        } else {
          throw std::logic_error("set_text: field " + std::string(f.key) + " is not an option");
        }
      },
      f.member);
  check_field(s, f, option);
}

/// Sets field @p f of @p s to the number @p si (in SI units, speeds in rad/s, as the
/// Python module takes a bare number) and checks it; throws Error naming @p option.
template <class S>
void set_number(S& s, const Field<S>& f, Real si, std::string_view option) {
  std::visit(
      [&](auto member) {
        using T = std::remove_cvref_t<decltype(member_of(s, member))>;
        if constexpr (std::is_same_v<T, std::optional<Real>>)
          member_of(s, member) = si;
        else
          throw std::logic_error("set_number: field " + std::string(f.key) + " is not a number");
      },
      f.member);
  check_field(s, f, option);
}

/// Sets the flag field @p f of @p s.
template <class S>
void set_flag(S& s, const Field<S>& f, bool on) {
  std::visit(
      [&](auto member) {
        using T = std::remove_cvref_t<decltype(member_of(s, member))>;
        if constexpr (std::is_same_v<T, std::optional<bool>>)
          member_of(s, member) = on;
        else
          throw std::logic_error("set_flag: field " + std::string(f.key) + " is not a flag");
      },
      f.member);
}

/// The value of field @p f of @p s as text in the field's unit ("9.81 m/s^2", "-y",
/// "true"), as help texts and documentation show a default; empty when it has none.
template <class S>
std::string value_text(const S& s, const Field<S>& f);

namespace detail {
std::string real_text(Real v, FieldKind kind, Quantity quantity, std::string_view unit);
std::string node_text(const NodeRef& ref);
}  // namespace detail

template <class S>
std::string value_text(const S& s, const Field<S>& f) {
  return std::visit(
      [&](auto member) -> std::string {
        using T = std::remove_cvref_t<decltype(member_of(s, member))>;
        const T& v = member_of(s, member);
        if constexpr (std::is_same_v<T, std::optional<Real>>)
          return v ? detail::real_text(*v, f.kind, f.quantity, f.unit) : std::string();
        else if constexpr (std::is_same_v<T, Real>)
          return detail::real_text(v, f.kind, f.quantity, f.unit);
        else if constexpr (std::is_same_v<T, std::optional<int>> || std::is_same_v<T, std::optional<std::int64_t>>)
          return v ? std::to_string(*v) : std::string();
        else if constexpr (std::is_same_v<T, std::optional<bool>>)
          return v ? (*v ? "true" : "false") : std::string();
        else if constexpr (std::is_same_v<T, std::optional<std::string>>)
          return v.value_or(std::string());
        else if constexpr (std::is_same_v<T, std::optional<NodeRef>>)
          return v ? detail::node_text(*v) : std::string();
        else
          return std::string();
      },
      f.member);
}

}  // namespace feran::spec
