#include <feran/io/study_reader.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include <feran/analyses/common/operating_state.hpp>
#include <feran/spec/build_model.hpp>
#include <feran/spec/parameters.hpp>

#include "suggestions.hpp"
#include "table_reader.hpp"

namespace feran {

namespace {

using detail::closest_match;
using detail::join_list;
using detail::TableReader;

class StudyReader {
 public:
  StudyReader(const toml::table& root, const std::string& path, const StudyCode* code)
      : root_(root, "", path), path_(path), code_(code) {}

  StudyFile read() {
    root_.check_keys({"title", "model", "settings", "variables", "quantities", "objectives", "constraints", "explore"});
    StudyFile file;
    file.path = path_;
    auto& study = file.study;
    study.title = root_.string("title").value_or("");
    if (code_ != nullptr) {
      if (const auto* m = root_.find("model"))
        root_.fail(*m, "a study built in code is given its base model; it has no 'model' key");
      study.model_path = code_->model_name;
      file.base = code_->base;
    } else {
      const auto& model_node = root_.require("model", "the path of the base model file, a string");
      const auto model = model_node.value<std::string>();
      if (!model)
        root_.fail(model_node,
                   fmt::format("'model' must be a string (a file path), got {}", detail::type_name(model_node)));
      study.model_path = *model;
      namespace fs = std::filesystem;
      fs::path model_path(*model);
      if (model_path.is_relative()) model_path = fs::path(path_).parent_path() / model_path;
      try {
        file.base = read_model_file(model_path.lexically_normal().string());
      } catch (const ModelError&) {
        throw;
      } catch (const Error& e) {
        root_.fail(model_node, e.what());
      }
    }
    study.base = file.base.spec;
    read_settings(study, file.base);
    read_variables(study);
    read_quantities(study);
    read_objectives(study);
    read_constraints(study);
    read_explore(study);
    return file;
  }

 private:
  // An array of tables at the top level, each read by @p each.
  template <class F>
  void each_table(std::string_view key, std::string_view what, F&& each) {
    const toml::node* node = root_.find(key);
    if (node == nullptr) return;
    const auto* array = node->as_array();
    if (array == nullptr || !array->is_array_of_tables())
      root_.fail(*node, fmt::format("'{}' must be an array of tables ([[{}]], one per {})", key, key, what));
    int i = 0;
    for (const auto& element : *array) {
      TableReader t(*element.as_table(), fmt::format("[[{}]] {}", key, i + 1), path_);
      each(t, i++);
    }
  }

  // Settings: parameter paths set on the base model before the study.
  void read_settings(StudySpec& study, const ModelFile& base) {
    const toml::node* node = root_.find("settings");
    if (node == nullptr) return;
    const auto* table = node->as_table();
    if (table == nullptr) root_.fail(*node, "'settings' must be a table of parameter paths and values");
    std::vector<std::pair<std::string, std::string>> changed;
    for (auto&& [key, value] : *table) {
      std::string text;
      if (const auto s = value.value<std::string>(); s && value.is_string())
        text = *s;
      else if (value.is_integer() || value.is_floating_point())
        text = fmt::format("{}", *value.value<double>());
      else
        root_.fail(value, fmt::format("setting '{}' must be a number or a text with its unit, got {}", key.str(),
                                      detail::type_name(value)));
      try {
        const auto canonical = set_parameter(study.base, key.str(), text);
        const auto at = detail::location_of(path_, value);
        changed.emplace_back(fmt::format("{}:{}:{}: setting '{}'", at.file, at.line, at.column, key.str()), canonical);
      } catch (const ParameterError& e) {
        root_.fail(value, fmt::format("setting '{}': {}", key.str(), e.what()));
      }
    }
    if (!changed.empty()) build_model_file(study.base, base.source, base.path, changed);
  }

  void read_variables(StudySpec& study) {
    // Every number one variable sets, by its canonical path: two variables (or two
    // tied paths) setting one number would fight over it.
    std::map<std::string, std::string> owner;
    each_table("variables", "design variable", [&](const TableReader& t, int i) {
      t.check_keys({"name", "path", "paths", "lower", "upper", "scale", "values", "unit"});
      DesignVariable v;
      v.name = t.required_string("name", "the variable's name, a string");
      if (t.has("path") == t.has("paths"))
        t.fail_here("give either 'path' (one parameter path) or 'paths' (tied ones)");
      std::vector<const toml::node*> path_nodes;
      std::vector<const toml::table*> maps;  // per path: its { factor, offset } table, or none
      if (t.has("path")) {
        v.paths.push_back(t.required_string("path", "a parameter path"));
        path_nodes.push_back(t.find("path"));
      } else {
        const auto& array = t.required_array("paths", "parameter paths, strings");
        int k = 0;
        for (const auto& p : array) {
          if (p.is_string()) {
            v.paths.push_back(*p.value<std::string>());
            path_nodes.push_back(&p);
            maps.push_back(nullptr);
          } else if (const auto* map = p.as_table()) {
            // { path = "...", factor = F, offset = O }: the path is set to O + F·value.
            TableReader m(*map, fmt::format("{} paths[{}]", t.context(), k), path_);
            m.check_keys({"path", "factor", "offset"});
            v.paths.push_back(m.required_string("path", "a parameter path"));
            path_nodes.push_back(m.find("path"));
            maps.push_back(map);
          } else {
            t.fail(p,
                   fmt::format("'paths' must hold parameter paths (strings) or tables {{ path = \"...\", factor = F, "
                               "offset = O }}, got {}",
                               detail::type_name(p)));
          }
          ++k;
        }
        if (v.paths.empty()) t.fail(*t.find("paths"), "'paths' needs at least one parameter path");
      }
      // Each path must name a number of the base model; tied paths one kind.
      for (std::size_t k = 0; k < v.paths.size(); ++k) {
        Parameter p;
        try {
          p = get_parameter(study.base, v.paths[k]);
        } catch (const ParameterError& e) {
          t.fail(*path_nodes[k], e.what());
        }
        ModelSpec scratch = study.base;  // the canonical path (entries by index), from setting it
        const auto [it, fresh] = owner.emplace(set_parameter(scratch, v.paths[k], p.value), v.name);
        if (!fresh)
          t.fail(*path_nodes[k], it->second == v.name
                                     ? fmt::format("'{}' is given twice in this variable's paths", v.paths[k])
                                     : fmt::format("'{}' is already set by the variable '{}': one number, one "
                                                   "variable (tie paths within one variable with 'paths')",
                                                   v.paths[k], it->second));
        if (k == 0) {
          v.quantity = p.quantity;
          v.unit = p.unit;
        } else if (p.quantity != v.quantity) {
          t.fail(*path_nodes[k], fmt::format("'{}' is not of the same kind as '{}': tied paths take one value",
                                             v.paths[k], v.paths[0]));
        }
      }
      if (std::any_of(maps.begin(), maps.end(), [](const toml::table* m) { return m != nullptr; })) {
        for (std::size_t k = 0; k < maps.size(); ++k) {
          Real factor = 1.0, offset = 0.0;
          if (maps[k] != nullptr) {
            TableReader m(*maps[k], fmt::format("{} paths[{}]", t.context(), k), path_);
            factor = m.number("factor").value_or(1.0);
            if (!std::isfinite(factor) || factor == 0.0)
              m.fail(*m.find("factor"), "'factor' must be a finite number other than 0");
            if (const auto* o = m.find("offset")) {
              if (v.quantity)
                offset = m.quantity_at(*o, "offset", *v.quantity).si;
              else if (const auto x = o->value<double>(); x && (o->is_integer() || o->is_floating_point()))
                offset = *x;
              else
                m.fail(*o, fmt::format("'offset' must be a number, got {}", detail::type_name(*o)));
            }
          }
          v.factors.push_back(factor);
          v.offsets.push_back(offset);
        }
      }
      if (const auto unit = t.string("unit")) v.unit = *unit;
      const auto value_of = [&](const toml::node& n, std::string_view name) {
        if (v.quantity) return t.quantity_at(n, name, *v.quantity).si;
        if (const auto x = n.value<double>(); x && (n.is_integer() || n.is_floating_point())) return *x;
        t.fail(n, fmt::format("'{}' must be a number, got {}", name, detail::type_name(n)));
      };
      if (const auto* values = t.array("values")) {
        if (t.has("lower") || t.has("upper") || t.has("scale"))
          t.fail_here("a variable has either 'values' (discrete) or 'lower' and 'upper', not both");
        int k = 0;
        for (const auto& n : *values) v.values.push_back(value_of(n, fmt::format("values[{}]", k++)));
        if (v.values.empty()) t.fail(*t.find("values"), "'values' needs at least one value");
      } else {
        v.lower = value_of(t.require("lower", "the lower bound"), "lower");
        v.upper = value_of(t.require("upper", "the upper bound"), "upper");
        if (const auto scale = t.string("scale")) {
          if (*scale == "log")
            v.scale = VariableScale::log;
          else if (*scale != "linear")
            t.fail(*t.find("scale"), fmt::format("'scale' must be \"linear\" or \"log\", got \"{}\"", *scale));
        }
      }
      study.variables.push_back(std::move(v));
      try {
        check_variables(study.variables);
      } catch (const SpecError& e) {
        t.fail_here(e.message());
      }
      (void)i;
    });
    if (study.variables.empty()) root_.fail_here("a study needs at least one [[variables]] entry");
  }

  void read_quantities(StudySpec& study) {
    each_table("quantities", "quantity", [&](const TableReader& t, int) {
      t.check_keys({"name", "kind", "whirl", "order", "n", "range", "operating", "speed", "probe", "spring", "bearing",
                    "value", "path", "unit"});
      QuantitySpec q;
      q.name = t.required_string("name", "the quantity's name, a string");
      for (const auto& other : study.quantities)
        if (other.name == q.name) t.fail(*t.find("name"), fmt::format("another quantity is named '{}'", q.name));
      const auto& kind_node = t.require("kind", "what to compute");
      const auto kind_name = t.required_string("kind", "what to compute");
      const QuantityRow* row = quantity_row(kind_name);
      if (row == nullptr) {
        std::vector<std::string> names;
        for (const QuantityRow& r : quantity_rows()) names.emplace_back(r.name);
        std::string message = fmt::format("unknown quantity kind '{}'", kind_name);
        std::vector<std::string> longer;  // kinds the name is the start of ("min_damping")
        for (const auto& n : names)
          if (n.starts_with(kind_name)) longer.push_back(n);
        if (const auto m = closest_match(kind_name, names, 4))
          message += fmt::format("; did you mean '{}'?", *m);
        else if (!longer.empty())
          message += fmt::format("; did you mean {}?", join_list(longer, "or", '\''));
        else
          message += fmt::format("; the kinds are {}", join_list(names, "and", '\''));
        t.fail(kind_node, message);
      }
      q.kind = kind_name;
      if (row->code_only && code_ == nullptr)
        t.fail(kind_node,
               "a quantity of kind \"function\" is computed by code: it belongs to studies built in code "
               "(the Python package's feran.Study), not to study files");
      q.whirl = row->any_whirl ? WhirlSelection::any : WhirlSelection::forward;
      if (const auto w = t.string("whirl")) {
        if (*w == "forward")
          q.whirl = WhirlSelection::forward;
        else if (*w == "backward")
          q.whirl = WhirlSelection::backward;
        else if (*w == "any")
          q.whirl = WhirlSelection::any;
        else
          t.fail(*t.find("whirl"), fmt::format("'whirl' must be \"forward\", \"backward\" or \"any\", got \"{}\"", *w));
      }
      q.order = t.integer("order", 1, 100).value_or(1);
      q.n = t.integer("n", 1, 1000).value_or(1);
      if (const auto* range = t.array("range")) {
        if (range->size() != 2) t.fail(*t.find("range"), "'range' must be [low, high], two speeds");
        q.low = t.quantity_at(*range->get(0), "range[0]", Quantity::speed).si;
        q.high = t.quantity_at(*range->get(1), "range[1]", Quantity::speed).si;
        if (!(*q.low < *q.high)) t.fail(*t.find("range"), "'range' must be [low, high] with low < high");
      }
      if (const auto* op = t.array("operating")) {
        if (op->size() != 2) t.fail(*t.find("operating"), "'operating' must be [low, high], two speeds");
        q.operating_low = t.quantity_at(*op->get(0), "operating[0]", Quantity::speed).si;
        q.operating_high = t.quantity_at(*op->get(1), "operating[1]", Quantity::speed).si;
        if (!(q.operating_low > 0 && q.operating_low <= q.operating_high))
          t.fail(*t.find("operating"), "'operating' must be [low, high] with 0 < low ≤ high");
      } else if (row->needs_operating) {
        t.fail_here(fmt::format("a {} needs 'operating' = [low, high], the operating speed range", q.kind));
      }
      if (const auto s = t.quantity("speed", Quantity::speed)) q.speed = s->si;
      if (row->needs_speed && !(q.speed && *q.speed > 0))
        t.fail_here(fmt::format("a {} needs 'speed' > 0, the maximum continuous speed", q.kind));
      if (const auto* p = t.find("probe")) {
        if (p->is_string())
          q.probe = NodeRef(*p->value<std::string>());
        else if (p->is_integer())
          q.probe = NodeRef(*p->value<std::int64_t>());
        else
          t.fail(*p, fmt::format("'probe' must be a node name or number, got {}", detail::type_name(*p)));
      }
      if (const auto s = t.string("spring")) q.spring = *s;
      read_bearing_value(t, study, q);
      if (row->parameter) {
        q.path = t.required_string("path", "the parameter path of the number");
        try {
          q.value_kind = get_parameter(study.base, q.path).quantity;
        } catch (const ParameterError& e) {
          t.fail(*t.find("path"), e.what());
        }
      } else if (t.has("path")) {
        t.fail(*t.find("path"), "'path' belongs to quantities of kind \"parameter\"");
      }
      if (const auto u = t.string("unit")) {
        const auto kind_unit = quantity_unit(q);
        if (!kind_unit || !to_si(*kind_unit, 1.0, *u))
          t.fail(*t.find("unit"), kind_unit ? fmt::format("'unit' must be a unit of {}: {}", quantity_name(*kind_unit),
                                                          accepted_units_text(*kind_unit))
                                            : fmt::format("a {} is a pure number and takes no unit", kind_name));
        q.unit = *u;
      }
      study.quantities.push_back(std::move(q));
    });
    if (study.quantities.empty()) root_.fail_here("a study needs at least one [[quantities]] entry");
  }

  // min_bearing_value and max_bearing_value: 'value', the name of a bearing's operating
  // quantity, checked against the bearings of the base model (a model without bearings
  // leaves it to the evaluation, which fails the design with the reason); 'bearing'.
  void read_bearing_value(const TableReader& t, const StudySpec& study, QuantitySpec& q) {
    const bool bearing_kind = row_of(q).bearing_value;
    for (const char* key : {"value", "bearing"})
      if (!bearing_kind && t.has(key)) {
        std::vector<std::string> kinds;
        for (const QuantityRow& r : quantity_rows())
          if (r.bearing_value) kinds.push_back(fmt::format("\"{}\"", r.name));
        t.fail(*t.find(key), fmt::format("'{}' belongs to quantities of kind {}", key, join_list(kinds)));
      }
    if (!bearing_kind) return;
    q.value = t.required_string("value", "the bearing's operating quantity, e.g. \"min_film_thickness_m\"");
    if (const auto b = t.string("bearing")) q.bearing = *b;
    std::vector<OperatingSeries> series;
    Model model;
    try {
      model = build_model(study.base);
      series = operating_series(model);
    } catch (const Error&) {
      return;  // the base model's own mistakes are reported where it is read
    }
    if (series.empty()) return;
    std::vector<std::string> labels, names;
    for (const OperatingSeries& s : series) {
      labels.push_back(model.forces[static_cast<std::size_t>(s.force)].label());
      if (!q.bearing || *q.bearing == labels.back())
        for (const std::string& n : s.quantities)
          if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
    }
    if (q.bearing && std::find(labels.begin(), labels.end(), *q.bearing) == labels.end()) {
      std::string message = fmt::format("no bearing named '{}'", *q.bearing);
      if (const auto m = closest_match(*q.bearing, labels, 3))
        message += fmt::format("; did you mean '{}'?", *m);
      else
        message += fmt::format("; the bearings are {}", join_list(labels, "and", '\''));
      t.fail(*t.find("bearing"), message);
    }
    if (std::find(names.begin(), names.end(), q.value) == names.end()) {
      std::string message = fmt::format("unknown bearing quantity '{}'", q.value);
      if (const auto m = closest_match(q.value, names, 4))
        message += fmt::format("; did you mean '{}'?", *m);
      else
        message += fmt::format("; the quantities are {}", join_list(names, "and", '\''));
      t.fail(*t.find("value"), message);
    }
  }

  Index quantity_named(const TableReader& t) {
    const auto& node = t.require("quantity", "the name of a quantity");
    const auto name = t.required_string("quantity", "the name of a quantity");
    for (std::size_t i = 0; i < quantities_->size(); ++i)
      if ((*quantities_)[i].name == name) return static_cast<Index>(i);
    std::vector<std::string> names;
    for (const auto& q : *quantities_) names.push_back(q.name);
    std::string message = fmt::format("no quantity named '{}'", name);
    if (const auto m = closest_match(name, names, 3))
      message += fmt::format("; did you mean '{}'?", *m);
    else
      message += fmt::format("; the quantities are {}", join_list(names, "and", '\''));
    t.fail(node, message);
  }

  void read_objectives(StudySpec& study) {
    quantities_ = &study.quantities;
    each_table("objectives", "objective", [&](const TableReader& t, int) {
      t.check_keys({"quantity", "sense"});
      Objective o;
      o.quantity = quantity_named(t);
      const auto sense = t.required_string("sense", "\"minimise\" or \"maximise\"");
      if (sense == "minimise" || sense == "minimize")
        o.sense = Sense::minimise;
      else if (sense == "maximise" || sense == "maximize")
        o.sense = Sense::maximise;
      else
        t.fail(*t.find("sense"), fmt::format("'sense' must be \"minimise\" or \"maximise\", got \"{}\"", sense));
      study.objectives.push_back(o);
    });
  }

  void read_constraints(StudySpec& study) {
    quantities_ = &study.quantities;
    each_table("constraints", "constraint", [&](const TableReader& t, int) {
      t.check_keys({"quantity", "at_most", "at_least"});
      Constraint c;
      c.quantity = quantity_named(t);
      const auto kind = quantity_unit(study.quantities[static_cast<std::size_t>(c.quantity)]);
      const auto bound = [&](std::string_view key) -> std::optional<Real> {
        const auto* n = t.find(key);
        if (n == nullptr) return std::nullopt;
        if (kind) return t.quantity_at(*n, key, *kind).si;
        if (const auto x = n->value<double>(); x && (n->is_integer() || n->is_floating_point())) return *x;
        t.fail(*n, fmt::format("'{}' must be a number, got {}", key, detail::type_name(*n)));
      };
      c.at_most = bound("at_most");
      c.at_least = bound("at_least");
      if (!c.at_most && !c.at_least) t.fail_here("a constraint needs 'at_most' or 'at_least'");
      study.constraints.push_back(c);
    });
  }

  void read_explore(StudySpec& study) {
    const toml::node* node = root_.find("explore");
    if (node == nullptr) return;
    const auto* table = node->as_table();
    if (table == nullptr) root_.fail(*node, "'explore' must be a table ([explore])");
    TableReader t(*table, "[explore]", path_);
    t.check_keys({"method", "levels", "samples", "seed", "algorithm", "population", "generations", "polish"});
    auto& x = study.explore;
    if (const auto m = t.string("method")) {
      if (*m == "grid")
        x.method = ExploreMethod::grid;
      else if (*m == "latin_hypercube" || *m == "lhs")
        x.method = ExploreMethod::latin_hypercube;
      else if (*m == "sobol")
        x.method = ExploreMethod::sobol;
      else if (*m == "optimise" || *m == "optimize")
        x.method = ExploreMethod::optimise;
      else if (*m == "pareto")
        x.method = ExploreMethod::pareto;
      else
        t.fail(*t.find("method"), fmt::format("'method' must be \"grid\", \"latin_hypercube\", \"sobol\", "
                                              "\"optimise\" or \"pareto\", got \"{}\"",
                                              *m));
    }
    const bool optimiser = x.method == ExploreMethod::optimise || x.method == ExploreMethod::pareto;
    for (const char* key : {"algorithm", "population", "generations", "polish"})
      if (!optimiser && t.has(key))
        t.fail(*t.find(key), fmt::format("'{}' belongs to the methods \"optimise\" and \"pareto\"", key));
    if (const auto a = t.string("algorithm")) {
      if (x.method == ExploreMethod::pareto)
        t.fail(*t.find("algorithm"), "method \"pareto\" is NSGA-II; it takes no 'algorithm'");
      if (*a == "pso")
        x.algorithm = GlobalAlgorithm::pso;
      else if (*a == "gaco")
        x.algorithm = GlobalAlgorithm::gaco;
      else
        t.fail(*t.find("algorithm"), fmt::format("'algorithm' must be \"pso\" or \"gaco\", got \"{}\"", *a));
    }
    x.population = t.integer("population", 2, 100000).value_or(x.method == ExploreMethod::pareto ? 32 : 16);
    x.generations = t.integer("generations", 0, 100000).value_or(20);
    x.polish = t.integer("polish", 0, 1000000).value_or(0);
    if (x.method == ExploreMethod::pareto && (x.population < 8 || x.population % 4 != 0))
      t.fail(t.has("population") ? *t.find("population") : *node,
             fmt::format("NSGA-II needs a population that is a multiple of 4 and at least 8, got {}", x.population));
    if (x.method == ExploreMethod::pareto && study.objectives.size() < 2)
      t.fail(*t.find("method"),
             fmt::format("method \"pareto\" needs two objectives or more, the study has {}", study.objectives.size()));
    if (x.method == ExploreMethod::optimise && study.objectives.size() != 1)
      t.fail(*t.find("method"), fmt::format("method \"optimise\" takes one objective, the study has {}; "
                                            "\"pareto\" takes several",
                                            study.objectives.size()));
    x.levels = t.integer("levels", 1, 10000).value_or(5);
    x.samples = t.integer("samples", 1, 10'000'000).value_or(32);
    if (const auto* s = t.find("seed")) {
      if (!s->is_integer() || *s->value<std::int64_t>() < 0) t.fail(*s, "'seed' must be a non-negative integer");
      study.explore.seed = static_cast<std::uint64_t>(*s->value<std::int64_t>());
    }
    if (study.explore.method == ExploreMethod::sobol &&
        static_cast<Index>(study.variables.size()) > max_sobol_dimensions)
      t.fail(*t.find("method"), fmt::format("a Sobol' sequence takes at most {} variables, the study has {}",
                                            max_sobol_dimensions, study.variables.size()));
  }

  TableReader root_;
  const std::string& path_;
  const StudyCode* code_;
  const std::vector<QuantitySpec>* quantities_ = nullptr;
};

}  // namespace

namespace {

StudyFile read_study(std::string_view toml_text, const std::string& path, const StudyCode* code) {
  const toml::table root = detail::parse_toml(toml_text, path);
  return StudyReader(root, path, code).read();
}

}  // namespace

StudyFile read_study_string(std::string_view toml_text, const std::string& path) {
  return read_study(toml_text, path, nullptr);
}

StudyFile read_study_string(std::string_view toml_text, const std::string& path, const StudyCode& code) {
  return read_study(toml_text, path, &code);
}

StudyFile read_study_file(const std::string& path) { return read_study_string(read_text_file(path), path); }

}  // namespace feran
