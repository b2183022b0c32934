#include <feran/io/study_log.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/core/error.hpp>
#include <feran/io/model_writer.hpp>
#include <feran/study/sensitivity.hpp>

#include "csv_text.hpp"
#include "json_text.hpp"

namespace feran {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const char* scale_name(VariableScale s) { return s == VariableScale::log ? "log" : "linear"; }
std::string si_unit_of(const std::optional<Quantity>& q) { return q ? std::string(si_unit(*q)) : std::string(); }

using detail::json_number;

void write_all(std::FILE* f, const std::string& text, const std::string& path) {
  if (std::fwrite(text.data(), 1, text.size(), f) != text.size() || std::fflush(f) != 0 || ::fsync(fileno(f)) != 0)
    throw Error(fmt::format("cannot write '{}'", path));
}

std::string csv_header(const StudySpec& study) {
  std::vector<std::string> cells{"index"};
  for (const auto& v : study.variables) {
    const auto unit = si_unit_of(v.quantity);
    cells.push_back(unit.empty() ? v.name : fmt::format("{} [{}]", v.name, unit));
  }
  for (const auto& q : study.quantities) {
    const auto unit = si_unit_of(quantity_unit(q));
    cells.push_back(unit.empty() ? q.name : fmt::format("{} [{}]", q.name, unit));
  }
  for (const char* c : {"evaluated", "feasible", "seconds", "message", "clipped"}) cells.emplace_back(c);
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + detail::csv_field(cells[i]);
  return line + "\n";
}

std::string csv_row(const StudySpec& study, const Evaluation& e) {
  std::string line = fmt::format("{}", e.index);
  for (const Real v : e.values) line += fmt::format(",{:.17g}", v);
  for (std::size_t i = 0; i < study.quantities.size(); ++i)
    line += e.quantities.empty() ? std::string(",") : fmt::format(",{:.17g}", e.quantities[i]);
  std::string clipped;  // "NAME: why; NAME: why" for the quantities that are only bounds
  for (std::size_t i = 0; i < e.clipped.size() && i < study.quantities.size(); ++i)
    if (!e.clipped[i].empty())
      clipped += (clipped.empty() ? "" : "; ") + study.quantities[i].name + ": " + e.clipped[i];
  line += fmt::format(",{},{},{:.6f},{},{}\n", e.evaluated, e.feasible, e.seconds, detail::csv_field(e.message),
                      detail::csv_field(clipped));
  return line;
}

std::FILE* open_append(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "ab");
  if (f == nullptr) throw Error(fmt::format("cannot open '{}' for writing", path));
  return f;
}

}  // namespace

std::string study_json(const StudySpec& study) {
  json variables = json::array(), quantities = json::array();
  for (const auto& v : study.variables) {
    json j = {{"name", v.name}, {"paths", v.paths}, {"unit", si_unit_of(v.quantity)}};
    if (!v.factors.empty()) {
      j["factors"] = v.factors;
      j["offsets"] = v.offsets;
    }
    if (v.discrete())
      j["values"] = v.values;
    else
      j.update({{"lower", v.lower}, {"upper", v.upper}, {"scale", scale_name(v.scale)}});
    variables.push_back(j);
  }
  for (const auto& q : study.quantities)
    quantities.push_back({{"name", q.name}, {"kind", q.kind}, {"unit", si_unit_of(quantity_unit(q))}});
  json objectives = json::array(), constraints = json::array();
  for (const auto& o : study.objectives)
    objectives.push_back({{"quantity", study.quantities[static_cast<std::size_t>(o.quantity)].name},
                          {"sense", o.sense == Sense::minimise ? "minimise" : "maximise"}});
  for (const auto& c : study.constraints) {
    json j = {{"quantity", study.quantities[static_cast<std::size_t>(c.quantity)].name}};
    if (c.at_most) j["at_most"] = *c.at_most;
    if (c.at_least) j["at_least"] = *c.at_least;
    constraints.push_back(j);
  }
  const auto& x = study.explore;
  json explore = {{"method", to_string(x.method)}, {"seed", x.seed}};
  if (x.method == ExploreMethod::grid)
    explore["levels"] = x.levels;
  else if (x.method == ExploreMethod::latin_hypercube || x.method == ExploreMethod::sobol)
    explore["samples"] = x.samples;
  else {
    explore.update({{"population", x.population}, {"generations", x.generations}});
    if (x.method == ExploreMethod::optimise)
      explore.update({{"algorithm", x.algorithm == GlobalAlgorithm::pso ? "pso" : "gaco"}, {"polish", x.polish}});
  }
  const json j = {{"program", "feran"},         {"format_version", 1},       {"analysis", "study"},
                  {"title", study.title},       {"model", study.model_path}, {"base_model", write_toml(study.base)},
                  {"variables", variables},     {"quantities", quantities},  {"objectives", objectives},
                  {"constraints", constraints}, {"explore", explore}};
  return j.dump(1) + "\n";
}

std::string evaluation_json(const StudySpec& study, const Evaluation& e) {
  json values = json::object(), quantities = nullptr;
  for (std::size_t i = 0; i < study.variables.size(); ++i) values[study.variables[i].name] = e.values[i];
  if (!e.quantities.empty()) {
    quantities = json::object();
    for (std::size_t i = 0; i < study.quantities.size(); ++i)
      quantities[study.quantities[i].name] = json_number(e.quantities[i]);
  }
  json clipped = json::object();
  for (std::size_t i = 0; i < e.clipped.size() && i < study.quantities.size(); ++i)
    if (!e.clipped[i].empty()) clipped[study.quantities[i].name] = e.clipped[i];
  const json j = {{"index", e.index},         {"unit", e.unit},       {"variables", values},
                  {"quantities", quantities}, {"clipped", clipped},   {"evaluated", e.evaluated},
                  {"feasible", e.feasible},   {"message", e.message}, {"seconds", e.seconds}};
  return j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
}

Evaluation evaluation_from_json(const StudySpec& study, const std::string& line) {
  try {
    const json j = json::parse(line);
    Evaluation e;
    e.index = j.at("index").get<Index>();
    e.unit = j.at("unit").get<std::vector<Real>>();
    for (const auto& v : study.variables) e.values.push_back(j.at("variables").at(v.name).get<Real>());
    if (!j.at("quantities").is_null())
      for (const auto& q : study.quantities) {
        const auto& x = j.at("quantities").at(q.name);
        e.quantities.push_back(x.is_null() ? std::numeric_limits<Real>::quiet_NaN() : x.get<Real>());
      }
    if (!e.quantities.empty()) {
      e.clipped.assign(study.quantities.size(), std::string());
      if (const auto c = j.find("clipped"); c != j.end())
        for (std::size_t i = 0; i < study.quantities.size(); ++i)
          if (c->contains(study.quantities[i].name)) e.clipped[i] = c->at(study.quantities[i].name).get<std::string>();
    }
    e.evaluated = j.at("evaluated").get<bool>();
    e.feasible = j.at("feasible").get<bool>();
    e.message = j.at("message").get<std::string>();
    e.seconds = j.at("seconds").get<Real>();
    if (e.unit.size() != study.variables.size()) throw Error("wrong number of coordinates");
    return e;
  } catch (const json::exception& error) {
    throw Error(error.what());
  }
}

namespace {

// Whether @p name is a file the study writes in its directory.
bool written_by_study(const std::string& name) {
  const auto pareto = [&] {  // pareto-INDEX.toml
    const std::size_t n = name.size();
    if (n <= 12 || name.rfind("pareto-", 0) != 0 || name.compare(n - 5, 5, ".toml") != 0) return false;
    return name.find_first_not_of("0123456789", 7) == n - 5;
  };
  return name == study_files::evaluations || name == study_files::evaluations_csv || name == study_files::study ||
         name == study_files::summary || name == "best.toml" || pareto();
}

// Refuses @p directory if a file the study writes there is one of @p inputs: the
// input's own name there, or a name there that leads to it (a link, a hard link).
void refuse_inputs(const std::string& directory, const std::vector<std::string>& inputs) {
  std::error_code ec;
  for (const auto& input : inputs) {
    if (input.empty() || !fs::exists(input, ec)) continue;
    const fs::path real = fs::canonical(input, ec);
    if (!ec && written_by_study(real.filename().string()) && fs::equivalent(real.parent_path(), directory, ec))
      throw Error(
          fmt::format("cannot write the study's results in '{}': they would replace its input '{}' (the study "
                      "writes {} there); give another directory with -o",
                      directory, input, real.filename().string()));
    for (const auto& entry : fs::directory_iterator(directory, ec)) {
      const std::string name = entry.path().filename().string();
      if (written_by_study(name) && fs::equivalent(entry.path(), input, ec))
        throw Error(
            fmt::format("cannot write the study's results in '{}': its '{}' is the input '{}'; give another "
                        "directory with -o",
                        directory, name, input));
    }
  }
}

}  // namespace

StudyLog::StudyLog(std::string directory, const StudySpec& study, bool resume, const std::vector<std::string>& inputs)
    : directory_(std::move(directory)), study_(study) {
  std::error_code ec;
  fs::create_directories(directory_, ec);
  if (!fs::is_directory(directory_))
    throw Error(fmt::format("cannot make the output directory '{}'{}", directory_, ec ? ": " + ec.message() : ""));
  refuse_inputs(directory_, inputs);
  const auto jsonl_path = (fs::path(directory_) / study_files::evaluations).string();
  const auto csv_path = (fs::path(directory_) / study_files::evaluations_csv).string();
  const auto study_path = (fs::path(directory_) / study_files::study).string();
  const std::string description = study_json(study);
  const bool has_results = fs::exists(jsonl_path) && fs::file_size(jsonl_path, ec) > 0;
  if (has_results && !resume)
    throw Error(
        fmt::format("'{}' already holds the evaluations of a study; --resume continues it, or give "
                    "another directory with -o",
                    directory_));
  if (has_results) {
    std::ifstream old_description(study_path);
    const std::string old((std::istreambuf_iterator<char>(old_description)), std::istreambuf_iterator<char>());
    if (old != description)
      throw Error(
          fmt::format("'{}' holds the evaluations of a different study (its study.json differs: the "
                      "model, variables, quantities, objectives, constraints or exploration changed); "
                      "resume only the same study, or give another directory with -o",
                      directory_));
    // Read back every complete line; a line cut short (a crash while writing) ends
    // the valid part, and the files are cut back to it.
    std::ifstream in(jsonl_path, std::ios::binary);
    std::string line, valid;
    while (std::getline(in, line)) {
      if (in.eof()) break;  // no newline: cut short
      try {
        done_.push_back(evaluation_from_json(study, line));
      } catch (const Error&) {
        break;
      }
      valid += line + "\n";
    }
    in.close();
    std::ofstream(jsonl_path, std::ios::binary | std::ios::trunc) << valid;
    std::string csv = csv_header(study);
    for (const auto& e : done_) csv += csv_row(study, e);
    std::ofstream(csv_path, std::ios::binary | std::ios::trunc) << csv;
    std::sort(done_.begin(), done_.end(), [](const Evaluation& a, const Evaluation& b) { return a.index < b.index; });
  } else {
    std::ofstream(study_path, std::ios::binary | std::ios::trunc) << description;
    const std::ofstream emptied(jsonl_path, std::ios::binary | std::ios::trunc);
    std::ofstream(csv_path, std::ios::binary | std::ios::trunc) << csv_header(study);
  }
  jsonl_ = open_append(jsonl_path);
  csv_ = open_append(csv_path);
}

StudyLog::~StudyLog() {
  if (jsonl_ != nullptr) std::fclose(jsonl_);
  if (csv_ != nullptr) std::fclose(csv_);
}

void StudyLog::append(std::span<const Evaluation> evaluations) {
  std::string lines, rows;
  for (const auto& e : evaluations) {
    lines += evaluation_json(study_, e);
    rows += csv_row(study_, e);
  }
  write_all(jsonl_, lines, (fs::path(directory_) / study_files::evaluations).string());
  write_all(csv_, rows, (fs::path(directory_) / study_files::evaluations_csv).string());
}

std::vector<std::string> StudyLog::finish(std::span<const Evaluation> all, bool complete) {
  std::vector<std::string> written;
  const auto write_model = [&](const Evaluation& e, const std::string& name) {
    const ModelSpec spec = apply_design(study_.base, study_.variables, e.values);
    const auto path = (fs::path(directory_) / name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << fmt::format("# design {} of the study '{}' (feran study), model {}\n", e.index, study_.title,
                       study_.model_path)
        << write_toml(spec);
    if (!out) throw Error(fmt::format("cannot write '{}'", path));
    written.push_back(path);
  };
  Index evaluated = 0, feasible = 0;
  for (const auto& e : all) {
    evaluated += e.evaluated;
    feasible += e.feasible;
  }
  json summary = {{"program", "feran"},        {"format_version", 1},    {"analysis", "study"}, {"complete", complete},
                  {"evaluations", all.size()}, {"evaluated", evaluated}, {"feasible", feasible}};
  // Per quantity clipped in any design: in how many, and the first design's reason.
  json clipped = json::object();
  for (const auto& e : all)
    for (std::size_t i = 0; i < e.clipped.size() && i < study_.quantities.size(); ++i) {
      if (e.clipped[i].empty()) continue;
      json& c = clipped[study_.quantities[i].name];
      if (c.is_null()) c = {{"designs", 0}, {"first", e.index}, {"reason", e.clipped[i]}};
      c["designs"] = c["designs"].get<Index>() + 1;
    }
  summary["clipped"] = clipped;
  if (study_.objectives.size() == 1) {
    if (const auto best = best_design(study_, all)) {
      summary["best"] = json::parse(evaluation_json(study_, all[static_cast<std::size_t>(*best)]));
      write_model(all[static_cast<std::size_t>(*best)], "best.toml");
    } else {
      summary["best"] = nullptr;
    }
  } else if (study_.objectives.size() > 1) {
    json pareto = json::array(), models = json::array();
    const auto front = pareto_set(study_, all);
    for (const Index i : front)
      pareto.push_back(json::parse(evaluation_json(study_, all[static_cast<std::size_t>(i)])));
    // Model files for at most a population's worth, spread along the front.
    const Index count = study_.explore.method == ExploreMethod::pareto ? study_.explore.population : 32;
    for (const Index i : spread_along_front(study_, all, front, count)) {
      const auto& e = all[static_cast<std::size_t>(i)];
      write_model(e, fmt::format("pareto-{}.toml", e.index));
      models.push_back(e.index);
    }
    summary["pareto"] = pareto;
    summary["pareto_models"] = models;
  }
  const bool sampled =
      study_.explore.method != ExploreMethod::optimise && study_.explore.method != ExploreMethod::pareto;
  if (sampled) {
    json table = json::array();
    for (const auto& x : sensitivities(study_, all)) {
      if (x.src.empty()) continue;
      json src = json::object(), srrc = json::object();
      for (std::size_t j = 0; j < study_.variables.size(); ++j) {
        src[study_.variables[j].name] = json_number(x.src[j]);
        srrc[study_.variables[j].name] = json_number(x.srrc[j]);
      }
      table.push_back({{"quantity", x.quantity},
                       {"src", src},
                       {"r2", json_number(x.r2)},
                       {"srrc", srrc},
                       {"r2_ranks", json_number(x.r2_ranks)},
                       {"samples", x.samples}});
    }
    summary["sensitivity"] = table;
  }
  const auto path = (fs::path(directory_) / study_files::summary).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc) << summary.dump(1) << "\n";
  return written;
}

}  // namespace feran
