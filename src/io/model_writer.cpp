#include <feran/io/model_writer.hpp>

#include <cstdint>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>

#include <feran/core/units.hpp>
#include <feran/spec/fields.hpp>

namespace feran {

namespace {

using spec::Field;
using spec::FieldKind;

/// A TOML basic string: quotes, backslashes and control characters escaped.
std::string toml_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\f':
        out += "\\f";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
          out += fmt::format("\\u{:04X}", static_cast<unsigned>(static_cast<unsigned char>(c)));
        else
          out += c;
    }
  }
  return out + "\"";
}

/// A dimensionless number as TOML: the shortest digits that read back exactly.
std::string number(Real value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{}", value);
}

std::string quantity(Real si, Quantity kind, std::string_view unit) {
  return toml_string(format_quantity(si, kind, unit));
}

std::string node(const NodeRef& ref) {
  if (const auto* number = std::get_if<std::int64_t>(&ref)) return fmt::format("{}", *number);
  return toml_string(std::get<std::string>(ref));
}

template <class T, class F>
std::string array(const std::vector<T>& items, F&& format) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += ", ";
    out += format(items[i]);
  }
  return out + "]";
}

std::string coefficient(const SpeedCoefficient& c, Quantity kind) {
  const auto value = [&](Real v) { return quantity(v, kind, {}); };
  const auto speed = [&](Real v) { return quantity(v, Quantity::speed, "Hz"); };
  return std::visit(
      [&](const auto& law) -> std::string {
        using L = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<L, SpeedCoefficient::Constant>) {
          return value(law.value);
        } else if constexpr (std::is_same_v<L, SpeedCoefficient::Table>) {
          return fmt::format("{{ law = \"table\", speeds = {}, values = {} }}", array(law.speeds, speed),
                             array(law.values, value));
        } else if constexpr (std::is_same_v<L, SpeedCoefficient::Step>) {
          return fmt::format("{{ law = \"step\", below = {}, above = {}, at = {} }}", value(law.below),
                             value(law.above), speed(law.at));
        } else if constexpr (std::is_same_v<L, SpeedCoefficient::FrequencyTable>) {
          const std::size_t nf = law.frequencies.size();
          const auto row = [&](std::size_t i) {
            return array(std::vector<Real>(law.values.begin() + static_cast<std::ptrdiff_t>(i * nf),
                                           law.values.begin() + static_cast<std::ptrdiff_t>((i + 1) * nf)),
                         value);
          };
          if (law.speeds.empty())
            return fmt::format("{{ law = \"frequency_table\", frequencies = {}, values = {} }}",
                               array(law.frequencies, speed), row(0));
          std::vector<std::size_t> rows(law.speeds.size());
          for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
          return fmt::format("{{ law = \"frequency_table\", speeds = {}, frequencies = {}, values = {} }}",
                             array(law.speeds, speed), array(law.frequencies, speed), array(rows, row));
        } else {
          return fmt::format("{{ law = \"arctan\", value = {}, f_as = {}, c0 = {}, c1 = {}, c2 = {} }}",
                             value(law.value), quantity(law.f_as, Quantity::frequency, {}), number(law.c0),
                             number(law.c1), number(law.c2));
        }
      },
      c.law());
}

/// A default-constructed S, whose fields are the defaults a writer leaves out.
template <class S>
const S& default_value() {
  static const S value{};
  return value;
}

/// The TOML value of field @p f of @p entry, or "" when it is absent or has its default.
template <class S>
std::string value_of(const S& entry, const Field<S>& f) {
  return std::visit(
      [&](auto member) -> std::string {
        using T = std::remove_cvref_t<decltype(spec::member_of(entry, member))>;
        const T& v = spec::member_of(entry, member);
        if (!f.required && v == spec::member_of(default_value<S>(), member)) return {};
        if constexpr (std::is_same_v<T, Real> || std::is_same_v<T, std::optional<Real>>) {
          const Real x = [&] {
            if constexpr (std::is_same_v<T, Real>)
              return v;
            else
              return *v;
          }();
          if (f.kind != FieldKind::quantity) return number(x);
          return quantity(x, spec::value_quantity(entry, f), f.unit);
        } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, bool>) {
          return fmt::format("{}", v);
        } else if constexpr (std::is_same_v<T, std::optional<int>> || std::is_same_v<T, std::optional<std::int64_t>> ||
                             std::is_same_v<T, std::optional<bool>>) {
          return fmt::format("{}", *v);
        } else if constexpr (std::is_same_v<T, std::string>) {
          return toml_string(v);
        } else if constexpr (std::is_same_v<T, std::optional<std::string>>) {
          return toml_string(*v);
        } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
          return array(v, [](const std::string& s) { return toml_string(s); });
        } else if constexpr (std::is_same_v<T, NodeRef>) {
          return node(v);
        } else if constexpr (std::is_same_v<T, std::optional<NodeRef>>) {
          return node(*v);
        } else if constexpr (std::is_same_v<T, std::vector<NodeRef>>) {
          return array(v, node);
        } else if constexpr (std::is_same_v<T, std::vector<int>>) {
          return array(v, [](int i) { return fmt::format("{}", i); });
        } else if constexpr (std::is_same_v<T, std::optional<SpeedCoefficient>>) {
          return coefficient(*v, f.quantity);
        } else {
          const Quantity kind = spec::value_quantity(entry, f);
          return array(v, [&f, kind](const std::pair<Real, Real>& p) {
            return fmt::format("[{}, {}]", quantity(p.first, Quantity::time, {}), quantity(p.second, kind, f.unit));
          });
        }
      },
      f.member);
}

template <class S>
void write_keys(std::string& out, const S& entry, std::string_view indent) {
  for (const Field<S>& f : spec::fields_of<S>()) {
    const std::string v = value_of(entry, f);
    if (!v.empty()) out += fmt::format("{}{} = {}\n", indent, f.key, v);
  }
}

template <class S>
void write_entry(std::string& out, std::string_view key, const S& entry) {
  out += fmt::format("\n[[{}]]\n", key);
  write_keys(out, entry, "");
  spec::visit_children(entry, [&](std::string_view child, std::string_view, const auto& children) {
    for (const auto& c : children) {
      out += fmt::format("\n  [[{}.{}]]\n", key, child);
      write_keys(out, c, "  ");
    }
  });
}

}  // namespace

std::string write_toml(const ModelSpec& spec) {
  std::string out;
  if (!spec.title.empty()) out += fmt::format("title = {}\n", toml_string(spec.title));
  spec::visit_tables(spec, [&](std::string_view key, spec::TableForm, std::string_view, const auto& member) {
    using M = std::remove_cvref_t<decltype(member)>;
    if constexpr (requires { typename M::value_type; }) {
      for (const auto& entry : member) write_entry(out, key, entry);
    } else {
      if (member == M{}) return;
      out += fmt::format("\n[{}]\n", key);
      write_keys(out, member, "");
    }
  });
  return out;
}

}  // namespace feran
