// The steady-state response's study quantities (analyses/response/analysis.hpp): the
// peaks of the design's unbalance response, its resonances' amplification factors and
// separation margins (API 684), its spring forces and shaft stresses.
#include <algorithm>

#include <fmt/format.h>

#include <feran/analyses/harmonic/api684.hpp>
#include <feran/analyses/response/analysis.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/core/error.hpp>
#include <feran/study/design_analyses.hpp>

namespace feran {

namespace {

// Whether speed @p speed is within quantity @p q's range.
bool in_range(const QuantitySpec& q, Real speed) { return !(q.low && speed < *q.low) && !(q.high && speed > *q.high); }

// The design's response; none where the rotor is unstable within the quantity's range:
// a response there is no steady state the rotor reaches.
const HarmonicResult& steady_result(DesignAnalyses& a, const QuantitySpec& q) {
  const HarmonicResult& r = a.result<ResponseAnalysis>();
  for (std::size_t k = 0; k < r.stability.size(); ++k)
    if (r.stability[k].unstable && in_range(q, r.speeds[k]))
      throw Error(
          fmt::format("the rotor is unstable at {} within the response's speeds, where the response is no "
                      "steady state: {}",
                      rpm(r.speeds[k]), stability_phrase(r.stability[k])));
  return r;
}

// The amplitude (orbit semi-major axis) at a quantity's probe against speed, within
// its range.
struct Curve {
  std::vector<Real> speeds, amplitude;
};

Curve probe_curve(DesignAnalyses& a, const QuantitySpec& q) {
  const HarmonicResult& r = steady_result(a, q);
  if (r.probes.empty()) throw Error("the response has no probe: give the quantity a 'probe'");
  const Index node = q.probe ? node_index(a.model(), *q.probe) : r.probes.front().node;
  for (const auto& p : r.probes) {
    if (p.node != node) continue;
    Curve c;
    for (std::size_t k = 0; k < p.orbit.size(); ++k) {
      if (!in_range(q, r.speeds[k])) continue;
      c.speeds.push_back(r.speeds[k]);
      c.amplitude.push_back(p.orbit[k].major);
    }
    return c;
  }
  throw Error("the response has no such probe");
}

Real peak_response(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const auto curve = probe_curve(a, q);
  return curve.amplitude.empty() ? 0.0 : *std::max_element(curve.amplitude.begin(), curve.amplitude.end());
}

// What a row reads off the resonance peaks at a probe.
enum class PeakValue { amplification_factor, required_margin, margin_surplus, min_margin_surplus };

template <PeakValue what>
Real peak_value(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const auto curve = probe_curve(a, q);
  std::vector<ResponsePeak> resolved;
  for (const auto& p : response_peaks(curve.speeds, curve.amplitude))
    if (p.resolved()) resolved.push_back(p);
  const int needed = what == PeakValue::min_margin_surplus ? 1 : q.n;
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
  if constexpr (what == PeakValue::min_margin_surplus) {
    Real least = surplus(resolved.front());
    for (const auto& peak : resolved) least = std::min(least, surplus(peak));
    return least;
  }
  const auto& peak = resolved[static_cast<std::size_t>(q.n - 1)];
  if constexpr (what == PeakValue::amplification_factor) return peak.amplification_factor;
  return what == PeakValue::required_margin ? required(peak) : surplus(peak);
}

Real peak_spring_force(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const HarmonicResult& r = steady_result(a, q);
  const Index only = q.spring ? spring_element(a.model(), *q.spring) : -1;
  Real peak = 0;
  for (const auto& s : r.springs) {
    if (only >= 0 && s.element != only) continue;
    for (std::size_t k = 0; k < s.peak_lateral.size(); ++k)
      if (in_range(q, r.speeds[k])) peak = std::max(peak, s.peak_lateral[k]);
  }
  return peak;
}

Real peak_stress(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const HarmonicResult& r = steady_result(a, q);
  Real peak = 0;
  for (std::size_t k = 0; k < r.station_peaks.size(); ++k)
    if (in_range(q, r.speeds[k])) peak = std::max(peak, r.station_peaks[k].von_mises.value);
  return peak;
}

}  // namespace

const std::vector<QuantityRow>& ResponseAnalysis::quantities() {
  using Q = Quantity;
  static const std::vector<QuantityRow> rows = {
      {.name = "peak_response",
       .doc = "largest orbit semi-axis at a probe over the unbalance response",
       .analysis = "response",
       .unit = Q::length,
       .evaluate = peak_response},
      {.name = "amplification_factor",
       .doc = "API 684 amplification factor (half-power) of the n-th resonance peak at a probe",
       .analysis = "response",
       .evaluate = peak_value<PeakValue::amplification_factor>},
      {.name = "required_margin",
       .doc = "the separation margin API 617 requires of that peak from the operating range",
       .analysis = "response",
       .evaluate = peak_value<PeakValue::required_margin>,
       .needs_operating = true},
      {.name = "margin_surplus",
       .doc = "that peak's separation margin less the required one: ≥ 0 passes",
       .analysis = "response",
       .evaluate = peak_value<PeakValue::margin_surplus>,
       .needs_operating = true},
      {.name = "min_margin_surplus",
       .doc = "the smallest margin_surplus of every resonance peak at the probe: ≥ 0 all pass",
       .analysis = "response",
       .evaluate = peak_value<PeakValue::min_margin_surplus>,
       .needs_operating = true},
      {.name = "peak_spring_force",
       .doc = "largest lateral force of a spring (or of all) over the response",
       .analysis = "response",
       .unit = Q::force,
       .evaluate = peak_spring_force},
      {.name = "peak_stress",
       .doc = "largest equivalent (von Mises) shaft stress over the response",
       .analysis = "response",
       .unit = Q::pressure,
       .evaluate = peak_stress},
  };
  return rows;
}

ResponseSpec ResponseAnalysis::study_request(const Model& model, std::span<const QuantitySpec> quantities) {
  // The probes the quantities name, each node once; none: the file's, else the defaults.
  ResponseSpec request;
  request.probes = quantity_probes(model, quantities, name);
  return request;
}

}  // namespace feran
