// The periodic orbits' Python result: per branch its steady states as numpy arrays
// (parameter, speed, frequency, stability, the orbit at each probe), its bifurcations,
// and any orbit in time (analysis_binding.hpp binds feran.orbits and what every result
// has).
#include <cmath>
#include <string>

#include <pybind11/stl.h>

#include <feran/analyses/periodic/aft.hpp>
#include <feran/analyses/periodic/analysis.hpp>
#include <feran/core/units.hpp>

#include "analysis_binding.hpp"

namespace feran::python {

namespace {

using PyOrbitsResult = Outcome<OrbitsAnalysis>;

// A probe quantity of each state: states × probes.
template <class F>
py::array_t<Real> per_probe(const std::vector<std::vector<ProbeOrbit>>& states, std::size_t probes, F&& value) {
  return array_2d(states.size(), probes, [&](std::size_t k, std::size_t i) { return value(states[k][i]); });
}

py::dict states_dict(const std::vector<const SteadyState*>& s, const std::vector<std::vector<ProbeOrbit>>& probes,
                     std::size_t n_probes) {
  py::dict d;
  const auto column = [&](auto value) { return array_1d(s.size(), [&](std::size_t k) { return value(*s[k]); }); };
  d["parameter"] = column([](const SteadyState& x) { return x.parameter; });
  d["speed"] = column([](const SteadyState& x) { return x.speed; });
  d["frequency"] = column([](const SteadyState& x) { return x.frequency; });
  d["stable"] = array_1d<bool>(s.size(), [&](std::size_t k) { return s[k]->stable; });
  d["largest_multiplier"] = column([](const SteadyState& x) { return x.floquet.largest; });
  d["truncation"] = column([](const SteadyState& x) { return x.truncation; });
  d["amplitude"] = per_probe(probes, n_probes, [](const ProbeOrbit& p) { return p.amplitude; });
  d["largest"] = per_probe(probes, n_probes, [](const ProbeOrbit& p) { return p.largest; });
  d["mean_v"] = per_probe(probes, n_probes, [](const ProbeOrbit& p) { return p.mean_v; });
  d["mean_w"] = per_probe(probes, n_probes, [](const ProbeOrbit& p) { return p.mean_w; });
  return d;
}

py::dict branch_dict(const OrbitsBranch& b, std::size_t n_probes) {
  std::vector<const SteadyState*> orbits, at;
  for (const SteadyState& s : b.branch.orbits) orbits.push_back(&s);
  for (const Bifurcation& f : b.branch.bifurcations) at.push_back(&f.at);
  py::dict d = states_dict(orbits, b.probes, n_probes);
  d["name"] = b.name;
  d["kind"] = branch_kind_name(b.branch.kind);
  d["ended_by"] = b.branch.ended_by;
  d["clipped"] = b.branch.clipped;
  d["criticality"] = b.branch.criticality.empty() ? py::none() : py::cast(b.branch.criticality);
  py::dict f = states_dict(at, b.bifurcation, n_probes);
  f["kind"] = string_list(at.size(),
                          [&](std::size_t k) { return std::string(bifurcation_name(b.branch.bifurcations[k].kind)); });
  f["critical_frequency"] =
      array_1d(at.size(), [&](std::size_t k) { return critical_frequency(b.branch.bifurcations[k]); });
  f["after"] =
      array_1d<Index>(at.size(), [&](std::size_t k) { return static_cast<Index>(b.branch.bifurcations[k].after); });
  d["bifurcations"] = f;
  return d;
}

// One orbit of each probe over a period: (θ, v, w), shapes (samples,), (probes, samples).
py::tuple orbit_in_time(const PyOrbitsResult& r, std::size_t branch, std::size_t point, std::size_t samples) {
  if (branch >= r.result.branches.size()) throw py::index_error("orbit: no branch " + std::to_string(branch));
  const OrbitsBranch& b = r.result.branches[branch];
  if (point >= b.probes.size()) throw py::index_error("orbit: the branch has no point " + std::to_string(point));
  if (samples < 2) throw py::value_error("orbit: samples must be at least 2 (the period's both ends)");
  const std::vector<ProbeOrbit>& p = b.probes[point];
  // Each probe's (v, w) as a two-DOF motion on the branch's harmonics (aft.hpp).
  const Index terms = p.empty() ? 1 : p[0].v.size(), H = (terms - 1) / 2;
  const FourierBasis basis{.harmonics = H, .samples = 2 * H + 1};
  const auto theta = [&](std::size_t j) { return 2.0 * pi * static_cast<Real>(j) / static_cast<Real>(samples - 1); };
  Matrix v(static_cast<Index>(p.size()), static_cast<Index>(samples)), w = v;
  Vector X(2 * terms), x, xdot;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (Index k = 0; k < terms; ++k) X(2 * k) = p[i].v(k), X(2 * k + 1) = p[i].w(k);
    for (std::size_t j = 0; j < samples; ++j) {
      motion_at(basis, 1.0, X, theta(j), x, xdot);
      v(static_cast<Index>(i), static_cast<Index>(j)) = x(0);
      w(static_cast<Index>(i), static_cast<Index>(j)) = x(1);
    }
  }
  const auto at = [](const Matrix& m) {
    return array_2d(static_cast<std::size_t>(m.rows()), static_cast<std::size_t>(m.cols()),
                    [&](std::size_t i, std::size_t j) { return m(static_cast<Index>(i), static_cast<Index>(j)); });
  };
  return py::make_tuple(array_1d(samples, theta), at(v), at(w));
}

}  // namespace

template <>
void bind_result<OrbitsAnalysis>(py::class_<Outcome<OrbitsAnalysis>>& result) {
  result
      .def_property_readonly(
          "branch", [](const PyOrbitsResult& r) { return r.result.branch; },
          "what the branches are: \"forced\", \"whirl\" or \"equilibrium\"")
      .def_property_readonly(
          "parameter", [](const PyOrbitsResult& r) { return r.options.build ? r.options.parameter : "speed"; },
          "the branches' parameter: \"speed\" (rad/s) or a parameter path (its SI unit)")
      .def_property_readonly("probes",
                             [](const PyOrbitsResult& r) {
                               return string_list(r.options.probes.size(), [&](std::size_t i) {
                                 return node_name(r.model(), r.options.probes[i]);
                               });
                             })
      .def_property_readonly(
          "branches",
          [](const PyOrbitsResult& r) {
            py::list out;
            for (const OrbitsBranch& b : r.result.branches) out.append(branch_dict(b, r.options.probes.size()));
            return out;
          },
          "per branch a dict: name, kind, ended_by, clipped, criticality, and numpy arrays over its steady\n"
          "states: parameter, speed [rad/s], frequency [rad/s] (the orbit's base frequency; 0 at an\n"
          "equilibrium), stable, largest_multiplier, truncation, and per probe (states × probes)\n"
          "amplitude, largest, mean_v, mean_w [m]; bifurcations: the same arrays for the bifurcations\n"
          "located on it, with kind and after (the state before it)")
      .def_property_readonly(
          "run",
          [](const PyOrbitsResult& r) -> py::object {
            if (!r.result.settled) return py::none();
            const SettledOrbit& s = *r.result.settled;
            py::dict d;
            d["parameter"] = s.start.parameter;
            d["speed"] = s.start.speed;
            d["kind"] = branch_kind_name(s.kind);
            d["settled_after"] = s.time;
            d["frequency"] = s.start.frequency;
            d["mismatch"] = s.mismatch;
            return d;
          },
          "with start_at: the run's orbit before the balance corrected it, a dict: parameter (SI), speed\n"
          "and frequency [rad/s], kind (\"forced\" or \"self_excited\"), settled_after [s] (the simulated\n"
          "time until its motion repeated), mismatch (how far one period fails to close, relative to\n"
          "its extent); None without start_at")
      .def("orbit", &orbit_in_time, py::arg("branch"), py::arg("point"), py::arg("samples") = 129,
           "The orbit of each probe over one period at a branch's point: (theta, v, w), theta the\n"
           "phase [rad] (samples,), v and w [m] (probes, samples)");
}

}  // namespace feran::python
