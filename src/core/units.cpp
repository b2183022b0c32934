#include <feran/core/units.hpp>

#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace feran {

namespace {

/// One accepted unit: value_SI = value · multiply / divide. Sub-units divide so that
/// e.g. "68 mm" gives exactly the double nearest to 0.068.
struct UnitDef {
  std::string_view name;
  Real multiply = 1.0;
  Real divide = 1.0;
};

struct KindDef {
  Quantity kind;
  std::string_view article_name;  ///< "a length"
  std::string_view noun;          ///< "length"
  std::string_view si_example;
  std::string_view unit_example;
  std::vector<UnitDef> units;  ///< SI unit first
  PhysicalRange range;         ///< in SI
};

const std::vector<KindDef>& kinds() {
  static const std::vector<KindDef> table = {
      {Quantity::length,
       "a length",
       "length",
       "0.068",
       "68 mm",
       {{"m"}, {"mm", 1.0, 1e3}, {"cm", 1.0, 1e2}, {"um", 1.0, 1e6}},
       {1e4, 1e-9}},
      {Quantity::mass, "a mass", "mass", "1.93", "1.93 kg", {{"kg"}, {"g", 1.0, 1e3}}, {1e9, 1e-12}},
      {Quantity::inertia,
       "a moment of inertia",
       "moment of inertia",
       "0.0063",
       "6300 kg*mm^2",
       {{"kg*m^2"}, {"kg*mm^2", 1.0, 1e6}},
       {1e12, 1e-18}},
      {Quantity::pressure,
       "a pressure",
       "pressure",
       "2.1e11",
       "210 GPa",
       {{"Pa"}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}, {"N/mm^2", 1e6}},
       {1e13, 1e-3}},
      {Quantity::density, "a density", "density", "7850", "7.85 g/cm^3", {{"kg/m^3"}, {"g/cm^3", 1e3}}, {1e6, 1e-3}},
      {Quantity::stiffness,
       "a stiffness",
       "stiffness",
       "6e7",
       "6e7 N/m",
       {{"N/m"}, {"kN/m", 1e3}, {"MN/m", 1e6}, {"N/mm", 1e3}, {"kN/mm", 1e6}},
       {1e15, 1e-12}},
      {Quantity::rotational_stiffness,
       "a rotational stiffness",
       "rotational stiffness",
       "180",
       "180 N*m/rad",
       {{"N*m/rad"}, {"Nm/rad"}, {"N*m"}},
       {1e15, 1e-12}},
      {Quantity::damping,
       "a damping coefficient",
       "damping",
       "75",
       "75 N*s/m",
       {{"N*s/m"}, {"Ns/m"}, {"kN*s/m", 1e3}},
       {1e12, 1e-12}},
      {Quantity::rotational_damping,
       "a rotational damping coefficient",
       "rotational damping",
       "0.06",
       "0.06 N*m*s/rad",
       {{"N*m*s/rad"}, {"Nms/rad"}, {"N*m*s"}, {"Nms"}},
       {1e12, 1e-12}},
      {Quantity::speed,
       "a speed",
       "speed",
       "188.5",
       "30 Hz",
       {{"rad/s"}, {"Hz", 2.0 * pi}, {"rpm", 2.0 * pi, 60.0}},
       {1e6, 1e-9}},
      {Quantity::frequency, "a frequency", "frequency", "3.98", "3.98 Hz", {{"Hz"}}, {1e6, 1e-9}},
      {Quantity::angle, "an angle", "angle", "0.5236", "30 deg", {{"rad"}, {"deg", pi, 180.0}}, {1e4, 0.0}},
      {Quantity::force, "a force", "force", "5.2", "5.2 N", {{"N"}, {"kN", 1e3}}, {1e12, 1e-12}},
      {Quantity::moment, "a moment", "moment", "0.1", "0.1 N*m", {{"N*m"}, {"Nm"}}, {1e12, 1e-12}},
      {Quantity::time, "a time", "time", "0.001", "1 ms", {{"s"}, {"ms", 1.0, 1e3}}, {1e8, 1e-12}},
      {Quantity::velocity, "a velocity", "velocity", "1e-4", "0.1 mm/s", {{"m/s"}, {"mm/s", 1.0, 1e3}}, {1e4, 1e-15}},
      {Quantity::angular_velocity,
       "an angular velocity",
       "angular velocity",
       "0.001",
       "0.001 rad/s",
       {{"rad/s"}},
       {1e6, 1e-15}},
      {Quantity::inverse_time, "a rate", "rate", "0.5", "0.5 1/s", {{"1/s"}}, {1e9, 1e-15}},
      {Quantity::acceleration,
       "an acceleration",
       "acceleration",
       "9.81",
       "9.81 m/s^2",
       {{"m/s^2"}, {"mm/s^2", 1.0, 1e3}},
       {1e7, 1e-9}},
      {Quantity::viscosity,
       "a viscosity",
       "viscosity",
       "0.1",
       "0.1 Pa*s",
       {{"Pa*s"}, {"mPa*s", 1.0, 1e3}, {"cP", 1.0, 1e3}},
       {1e6, 1e-9}},
  };
  return table;
}

const KindDef& kind_def(Quantity kind) {
  for (const KindDef& k : kinds())
    if (k.kind == kind) return k;
  return kinds().front();  // unreachable: every enumerator has an entry
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

bool iequal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// The SI prefixes (the BIPM's SI Brochure, 9th ed., table 7), each a power of ten.
struct Prefix {
  std::string_view symbol;
  int power;
};
constexpr Prefix si_prefixes[] = {{"da", 1}, {"Y", 24}, {"Z", 21}, {"E", 18},  {"P", 15},  {"T", 12},
                                  {"G", 9},  {"M", 6},  {"k", 3},  {"h", 2},   {"d", -1},  {"c", -2},
                                  {"m", -3}, {"u", -6}, {"n", -9}, {"p", -12}, {"f", -15}, {"a", -18}};

// The units an SI prefix may stand before: those whose first factor is a coherent SI
// unit or the gram (not kg, rpm, deg, cP, nor an already prefixed one), without an
// exponent on it.
bool prefixable(std::string_view name) {
  const std::size_t end = name.find_first_of("*/^");
  if (end != std::string_view::npos && name[end] == '^') return false;
  const std::string_view first = name.substr(0, end);
  for (const std::string_view base : {"m", "g", "s", "N", "Pa", "Hz", "rad"})
    if (first == base) return true;
  return false;
}

// The listed unit and the power of ten of @p normalized: a listed unit itself
// (power 0), or an SI prefix before a prefixable listed unit ("MN", "kHz", "nm").
std::optional<std::pair<UnitDef, int>> find_unit(Quantity kind, const std::string& normalized) {
  for (const UnitDef& u : kind_def(kind).units)
    if (u.name == normalized) return std::pair{u, 0};
  for (const Prefix& p : si_prefixes) {
    if (!std::string_view(normalized).starts_with(p.symbol)) continue;
    const std::string_view rest = std::string_view(normalized).substr(p.symbol.size());
    for (const UnitDef& u : kind_def(kind).units)
      if (u.name == rest && prefixable(u.name)) return std::pair{u, p.power};
  }
  return std::nullopt;
}

// 10^|power| exactly (every power of ten up to 1e22 is a double).
Real ten_to(int power) {
  Real out = 1;
  for (int i = 0; i < std::abs(power); ++i) out *= 10;
  return out;
}

}  // namespace

std::string_view quantity_name(Quantity kind) { return kind_def(kind).article_name; }
std::string_view quantity_noun(Quantity kind) { return kind_def(kind).noun; }

PhysicalRange physical_range(Quantity kind) { return kind_def(kind).range; }

std::string_view si_unit(Quantity kind) { return kind_def(kind).units.front().name; }

std::vector<std::string_view> accepted_units(Quantity kind) {
  std::vector<std::string_view> out;
  for (const UnitDef& u : kind_def(kind).units) out.push_back(u.name);
  // "kg m^2" is only a spelling of kg*m^2, but users asked to see it listed.
  if (kind == Quantity::inertia) out.push_back("kg m^2");
  return out;
}

std::string accepted_units_text(Quantity kind) {
  const std::vector<std::string_view> units = accepted_units(kind);
  std::string out;
  for (std::size_t i = 0; i < units.size(); ++i) {
    if (i > 0) out += (i + 1 == units.size()) ? " or " : ", ";
    out += units[i];
  }
  for (const std::string_view u : units)
    if (prefixable(u)) {
      out += fmt::format(" (any SI prefix on {0} too: k{0}, m{0}, …)", u);
      break;
    }
  return out;
}

std::string_view unit_example(Quantity kind) { return kind_def(kind).unit_example; }

std::string_view si_example(Quantity kind) { return kind_def(kind).si_example; }

std::string normalize_unit(std::string_view unit) {
  // First replace the non-ASCII spellings, then drop spaces around operators and
  // read the remaining spaces as multiplication.
  std::string ascii;
  const std::string_view in = trim(unit);
  for (std::size_t i = 0; i < in.size();) {
    const auto rest = in.substr(i);
    if (rest.starts_with("\u00b7")) {  // middle dot
      ascii += '*';
      i += 2;
    } else if (rest.starts_with("\u22c5")) {  // dot operator
      ascii += '*';
      i += 3;
    } else if (rest.starts_with("\u00b2")) {
      ascii += "^2";
      i += 2;
    } else if (rest.starts_with("\u00b3")) {
      ascii += "^3";
      i += 2;
    } else if (rest.starts_with("\u00b5") || rest.starts_with("\u03bc")) {  // micro, mu
      ascii += 'u';
      i += 2;
    } else {
      ascii += in[i];
      ++i;
    }
  }
  std::string out;
  bool pending_space = false;
  for (const char c : ascii) {
    if (is_space(c)) {
      pending_space = true;
      continue;
    }
    const bool op = c == '*' || c == '/' || c == '^';
    if (pending_space && !out.empty() && !op) {
      const char last = out.back();
      if (last != '*' && last != '/' && last != '^') out += '*';
    }
    pending_space = false;
    out += c;
  }
  return out;
}

std::optional<Real> to_si(Quantity kind, Real value, std::string_view unit) {
  const auto found = find_unit(kind, normalize_unit(unit));
  if (!found) return std::nullopt;
  const auto& [u, power] = *found;
  // Sub-multiples divide, so that "68 mm" and "68 nm" give the nearest doubles.
  return power >= 0 ? value * (u.multiply * ten_to(power)) / u.divide : value * u.multiply / (u.divide * ten_to(power));
}

std::optional<Real> from_si(Quantity kind, Real si, std::string_view unit) {
  const auto found = find_unit(kind, normalize_unit(unit));
  if (!found) return std::nullopt;
  const auto& [u, power] = *found;
  return power >= 0 ? si * u.divide / (u.multiply * ten_to(power)) : si * (u.divide * ten_to(power)) / u.multiply;
}

std::string format_quantity(Real si, Quantity kind, std::string_view unit) {
  if (!unit.empty())
    if (const auto value = from_si(kind, si, unit))
      if (std::isfinite(*value) && to_si(kind, *value, unit) == si) return fmt::format("{} {}", *value, unit);
  return fmt::format("{} {}", si, si_unit(kind));
}

std::string approximate_quantity(Real si, Quantity kind, std::string_view unit) {
  if (!unit.empty())
    if (const auto value = from_si(kind, si, unit); value && std::isfinite(*value))
      return fmt::format("{:.6g} {}", *value, unit);
  return fmt::format("{:.6g} {}", si, si_unit(kind));
}

std::string must_be_quantity(std::string_view name, Quantity kind) {
  return fmt::format("'{}' must be {} (a number in {}, or a string such as \"{}\")", name, quantity_name(kind),
                     si_unit(kind), unit_example(kind));
}

std::string expected_quantity(Quantity kind) {
  return fmt::format("{}, e.g. {} or \"{}\"", quantity_name(kind), si_example(kind), unit_example(kind));
}

std::optional<QuantityText> split_quantity(std::string_view text) {
  const std::string_view s = trim(text);
  std::size_t pos = 0;
  bool negative = false;
  if (pos < s.size() && (s[pos] == '+' || s[pos] == '-')) {
    negative = s[pos] == '-';
    ++pos;
  }
  // from_chars rejects a leading '+' and would read "1e" as 1 followed by "e",
  // which then fails as a unit: both behave as intended.
  Real value = 0.0;
  const char* first = s.data() + pos;
  const char* last = s.data() + s.size();
  if (pos < s.size() && s[pos] == '-') return std::nullopt;  // "--1"
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc{} && ec != std::errc::result_out_of_range) return std::nullopt;
  if (ec == std::errc::result_out_of_range) {
    // Too large is not finite (rejected by the callers); too small is zero.
    const std::string_view number(first, static_cast<std::size_t>(ptr - first));
    const bool underflow = number.find("e-") != std::string_view::npos || number.find("E-") != std::string_view::npos;
    value = underflow ? 0.0 : HUGE_VAL;
  }
  QuantityText out;
  out.value = negative ? -value : value;
  out.unit = std::string(trim(std::string_view(ptr, static_cast<std::size_t>(last - ptr))));
  return out;
}

std::string unit_hint(Quantity kind, std::string_view unit) {
  const std::string normalized = normalize_unit(unit);
  for (const UnitDef& u : kind_def(kind).units)
    if (iequal(u.name, normalized)) return fmt::format("units are case-sensitive: did you mean '{}'?", u.name);
  std::string nouns;
  for (const KindDef& k : kinds()) {
    if (k.kind == kind) continue;
    for (const UnitDef& u : k.units)
      if (u.name == normalized) nouns += std::string(nouns.empty() ? "" : " or ") + std::string(k.noun);
  }
  if (nouns.empty()) return {};
  return fmt::format("'{}' is a unit of {}", trim(unit), nouns);
}

Real parse_quantity(std::string_view text, Quantity kind) {
  const std::string written(trim(text));
  const auto parts = split_quantity(written);
  if (!parts)
    throw QuantityError(QuantityError::Reason::not_a_number, kind, written, {},
                        fmt::format("\"{}\" is not {} (expected a number in {}, or a number "
                                    "with a unit such as \"{}\")",
                                    written, quantity_name(kind), si_unit(kind), unit_example(kind)));
  if (!std::isfinite(parts->value))
    throw QuantityError(QuantityError::Reason::not_finite, kind, written, {},
                        fmt::format("\"{}\" is not a finite number", written));
  if (parts->unit.empty()) return parts->value;
  const auto si = to_si(kind, parts->value, parts->unit);
  if (!si) {
    std::string message = fmt::format("\"{}\" has unit '{}', expected {} in {}", written, parts->unit,
                                      quantity_name(kind), accepted_units_text(kind));
    if (const std::string hint = unit_hint(kind, parts->unit); !hint.empty()) message += fmt::format(" ({})", hint);
    throw QuantityError(QuantityError::Reason::wrong_unit, kind, written, parts->unit, message);
  }
  return *si;
}

}  // namespace feran
