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

/// A quantity computed by the caller's code from the design's model (its
/// specification and the model built from it). Called on the study's worker threads,
/// side by side: it must be safe to call concurrently. Throws for a design it cannot
/// evaluate (the design is recorded as failed with the message).
using QuantityFunction = std::function<Real(const ModelSpec& spec, const Model& model)>;

/// Which modes a modal quantity looks at.
enum class WhirlSelection { forward, backward, any };

struct QuantitySpec {
  std::string name;
  std::string kind = "critical_speed";  ///< the name of its row of quantity_rows()
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

class DesignAnalyses;

/// One kind of quantity a study can read off a design: a row of the table of
/// quantities. Each analysis's folder gives the rows of its own results
/// (StaticAnalysis::quantities()); quantity_rows() lists them all.
struct QuantityRow {
  std::string_view name = {};  ///< as a study file names it ("peak_response")
  std::string_view doc = {};   ///< one line for the documentation
  /// The analysis it reads ("campbell", "static"; empty for none), whose settings the
  /// design's model tables give.
  std::string_view analysis = {};
  std::optional<Quantity> unit = {};  ///< the kind of its value; none: a pure number
  /// Its value for the design, in SI units; sets @p clipped to why the value is only a
  /// bound set by the range an analysis covered. Throws Error when there is none.
  Real (*evaluate)(DesignAnalyses& a, const QuantitySpec& q, std::string& clipped) = nullptr;
  // What a study file's entry of this kind needs or may hold:
  bool any_whirl = false;        ///< 'whirl' defaults to "any" (damping), else "forward"
  bool needs_operating = false;  ///< 'operating' = [low, high] is required
  bool needs_speed = false;      ///< 'speed' > 0 is required
  bool bearing_value = false;    ///< 'value' (a bearing's operating quantity) and 'bearing'
  bool parameter = false;        ///< 'path' (its unit is the parameter's)
  bool code_only = false;        ///< computed by code (feran.Study), not in study files
};

/// Every row, in the order the documentation lists them.
const std::vector<QuantityRow>& quantity_rows();
/// The row named @p name, or nullptr.
const QuantityRow* quantity_row(std::string_view name);
/// The row of @p q (Error for an unknown kind).
const QuantityRow& row_of(const QuantitySpec& q);

/// The kind of @p q's value: its row's, for a parameter its kind, for a bearing value
/// its quantity's.
std::optional<Quantity> quantity_unit(const QuantitySpec& q);

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
