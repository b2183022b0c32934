#include <feran/io/result_writer.hpp>

#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/static/equilibrium.hpp>

#include "result_text.hpp"

#include <feran/core/error.hpp>

namespace feran {

namespace {

using nlohmann::json;

using namespace detail;  // NOLINT(google-build-using-namespace): the writers' shared vocabulary (result_text.hpp)

}  // namespace

std::string parameters_json(const std::vector<Parameter>& parameters, const ResultSource& source) {
  json out = header("params", source);
  json list = json::array();
  for (const Parameter& p : parameters)
    list.push_back({{"path", p.path},
                    {"value", json_number(p.value)},
                    {"si_unit", p.quantity ? std::string(si_unit(*p.quantity)) : std::string()},
                    {"quantity", p.quantity ? std::string(quantity_name(*p.quantity)) : std::string()},
                    {"integer", p.integer},
                    {"text", p.text()},
                    {"doc", p.doc}});
  out["parameters"] = std::move(list);
  return detail::json_text(out, 2);
}

}  // namespace feran
