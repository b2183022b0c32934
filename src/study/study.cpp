#include <feran/study/study.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/core/parallel.hpp>
#include <feran/spec/build_model.hpp>

namespace feran {

namespace {

std::string violated(const StudySpec& study, const Evaluation& e) {
  for (const auto& c : study.constraints) {
    const auto& q = study.quantities[static_cast<std::size_t>(c.quantity)];
    const Real v = e.quantities[static_cast<std::size_t>(c.quantity)];
    if (c.at_most && !(v <= *c.at_most))
      return fmt::format("constraint {} <= {:g} violated ({:g})", q.name, *c.at_most, v);
    if (c.at_least && !(v >= *c.at_least))
      return fmt::format("constraint {} >= {:g} violated ({:g})", q.name, *c.at_least, v);
  }
  return {};
}

// Objective values with maximised ones negated: smaller is better in each.
std::vector<Real> costs(const StudySpec& study, const Evaluation& e) {
  std::vector<Real> f;
  for (const auto& o : study.objectives) {
    const Real v = e.quantities[static_cast<std::size_t>(o.quantity)];
    f.push_back(o.sense == Sense::minimise ? v : -v);
  }
  return f;
}

}  // namespace

std::string_view to_string(ExploreMethod method) {
  switch (method) {
    case ExploreMethod::grid:
      return "grid";
    case ExploreMethod::latin_hypercube:
      return "latin_hypercube";
    case ExploreMethod::sobol:
      return "sobol";
    case ExploreMethod::optimise:
      return "optimise";
    case ExploreMethod::pareto:
      return "pareto";
  }
  return "?";
}

Evaluation evaluate_design(const StudySpec& study, Index index, std::span<const Real> unit, const StopToken& stop) {
  const auto start = std::chrono::steady_clock::now();
  Evaluation e;
  e.index = index;
  e.unit.assign(unit.begin(), unit.end());
  e.values = design_values(study.variables, unit);
  try {
    const ModelSpec spec = apply_design(study.base, study.variables, e.values);
    const Model model = build_model(spec);
    e.quantities = evaluate_quantities(spec, model, study.quantities, stop, &e.clipped);
    e.evaluated = std::all_of(e.quantities.begin(), e.quantities.end(), [](Real v) { return std::isfinite(v); });
    if (!e.evaluated) e.message = "a quantity is not finite";
  } catch (const std::exception& error) {
    e.quantities.clear();
    e.clipped.clear();
    e.message = error.what();
  }
  if (e.evaluated) {
    e.message = violated(study, e);
    e.feasible = e.message.empty();
  } else {
    e.quantities.clear();
    e.clipped.clear();
  }
  e.interrupted = stop.requested();
  e.seconds = std::chrono::duration<Real>(std::chrono::steady_clock::now() - start).count();
  return e;
}

std::vector<UnitPoint> exploration_points(const StudySpec& study) {
  const auto dim = static_cast<Index>(study.variables.size());
  switch (study.explore.method) {
    case ExploreMethod::grid: {
      std::vector<Index> levels;
      std::vector<bool> discrete;
      for (const auto& v : study.variables) {
        levels.push_back(v.discrete() ? v.levels() : study.explore.levels);
        discrete.push_back(v.discrete());
      }
      return full_grid(levels, discrete);
    }
    case ExploreMethod::latin_hypercube:
      return latin_hypercube(study.explore.samples, dim, study.explore.seed);
    case ExploreMethod::sobol:
      return sobol(study.explore.samples, dim);
    case ExploreMethod::optimise:
    case ExploreMethod::pareto:
      break;
  }
  return {};
}

Index planned_evaluations(const StudySpec& study) {
  const auto& x = study.explore;
  if (x.method == ExploreMethod::optimise || x.method == ExploreMethod::pareto)
    return x.population * (x.generations + 1) + (x.method == ExploreMethod::optimise ? x.polish : 0);
  return static_cast<Index>(exploration_points(study).size());
}

std::vector<Evaluation> ThreadEvaluator::evaluate(const StudySpec& study,
                                                  const std::vector<std::pair<Index, UnitPoint>>& batch) {
  std::vector<Evaluation> out(batch.size());
  parallel_for(static_cast<Index>(batch.size()), n_threads_, [&](Index i, int) {
    const auto& [index, point] = batch[static_cast<std::size_t>(i)];
    out[static_cast<std::size_t>(i)] = evaluate_design(study, index, point, stop_);
  });
  return out;
}

std::vector<Evaluation> run_exploration(const StudySpec& study, BatchEvaluator& evaluator,
                                        const std::vector<Evaluation>& done, const EvaluationSink& sink,
                                        Index batch_size, const StopToken& stop) {
  if (study.explore.method == ExploreMethod::optimise || study.explore.method == ExploreMethod::pareto)
    return run_optimisation(study, evaluator, done, sink, stop);
  std::map<Index, Evaluation> all;
  for (const auto& e : done) all.emplace(e.index, e);
  const auto points = exploration_points(study);
  std::vector<std::pair<Index, UnitPoint>> batch;
  const auto flush = [&] {
    if (batch.empty()) return;
    auto results = evaluator.evaluate(study, batch);
    std::erase_if(results, [](const Evaluation& e) { return e.interrupted; });
    if (sink) sink(results);
    for (auto& e : results) all.emplace(e.index, std::move(e));
    batch.clear();
  };
  for (Index i = 0; i < static_cast<Index>(points.size()) && !stop.requested(); ++i) {
    if (all.count(i)) continue;
    batch.emplace_back(i, points[static_cast<std::size_t>(i)]);
    if (static_cast<Index>(batch.size()) >= std::max<Index>(batch_size, 1)) flush();
  }
  if (!stop.requested()) flush();
  std::vector<Evaluation> out;
  for (auto& [i, e] : all) out.push_back(std::move(e));
  return out;
}

std::optional<Index> best_design(const StudySpec& study, std::span<const Evaluation> evaluations) {
  std::optional<Index> best;
  Real best_cost = 0;
  for (Index i = 0; i < static_cast<Index>(evaluations.size()); ++i) {
    const auto& e = evaluations[static_cast<std::size_t>(i)];
    if (!e.feasible || study.objectives.empty()) continue;
    const Real c = costs(study, e).front();
    if (!best || c < best_cost) {
      best = i;
      best_cost = c;
    }
  }
  return best;
}

std::vector<Index> pareto_set(const StudySpec& study, std::span<const Evaluation> evaluations) {
  std::vector<Index> feasible;
  std::vector<std::vector<Real>> f;
  for (Index i = 0; i < static_cast<Index>(evaluations.size()); ++i)
    if (evaluations[static_cast<std::size_t>(i)].feasible) {
      feasible.push_back(i);
      f.push_back(costs(study, evaluations[static_cast<std::size_t>(i)]));
    }
  const auto dominates = [](const std::vector<Real>& a, const std::vector<Real>& b) {
    bool better = false;
    for (std::size_t k = 0; k < a.size(); ++k) {
      if (a[k] > b[k]) return false;
      better = better || a[k] < b[k];
    }
    return better;
  };
  std::vector<Index> out;
  for (std::size_t i = 0; i < feasible.size(); ++i) {
    bool dominated = false;
    // Dominated by another, or the same objectives as an earlier design (an
    // optimiser evaluating one point twice): left out.
    for (std::size_t j = 0; j < feasible.size() && !dominated; ++j)
      dominated = j != i && (dominates(f[j], f[i]) || (j < i && f[j] == f[i]));
    if (!dominated) out.push_back(feasible[i]);
  }
  return out;
}

std::vector<Index> spread_along_front(const StudySpec& study, std::span<const Evaluation> evaluations,
                                      std::vector<Index> front, Index count) {
  if (front.empty() || count <= 0) return {};
  const auto first = [&](Index i) { return costs(study, evaluations[static_cast<std::size_t>(i)]).front(); };
  std::stable_sort(front.begin(), front.end(), [&](Index a, Index b) { return first(a) < first(b); });
  const auto n = static_cast<Index>(front.size());
  if (n <= count) return front;
  std::vector<Index> out;
  for (Index k = 0; k < count; ++k) {
    const Index at = count == 1 ? 0 : (k * (n - 1) + (count - 1) / 2) / (count - 1);
    if (out.empty() || out.back() != front[static_cast<std::size_t>(at)])
      out.push_back(front[static_cast<std::size_t>(at)]);
  }
  return out;
}

}  // namespace feran
