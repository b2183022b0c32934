// The non-template parts of the generic request step: values read from text and
// checked by the rules their fields declare.
#include <feran/spec/request.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/core/suggestions.hpp>
#include <feran/core/units.hpp>

namespace feran::spec::detail {

Real number_text(std::string_view text, std::string_view option) {
  const auto q = split_quantity(text);
  if (!q || !q->unit.empty()) throw Error(fmt::format("{}: expected a number, got '{}'", option, text));
  if (!std::isfinite(q->value)) throw Error(fmt::format("{}: must be a finite number, got '{}'", option, text));
  return q->value;
}

std::int64_t integer_text(std::string_view text, std::string_view option) {
  std::int64_t v = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec == std::errc::result_out_of_range)
    throw Error(fmt::format("{}: '{}' is too large for an integer", option, text));
  if (ec != std::errc() || ptr != end) throw Error(fmt::format("{}: expected an integer, got '{}'", option, text));
  return v;
}

Real quantity_text(std::string_view text, Quantity kind, std::string_view option) {
  if (kind == Quantity::speed) {
    const auto q = split_quantity(text);
    if (!q || q->unit.empty())
      throw Error(fmt::format("{} '{}': give a speed with its unit, e.g. 30Hz, 1800rpm or 188.5rad/s", option, text));
    const auto si = to_si(Quantity::speed, q->value, q->unit);
    if (!si) throw Error(fmt::format("{} '{}': the unit must be Hz, rpm or rad/s", option, text));
    const Real largest = physical_range(Quantity::speed).largest;
    if (!std::isfinite(*si) || std::abs(*si) > largest)
      throw Error(fmt::format("{} '{}': beyond the physical range of a speed (at most {} in magnitude)", option, text,
                              approximate_quantity(largest, Quantity::speed, q->unit)));
    return *si;
  }
  try {
    return parse_quantity(text, kind);
  } catch (const QuantityError& e) {
    throw Error(fmt::format("{}: {}", option, e.what()));
  }
}

std::vector<std::pair<Real, Real>> time_table_text(std::string_view text, Quantity kind, std::string_view option) {
  std::vector<std::pair<Real, Real>> points;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string_view item = text.substr(start, end - start);
    const std::size_t colon = item.find(':');
    if (colon == std::string_view::npos)
      throw Error(fmt::format("{} '{}': each point is TIME:VALUE, e.g. 0s:0Hz,5s:80Hz", option, text));
    const Real t = quantity_text(item.substr(0, colon), Quantity::time, option);
    if (!std::isfinite(t)) throw Error(fmt::format("{} '{}': a time must be finite", option, text));
    points.emplace_back(t, quantity_text(item.substr(colon + 1), kind, option));
    start = end + 1;
  }
  return points;
}

bool flag_text(std::string_view text, std::string_view option) {
  if (text == "true") return true;
  if (text == "false") return false;
  throw Error(fmt::format("{}: expected true or false, got '{}'", option, text));
}

void check_number(Real v, const Bound& bound, std::optional<Quantity> kind, std::string_view unit,
                  std::string_view option) {
  const auto text = [&] { return kind ? format_quantity(v, *kind, unit) : fmt::format("{:g}", v); };
  if (!std::isfinite(v)) throw Error(fmt::format("{}: must be a finite number", option));
  if (bound.kind == Bound::Kind::positive && !(v > 0.0))
    throw Error(fmt::format("{}: must be positive, got {}", option, text()));
  if (bound.kind == Bound::Kind::non_negative && !(v >= 0.0))
    throw Error(fmt::format("{}: must not be negative, got {}", option, text()));
  if (kind) {
    const PhysicalRange range = physical_range(*kind);
    const auto limit = [&](Real si) { return approximate_quantity(si, *kind, unit); };
    if (std::abs(v) > range.largest)
      throw Error(fmt::format("{}: {} is beyond the physical range of {} (at most {} in magnitude)", option, text(),
                              quantity_name(*kind), limit(range.largest)));
    if (bound.kind == Bound::Kind::positive && v < range.smallest_positive)
      throw Error(fmt::format("{}: {} is below the physical range of {} (at least {})", option, text(),
                              quantity_name(*kind), limit(range.smallest_positive)));
  }
}

void check_integer(std::int64_t v, const Bound& bound, std::string_view option) {
  if (bound.kind != Bound::Kind::at_least) return;
  if (v < bound.minimum) throw Error(fmt::format("{}: must be at least {}, got {}", option, bound.minimum, v));
  if (v > bound.maximum) throw Error(fmt::format("{}: must be at most {}, got {}", option, bound.maximum, v));
}

void check_choice(std::string_view word, std::span<const std::string_view> choices, std::string_view option) {
  std::vector<std::string> names;
  for (const std::string_view c : choices) {
    if (c == word) return;
    names.emplace_back(c);
  }
  std::string message = fmt::format("{} must be {}, got '{}'", option, feran::detail::join_list(names), word);
  if (const auto match = feran::detail::closest_match(word, names, std::min<std::size_t>(2, word.size() / 2)))
    message += fmt::format("; did you mean '{}'?", *match);
  throw Error(message);
}

std::string real_text(Real v, FieldKind kind, Quantity quantity, std::string_view unit) {
  if (kind == FieldKind::quantity) return format_quantity(v, quantity, unit);
  return fmt::format("{:g}", v);
}

std::string node_text(const NodeRef& ref) {
  if (const auto* n = std::get_if<std::int64_t>(&ref)) return std::to_string(*n);
  return std::get<std::string>(ref);
}

}  // namespace feran::spec::detail
