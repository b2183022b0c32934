#pragma once
/// @file
/// How a model file refers to a node.

#include <cstdint>
#include <string>
#include <variant>

namespace feran {

/// A reference to a node: its number (an integer) or its name (a string). A string
/// is always a name, even when it is all digits.
using NodeRef = std::variant<std::int64_t, std::string>;

}  // namespace feran
