#include <feran/study/quantity.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/analyses/harmonic/api684.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>
#include <feran/spec/parameters.hpp>

namespace feran {

namespace {

constexpr std::array<std::pair<QuantityKind, std::string_view>, 24> kind_names{{
    {QuantityKind::critical_speed, "critical_speed"},
    {QuantityKind::separation_margin, "separation_margin"},
    {QuantityKind::min_damping_ratio, "min_damping_ratio"},
    {QuantityKind::min_log_decrement, "min_log_decrement"},
    {QuantityKind::stability_threshold, "stability_threshold"},
    {QuantityKind::natural_frequency, "natural_frequency"},
    {QuantityKind::damping_ratio, "damping_ratio"},
    {QuantityKind::log_decrement, "log_decrement"},
    {QuantityKind::peak_response, "peak_response"},
    {QuantityKind::amplification_factor, "amplification_factor"},
    {QuantityKind::required_margin, "required_margin"},
    {QuantityKind::margin_surplus, "margin_surplus"},
    {QuantityKind::min_margin_surplus, "min_margin_surplus"},
    {QuantityKind::undamped_critical_speed, "undamped_critical_speed"},
    {QuantityKind::level1_q_zero, "level1_q_zero"},
    {QuantityKind::peak_spring_force, "peak_spring_force"},
    {QuantityKind::peak_stress, "peak_stress"},
    {QuantityKind::runup_peak, "runup_peak"},
    {QuantityKind::runup_spring_force, "runup_spring_force"},
    {QuantityKind::rotor_mass, "rotor_mass"},
    {QuantityKind::min_bearing_value, "min_bearing_value"},
    {QuantityKind::max_bearing_value, "max_bearing_value"},
    {QuantityKind::parameter, "parameter"},
    {QuantityKind::function, "function"},
}};

bool uses_response(QuantityKind k) {
  return k == QuantityKind::peak_response || k == QuantityKind::peak_spring_force || k == QuantityKind::peak_stress ||
         k == QuantityKind::amplification_factor || k == QuantityKind::required_margin ||
         k == QuantityKind::margin_surplus || k == QuantityKind::min_margin_surplus;
}
bool uses_runup(QuantityKind k) { return k == QuantityKind::runup_peak || k == QuantityKind::runup_spring_force; }

bool selected(Whirl w, WhirlSelection s) {
  switch (s) {
    case WhirlSelection::forward:
      return w == Whirl::forward;
    case WhirlSelection::backward:
      return w == Whirl::backward;
    case WhirlSelection::any:
      return w != Whirl::none;
  }
  return false;
}

std::string_view whirl_word(WhirlSelection s) {
  switch (s) {
    case WhirlSelection::forward:
      return "forward ";
    case WhirlSelection::backward:
      return "backward ";
    case WhirlSelection::any:
      return "";
  }
  return "";
}

std::string ordinal(int n) {
  const int tens = n % 100, units = n % 10;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                       : units == 1               ? "st"
                       : units == 2               ? "nd"
                       : units == 3               ? "rd"
                                                  : "th";
  return fmt::format("{}{}", n, suffix);
}

std::string rpm(Real speed) { return approximate_quantity(speed, Quantity::speed, "rpm"); }

void check_solver(const SolverInfo& info, std::string_view analysis) {
  if (!info.converged()) throw Error(fmt::format("the {} failed: {}", analysis, info.message));
}

Index spring_index(const Model& model, const std::string& name) { return spring_element(model, name); }

// The analyses of one design, each run when a quantity first needs it.
class Analyses {
 public:
  Analyses(const ModelSpec& spec, const Model& model, std::span<const QuantitySpec> quantities, StopToken stop)
      : spec_(spec), model_(model), stop_(stop) {
    for (const auto& q : quantities) {
      if (q.probe && uses_response(q.kind)) add(response_probes_, node_index(model, *q.probe));
      if (q.probe && uses_runup(q.kind)) add(runup_probes_, node_index(model, *q.probe));
      if (q.kind == QuantityKind::runup_spring_force) {
        if (q.spring)
          add(runup_springs_, spring_index(model, *q.spring));
        else
          all_runup_springs_ = true;
      }
    }
  }

  const CampbellResult& campbell() {
    if (!campbell_) {
      CampbellRequest request;
      request.n_threads = 1;
      options_ = campbell_settings(spec_.campbell, request);
      options_.stop = stop_;
      campbell_ = run_campbell(model_, options_);
      check_solver(campbell_->info, "Campbell diagram");
    }
    return *campbell_;
  }

  const HarmonicResult& response() {
    if (!response_) {
      ResponseRequest request;
      request.n_threads = 1;
      request.probes = response_probes_;
      auto options = response_settings(model_, spec_.response, request);
      options.stop = stop_;
      response_ = run_harmonic_response(model_, options);
      check_solver(response_->info, "unbalance response");
    }
    return *response_;
  }

  const TransientResult& runup() {
    if (!runup_) {
      RunupRequest request;
      request.probes = runup_probes_;
      if (all_runup_springs_) {
        for (Index e = 0; e < static_cast<Index>(model_.elements.size()); ++e)
          if (model_.elements[static_cast<std::size_t>(e)].kind() == "spring_damper") add(runup_springs_, e);
      }
      request.springs = runup_springs_;
      auto options = runup_settings(model_, spec_.runup, request);
      options.keep_samples = !runup_springs_.empty();
      options.stop = stop_;
      runup_ = run_transient(model_, options);
      check_solver(runup_->info, "run-up");
      runup_probe_nodes_ = options.probes;
      runup_spring_elements_ = options.springs;
    }
    return *runup_;
  }

  Real campbell_low() { return campbell().speeds.front(); }
  Real campbell_high() { return campbell().speeds.back(); }
  const std::vector<Index>& runup_probe_nodes() const { return runup_probe_nodes_; }
  const std::vector<Index>& runup_spring_elements() const { return runup_spring_elements_; }
  const Model& model() const { return model_; }
  const ModelSpec& spec() const { return spec_; }
  const StopToken& stop() const { return stop_; }

 private:
  static void add(std::vector<Index>& list, Index i) {
    if (std::find(list.begin(), list.end(), i) == list.end()) list.push_back(i);
  }
  const ModelSpec& spec_;
  const Model& model_;
  StopToken stop_;
  CampbellOptions options_;
  std::optional<CampbellResult> campbell_;
  std::optional<HarmonicResult> response_;
  std::optional<TransientResult> runup_;
  std::vector<Index> response_probes_, runup_probes_, runup_springs_;
  bool all_runup_springs_ = false;
  std::vector<Index> runup_probe_nodes_, runup_spring_elements_;
};

// The critical speeds a quantity selects, in increasing order, within [low, high].
std::vector<Real> selected_criticals(const CampbellResult& c, const QuantitySpec& q, Real low, Real high) {
  std::vector<Real> out;
  for (const auto& x : c.critical_speeds) {
    const auto& mode = c.modes[static_cast<std::size_t>(x.mode)];
    if (mode.type != ModeType::lateral || x.order != q.order || !selected(x.whirl, q.whirl)) continue;
    if (x.speed >= low && x.speed <= high) out.push_back(x.speed);
  }
  std::sort(out.begin(), out.end());
  return out;
}

Real smallest_damping(const CampbellResult& c, const QuantitySpec& q, Real low, Real high, bool log_decrement) {
  Real smallest = std::numeric_limits<Real>::infinity();
  for (const auto& mode : c.modes) {
    if (mode.type != ModeType::lateral) continue;
    for (std::size_t k = 0; k < c.speeds.size(); ++k) {
      if (c.speeds[k] < low || c.speeds[k] > high || !selected(mode.whirl_at[k], q.whirl)) continue;
      const Real d = log_decrement ? mode.log_decrement[k] : mode.damping_ratio[k];
      if (std::isfinite(d)) smallest = std::min(smallest, d);
    }
  }
  if (!std::isfinite(smallest))
    throw Error(fmt::format("no {}lateral mode between {} and {}", whirl_word(q.whirl), rpm(low), rpm(high)));
  return smallest;
}

// The amplitude (orbit semi-major axis) at a quantity's probe against speed, within
// its range.
struct Curve {
  std::vector<Real> speeds, amplitude;
};

Curve probe_curve(Analyses& a, const QuantitySpec& q) {
  const auto& r = a.response();
  if (r.probes.empty()) throw Error("the response has no probe: give the quantity a 'probe'");
  const Index node = q.probe ? node_index(a.model(), *q.probe) : r.probes.front().node;
  for (const auto& p : r.probes) {
    if (p.node != node) continue;
    Curve c;
    for (std::size_t k = 0; k < p.orbit.size(); ++k) {
      if ((q.low && r.speeds[k] < *q.low) || (q.high && r.speeds[k] > *q.high)) continue;
      c.speeds.push_back(r.speeds[k]);
      c.amplitude.push_back(p.orbit[k].major);
    }
    return c;
  }
  throw Error("the response has no such probe");
}

Real evaluate_one(Analyses& a, const QuantitySpec& q, std::string& clipped) {
  switch (q.kind) {
    case QuantityKind::critical_speed: {
      const auto& c = a.campbell();
      const Real low = q.low.value_or(c.speeds.front()), high = q.high.value_or(c.speeds.back());
      const auto criticals = selected_criticals(c, q, low, high);
      if (static_cast<int>(criticals.size()) < q.n)
        throw Error(fmt::format("no {} {}critical speed of order {} between {} and {} (found {})", ordinal(q.n),
                                whirl_word(q.whirl), q.order, rpm(low), rpm(high), criticals.size()));
      return criticals[static_cast<std::size_t>(q.n - 1)];
    }
    case QuantityKind::separation_margin: {
      const auto& c = a.campbell();
      const Real low = q.low.value_or(c.speeds.front()), high = q.high.value_or(c.speeds.back());
      // Critical speeds beyond the analysed range are unknown but at least as far
      // away as its ends: the margin of the ends bounds theirs.
      Real margin = std::min(separation_margin(low, q.operating_low, q.operating_high),
                             separation_margin(high, q.operating_low, q.operating_high));
      if (low <= 0) margin = separation_margin(high, q.operating_low, q.operating_high);
      Real nearest = std::numeric_limits<Real>::infinity();
      for (const Real s : selected_criticals(c, q, low, high))
        nearest = std::min(nearest, separation_margin(s, q.operating_low, q.operating_high));
      if (!(nearest <= margin))
        clipped = fmt::format(
            "a lower bound: no {}critical speed of order {} between {} and {} lies nearer the "
            "operating range than the range's {}; widen the Campbell range to find the margin",
            whirl_word(q.whirl), q.order, rpm(low), rpm(high), low > 0 ? "ends" : "end");
      return std::min(margin, nearest);
    }
    case QuantityKind::min_damping_ratio:
    case QuantityKind::min_log_decrement: {
      const auto& c = a.campbell();
      return smallest_damping(c, q, q.low.value_or(c.speeds.front()), q.high.value_or(c.speeds.back()),
                              q.kind == QuantityKind::min_log_decrement);
    }
    case QuantityKind::stability_threshold: {
      const auto& c = a.campbell();
      // None in the range: the threshold lies above it; its end is a lower bound.
      if (c.stability_threshold) return c.stability_threshold->speed;
      clipped = fmt::format(
          "a lower bound: the rotor is stable up to the Campbell range's end, {}; widen the range to "
          "find the threshold",
          rpm(c.speeds.back()));
      return c.speeds.back();
    }
    case QuantityKind::natural_frequency:
    case QuantityKind::damping_ratio:
    case QuantityKind::log_decrement: {
      ModalRequest request;
      request.speed = q.speed;
      auto settings = modal_settings(a.spec().modal, request);
      const auto result = run_modal(a.model(), settings.speed, settings.options);
      check_solver(result.info, "modal analysis");
      int seen = 0;
      for (const auto& m : result.modes)
        if (m.type == ModeType::lateral && m.oscillatory && selected(m.whirl, q.whirl) && ++seen == q.n)
          return q.kind == QuantityKind::natural_frequency ? m.frequency_hz
                 : q.kind == QuantityKind::damping_ratio   ? m.damping_ratio
                                                           : m.log_decrement;
      throw Error(fmt::format("no {} {}lateral mode at {} (found {})", ordinal(q.n), whirl_word(q.whirl),
                              rpm(settings.speed), seen));
    }
    case QuantityKind::peak_response: {
      const auto curve = probe_curve(a, q);
      return curve.amplitude.empty() ? 0.0 : *std::max_element(curve.amplitude.begin(), curve.amplitude.end());
    }
    case QuantityKind::amplification_factor:
    case QuantityKind::required_margin:
    case QuantityKind::margin_surplus:
    case QuantityKind::min_margin_surplus: {
      const auto curve = probe_curve(a, q);
      std::vector<ResponsePeak> resolved;
      for (const auto& p : response_peaks(curve.speeds, curve.amplitude))
        if (p.resolved()) resolved.push_back(p);
      const int needed = q.kind == QuantityKind::min_margin_surplus ? 1 : q.n;
      if (static_cast<int>(resolved.size()) < needed)
        throw Error(
            fmt::format("no {} resonance peak in the response at the probe{} (found {}; a peak counts when "
                        "the amplitude falls to 1/√2 of it on both sides within the sweep)",
                        ordinal(needed),
                        q.low || q.high ? fmt::format(" between {} and {}", rpm(q.low.value_or(0)),
                                                      q.high ? rpm(*q.high) : std::string("the sweep's end"))
                                        : std::string(),
                        resolved.size()));
      const auto required = [&](const ResponsePeak& peak) {
        return required_separation_margin(peak.amplification_factor, peak.speed, q.operating_low, q.operating_high);
      };
      const auto surplus = [&](const ResponsePeak& peak) {
        return separation_margin(peak.speed, q.operating_low, q.operating_high) - required(peak);
      };
      if (q.kind == QuantityKind::min_margin_surplus) {
        Real least = surplus(resolved.front());
        for (const auto& peak : resolved) least = std::min(least, surplus(peak));
        return least;
      }
      const auto& peak = resolved[static_cast<std::size_t>(q.n - 1)];
      if (q.kind == QuantityKind::amplification_factor) return peak.amplification_factor;
      return q.kind == QuantityKind::required_margin ? required(peak) : surplus(peak);
    }
    case QuantityKind::undamped_critical_speed: {
      // As API 684's: journal and rolling bearings by their direct stiffness about
      // the equilibrium at each critical speed, the search starting from the
      // operating range's top (or the Campbell range's end) on an oil film.
      SolverInfo info;
      const Model lin = has_supports(a.model()) ? linearised(a.model()) : Model();
      const Model* rotor = &a.model();
      Model direct;
      if (has_supports(a.model())) {
        direct = with_direct_bearing_stiffness(lin, bearing_elements(lin));
        rotor = &direct;
      }
      const Real start = !needs_speed(a.model()) ? 0.0
                         : q.operating_high > 0  ? q.operating_high
                                                 : a.campbell().speeds.back();
      const auto criticals = undamped_critical_speeds(*rotor, q.n, true, &info, start);
      check_solver(info, "undamped critical speeds");
      if (static_cast<int>(criticals.size()) < q.n)
        throw Error(fmt::format("the rotor has {} forward undamped critical speeds, not {}", criticals.size(), q.n));
      return criticals[static_cast<std::size_t>(q.n - 1)].speed;
    }
    case QuantityKind::level1_q_zero: {
      StabilitySweepOptions s;
      s.speed = *q.speed;  // the reader requires it
      s.node = q.probe ? node_index(a.model(), *q.probe) : largest_forward_motion_node(a.model(), s.speed);
      s.points = 2;
      const StabilitySweepResult r = run_stability_sweep(a.model(), s);
      if (!r.q_zero)
        throw Error(
            fmt::format("no Q₀: the first forward mode at {} is {}", rpm(s.speed),
                        r.log_decrement.front() <= 0 ? "unstable without cross-coupling" : "stable up to 1e13 N/m"));
      return *r.q_zero;
    }
    case QuantityKind::peak_spring_force: {
      const auto& r = a.response();
      const Index only = q.spring ? spring_index(a.model(), *q.spring) : -1;
      Real peak = 0;
      for (const auto& s : r.springs) {
        if (only >= 0 && s.element != only) continue;
        for (std::size_t k = 0; k < s.peak_lateral.size(); ++k)
          if (!(q.low && r.speeds[k] < *q.low) && !(q.high && r.speeds[k] > *q.high))
            peak = std::max(peak, s.peak_lateral[k]);
      }
      return peak;
    }
    case QuantityKind::peak_stress: {
      const auto& r = a.response();
      Real peak = 0;
      for (std::size_t k = 0; k < r.station_peaks.size(); ++k)
        if (!(q.low && r.speeds[k] < *q.low) && !(q.high && r.speeds[k] > *q.high))
          peak = std::max(peak, r.station_peaks[k].von_mises.value);
      return peak;
    }
    case QuantityKind::runup_peak: {
      const auto& r = a.runup();
      const auto& nodes = a.runup_probe_nodes();
      if (nodes.empty()) throw Error("the run-up records no probe: give the quantity a 'probe'");
      const Index node = q.probe ? node_index(a.model(), *q.probe) : nodes.front();
      const auto at = std::find(nodes.begin(), nodes.end(), node);
      return r.envelopes[static_cast<std::size_t>(at - nodes.begin())].peak;
    }
    case QuantityKind::runup_spring_force: {
      const auto& r = a.runup();
      const auto& springs = a.runup_spring_elements();
      const Index only = q.spring ? spring_index(a.model(), *q.spring) : -1;
      Real peak = 0;
      for (const auto& sample : r.samples)
        for (std::size_t i = 0; i < springs.size(); ++i)
          if (only < 0 || springs[i] == only)
            peak = std::max(peak, std::hypot(sample.springs[i][1], sample.springs[i][2]));
      return peak;
    }
    case QuantityKind::rotor_mass:
      return rotating_mass(a.model());
    case QuantityKind::min_bearing_value:
    case QuantityKind::max_bearing_value: {
      // Over the Campbell diagram's speeds within the range: each bearing's state at
      // the equilibrium about which the diagram linearises it.
      const auto& c = a.campbell();
      const Real low = q.low.value_or(c.speeds.front()), high = q.high.value_or(c.speeds.back());
      const bool smallest = q.kind == QuantityKind::min_bearing_value;
      const Real scale = q.value.ends_with("_deg") ? pi / 180 : 1.0;
      Real best = std::numeric_limits<Real>::quiet_NaN();
      bool named = false;
      std::vector<std::string> bearings;
      for (const OperatingSeries& s : c.operating) {
        const std::string label = a.model().forces[static_cast<std::size_t>(s.force)].label();
        bearings.push_back(label);
        if (q.bearing && *q.bearing != label) continue;
        named = true;
        const std::vector<Real> values = s.series(q.value);
        if (values.empty())
          throw Error(fmt::format("bearing '{}' has no operating quantity '{}'; it has {}", label, q.value,
                                  fmt::join(s.quantities, ", ")));
        for (std::size_t k = 0; k < values.size(); ++k)
          if (c.speeds[k] >= low && c.speeds[k] <= high && std::isfinite(values[k]))
            if (std::isnan(best) || (smallest ? values[k] < best : values[k] > best)) best = values[k];
      }
      if (c.operating.empty()) throw Error("the model has no journal or rolling bearing");
      if (!named)
        throw Error(fmt::format("no bearing named '{}'; the bearings are {}", *q.bearing, fmt::join(bearings, ", ")));
      if (std::isnan(best))
        throw Error(fmt::format("no value of '{}' between {} and {}", q.value, rpm(low), rpm(high)));
      return best * scale;
    }
    case QuantityKind::parameter:
      return get_parameter(a.spec(), q.path).value;
    case QuantityKind::function:
      if (!q.function || !*q.function)
        throw Error(
            "no function is given for it (a quantity of kind \"function\" is computed by code, e.g. feran.Study's "
            "quantities)");
      return (*q.function)(a.spec(), a.model());
  }
  throw Error("unknown quantity");
}

}  // namespace

std::optional<Quantity> quantity_kind_unit(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::critical_speed:
    case QuantityKind::stability_threshold:
    case QuantityKind::undamped_critical_speed:
      return Quantity::speed;
    case QuantityKind::level1_q_zero:
      return Quantity::stiffness;
    case QuantityKind::natural_frequency:
      return Quantity::frequency;
    case QuantityKind::peak_response:
    case QuantityKind::runup_peak:
      return Quantity::length;
    case QuantityKind::peak_spring_force:
    case QuantityKind::runup_spring_force:
      return Quantity::force;
    case QuantityKind::peak_stress:
      return Quantity::pressure;
    case QuantityKind::rotor_mass:
      return Quantity::mass;
    default:
      return std::nullopt;
  }
}

std::optional<Quantity> operating_value_unit(std::string_view name) {
  if (name.ends_with("_nm")) return Quantity::moment;
  if (name.ends_with("_pa")) return Quantity::pressure;
  if (name.ends_with("_deg")) return Quantity::angle;
  if (name.ends_with("_m")) return Quantity::length;
  if (name.ends_with("_n")) return Quantity::force;
  return std::nullopt;
}

std::optional<Quantity> quantity_unit(const QuantitySpec& q) {
  if (q.kind == QuantityKind::min_bearing_value || q.kind == QuantityKind::max_bearing_value)
    return operating_value_unit(q.value);
  return q.kind == QuantityKind::parameter ? q.value_kind : quantity_kind_unit(q.kind);
}

std::string_view to_string(QuantityKind kind) {
  for (const auto& [k, name] : kind_names)
    if (k == kind) return name;
  return "?";
}

std::optional<QuantityKind> quantity_kind_named(std::string_view name) {
  for (const auto& [k, n] : kind_names)
    if (n == name) return k;
  return std::nullopt;
}

std::vector<std::string_view> quantity_kind_names() {
  std::vector<std::string_view> out;
  for (const auto& [k, n] : kind_names) out.push_back(n);
  return out;
}

std::vector<Real> evaluate_quantities(const ModelSpec& spec, const Model& model,
                                      std::span<const QuantitySpec> quantities, const StopToken& stop,
                                      std::vector<std::string>* clipped) {
  Analyses analyses(spec, model, quantities, stop);
  std::vector<Real> values;
  values.reserve(quantities.size());
  if (clipped) clipped->assign(quantities.size(), std::string());
  for (const auto& q : quantities) {
    try {
      std::string note;
      values.push_back(evaluate_one(analyses, q, note));
      if (clipped) (*clipped)[values.size() - 1] = std::move(note);
    } catch (const Error& e) {
      throw Error(fmt::format("quantity '{}': {}", q.name, e.what()));
    }
  }
  return values;
}

}  // namespace feran
