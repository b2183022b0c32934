#pragma once
/// @file
/// The key tables of docs/model-format.md, generated from the field tables.

#include <string>
#include <string_view>
#include <vector>

namespace feran {

/// The tables of a model file that have keys, in file order: "options", "materials",
/// "shafts", "shafts.sections", "nodes", …, "runup".
std::vector<std::string> documented_tables();

/// The markdown table of the keys of @p table (one of documented_tables()): key,
/// kind, default and constraints / meaning, each row from the key's field
/// (spec/fields.hpp). docs/model-format.md shows exactly these tables, and a test
/// keeps the two equal. Throws feran::Error for an unknown table.
std::string key_table_markdown(std::string_view table);

}  // namespace feran
