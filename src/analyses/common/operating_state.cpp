#include <feran/analyses/common/operating_state.hpp>

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

std::vector<Real> OperatingSeries::series(std::string_view name) const {
  const auto it = std::find(quantities.begin(), quantities.end(), name);
  if (it == quantities.end()) return {};
  const auto k = static_cast<std::size_t>(it - quantities.begin());
  std::vector<Real> out;
  out.reserve(values.size());
  for (const std::vector<Real>& row : values) out.push_back(row[k]);
  return out;
}

void OperatingSeries::append(const std::vector<OperatingValue>& data) {
  std::vector<Real> row(quantities.size(), std::numeric_limits<Real>::quiet_NaN());
  if (!data.empty()) {
    if (data.size() != quantities.size()) throw Error("a support reported other operating quantities than before");
    for (std::size_t k = 0; k < data.size(); ++k) {
      if (data[k].name != quantities[k]) throw Error("a support reported other operating quantities than before");
      row[k] = data[k].value;
    }
  }
  values.push_back(std::move(row));
}

std::vector<OperatingSeries> operating_series(const Model& model) {
  std::vector<OperatingSeries> out;
  for (std::size_t i = 0; i < model.forces.size(); ++i) {
    const Force& force = model.forces[i];
    if (!force.supports()) continue;
    OperatingSeries s{.force = static_cast<Index>(i), .quantities = {}, .values = {}};
    const auto n = static_cast<Index>(force.dofs().size());
    // At rest in its centre a film is asked at unit speed: only the names are kept.
    for (const OperatingValue& v : force.operating_data({.speed = 1.0}, Vector::Zero(n), Vector::Zero(n)))
      s.quantities.push_back(v.name);
    out.push_back(std::move(s));
  }
  return out;
}

void append_at_equilibrium(std::vector<OperatingSeries>& series, const Model& linear, Real speed) {
  std::size_t k = 0;
  for (const Element& e : linear.elements) {
    std::optional<std::vector<OperatingValue>> data = e.operating_data(speed);
    if (!data) continue;
    if (k == series.size()) throw Error("the linearised model has more supports than the model");
    series[k++].append(*data);
  }
  if (k != series.size()) throw Error("the linearised model has fewer supports than the model");
}

void append_in_motion(std::vector<OperatingSeries>& series, const Model& model, const MotionState& state,
                      const Vector& x, const Vector& v) {
  for (OperatingSeries& s : series) {
    const Force& force = model.forces[static_cast<std::size_t>(s.force)];
    const std::vector<Index> dofs = force.dofs();
    const auto n = static_cast<Index>(dofs.size());
    Vector xl(n), vl(n);
    for (Index k = 0; k < n; ++k) {
      xl(k) = x(dofs[static_cast<std::size_t>(k)]);
      vl(k) = v(dofs[static_cast<std::size_t>(k)]);
    }
    // A state the force cannot be evaluated in (an interpolated sample with the journal
    // at its bearing's wall) gives a row of NaN rather than ending the analysis.
    std::vector<OperatingValue> data;
    try {
      data = force.operating_data(state, xl, vl);
    } catch (const Error&) {
      data.clear();
    }
    s.append(data);
  }
}

}  // namespace feran
