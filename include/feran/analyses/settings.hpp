#pragma once
/// @file
/// What the analyses share: their built-in defaults used by more than one, the probes
/// they report by default, evenly spaced sweeps, node options, range warnings and
/// bearings by name. Each analysis's own options are its room's (analyses/<name>/),
/// taken through analyses/analysis.hpp's generic request step.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/campbell/campbell.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/static/static_analysis.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/model/model.hpp>
#include <feran/spec/model_spec.hpp>

namespace feran {

/// Built-in defaults, used when neither the request nor the model file gives a value.
namespace defaults {
inline constexpr int campbell_points = 101;
inline constexpr int campbell_modes = 8;
inline constexpr int response_points = 201;
inline constexpr int frequency_points = 201;
inline constexpr Real gravity = standard_gravity;  ///< [m/s²], pulling along −y
inline constexpr Real runup_dt = 1e-4;             ///< [s]
inline constexpr Real output_interval = 1e-3;      ///< [s]
/// The most steps a fixed-step run-up takes (duration / dt), and the most samples it
/// records (duration / output interval): bounds on its work and its output files, the
/// same whether the values come from the model file or the command line.
inline constexpr Real max_runup_steps = 1e9;
inline constexpr Real max_runup_samples = 1e7;
}  // namespace defaults

/// @p n values from @p a to @p b evenly spaced (@p a alone for n = 1).
std::vector<Real> evenly_spaced(Real a, Real b, int n);

/// The nodes a response or a run-up reports when neither the request nor the file
/// names any: every node carrying an unbalance, then every node of @p extra forces,
/// in order, each once.
std::vector<Index> default_probes(const Model& model, std::span<const HarmonicForce> extra = {});

/// The nodes @p refs denote (names or numbers), as an option named @p option gives
/// them; throws Error for an unknown node (with a suggestion) or a node given twice.
std::vector<Index> distinct_nodes(const Model& model, const std::vector<NodeRef>& refs, const std::string& option);

/// The node a (validated) reference of a spec denotes; throws Error when there is none.
Index node_index(const Model& model, const NodeRef& ref);

/// Warnings for the tabulated data of @p model that an analysis over the speeds
/// [@p low, @p high] (rad/s) evaluates beyond its range, one per table: "spring
/// 'bearing': coefficient 'ky' is tabulated from 0 to 100 Hz; the analysis reaches
/// 150 Hz, where its last value is held". Frequency tables are checked against the
/// frequencies of the motion [@p frequencies] (rad/s; empty: synchronous, the speeds').
std::vector<std::string> range_warnings(const Model& model, Real low, Real high,
                                        std::optional<std::pair<Real, Real>> frequencies = std::nullopt);

/// The span [rad/s] of the motion's frequencies @p frequencies_hz [Hz] (their absolute
/// values, the non-finite left out), for range_warnings(); empty when there are none.
std::optional<std::pair<Real, Real>> frequency_span(std::span<const Real> frequencies_hz);

/// The speeds a run-up visits: the lowest and highest of its profile up to its end; for
/// a torque-driven run, from its first speed to its motor's free speed.
std::pair<Real, Real> speed_span(const Model& model, const TransientOptions& options);

/// The spring–damper element labelled @p name; throws Error when there is none.
Index spring_element(const Model& model, const std::string& name);

/// The bearing labelled @p name, numbered as an element of linearised(@p model): a
/// spring–damper, or a journal or rolling bearing (after the model's own elements).
/// Throws Error, listing the named ones, when there is none.
Index bearing_element(const Model& model, const std::string& name);

}  // namespace feran
