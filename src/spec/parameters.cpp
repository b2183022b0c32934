#include <feran/spec/parameters.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include <feran/core/suggestions.hpp>
#include <feran/spec/fields.hpp>
#include <feran/spec/spec_path.hpp>

namespace feran {

std::string Parameter::text() const {
  if (quantity) return format_quantity(value, *quantity, unit);
  return fmt::format("{}", value);
}

namespace {

using detail::closest_match;
using detail::join_list;
using spec::FieldKind;

/// One part of a path: a key and its selectors ("sections[2]", "table[1][0]").
struct Segment {
  std::string key;
  std::vector<std::string> selectors;
};

std::vector<Segment> parse_path(std::string_view path) {
  std::vector<Segment> segments;
  Segment current;
  bool in_key = true;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const char c = path[i];
    if (c == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string_view::npos)
        throw ParameterError(fmt::format("parameter path '{}': '[' without a closing ']'", path));
      current.selectors.emplace_back(path.substr(i + 1, close - i - 1));
      i = close;
      in_key = false;
    } else if (c == '.') {
      if (current.key.empty()) throw ParameterError(fmt::format("parameter path '{}': empty key before '.'", path));
      segments.push_back(std::move(current));
      current = {};
      in_key = true;
    } else if (!in_key) {
      throw ParameterError(fmt::format("parameter path '{}': expected '.' or '[' after ']', got '{}'", path, c));
    } else {
      current.key += c;
    }
  }
  if (current.key.empty()) throw ParameterError(fmt::format("parameter path '{}': it ends without a key", path));
  segments.push_back(std::move(current));
  return segments;
}

/// A number a path has found: how to read and write it, and what it is.
struct Slot {
  std::string path;  ///< the canonical path (entries by index)
  std::optional<Quantity> quantity;
  bool integer = false;
  std::string unit;
  std::string doc;
  std::function<std::optional<Real>()> get;
  std::function<void(Real)> set;
};

/// Walks a path through a spec (non-const: the slot may set the value).
class Resolver {
 public:
  Resolver(ModelSpec& spec, std::string_view path) : spec_(spec), text_(path) {}

  Slot resolve();

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ParameterError(fmt::format("parameter path '{}': {}", text_, what));
  }
  void no_selectors(const Segment& s) const {
    if (!s.selectors.empty()) fail(fmt::format("'{}' is not a list; leave out '[{}]'", s.key, s.selectors.front()));
  }
  void last(std::size_t i, const Segment& s) const {
    if (i + 1 != segments_.size())
      fail(fmt::format("'{}' is a number; nothing follows it ('{}')", s.key, segments_[i + 1].key));
  }
  template <class S>
  std::size_t find_entry(const std::vector<S>& entries, const Segment& s) const;
  template <class S>
  Slot entry(S& e, std::size_t i, const std::string& path);
  template <class S>
  Slot field(S& e, const spec::Field<S>& f, std::size_t i, const std::string& path);
  Slot coefficient(std::optional<SpeedCoefficient>& c, Quantity kind, std::size_t i, const std::string& path,
                   std::string_view doc);

  ModelSpec& spec_;
  std::string text_;
  std::vector<Segment> segments_;
};

Slot Resolver::resolve() {
  segments_ = parse_path(text_);
  const Segment& top = segments_.front();
  std::optional<Slot> slot;
  std::vector<std::string> keys;
  spec::visit_tables(spec_, [&](std::string_view key, spec::TableForm, std::string_view, auto& member) {
    keys.emplace_back(key);
    if (key != top.key || slot) return;
    using M = std::remove_cvref_t<decltype(member)>;
    if constexpr (requires { typename M::value_type; }) {
      if (top.selectors.size() != 1)
        fail(
            fmt::format("'{}' is a list of [[{}]] entries: name one by index or name, e.g. "
                        "{}[0]",
                        key, key, key));
      const std::size_t index = find_entry(member, top);
      slot = entry(member[index], 1, spec::element(key, index));
    } else {
      no_selectors(top);
      slot = entry(member, 1, std::string(key));
    }
  });
  if (slot) return *slot;
  std::string message = fmt::format("there is no table '{}'", top.key);
  if (const auto m = closest_match(top.key, keys, 3))
    message += fmt::format("; did you mean '{}'?", *m);
  else
    message += fmt::format("; the tables are {}", join_list(keys, "and", '\''));
  fail(message);
}

template <class S>
std::size_t Resolver::find_entry(const std::vector<S>& entries, const Segment& s) const {
  const std::string& selector = s.selectors.front();
  if (detail::all_digits(selector)) {
    const std::size_t index = std::stoul(selector);
    if (index >= entries.size())
      fail(entries.empty() ? fmt::format("'{}' has no entries", s.key)
                           : fmt::format("'{}' has {} entries, indices 0 to {}; got {}", s.key, entries.size(),
                                         entries.size() - 1, index));
    return index;
  }
  std::vector<std::size_t> found;
  std::vector<std::string> names;
  if constexpr (requires(const S& e) { e.name; }) {
    for (std::size_t i = 0; i < entries.size(); ++i) {
      if (entries[i].name == selector) found.push_back(i);
      if (!entries[i].name.empty()) names.push_back(entries[i].name);
    }
  }
  if constexpr (requires(const S& e) { e.node; }) {
    if (found.empty())
      for (std::size_t i = 0; i < entries.size(); ++i)
        if (const auto* n = std::get_if<std::string>(&entries[i].node)) {
          bool unnamed = true;
          if constexpr (requires(const S& e) { e.name; }) unnamed = entries[i].name.empty();
          if (unnamed && *n == selector) found.push_back(i);
          if (unnamed) names.push_back(*n);
        }
  }
  if (found.size() == 1) return found.front();
  if (found.size() > 1)
    fail(fmt::format("'{}[{}]' is ambiguous: {} entries have that name; use an index", s.key, selector, found.size()));
  std::string message = fmt::format("'{}' has no entry named '{}'", s.key, selector);
  if (const auto m = closest_match(selector, names, 2))
    message += fmt::format("; did you mean '{}'?", *m);
  else if (!names.empty() && names.size() <= 10)
    message += fmt::format("; the names are {}", join_list(names, "and", '\''));
  else if (names.empty())
    message += "; its entries have no names: use an index, e.g. [0]";
  fail(message);
}

template <class S>
Slot Resolver::entry(S& e, std::size_t i, const std::string& path) {
  if (i >= segments_.size())
    fail(
        fmt::format("'{}' is a table; name one of its keys, e.g. {}.{}", path, path, spec::fields_of<S>().front().key));
  const Segment& s = segments_[i];
  std::optional<Slot> slot;
  spec::visit_children(e, [&](std::string_view key, std::string_view, auto& children) {
    if (key != s.key) return;
    if (s.selectors.size() != 1)
      fail(fmt::format("'{}' is a list: name one entry by index or name, e.g. {}[0]", key, key));
    const std::size_t index = find_entry(children, s);
    slot = entry(children[index], i + 1, spec::element(spec::child(path, key), index));
  });
  if (slot) return *slot;
  std::vector<std::string> numeric;
  for (const spec::Field<S>& f : spec::fields_of<S>()) {
    const bool is_number = f.kind == FieldKind::quantity || f.kind == FieldKind::number ||
                           f.kind == FieldKind::coefficient || f.kind == FieldKind::time_table ||
                           f.kind == FieldKind::integer_list || (f.kind == FieldKind::integer && f.key != "number");
    if (is_number) numeric.emplace_back(f.key);
    if (f.key != s.key) continue;
    if (!is_number)
      fail(fmt::format("'{}' is not a number (it is {}); only numbers can be set by a path", s.key,
                       f.kind == FieldKind::integer                                  ? "a node number"
                       : f.kind == FieldKind::flag                                   ? "true or false"
                       : f.kind == FieldKind::node || f.kind == FieldKind::node_list ? "a node reference"
                                                                                     : "a name or a choice"));
    return field(e, f, i, spec::child(path, f.key));
  }
  spec::visit_children(e, [&](std::string_view key, std::string_view, auto&) { numeric.emplace_back(key); });
  std::string message = fmt::format("'{}' has no key '{}'", path, s.key);
  if (const auto m = closest_match(s.key, numeric, 3))
    message += fmt::format("; did you mean '{}'?", *m);
  else
    message += fmt::format("; its numbers are {}", join_list(numeric, "and", '\''));
  fail(message);
}

template <class S>
Slot Resolver::field(S& e, const spec::Field<S>& f, std::size_t i, const std::string& path) {
  const Segment& s = segments_[i];
  Slot slot;
  slot.path = path;
  slot.doc = std::string(f.doc);
  slot.unit = std::string(f.unit);
  if (f.kind == FieldKind::quantity) slot.quantity = spec::value_quantity(e, f);
  std::visit(
      [&](auto member) {
        using T = std::remove_cvref_t<decltype(spec::member_of(e, member))>;
        T& v = spec::member_of(e, member);
        if constexpr (std::is_same_v<T, Real>) {
          no_selectors(s);
          last(i, s);
          slot.get = [&v] { return std::optional<Real>(v); };
          slot.set = [&v](Real x) { v = x; };
        } else if constexpr (std::is_same_v<T, std::optional<Real>>) {
          no_selectors(s);
          last(i, s);
          slot.get = [&v] { return v; };
          slot.set = [&v](Real x) { v = x; };
        } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>) {
          no_selectors(s);
          last(i, s);
          slot.integer = true;
          slot.get = [&v]() -> std::optional<Real> {
            if constexpr (std::is_same_v<T, int>)
              return static_cast<Real>(v);
            else
              return v ? std::optional<Real>(static_cast<Real>(*v)) : std::nullopt;
          };
          slot.set = [&v](Real x) { v = static_cast<int>(x); };
        } else if constexpr (std::is_same_v<T, std::vector<int>>) {
          last(i, s);
          if (s.selectors.size() != 1) fail(fmt::format("'{}' is a list: name an entry, e.g. {}[0]", s.key, s.key));
          Segment list{s.key, s.selectors};
          const std::size_t index = find_entry(v, list);
          slot.path = spec::element(path, index);
          slot.integer = true;
          slot.get = [&v, index] { return std::optional<Real>(static_cast<Real>(v[index])); };
          slot.set = [&v, index](Real x) { v[index] = static_cast<int>(x); };
        } else if constexpr (std::is_same_v<T, std::vector<std::pair<Real, Real>>>) {
          last(i, s);
          if (s.selectors.size() != 2 || !detail::all_digits(s.selectors[1]) || std::stoul(s.selectors[1]) > 1)
            fail(
                fmt::format("'{0}' is a list of [time, {1}] points: name one number, e.g. "
                            "{0}[1][0] for the second point's time or {0}[1][1] for its {1}",
                            s.key, quantity_noun(spec::value_quantity(e, f))));
          const std::size_t index = find_entry(v, s);
          const bool speed = s.selectors[1] == "1";  // the value column
          slot.path = spec::element(spec::element(path, index), speed ? 1 : 0);
          slot.quantity = speed ? spec::value_quantity(e, f) : Quantity::time;
          slot.unit = speed ? std::string(f.unit) : "";
          slot.get = [&v, index, speed] { return std::optional<Real>(speed ? v[index].second : v[index].first); };
          slot.set = [&v, index, speed](Real x) { (speed ? v[index].second : v[index].first) = x; };
        } else if constexpr (std::is_same_v<T, std::optional<SpeedCoefficient>>) {
          no_selectors(s);
          slot = coefficient(v, f.quantity, i, path, f.doc);
        } else {
          fail(fmt::format("'{}' is not a number", s.key));
        }
      },
      f.member);
  return slot;
}

Slot Resolver::coefficient(std::optional<SpeedCoefficient>& c, Quantity kind, std::size_t i, const std::string& path,
                           std::string_view doc) {
  Slot slot;
  slot.path = path;
  slot.doc = std::string(doc);
  slot.quantity = kind;
  if (i + 1 == segments_.size()) {
    // The coefficient itself: a constant, or the value an arctan law scales.
    if (c && std::holds_alternative<SpeedCoefficient::Table>(c->law()))
      fail(fmt::format("'{}' follows a table law: name an entry, e.g. {}.values[0]", segments_[i].key, path));
    if (c && std::holds_alternative<SpeedCoefficient::FrequencyTable>(c->law()))
      fail(
          fmt::format("'{}' follows a frequency table law: name an entry, e.g. {}.values[0] (or "
                      "{}.values[0][0] with speeds)",
                      segments_[i].key, path, path));
    if (c && std::holds_alternative<SpeedCoefficient::Step>(c->law()))
      fail(fmt::format("'{}' follows a step law: name a part, {}.below, {}.above or {}.at", segments_[i].key, path,
                       path, path));
    slot.get = [&c]() -> std::optional<Real> {
      if (!c) return std::nullopt;
      if (const auto* a = std::get_if<SpeedCoefficient::Arctan>(&c->law())) return a->value;
      return std::get<SpeedCoefficient::Constant>(c->law()).value;
    };
    slot.set = [&c](Real x) {
      if (c)
        if (const auto* a = std::get_if<SpeedCoefficient::Arctan>(&c->law())) {
          SpeedCoefficient::Arctan changed = *a;
          changed.value = x;
          c = SpeedCoefficient(SpeedCoefficient::Law{changed});
          return;
        }
      c = SpeedCoefficient(x);
    };
    return slot;
  }
  const Segment& part = segments_[i + 1];
  last(i + 1, part);
  if (!c) fail(fmt::format("'{}' is not given, so it has no part '{}'", segments_[i].key, part.key));
  slot.path = spec::child(path, part.key);
  // Each law's parts as (name, member reader); the law is rebuilt when one is set.
  std::vector<std::string> parts;
  const auto bind = [&](auto law, auto pick, std::optional<Quantity> q, std::string unit) {
    slot.quantity = q;
    slot.unit = std::move(unit);
    slot.get = [&c, pick] {
      auto l = std::get<decltype(law)>(c->law());
      return std::optional<Real>(pick(l));
    };
    slot.set = [&c, pick](Real x) {
      auto l = std::get<decltype(law)>(c->law());
      pick(l) = x;
      c = SpeedCoefficient(SpeedCoefficient::Law{l});
    };
  };
  bool found = false;
  std::visit(
      [&](const auto& law) {
        using L = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<L, SpeedCoefficient::Constant>) {
          parts = {};
        } else if constexpr (std::is_same_v<L, SpeedCoefficient::Arctan>) {
          parts = {"value", "f_as", "c0", "c1", "c2"};
          if (!part.selectors.empty()) return;
          found = true;
          if (part.key == "value")
            bind(
                L{}, [](L& l) -> Real& { return l.value; }, kind, "");
          else if (part.key == "f_as")
            bind(
                L{}, [](L& l) -> Real& { return l.f_as; }, Quantity::frequency, "");
          else if (part.key == "c0")
            bind(
                L{}, [](L& l) -> Real& { return l.c0; }, std::nullopt, "");
          else if (part.key == "c1")
            bind(
                L{}, [](L& l) -> Real& { return l.c1; }, std::nullopt, "");
          else if (part.key == "c2")
            bind(
                L{}, [](L& l) -> Real& { return l.c2; }, std::nullopt, "");
          else
            found = false;
        } else if constexpr (std::is_same_v<L, SpeedCoefficient::Step>) {
          parts = {"below", "above", "at"};
          if (!part.selectors.empty()) return;
          found = true;
          if (part.key == "below")
            bind(
                L{}, [](L& l) -> Real& { return l.below; }, kind, "");
          else if (part.key == "above")
            bind(
                L{}, [](L& l) -> Real& { return l.above; }, kind, "");
          else if (part.key == "at")
            bind(
                L{}, [](L& l) -> Real& { return l.at; }, Quantity::speed, "Hz");
          else
            found = false;
        } else if constexpr (std::is_same_v<L, SpeedCoefficient::FrequencyTable>) {
          parts = {"frequencies", "speeds", "values"};
          if (part.key != "frequencies" && part.key != "speeds" && part.key != "values") return;
          const bool grid = !law.speeds.empty() && part.key == "values";  // values[speed][frequency]
          const std::size_t wanted = grid ? 2 : 1;
          if (part.selectors.size() != wanted)
            fail(grid ? fmt::format("'values' is a table over speeds and frequencies: name an entry, e.g. values[0][0]")
                      : fmt::format("'{}' is a list: name an entry, e.g. {}[0]", part.key, part.key));
          const std::size_t nf = law.frequencies.size();
          const auto index_in = [&](std::size_t size, std::size_t s) {
            std::vector<Real> dummy(size);
            return find_entry(dummy, Segment{part.key, {part.selectors[s]}});
          };
          found = true;
          if (part.key == "frequencies") {
            const std::size_t index = find_entry(law.frequencies, part);
            slot.path = spec::element(slot.path, index);
            bind(
                L{}, [index](L& l) -> Real& { return l.frequencies[index]; }, Quantity::speed, "Hz");
          } else if (part.key == "speeds") {
            const std::size_t index = find_entry(law.speeds, part);
            slot.path = spec::element(slot.path, index);
            bind(
                L{}, [index](L& l) -> Real& { return l.speeds[index]; }, Quantity::speed, "Hz");
          } else {
            const std::size_t row = grid ? index_in(law.speeds.size(), 0) : 0;
            const std::size_t column = index_in(nf, grid ? 1 : 0);
            slot.path = grid ? spec::element(spec::element(slot.path, row), column) : spec::element(slot.path, column);
            const std::size_t index = row * nf + column;
            bind(
                L{}, [index](L& l) -> Real& { return l.values[index]; }, kind, "");
          }
        } else {
          parts = {"speeds", "values"};
          if (part.key != "speeds" && part.key != "values") return;
          if (part.selectors.size() != 1)
            fail(fmt::format("'{}' is a list: name an entry, e.g. {}[0]", part.key, part.key));
          const std::vector<Real>& list = part.key == "speeds" ? law.speeds : law.values;
          const std::size_t index = find_entry(list, part);
          slot.path = spec::element(slot.path, index);
          found = true;
          if (part.key == "speeds")
            bind(
                L{}, [index](L& l) -> Real& { return l.speeds[index]; }, Quantity::speed, "Hz");
          else
            bind(
                L{}, [index](L& l) -> Real& { return l.values[index]; }, kind, "");
        }
      },
      c->law());
  if (found) return slot;
  if (parts.empty())
    fail(fmt::format("'{}' is a constant; set it as {} (it has no part '{}')", segments_[i].key, path, part.key));
  std::string message = fmt::format("'{}' has no part '{}'", segments_[i].key, part.key);
  if (const auto m = closest_match(part.key, parts, 2))
    message += fmt::format("; did you mean '{}'?", *m);
  else
    message += fmt::format("; its parts are {}", join_list(parts, "and", '\''));
  fail(message);
}

Real parse_value(const Slot& slot, std::string_view text, std::string_view path) {
  try {
    if (slot.quantity) return parse_quantity(text, *slot.quantity);
  } catch (const QuantityError& e) {
    throw ParameterError(fmt::format("parameter '{}': {}", path, e.what()));
  }
  const auto q = split_quantity(text);
  if (!q || !q->unit.empty())
    throw ParameterError(fmt::format("parameter '{}': expected a number without unit, got '{}'", path, text));
  if (slot.integer && (q->value != std::floor(q->value) || std::abs(q->value) > std::numeric_limits<int>::max()))
    throw ParameterError(fmt::format("parameter '{}': expected an integer, got '{}'", path, text));
  return q->value;
}

Parameter to_parameter(const Slot& slot, Real value) {
  return Parameter{slot.path, value, slot.quantity, slot.integer, slot.unit, slot.doc};
}

/// The paths of every number of an entry; the entry's own path is @p path.
template <class S>
void list_entry(const ModelSpec& spec, const S& e, const std::string& path, std::vector<std::string>& out);

/// How a listing names entry @p i of @p entries: its name when unique, else its index.
template <class S>
std::string entry_name(const std::vector<S>& entries, std::size_t i) {
  if constexpr (requires(const S& e) { e.name; }) {
    const std::string& name = entries[i].name;
    const bool usable = !name.empty() && !detail::all_digits(name) && name.find(']') == std::string::npos &&
                        std::count_if(entries.begin(), entries.end(), [&](const S& e) { return e.name == name; }) == 1;
    if (usable) return name;
  }
  return std::to_string(i);
}

template <class S>
void list_entry(const ModelSpec& spec, const S& e, const std::string& path, std::vector<std::string>& out) {
  for (const spec::Field<S>& f : spec::fields_of<S>()) {
    const std::string at = spec::child(path, f.key);
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(spec::member_of(e, member))>;
          const T& v = spec::member_of(e, member);
          if constexpr (std::is_same_v<T, Real> || std::is_same_v<T, int>) {
            out.push_back(at);
          } else if constexpr (std::is_same_v<T, std::optional<Real>> || std::is_same_v<T, std::optional<int>>) {
            if (v) out.push_back(at);
          } else if constexpr (std::is_same_v<T, std::vector<int>>) {
            for (std::size_t i = 0; i < v.size(); ++i) out.push_back(spec::element(at, i));
          } else if constexpr (std::is_same_v<T, std::vector<std::pair<Real, Real>>>) {
            for (std::size_t i = 0; i < v.size(); ++i) {
              out.push_back(spec::element(spec::element(at, i), 0));
              out.push_back(spec::element(spec::element(at, i), 1));
            }
          } else if constexpr (std::is_same_v<T, std::optional<SpeedCoefficient>>) {
            if (!v) return;
            std::visit(
                [&](const auto& law) {
                  using L = std::decay_t<decltype(law)>;
                  if constexpr (std::is_same_v<L, SpeedCoefficient::Constant>) {
                    out.push_back(at);
                  } else if constexpr (std::is_same_v<L, SpeedCoefficient::Arctan>) {
                    for (const char* p : {"value", "f_as", "c0", "c1", "c2"}) out.push_back(spec::child(at, p));
                  } else if constexpr (std::is_same_v<L, SpeedCoefficient::Step>) {
                    for (const char* p : {"below", "above", "at"}) out.push_back(spec::child(at, p));
                  } else if constexpr (std::is_same_v<L, SpeedCoefficient::FrequencyTable>) {
                    for (std::size_t i = 0; i < law.speeds.size(); ++i)
                      out.push_back(spec::element(spec::child(at, "speeds"), i));
                    for (std::size_t j = 0; j < law.frequencies.size(); ++j)
                      out.push_back(spec::element(spec::child(at, "frequencies"), j));
                    const std::size_t nf = law.frequencies.size();
                    for (std::size_t k = 0; k < law.values.size(); ++k)
                      out.push_back(law.speeds.empty()
                                        ? spec::element(spec::child(at, "values"), k)
                                        : spec::element(spec::element(spec::child(at, "values"), k / nf), k % nf));
                  } else {
                    for (std::size_t i = 0; i < law.speeds.size(); ++i)
                      out.push_back(spec::element(spec::child(at, "speeds"), i));
                    for (std::size_t i = 0; i < law.values.size(); ++i)
                      out.push_back(spec::element(spec::child(at, "values"), i));
                  }
                },
                v->law());
          }
        },
        f.member);
  }
  spec::visit_children(e, [&](std::string_view key, std::string_view, const auto& children) {
    for (std::size_t i = 0; i < children.size(); ++i)
      list_entry(spec, children[i], spec::element(spec::child(path, key), i), out);
  });
}

Slot resolve(ModelSpec& spec, std::string_view path) { return Resolver(spec, path).resolve(); }

}  // namespace

std::vector<Parameter> list_parameters(const ModelSpec& spec) {
  std::vector<std::string> paths;
  spec::visit_tables(spec, [&](std::string_view key, spec::TableForm, std::string_view, const auto& member) {
    using M = std::remove_cvref_t<decltype(member)>;
    if constexpr (requires { typename M::value_type; }) {
      for (std::size_t i = 0; i < member.size(); ++i)
        list_entry(spec, member[i], fmt::format("{}[{}]", key, entry_name(member, i)), paths);
    } else {
      list_entry(spec, member, std::string(key), paths);
    }
  });
  std::vector<Parameter> out;
  ModelSpec copy = spec;  // resolving binds to a spec it could change; this one stays as it is
  for (const std::string& path : paths) {
    const Slot slot = resolve(copy, path);
    Parameter p = to_parameter(slot, *slot.get());
    p.path = path;
    out.push_back(std::move(p));
  }
  return out;
}

Parameter get_parameter(const ModelSpec& spec, std::string_view path) {
  ModelSpec copy = spec;  // resolving binds to a spec it could change; this one stays as it is
  const Slot slot = resolve(copy, path);
  const std::optional<Real> value = slot.get();
  if (!value) throw ParameterError(fmt::format("parameter '{}' is not given in this model (it can be set)", path));
  Parameter p = to_parameter(slot, *value);
  p.path = std::string(path);
  return p;
}

std::string set_parameter(ModelSpec& spec, std::string_view path, std::string_view value) {
  const Slot slot = resolve(spec, path);
  slot.set(parse_value(slot, value, path));
  return slot.path;
}

std::string set_parameter(ModelSpec& spec, std::string_view path, Real si) {
  const Slot slot = resolve(spec, path);
  if (slot.integer && (si != std::floor(si) || std::abs(si) > std::numeric_limits<int>::max()))
    throw ParameterError(fmt::format("parameter '{}': expected an integer, got {}", path, si));
  slot.set(si);
  return slot.path;
}

std::string apply_assignment(ModelSpec& spec, std::string_view assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string_view::npos)
    throw ParameterError(
        fmt::format("--set '{}': expected PATH=VALUE, e.g. "
                    "'springs[bearing 1].ky=2e7 N/m'",
                    assignment));
  std::string_view path = assignment.substr(0, eq);
  std::string_view value = assignment.substr(eq + 1);
  while (!path.empty() && path.back() == ' ') path.remove_suffix(1);
  while (!path.empty() && path.front() == ' ') path.remove_prefix(1);
  try {
    return set_parameter(spec, path, value);
  } catch (const ParameterError& e) {
    throw ParameterError(fmt::format("--set '{}': {}", assignment, e.what()));
  }
}

}  // namespace feran
