#include <feran/io/report.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/text.hpp>

#include "result_text.hpp"

namespace feran {

namespace {

using namespace detail;  // NOLINT(google-build-using-namespace): the reports' shared vocabulary (result_text.hpp)

}  // namespace

std::string parameters_report(const std::vector<Parameter>& parameters, const ResultSource& source) {
  std::size_t path_width = 4, value_width = 5;
  for (const Parameter& p : parameters) {
    path_width = std::max(path_width, printable(p.path).size());
    value_width = std::max(value_width, printable(p.text()).size());
  }
  std::string out = fmt::format("{} settable parameters of {}\n", parameters.size(), printable(source.model_path));
  out += "(set one with --set 'PATH=VALUE' on any analysis, the value with its unit)\n\n";
  out += fmt::format("{:<{}}  {:<{}}  {}\n", "path", path_width, "value", value_width, "meaning");
  for (const Parameter& p : parameters)
    out += fmt::format("{:<{}}  {:<{}}  {}\n", printable(p.path), path_width, printable(p.text()), value_width, p.doc);
  return out;
}

}  // namespace feran
