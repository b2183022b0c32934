#pragma once
/// @file
/// From a model specification to a model: meshing, numbering and validation.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <feran/core/error.hpp>
#include <feran/model/model.hpp>
#include <feran/spec/model_spec.hpp>

namespace feran {

class Assembler;  // feran/assembly/assembler.hpp

/// Where the parts of a spec were written, for messages: filled by a reader (the
/// TOML reader records every key it reads), empty for a spec built in code.
/// Paths are those of SpecError ("shafts[0].sections[2].length"; tables too:
/// "shafts[0].sections[2]"; "" is the file as a whole).
struct SpecSource {
  std::string file;  ///< the file's name, for locations
  /// Where each path was written.
  std::map<std::string, SourceLocation, std::less<>> places;
  /// How each quantity was written ("68 mm", or "0.068 m" for a bare number).
  std::map<std::string, std::string, std::less<>> written;

  /// Where @p path was written: its own place, else that of its nearest recorded
  /// ancestor ("a.b[2].c" → "a.b[2]" → "a.b" → "a" → ""), else line 1 of the file.
  SourceLocation locate(std::string_view path) const;
  /// @p error as a ModelError located at its path.
  ModelError locate(const SpecError& error) const;
};

/// What build_model() can tell besides the model.
struct BuildInfo {
  /// The assembler the final check used: analyses of this very model may reuse it
  /// instead of assembling again (not after changing the model).
  std::shared_ptr<const Assembler> assembler;
  /// Per node (Model::nodes order): the path of the table that defines it
  /// ("shafts[0]" for a shaft's first node, "shafts[0].sections[1]" for the nodes of a
  /// section, "nodes[2]"), for messages about nodes.
  std::vector<std::string> node_paths;
};

/// Builds the model a spec describes: creates and numbers the nodes of shafts and
/// [[nodes]] (docs/model-format.md §3), meshes sections into shaft elements, resolves
/// every node, material and spring reference, checks every value against its field's
/// bounds and every rule between fields, checks the analysis tables, and finally
/// checks the assembled model (check_model(): no DOF without mass, no free motion
/// that the options do not allow).
///
/// Throws SpecError at the path of the first problem. @p source, when given, makes
/// messages quote values as they were written and name other places by line and
/// column. @p info, when given, receives the BuildInfo.
Model build_model(const ModelSpec& spec, const SpecSource* source = nullptr, BuildInfo* info = nullptr);

}  // namespace feran
