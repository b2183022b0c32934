#pragma once
/// @file
/// Reads a model file (TOML, format in docs/model-format.md) into a ModelSpec, and
/// through build_model() into a Model.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <feran/core/error.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>
#include <feran/spec/build_model.hpp>
#include <feran/spec/model_spec.hpp>

namespace feran {

class Assembler;  // feran/assembly/assembler.hpp

/// A model file as read: its spec and the model built from it. The analysis tables
/// stay in the spec (spec.modal, spec.campbell, …); analyses/settings.hpp resolves
/// them with a caller's request and the built-in defaults.
struct ModelFile {
  ModelSpec spec;     ///< what the file says
  SpecSource source;  ///< where the file says it (for messages about the spec)
  Model model;        ///< build_model(spec)
  /// The model as the reader's check assembled it: analyses of this very model may
  /// reuse it instead of assembling again (not after changing the model).
  std::shared_ptr<const Assembler> assembler;
  std::string path;   ///< the path the file was read from (or named for messages)
  std::string title;  ///< the file's title (also model.name); may be empty
  /// Per node index (model.nodes order): where the node was defined, for messages.
  std::vector<SourceLocation> node_locations;
};

/// Reads TOML text into a ModelSpec without checking its values (only what TOML can
/// get wrong: syntax, unknown and missing keys, types and units). @p source, when
/// given, receives where each part was written; SpecSource::locate() turns a
/// SpecError of build_model() into a ModelError at that place. Throws ModelError.
ModelSpec read_model_spec(std::string_view toml_text, const std::string& path_for_messages,
                          SpecSource* source = nullptr);

/// The largest model file read_text_file() reads: 64 MiB (a mesh of a million
/// elements is a few hundred bytes; a file this large is not a model).
inline constexpr std::uintmax_t max_model_file_bytes = std::uintmax_t{64} << 20;

/// The bytes of the file at @p path; throws feran::Error (saying why) when it does
/// not exist, cannot be read, is not a regular file (a directory, FIFO, device or
/// socket) or is larger than max_model_file_bytes.
std::string read_text_file(const std::string& path);

/// Reads and checks the model file at @p path.
/// Throws feran::Error when the file cannot be read, and ModelError (file, line,
/// column and message) for any problem in its content, including a model that
/// check_model() rejects (no mass on some DOF, an unintended free motion).
ModelFile read_model_file(const std::string& path);

/// Reads the model file at @p path, sets the parameters of @p assignments ("PATH=VALUE",
/// spec/parameters.hpp) in its spec, and then builds and checks it. A bad assignment
/// throws ParameterError; a problem that build_model() finds in a value that an
/// assignment set is reported as "--set 'PATH=VALUE': …" instead of at the file's line.
ModelFile read_model_file(const std::string& path, const std::vector<std::string>& assignments);

/// Builds and checks @p spec, read from @p path with @p source (where each part was
/// written, for located errors) and changed since by set_parameter(): @p changed
/// pairs how each change is named in messages ("--set 'PATH=VALUE'") with the
/// canonical path it set. A problem in a changed value is reported as "NAME: …"
/// instead of at the file's line. Throws ModelError, or Error for a changed value.
ModelFile build_model_file(ModelSpec spec, SpecSource source, std::string path,
                           const std::vector<std::pair<std::string, std::string>>& changed = {});

/// Reads and checks a model given as TOML text; @p path_for_messages names it in
/// errors and in ModelFile::path. Throws ModelError as read_model_file() does.
ModelFile read_model_string(std::string_view toml_text, const std::string& path_for_messages);

}  // namespace feran
