#pragma once
// One table of a TOML file read into a spec by its field table, as the model reader
// reads the model file's tables (keys, kinds, units, choices, every error located):
// REPORT.toml's [campbell], [response] and [api684] are read so (report_config.cpp).

#include <span>
#include <string>
#include <string_view>

#include "toml.hpp"

namespace feran::detail {

/// Reads @p table, shown as @p context ("[campbell]") in file @p file, into a spec of
/// type S; the keys in @p extra are left to the caller (they are not S's). Each value
/// is checked by its field's rule (bounds, physical range, choices), an error a
/// ModelError at the key. Instantiated for CampbellSpec, ResponseSpec and Api684Spec.
template <class S>
S read_spec_table(const toml::table& table, std::string_view context, const std::string& file,
                  std::span<const std::string_view> extra = {});

}  // namespace feran::detail
