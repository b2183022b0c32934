#pragma once
/// @file
/// What a study evaluates for each design: quantities of the analyses.
///
/// Each quantity names the analysis it comes from; the analyses run with the
/// settings of the model's own tables ([campbell], [response], [runup]; a study can
/// change them by parameter path, e.g. campbell.stop), each at most once per design
/// however many quantities use it, on one thread (studies run designs side by side).

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <feran/core/stop.hpp>
#include <feran/core/types.hpp>
#include <feran/core/units.hpp>
#include <feran/model/model.hpp>
#include <feran/spec/model_spec.hpp>

namespace feran {

enum class QuantityKind {
  critical_speed,           ///< the n-th critical speed of a whirl and order in a speed range [rad/s]
  separation_margin,        ///< smallest relative distance of the critical speeds from the operating range [-]
  min_damping_ratio,        ///< smallest damping ratio of the lateral modes over a speed range [-]
  min_log_decrement,        ///< smallest logarithmic decrement over a speed range [-]
  stability_threshold,      ///< lowest speed where a mode's damping turns negative [rad/s]
  natural_frequency,        ///< the n-th natural frequency of a whirl at a speed [Hz]
  damping_ratio,            ///< the damping ratio of that mode [-]
  log_decrement,            ///< the logarithmic decrement of that mode [-]
  peak_response,            ///< largest orbit semi-axis at a probe over the unbalance response [m]
  amplification_factor,     ///< API 684 amplification factor (half-power) of the n-th resonance peak at a probe [-]
  required_margin,          ///< the separation margin API 617 requires of that peak from the operating range [-]
  margin_surplus,           ///< that peak's separation margin less the required one: ≥ 0 passes [-]
  min_margin_surplus,       ///< the smallest margin_surplus of every resonance peak at the probe: ≥ 0 all pass [-]
  undamped_critical_speed,  ///< the n-th forward undamped critical speed with the bearings as given [rad/s]
  level1_q_zero,  ///< API 617 level I: the cross-coupling Q at the probe where the first forward mode's log decrement
                  ///< is 0 at the speed [N/m]
  peak_spring_force,   ///< largest lateral force of a spring (or of all) over the response [N]
  peak_stress,         ///< largest equivalent (von Mises) shaft stress over the response [Pa]
  runup_peak,          ///< largest |r| at a probe during the run-up [m]
  runup_spring_force,  ///< largest lateral force of a spring (or of all) during the run-up [N]
  rotor_mass,          ///< mass of the rotating parts [kg]
  min_bearing_value,   ///< smallest value of a bearing's operating quantity over the Campbell speeds [its unit]
  max_bearing_value,   ///< largest value of it [its unit]
  parameter,           ///< a number of the design's model, by its parameter path (its SI unit)
  function,            ///< a function given in code (the Python package's feran.Study) [its own unit]
};

/// A quantity computed by the caller's code from the design's model (its
/// specification and the model built from it). Called on the study's worker threads,
/// side by side: it must be safe to call concurrently. Throws for a design it cannot
/// evaluate (the design is recorded as failed with the message).
using QuantityFunction = std::function<Real(const ModelSpec& spec, const Model& model)>;

/// Which modes a modal quantity looks at.
enum class WhirlSelection { forward, backward, any };

struct QuantitySpec {
  std::string name;
  QuantityKind kind = QuantityKind::critical_speed;
  WhirlSelection whirl = WhirlSelection::forward;
  int order = 1;                                   ///< excitation order of critical speeds
  int n = 1;                                       ///< which one (1: the lowest)
  std::optional<Real> low, high;                   ///< the speed range it applies to [rad/s]; default the analysis'
  Real operating_low = 0.0, operating_high = 0.0;  ///< the operating speed range [rad/s]
  std::optional<Real> speed;           ///< natural_frequency, damping_ratio, log_decrement: the rotor speed [rad/s]
  std::optional<NodeRef> probe;        ///< peak_response, runup_peak
  std::optional<std::string> spring;   ///< *_spring_force: a spring's name; empty: all
  std::optional<std::string> bearing;  ///< *_bearing_value: a bearing's name; empty: all
  std::string value;                   ///< *_bearing_value: the operating quantity ("min_film_thickness_m")
  std::string path;                    ///< parameter: the parameter path
  std::optional<Quantity> value_kind;  ///< parameter: the kind of its value (none: a number)
  std::string unit;                    ///< unit the value is shown in ("rpm", "mm"); empty: SI
  std::shared_ptr<const QuantityFunction> function;  ///< function: the code computing it
};

/// The kind of a bearing's operating quantity @p name by the unit its name ends with
/// (_m, _pa, _n, _nm, _deg; a study gives angles in rad), or nullopt for a number
/// (ratios, counts, and the power loss, in W).
std::optional<Quantity> operating_value_unit(std::string_view name);

/// The kind of @p q's value: quantity_kind_unit(q.kind), for a parameter its kind, for
/// a bearing value its quantity's.
std::optional<Quantity> quantity_unit(const QuantitySpec& q);

/// The kind a quantity's value has (for units), or nullopt for a pure number.
std::optional<Quantity> quantity_kind_unit(QuantityKind kind);
/// "critical_speed", … (as a study file names them).
std::string_view to_string(QuantityKind kind);
/// The kind named @p name; nullopt for an unknown name.
std::optional<QuantityKind> quantity_kind_named(std::string_view name);
/// Every kind's name, for messages.
std::vector<std::string_view> quantity_kind_names();

/// The values of @p quantities for the built @p model of @p spec, in order, in SI
/// units. Throws Error when an analysis cannot give one: a solve that failed, no n-th
/// critical speed in the range, an unknown probe; the study records the message and
/// treats the design as failed. Analyses stop early through @p stop. With @p clipped,
/// sets it per quantity to why the value is only a bound set by the range an analysis
/// covered (a separation margin or a stability threshold beyond the Campbell range's
/// end), or "" when it is exact.
std::vector<Real> evaluate_quantities(const ModelSpec& spec, const Model& model,
                                      std::span<const QuantitySpec> quantities, const StopToken& stop = {},
                                      std::vector<std::string>* clipped = nullptr);

}  // namespace feran
