#pragma once
/// @file
/// Reads a model file (TOML, format in docs/model-format.md) into a ModelSpec, and
/// through build_model() into a Model.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <feran/core/error.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>
#include <feran/spec/build_model.hpp>
#include <feran/spec/model_spec.hpp>

namespace feran {

class Assembler;  // feran/assembly/assembler.hpp

/// Defaults for a Campbell diagram given in the model file's [campbell] table.
/// Empty members were not given.
struct CampbellDefaults {
  std::optional<Real> start;  ///< first speed [rad/s]
  std::optional<Real> stop;   ///< last speed [rad/s]
  std::optional<int> points;  ///< number of speeds (≥ 2)
  std::optional<int> modes;   ///< number of modes to track (≥ 1)
  std::vector<int> orders;    ///< excitation orders k of the k·Ω lines, as given
};

/// Defaults for a modal analysis given in the model file's [modal] table.
struct ModalDefaults {
  std::optional<Real> speed;  ///< [rad/s]
  std::optional<int> modes;   ///< number of modes (≥ 1)
};

/// Defaults for a steady-state (harmonic) response given in the model file's
/// [response] table. Empty members were not given.
struct ResponseDefaults {
  std::optional<Real> start;  ///< first speed or frequency of the sweep [rad/s]
  std::optional<Real> stop;   ///< last one [rad/s]; > start when both are given
  std::optional<int> points;  ///< number of sweep points (≥ 2)
  /// Nodes whose response is reported, as indices into model.nodes (no duplicates;
  /// empty when not given).
  std::vector<Index> probes;
  /// Global hysteretic loss factor η ≥ 0: adds j·η·K of every element to the
  /// dynamic stiffness, on top of the elements' own loss factors.
  std::optional<Real> loss_factor;
};

/// Defaults for a static analysis given in the model file's [static] table.
struct StaticDefaults {
  /// Gravitational acceleration vector (x, y, z) [m/s²]; the zero vector for
  /// gravity = "none"; empty when not given.
  std::optional<Eigen::Vector3d> gravity;
  /// Speed at which speed-dependent coefficients are evaluated [rad/s].
  std::optional<Real> speed;
};

/// Defaults for a run-up (transient) analysis given in the model file's [runup] table.
/// Empty members were not given.
struct RunupDefaults {
  /// Speed profile as (time [s], speed [rad/s]) points, piecewise linear, held
  /// constant after the last point; empty when not given. Times start at 0 and are
  /// strictly increasing; speeds are ≥ 0. A constant speed is one point (0, Ω), a
  /// ramp the two points (0, from) and (ramp_time, to).
  std::vector<std::pair<Real, Real>> profile;
  /// Length of the run [s] (> 0); when not given, the ramp time or the last table
  /// time (if > 0).
  std::optional<Real> duration;
  /// Time integrator: "trapezoidal", "rk3", "wolfbrandt" or "ros34pw2".
  std::optional<std::string> integrator;
  std::optional<Real> dt;               ///< fixed step / initial step [s] (> 0)
  std::optional<Real> rel_tol;          ///< relative tolerance of adaptive stepping (> 0)
  std::optional<Real> abs_tol;          ///< absolute tolerance of adaptive stepping (> 0)
  std::optional<Real> output_interval;  ///< time between recorded samples [s] (> 0)
  /// Integrate in a basis of this many undamped modes (≥ 1; see
  /// TransientOptions::reduced_modes); not given: the full model.
  std::optional<Index> modes;
  /// Nodes whose response is recorded, as indices into model.nodes (no duplicates;
  /// empty when not given).
  std::vector<Index> probes;
  /// Spring–dampers whose forces are recorded, as indices into model.elements, in
  /// the order given (no duplicates; empty when not given). Only a [[springs]] entry
  /// with a 'name' can be referenced.
  std::vector<Index> springs;
};

/// Gravitational acceleration used when [static] gives a direction but no 'g' [m/s²].
inline constexpr Real default_gravity = 9.81;

/// A model file as read: its spec, the model built from it and the analysis defaults
/// it states.
struct ModelFile {
  ModelSpec spec;      ///< what the file says
  SpecSource source;   ///< where the file says it (for messages about the spec)
  Model model;         ///< build_model(spec)
  /// The model as the reader's check assembled it: analyses of this very model may
  /// reuse it instead of assembling again (not after changing the model).
  std::shared_ptr<const Assembler> assembler;
  std::string path;   ///< the path the file was read from (or named for messages)
  std::string title;  ///< the file's title (also model.name); may be empty
  ModalDefaults modal;
  CampbellDefaults campbell;
  ResponseDefaults response;
  StaticDefaults static_;  ///< the [static] table ("static" is a C++ keyword)
  RunupDefaults runup;
  /// Per node index (model.nodes order): where the node was defined, for messages.
  std::vector<SourceLocation> node_locations;
};

/// Reads TOML text into a ModelSpec without checking its values (only what TOML can
/// get wrong: syntax, unknown and missing keys, types and units). @p source, when
/// given, receives where each part was written; SpecSource::locate() turns a
/// SpecError of build_model() into a ModelError at that place. Throws ModelError.
ModelSpec read_model_spec(std::string_view toml_text, const std::string& path_for_messages,
                          SpecSource* source = nullptr);

/// The bytes of the file at @p path; throws feran::Error when it cannot be read.
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

/// Reads and checks a model given as TOML text; @p path_for_messages names it in
/// errors and in ModelFile::path. Throws ModelError as read_model_file() does.
ModelFile read_model_string(std::string_view toml_text, const std::string& path_for_messages);

}  // namespace feran
