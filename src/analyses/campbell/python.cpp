// The Campbell diagram's Python result: tracked modes over a speed range as 2D numpy
// arrays (mode × speed), critical speeds with look-ups by whirl, order and mode, the
// stability threshold (analysis_binding.hpp binds feran.campbell and what every
// result has).
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <feran/analyses/campbell/analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/core/units.hpp>

#include "analysis_binding.hpp"

namespace feran::python {

namespace {

/// Per mode and speed: value(mode) [speed], NaN where a mode has no value.
template <class F>
py::array_t<double> per_mode_speed(const Outcome<CampbellAnalysis>& r, F&& values) {
  const auto& modes = r.result.modes;
  return array_2d(modes.size(), r.result.speeds.size(), [&](std::size_t i, std::size_t j) {
    const std::vector<Real>& v = values(modes[i]);
    return j < v.size() ? v[j] : std::numeric_limits<double>::quiet_NaN();
  });
}

/// A speed in rad/s converted to "rad/s", "Hz" or "rpm".
double in_unit(double speed, const std::string& unit) {
  if (unit == "rad/s") return speed;
  if (unit == "Hz") return rad_to_hz(speed);
  if (unit == "rpm") return 60.0 * rad_to_hz(speed);
  throw Error(fmt::format("unit='{}': expected 'rad/s', 'Hz' or 'rpm'", unit));
}

py::dict critical_dict(const Outcome<CampbellAnalysis>& r, const CriticalSpeed& c) {
  py::dict d;
  d["speed"] = c.speed;
  d["speed_hz"] = rad_to_hz(c.speed);
  d["speed_rpm"] = 60.0 * rad_to_hz(c.speed);
  d["frequency_hz"] = c.frequency_hz;
  d["order"] = c.order;
  d["mode"] = c.mode;
  d["label"] = r.result.modes.at(static_cast<std::size_t>(c.mode)).label;
  d["whirl"] = to_string(c.whirl);
  return d;
}

}  // namespace

template <>
void bind_result<CampbellAnalysis>(py::class_<Outcome<CampbellAnalysis>>& result) {
  using R = Outcome<CampbellAnalysis>;
  result
      .def_property_readonly(
          "speeds",
          [](const R& r) {
            return array_1d(r.result.speeds.size(), [&](std::size_t i) { return r.result.speeds[i]; });
          },
          "speeds solved [rad/s] (fewer than asked when a solve failed or it was interrupted)")
      .def_property_readonly("speeds_hz",
                             [](const R& r) {
                               return array_1d(r.result.speeds.size(),
                                               [&](std::size_t i) { return rad_to_hz(r.result.speeds[i]); });
                             })
      .def_property_readonly(
          "bearings", [](const R& r) { return bearing_labels(r.result.operating, r.model()); },
          "the bearings (journal and rolling) by their names")
      .def_property_readonly(
          "bearing_data", [](const R& r) { return bearing_data(r.result.operating); },
          "per bearing (as bearings), its operating state at the equilibrium at each speed: a dict\n"
          "of numpy arrays over speeds, named with their units as in static's bearing_data\n"
          "(eccentricity_ratio, attitude_angle_deg, min_film_thickness_m, sommerfeld_number,\n"
          "friction_torque_nm, power_loss_w, ...; max_element_load_n, ... for rolling bearings)")
      .def_property_readonly(
          "labels",
          [](const R& r) {
            return string_list(r.result.modes.size(), [&](std::size_t i) { return r.result.modes[i].label; });
          },
          "per mode: 'forward bending 1', 'backward cylindrical 1', 'axial 1', …")
      .def_property_readonly(
          "shape",
          [](const R& r) {
            return string_list(r.result.modes.size(),
                               [&](std::size_t i) { return to_string(r.result.modes[i].shape_kind); });
          },
          "per mode: its prevailing shape ('cylindrical', 'conical', 'bending'; 'none' without lateral motion)")
      .def_property_readonly(
          "bending",
          [](const R& r) {
            return per_mode_speed(r, [](const TrackedMode& x) -> const std::vector<Real>& { return x.bending; });
          },
          "the rotor's bending fraction per mode and speed (0 rigid, towards 1 bending), shape (modes, speeds)")
      .def_property_readonly(
          "whirl",
          [](const R& r) {
            return string_list(r.result.modes.size(),
                               [&](std::size_t i) { return to_string(r.result.modes[i].whirl); });
          },
          "per mode: its prevailing whirl ('forward', 'backward', 'planar', 'none')")
      .def_property_readonly(
          "type",
          [](const R& r) {
            return string_list(r.result.modes.size(), [&](std::size_t i) { return to_string(r.result.modes[i].type); });
          },
          "per mode: 'lateral', 'axial' or 'torsional'")
      .def_property_readonly(
          "whirl_at",
          [](const R& r) {
            py::list out;
            for (const TrackedMode& mode : r.result.modes)
              out.append(string_list(mode.whirl_at.size(), [&](std::size_t j) { return to_string(mode.whirl_at[j]); }));
            return out;
          },
          "per mode, per speed: the whirl there")
      .def_property_readonly(
          "frequency_hz",
          [](const R& r) {
            return per_mode_speed(r, [](const TrackedMode& x) -> const std::vector<Real>& { return x.frequency_hz; });
          },
          "damped natural frequencies [Hz], shape (modes, speeds)")
      .def_property_readonly(
          "damping_ratio",
          [](const R& r) {
            return per_mode_speed(r, [](const TrackedMode& x) -> const std::vector<Real>& { return x.damping_ratio; });
          },
          "shape (modes, speeds)")
      .def_property_readonly(
          "log_decrement",
          [](const R& r) {
            return per_mode_speed(r, [](const TrackedMode& x) -> const std::vector<Real>& { return x.log_decrement; });
          },
          "shape (modes, speeds); NaN for a non-oscillatory mode")
      .def_property_readonly(
          "directivity",
          [](const R& r) {
            return per_mode_speed(r, [](const TrackedMode& x) -> const std::vector<Real>& { return x.directivity; });
          },
          "+1 forward circles … -1 backward circles, shape (modes, speeds)")
      .def_property_readonly(
          "orders", [](const R& r) { return r.options.orders; },
          "harmonic orders k of the excitation lines f = k × speed")
      .def_property_readonly(
          "criticals",
          [](const R& r) {
            py::list out;
            for (const CriticalSpeed& c : r.result.critical_speeds) out.append(critical_dict(r, c));
            return out;
          },
          "every critical speed (crossing of a mode with an excitation line), sorted by speed, as dicts")
      .def(
          "critical_speeds",
          [](const R& r, std::optional<std::string> whirl, std::optional<int> order, std::optional<std::string> label,
             const std::string& unit) {
            if (whirl && *whirl != "forward" && *whirl != "backward" && *whirl != "planar" && *whirl != "none")
              throw Error(fmt::format("whirl='{}': expected 'forward', 'backward', 'planar' or 'none'", *whirl));
            std::vector<double> speeds;
            for (const CriticalSpeed& c : r.result.critical_speeds) {
              if (whirl && *whirl != to_string(c.whirl)) continue;
              if (order && *order != c.order) continue;
              if (label && *label != r.result.modes.at(static_cast<std::size_t>(c.mode)).label) continue;
              speeds.push_back(in_unit(c.speed, unit));
            }
            return array_1d(speeds.size(), [&](std::size_t i) { return speeds[i]; });
          },
          py::kw_only(), py::arg("whirl") = py::none(), py::arg("order") = py::none(), py::arg("label") = py::none(),
          py::arg("unit") = "rad/s",
          "The critical speeds, in increasing order, of the modes that whirl so at the crossing\n"
          "(whirl='forward'), of one excitation order (order=1) and/or of one tracked mode\n"
          "(label='forward 1'); unit 'rad/s', 'Hz' or 'rpm'. The whirl is the mode's at the\n"
          "critical speed itself, not a label's word.")
      .def_property_readonly(
          "stability_threshold",
          [](const R& r) -> py::object {
            if (!r.result.stability_threshold) return py::none();
            const StabilityThreshold& t = *r.result.stability_threshold;
            py::dict d;
            d["speed"] = t.speed;
            d["speed_hz"] = rad_to_hz(t.speed);
            d["mode"] = t.mode;
            d["label"] = threshold_label(r.result, t);
            d["frequency_hz"] = t.frequency_hz;
            d["unstable_at_start"] = t.unstable_at_start;
            d["kind"] = t.divergence ? "divergence" : "flutter";
            return d;
          },
          "the lowest speed at which a mode's damping turns negative (kind 'flutter') or a real\n"
          "eigenvalue turns positive (kind 'divergence', mode -1), a dict; or None")
      .def_property_readonly(
          "complete", [](const R& r) { return r.result.info.converged(); }, "whether every speed was solved")
      .def_property_readonly("message", [](const R& r) { return r.result.info.message; })
      .def_property_readonly("n_solves", [](const R& r) { return r.result.n_solves; });
}

}  // namespace feran::python
