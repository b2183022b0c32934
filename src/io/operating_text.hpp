#pragma once
// The supports' operating state (analyses/common/operating_state.hpp) in the JSON and
// CSV files feran writes (format in docs/output-format.md).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "csv_text.hpp"
#include "json_text.hpp"

#include <feran/analyses/common/operating_state.hpp>
#include <feran/model/model.hpp>

namespace feran::detail {

/// A force's name in the outputs: its label, or "force <position from 1>".
inline std::string force_label(const Model& model, Index force) {
  const std::string& label = model.forces[static_cast<std::size_t>(force)].label();
  return label.empty() ? fmt::format("force {}", force + 1) : label;
}

/// Per support: its label, kind, nodes and, per quantity, its values over the points
/// (a number each with @p one_point).
inline nlohmann::json operating_json(const std::vector<OperatingSeries>& series, const Model& model,
                                     bool one_point = false) {
  nlohmann::json out = nlohmann::json::array();
  for (const OperatingSeries& s : series) {
    const Force& force = model.forces[static_cast<std::size_t>(s.force)];
    const std::vector<Index> at = force.nodes();
    nlohmann::json js = {{"label", force_label(model, s.force)},
                         {"kind", force.kind()},
                         {"node", model.nodes[static_cast<std::size_t>(at.front())].number}};
    js["to"] =
        at.size() > 1 ? nlohmann::json(model.nodes[static_cast<std::size_t>(at[1])].number) : nlohmann::json("ground");
    nlohmann::json values = nlohmann::json::object();
    for (std::size_t q = 0; q < s.quantities.size(); ++q) {
      if (one_point) {
        values[s.quantities[q]] = s.values.empty() ? nlohmann::json(nullptr) : json_number(s.values.front()[q]);
        continue;
      }
      nlohmann::json column = nlohmann::json::array();
      for (const std::vector<Real>& row : s.values) column.push_back(json_number(row[q]));
      values[s.quantities[q]] = column;
    }
    js["operating"] = values;
    out.push_back(js);
  }
  return out;
}

/// The CSV columns of the supports' state: ",<label>_<quantity>" for each.
inline std::string operating_csv_header(const std::vector<OperatingSeries>& series, const Model& model) {
  std::string out;
  for (const OperatingSeries& s : series)
    for (const std::string& q : s.quantities) out += ',' + csv_column(force_label(model, s.force), "_" + q);
  return out;
}

/// The fields of one point under operating_csv_header(): @p rows holds per support its
/// values at the point.
inline void append_operating_csv(std::string& out, const std::vector<const std::vector<Real>*>& rows) {
  for (const std::vector<Real>* row : rows)
    for (const Real v : *row) {
      out += ',';
      out += csv_number(v);
    }
}

/// The same for point @p k of @p series.
inline std::string operating_csv_row(const std::vector<OperatingSeries>& series, std::size_t k) {
  std::vector<const std::vector<Real>*> rows;
  for (const OperatingSeries& s : series) rows.push_back(&s.values[k]);
  std::string out;
  append_operating_csv(out, rows);
  return out;
}

}  // namespace feran::detail
