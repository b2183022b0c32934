#include <feran/io/report_config.hpp>

#include <filesystem>

#include <fmt/format.h>

#include <feran/analyses/settings.hpp>
#include <feran/io/model_reader.hpp>

#include "spec_table.hpp"
#include "table_reader.hpp"

namespace feran {

namespace {

using detail::TableReader;

// A sub-table of @p root, or nullptr; a key that is not a table is an error.
const toml::table* sub_table(const TableReader& root, std::string_view key) {
  const toml::node* n = root.find(key);
  if (n == nullptr) return nullptr;
  if (!n->is_table())
    root.fail(*n, fmt::format("'{}' must be a table ([{}]), got {}", key, key, detail::type_name(*n)));
  return n->as_table();
}

std::optional<Real> speed(const TableReader& t, std::string_view key) {
  const auto q = t.quantity(key, Quantity::speed);
  if (!q) return std::nullopt;
  t.require_non_negative(*q, key);
  return q->si;
}

std::vector<Index> nodes(const TableReader& t, std::string_view key, const Model& model) {
  std::vector<Index> out;
  const toml::array* a = t.array(key);
  if (a == nullptr) return out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& n = *a->get(i);
    Index found = -1;
    if (const auto s = n.value<std::string>())
      found = model.find_node(*s);
    else if (const auto k = n.value<std::int64_t>())
      found = model.find_node(static_cast<int>(*k));
    else
      t.fail(n, fmt::format("'{}[{}]' must be a node name or number, got {}", key, i, detail::type_name(n)));
    if (found < 0) t.fail(n, fmt::format("'{}[{}]': the model has no such node", key, i));
    out.push_back(found);
  }
  return out;
}

}  // namespace

void read_report_config(std::string_view toml_text, const std::string& path, const Model& model,
                        ReportOptions& options) {
  const toml::table root_table = detail::parse_toml(toml_text, path);
  const TableReader root(root_table, "", path);
  root.check_keys(
      {"title", "speed_unit", "campbell", "modes", "response", "static", "api684", "runup", "orbits", "study"});
  if (const auto t = root.string("title")) options.title = *t;
  if (const auto u = root.string("speed_unit")) {
    if (*u != "rpm" && *u != "Hz")
      root.fail(*root.find("speed_unit"), fmt::format("'speed_unit' must be \"rpm\" or \"Hz\", got \"{}\"", *u));
    options.speed_unit = *u;
  }
  // [campbell], [response], [orbits] and [api684] take the keys of the model file's tables of the
  // same names, read by their field tables (docs/model-format.md), and a few of their own.
  if (const toml::table* c = sub_table(root, "campbell"))
    options.campbell = detail::read_spec_table<CampbellSpec>(*c, "[campbell]", path);
  if (const toml::table* m = sub_table(root, "modes")) {
    const TableReader t(*m, "[modes]", path);
    t.check_keys({"speeds", "count"});
    if (const toml::array* a = t.array("speeds")) {
      options.mode_speeds.clear();
      for (std::size_t i = 0; i < a->size(); ++i) {
        const auto q = t.quantity_at(*a->get(i), fmt::format("speeds[{}]", i), Quantity::speed);
        t.require_non_negative(q, fmt::format("speeds[{}]", i));
        options.mode_speeds.push_back(q.si);
      }
    }
    if (const auto n = t.integer("count", 1, 100)) options.mode_count = *n;
  }
  if (const toml::table* r = sub_table(root, "response")) {
    const TableReader t(*r, "[response]", path);
    constexpr std::string_view own[] = {"deflection_speed"};
    options.response = detail::read_spec_table<ResponseSpec>(*r, "[response]", path, own);
    (void)nodes(t, "probes", model);  // each a node of the model, located here
    options.deflection_speed = speed(t, "deflection_speed");
  }
  for (const auto& [name, enabled] :
       {std::pair<const char*, bool*>{"static", &options.static_analysis}, {"runup", &options.runup}})
    if (const toml::table* s = sub_table(root, name)) {
      const TableReader t(*s, fmt::format("[{}]", name), path);
      t.check_keys({"enabled"});
      *enabled = t.boolean("enabled").value_or(true);
    }
  if (const toml::table* o = sub_table(root, "orbits")) {
    const TableReader t(*o, "[orbits]", path);
    constexpr std::string_view own[] = {"enabled"};
    options.orbits_request = detail::read_spec_table<OrbitsSpec>(*o, "[orbits]", path, own);
    (void)nodes(t, "probes", model);  // each a node of the model, located here
    options.orbits = t.boolean("enabled").value_or(true);
  }
  if (const toml::table* a = sub_table(root, "api684")) {
    const TableReader t(*a, "[api684]", path);
    constexpr std::string_view own[] = {"enabled"};
    options.api684_request = detail::read_spec_table<Api684Spec>(*a, "[api684]", path, own);
    options.api684 = t.boolean("enabled").value_or(true);
  }
  if (const toml::table* s = sub_table(root, "study")) {
    const TableReader t(*s, "[study]", path);
    t.check_keys({"directory"});
    namespace fs = std::filesystem;
    fs::path dir(t.required_string("directory", "the output directory of feran study -o DIR"));
    if (dir.is_relative()) dir = fs::path(path).parent_path() / dir;
    if (!fs::is_directory(dir))
      t.fail(*t.find("directory"), fmt::format("study directory '{}' does not exist", dir.string()));
    options.study_directory = dir.lexically_normal().string();
  }
}

void read_report_config_file(const std::string& path, const Model& model, ReportOptions& options) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(fmt::format("cannot open the report configuration '{}': no such file", path));
  read_report_config(read_text_file(path), path, model, options);
}

}  // namespace feran
