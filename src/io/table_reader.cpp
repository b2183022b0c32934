#include "table_reader.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "suggestions.hpp"

namespace feran::detail {

namespace {

SourceLocation location_of_region(const std::string& path, const toml::source_region& r) {
  return SourceLocation{path, static_cast<int>(r.begin.line), static_cast<int>(r.begin.column)};
}

bool before(const toml::source_position& a, const toml::source_position& b) {
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

}  // namespace

std::string_view utf8_text(std::string_view text, const std::string& path) {
  const auto byte = [&](std::size_t i) { return i < text.size() ? static_cast<unsigned char>(text[i]) : 0x100u; };
  if (byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) return text.substr(3);
  const char* encoding = nullptr;
  if (byte(0) == 0xFF && byte(1) == 0xFE && byte(2) == 0 && byte(3) == 0)
    encoding = "UTF-32 (little-endian, by its byte-order mark)";
  else if (byte(0) == 0 && byte(1) == 0 && byte(2) == 0xFE && byte(3) == 0xFF)
    encoding = "UTF-32 (big-endian, by its byte-order mark)";
  else if (byte(0) == 0xFF && byte(1) == 0xFE)
    encoding = "UTF-16 (little-endian, by its byte-order mark)";
  else if (byte(0) == 0xFE && byte(1) == 0xFF)
    encoding = "UTF-16 (big-endian, by its byte-order mark)";
  else if (byte(0) == 0 && byte(1) == 0 && byte(2) == 0 && byte(3) != 0 && byte(3) < 0x100)
    encoding = "UTF-32 (big-endian, by the zero bytes of its first character)";
  else if (byte(0) != 0 && byte(0) < 0x100 && byte(1) == 0 && byte(2) == 0 && byte(3) == 0)
    encoding = "UTF-32 (little-endian, by the zero bytes of its first character)";
  else if (byte(0) == 0 && byte(1) != 0 && byte(1) < 0x100)
    encoding = "UTF-16 (big-endian, by the zero bytes of its first characters)";
  else if (byte(0) != 0 && byte(0) < 0x100 && byte(1) == 0)
    encoding = "UTF-16 (little-endian, by the zero bytes of its first characters)";
  if (encoding != nullptr)
    throw ModelError(SourceLocation{path, 1, 1},
                     fmt::format("the file is in {}; TOML files are UTF-8: save it as UTF-8 (the editor's 'UTF-8' "
                                 "encoding, or iconv -t UTF-8)",
                                 encoding));
  return text;
}

toml::table parse_toml(std::string_view text, const std::string& path) {
  try {
    return toml::parse(utf8_text(text, path), std::string_view{path});
  } catch (const toml::parse_error& e) {
    throw ModelError(location_of_region(path, e.source()), fmt::format("TOML syntax error: {}", e.description()));
  }
}

SourceLocation location_of(const std::string& path, const toml::node& node) {
  return location_of_region(path, node.source());
}

std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return fmt::format("a string (\"{}\")", *node.value<std::string>());
    case toml::node_type::integer:
      return fmt::format("an integer ({})", *node.value<std::int64_t>());
    case toml::node_type::floating_point: {
      // Show 1.0 as "1.0", not "1", so that the reader sees why it is not an integer.
      const double v = *node.value<double>();
      const bool integral = std::isfinite(v) && std::floor(v) == v && std::abs(v) < 1e15;
      return integral ? fmt::format("a floating-point number ({:.1f})", v)
                      : fmt::format("a floating-point number ({})", v);
    }
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

TableReader::TableReader(const toml::table& table, std::string context, const std::string& path)
    : table_(table), context_(std::move(context)), path_(path) {}

void TableReader::check_keys(const std::vector<std::string_view>& allowed) const {
  const toml::key* first_unknown = nullptr;
  for (auto&& [key, value] : table_) {
    bool known = false;
    for (const std::string_view a : allowed) known = known || key.str() == a;
    if (!known && (first_unknown == nullptr || before(key.source().begin, first_unknown->source().begin)))
      first_unknown = &key;
  }
  if (first_unknown == nullptr) return;

  const std::vector<std::string> candidates(allowed.begin(), allowed.end());
  const std::string where = context_.empty() ? "at the top level" : "in " + context_;
  std::string message = fmt::format("unknown key '{}' {}", first_unknown->str(), where);
  // Keys are short, so a distance of 3 still catches transpositions and a missing
  // character or two without suggesting unrelated keys.
  if (!context_.empty() && first_unknown->str() == "title")
    message += "; top-level keys such as 'title' must come before the first [table] header";
  else if (const auto match = closest_match(first_unknown->str(), candidates, 3))
    message += fmt::format("; did you mean '{}'?", *match);
  else if (candidates.empty())
    message += " (this table takes no keys)";
  else
    message += fmt::format("; valid keys are {}", join_list(candidates, "and", '\''));

  SourceLocation at = location_of_region(path_, first_unknown->source());
  if (at.line == 0) at = location_of(path_, *table_.get(first_unknown->str()));
  throw ModelError(at, message);
}

const toml::node* TableReader::find(std::string_view key) const { return table_.get(key); }

const toml::node& TableReader::require(std::string_view key, std::string_view expected) const {
  const toml::node* n = find(key);
  if (n == nullptr) {
    const std::string where = context_.empty() ? "at the top level" : "in " + context_;
    fail_here(fmt::format("missing key '{}' {} (expected {})", key, where, expected));
  }
  return *n;
}

void TableReader::fail(const toml::node& node, const std::string& message) const {
  throw ModelError(location_of(path_, node), message);
}

void TableReader::fail_here(const std::string& message) const {
  SourceLocation at = location_of(path_, table_);
  if (at.line == 0) at = SourceLocation{path_, 1, 1};
  throw ModelError(at, message);
}

QuantityValue TableReader::quantity_at(const toml::node& node, std::string_view name, Quantity kind) const {
  QuantityValue q;
  q.node = &node;
  if (const auto i = node.value_exact<std::int64_t>()) {
    q.si = static_cast<Real>(*i);
    q.written = fmt::format("{} {}", *i, si_unit(kind));
    return q;
  }
  if (const auto* f = node.as_floating_point()) {
    if (!std::isfinite(f->get())) fail(node, fmt::format("'{}' must be a finite number, got {}", name, f->get()));
    q.si = f->get();
    q.written = fmt::format("{} {}", q.si, si_unit(kind));
    return q;
  }
  if (const auto* s = node.as_string()) {
    const std::string& text = s->get();
    const auto parts = split_quantity(text);
    if (!parts) fail(node, fmt::format("{}, got \"{}\"", must_be_quantity(name, kind), text));
    if (!std::isfinite(parts->value)) fail(node, fmt::format("'{}' must be a finite number, got \"{}\"", name, text));
    if (parts->unit.empty()) {
      q.si = parts->value;
      q.written = fmt::format("{} {}", q.si, si_unit(kind));
      return q;
    }
    const auto si = to_si(kind, parts->value, parts->unit);
    if (!si) {
      std::string message = fmt::format("'{}' has unit '{}', expected {} in {}", name, parts->unit, quantity_name(kind),
                                        accepted_units_text(kind));
      if (const std::string hint = unit_hint(kind, parts->unit); !hint.empty()) message += fmt::format(" ({})", hint);
      fail(node, message);
    }
    q.si = *si;
    q.written = fmt::format("{} {}", parts->value, parts->unit);
    return q;
  }
  fail(node, fmt::format("{}, got {}", must_be_quantity(name, kind), type_name(node)));
}

std::optional<QuantityValue> TableReader::quantity(std::string_view key, Quantity kind) const {
  const toml::node* n = find(key);
  if (n == nullptr) return std::nullopt;
  return quantity_at(*n, key, kind);
}

QuantityValue TableReader::required_quantity(std::string_view key, Quantity kind) const {
  return quantity_at(require(key, expected_quantity(kind)), key, kind);
}

std::optional<Real> TableReader::number(std::string_view key) const {
  const toml::node* n = find(key);
  if (n == nullptr) return std::nullopt;
  if (const auto i = n->value_exact<std::int64_t>()) return static_cast<Real>(*i);
  if (const auto* f = n->as_floating_point()) {
    if (!std::isfinite(f->get())) fail(*n, fmt::format("'{}' must be a finite number, got {}", key, f->get()));
    return f->get();
  }
  fail(*n, fmt::format("'{}' must be a number without unit, got {}", key, type_name(*n)));
}

std::optional<Real> TableReader::non_negative_number(std::string_view key) const {
  const auto value = number(key);
  if (value && !(*value >= 0.0)) fail(*find(key), fmt::format("'{}' must not be negative, got {}", key, *value));
  return value;
}

std::optional<Real> TableReader::positive_number(std::string_view key) const {
  const auto value = number(key);
  if (value && !(*value > 0.0)) fail(*find(key), fmt::format("'{}' must be positive, got {}", key, *value));
  return value;
}

std::optional<bool> TableReader::boolean(std::string_view key) const {
  const toml::node* n = find(key);
  if (n == nullptr) return std::nullopt;
  if (const auto b = n->value_exact<bool>()) return *b;
  fail(*n, fmt::format("'{}' must be a boolean (true or false), got {}", key, type_name(*n)));
}

std::optional<std::string> TableReader::string(std::string_view key) const {
  const toml::node* n = find(key);
  if (n == nullptr) return std::nullopt;
  if (const auto s = n->value_exact<std::string>()) return *s;
  fail(*n, fmt::format("'{}' must be a string, got {}", key, type_name(*n)));
}

std::string TableReader::required_string(std::string_view key, std::string_view expected) const {
  require(key, expected);
  return *string(key);
}

int TableReader::integer_at(const toml::node& node, std::string_view name, int minimum, int maximum) const {
  const auto i = node.value_exact<std::int64_t>();
  if (!i) fail(node, fmt::format("'{}' must be an integer, got {}", name, type_name(node)));
  if (*i < minimum) fail(node, fmt::format("'{}' must be at least {}, got {}", name, minimum, *i));
  if (*i > maximum) fail(node, fmt::format("'{}' must be at most {}, got {}", name, maximum, *i));
  return static_cast<int>(*i);
}

std::optional<int> TableReader::integer(std::string_view key, int minimum, int maximum) const {
  const toml::node* n = find(key);
  if (n == nullptr) return std::nullopt;
  return integer_at(*n, key, minimum, maximum);
}

const toml::array* TableReader::array(std::string_view key) const {
  const toml::node* n = find(key);
  if (n == nullptr) return nullptr;
  if (const auto* a = n->as_array()) return a;
  fail(*n, fmt::format("'{}' must be an array, got {}", key, type_name(*n)));
}

const toml::array& TableReader::required_array(std::string_view key, std::string_view expected) const {
  require(key, expected);
  return *array(key);
}

void TableReader::require_positive(const QuantityValue& q, std::string_view name) const {
  if (!(q.si > 0.0)) fail(*q.node, fmt::format("'{}' must be positive, got {}", name, q.written));
}

void TableReader::require_non_negative(const QuantityValue& q, std::string_view name) const {
  if (!(q.si >= 0.0)) fail(*q.node, fmt::format("'{}' must not be negative, got {}", name, q.written));
}

}  // namespace feran::detail
