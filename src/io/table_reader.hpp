#pragma once
/// @file
/// Typed, located access to the keys of one TOML table (private to io/).
///
/// Every failure throws ModelError located at the offending value (or, for a
/// missing key, at the table) and phrased for the person who wrote the file.

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "toml.hpp"

#include <feran/core/error.hpp>
#include <feran/core/types.hpp>
#include <feran/core/units.hpp>

namespace feran::detail {

/// Where @p node is in file @p path.
SourceLocation location_of(const std::string& path, const toml::node& node);

/// @p text without a UTF-8 byte-order mark (which is skipped); a file in UTF-16 or
/// UTF-32 (by its byte-order mark, or by the zero bytes of its first characters) is
/// refused as such, located at @p path:1:1, since TOML files are UTF-8.
std::string_view utf8_text(std::string_view text, const std::string& path);

/// The TOML table of @p text (utf8_text() first); a syntax error is a ModelError at
/// its line and column of @p path.
toml::table parse_toml(std::string_view text, const std::string& path);

/// "a string", "an integer", "a floating-point number", "a boolean", "an array", …
std::string type_name(const toml::node& node);

/// A quantity read from a file: its SI value and how it was written ("68 mm", or
/// "0.068 m" for a bare number), for messages.
struct QuantityValue {
  Real si = 0.0;
  std::string written;
  const toml::node* node = nullptr;  ///< where it was written
};

/// One TOML table being read: its keys, their types and units.
class TableReader {
 public:
  /// @p context names the table in messages ("[[shafts.sections]]", "coefficient 'kx'");
  /// empty for the top level. @p path is the file name for locations; it must outlive
  /// the reader.
  TableReader(const toml::table& table, std::string context, const std::string& path);

  const toml::table& table() const { return table_; }
  const std::string& context() const { return context_; }
  const std::string& path() const { return path_; }

  /// Throws for the first key (in file order) that is not in @p allowed, suggesting
  /// the nearest allowed key (edit distance ≤ 3) or listing them all.
  void check_keys(const std::vector<std::string_view>& allowed) const;
  void check_keys(std::initializer_list<std::string_view> allowed) const {
    check_keys(std::vector<std::string_view>(allowed));
  }

  /// The value of @p key, or nullptr.
  const toml::node* find(std::string_view key) const;
  bool has(std::string_view key) const { return find(key) != nullptr; }
  /// The value of @p key; throws "missing key 'key' in <context> (expected <expected>)".
  const toml::node& require(std::string_view key, std::string_view expected) const;

  /// Throws ModelError at @p node.
  [[noreturn]] void fail(const toml::node& node, const std::string& message) const;
  /// Throws ModelError at the table itself.
  [[noreturn]] void fail_here(const std::string& message) const;

  /// A quantity of kind @p kind; nullopt when @p key is absent.
  std::optional<QuantityValue> quantity(std::string_view key, Quantity kind) const;
  QuantityValue required_quantity(std::string_view key, Quantity kind) const;
  /// A quantity at @p node, named @p name in messages (e.g. "kx.values[2]").
  QuantityValue quantity_at(const toml::node& node, std::string_view name, Quantity kind) const;

  /// A dimensionless number (integer or float); nullopt when absent.
  std::optional<Real> number(std::string_view key) const;
  /// A dimensionless number ≥ 0; throws "'key' must not be negative, got …".
  std::optional<Real> non_negative_number(std::string_view key) const;
  /// A dimensionless number > 0; throws "'key' must be positive, got …".
  std::optional<Real> positive_number(std::string_view key) const;
  std::optional<bool> boolean(std::string_view key) const;
  std::optional<std::string> string(std::string_view key) const;
  std::string required_string(std::string_view key, std::string_view expected) const;
  /// An integer ≥ @p minimum (and ≤ @p maximum); nullopt when absent.
  std::optional<int> integer(std::string_view key, int minimum, int maximum = 1'000'000'000) const;
  /// An integer at @p node, named @p name.
  int integer_at(const toml::node& node, std::string_view name, int minimum, int maximum = 1'000'000'000) const;
  /// An array; nullopt when absent.
  const toml::array* array(std::string_view key) const;
  /// An array that must be present.
  const toml::array& required_array(std::string_view key, std::string_view expected) const;

  /// Throws "'key' must be positive, got …" unless q > 0.
  void require_positive(const QuantityValue& q, std::string_view name) const;
  /// Throws "'key' must not be negative, got …" unless q ≥ 0.
  void require_non_negative(const QuantityValue& q, std::string_view name) const;

 private:
  const toml::table& table_;
  std::string context_;
  const std::string& path_;
};

using feran::expected_quantity;
using feran::must_be_quantity;

}  // namespace feran::detail
