#pragma once
/// @file
/// Paths into a ModelSpec as they appear in messages: "shafts[1].sections[2].length".

#include <cstddef>
#include <string>
#include <string_view>

namespace feran::spec {

/// "a.b" from "a" and "b"; "b" when @p path is empty.
std::string child(std::string_view path, std::string_view key);
/// "a[3]" from "a" and 3.
std::string element(std::string_view path, std::size_t index);
/// The path one step up: "a.b[2]" from "a.b[2].c", "a.b" from "a.b[2]", "" from "a".
std::string parent_path(std::string_view path);

}  // namespace feran::spec
