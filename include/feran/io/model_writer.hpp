#pragma once
/// @file
/// Writes a model specification as a model file (TOML, docs/model-format.md).

#include <string>

#include <feran/spec/model_spec.hpp>

namespace feran {

/// The model file that says what @p spec says: every table and key that differs from
/// its default, in the order of the field tables (spec/fields.hpp), quantities as
/// strings with their unit ("68 mm"; the SI unit where the field's unit would not
/// read back as exactly the same number), coefficient laws as inline tables.
/// read_model_spec(write_toml(spec)) == spec for every spec (values are written with
/// the shortest digits that read back exactly).
std::string write_toml(const ModelSpec& spec);

}  // namespace feran
