// The optimisers of a study, from pagmo2 (Biscani & Izzo 2020): the study as a pagmo
// problem in the unit cube whose batch fitness goes through the study's evaluator.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <utility>

#include <fmt/format.h>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/compass_search.hpp>
#include <pagmo/algorithms/gaco.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/algorithms/pso_gen.hpp>
#include <pagmo/batch_evaluators/member_bfe.hpp>
#include <pagmo/bfe.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include <feran/core/error.hpp>
#include <feran/study/study.hpp>

namespace feran {

namespace {

constexpr Real infeasible_scale = 1e30;
constexpr Real failed_violation = 1e3;

// Thrown through pagmo when the study is asked to stop.
struct Stopped {};

// What the copies of the problem pagmo makes share: the evaluator, the next index,
// the evaluations so far.
struct Context {
  const StudySpec* study = nullptr;
  BatchEvaluator* evaluator = nullptr;
  const EvaluationSink* sink = nullptr;
  StopToken stop;
  Index next = 0;
  std::map<Index, Evaluation> all;
};

Real relative_excess(Real value, Real bound) {
  const Real scale = std::max(std::abs(bound), Real(1e-300));
  return std::max(Real(0), value - bound) / scale;
}

pagmo::vector_double fitness_of(const StudySpec& study, const Evaluation& e) {
  pagmo::vector_double f;
  if (e.feasible) {
    for (const auto& o : study.objectives) {
      const Real v = e.quantities[static_cast<std::size_t>(o.quantity)];
      f.push_back(o.sense == Sense::minimise ? v : -v);
    }
    return f;
  }
  Real violation = failed_violation;
  if (e.evaluated) {
    violation = 0;
    for (const auto& c : study.constraints) {
      const Real v = e.quantities[static_cast<std::size_t>(c.quantity)];
      if (c.at_most) violation += relative_excess(v, *c.at_most);
      if (c.at_least) violation += relative_excess(-v, -*c.at_least);
    }
    violation = std::min(violation, failed_violation);
  }
  f.assign(study.objectives.size(), infeasible_scale * (1 + violation));
  return f;
}

struct StudyProblem {
  std::shared_ptr<Context> context;

  pagmo::vector_double fitness(const pagmo::vector_double& x) const { return batch_fitness(x); }

  pagmo::vector_double batch_fitness(const pagmo::vector_double& dvs) const {
    auto& c = *context;
    const auto& study = *c.study;
    const std::size_t dim = study.variables.size();
    const std::size_t n = dvs.size() / dim;
    // Each point gets the next index; a point already evaluated (a resumed study)
    // must be the one the optimiser asks for now.
    std::vector<Index> index(n);
    std::vector<std::pair<Index, UnitPoint>> todo;
    for (std::size_t k = 0; k < n; ++k) {
      UnitPoint p(dvs.begin() + static_cast<std::ptrdiff_t>(k * dim),
                  dvs.begin() + static_cast<std::ptrdiff_t>((k + 1) * dim));
      index[k] = c.next++;
      if (const auto at = c.all.find(index[k]); at != c.all.end()) {
        if (at->second.unit != p)
          throw Error(fmt::format("the resumed optimisation asked for another design {} than the recorded one: "
                                  "the study or the program changed; start it afresh in another directory",
                                  index[k]));
        continue;
      }
      todo.emplace_back(index[k], std::move(p));
    }
    if (!todo.empty()) {
      if (c.stop.requested()) throw Stopped{};
      auto results = c.evaluator->evaluate(study, todo);
      const bool stopped = std::any_of(results.begin(), results.end(), [](const Evaluation& e) { return e.interrupted; });
      std::erase_if(results, [](const Evaluation& e) { return e.interrupted; });
      if (*c.sink) (*c.sink)(results);
      for (auto& e : results) c.all.emplace(e.index, std::move(e));
      if (stopped || c.stop.requested()) throw Stopped{};
    }
    pagmo::vector_double f;
    for (const Index i : index) {
      const auto fi = fitness_of(study, c.all.at(i));
      f.insert(f.end(), fi.begin(), fi.end());
    }
    return f;
  }

  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    const std::size_t dim = context->study->variables.size();
    return {pagmo::vector_double(dim, 0.0), pagmo::vector_double(dim, 1.0)};
  }
  pagmo::vector_double::size_type get_nobj() const { return context->study->objectives.size(); }
  std::string get_name() const { return "feran study"; }
};

}  // namespace

std::vector<Evaluation> run_optimisation(const StudySpec& study, BatchEvaluator& evaluator,
                                         const std::vector<Evaluation>& done, const EvaluationSink& sink,
                                         const StopToken& stop) {
  const auto& x = study.explore;
  const bool pareto = x.method == ExploreMethod::pareto;
  if (study.objectives.empty()) throw Error("an optimisation needs an objective");
  if (pareto && study.objectives.size() < 2)
    throw Error("method \"pareto\" needs two objectives or more; \"optimise\" takes one");
  if (!pareto && study.objectives.size() != 1)
    throw Error("method \"optimise\" takes one objective; \"pareto\" takes several");
  auto context = std::make_shared<Context>();
  context->study = &study;
  context->evaluator = &evaluator;
  context->sink = &sink;
  context->stop = stop;
  for (const auto& e : done) context->all.emplace(e.index, e);

  try {
    pagmo::problem problem{StudyProblem{context}};
    const pagmo::bfe batch{pagmo::member_bfe{}};
    const auto seed = static_cast<unsigned>(x.seed);
    pagmo::population population{problem, batch, static_cast<pagmo::population::size_type>(x.population), seed};
    if (pareto) {
      pagmo::nsga2 nsga2(static_cast<unsigned>(x.generations), 0.95, 10., 0.01, 50., seed);
      nsga2.set_bfe(batch);
      population = pagmo::algorithm{nsga2}.evolve(population);
    } else {
      if (x.generations > 0) {
        if (x.algorithm == GlobalAlgorithm::gaco) {
          pagmo::gaco gaco(static_cast<unsigned>(x.generations), static_cast<unsigned>(std::min<Index>(x.population, 63)),
                           1.0, 0.0, 0.01, 1u, 7u, 100000u, 100000u, 0.0, false, seed);
          gaco.set_bfe(batch);
          population = pagmo::algorithm{gaco}.evolve(population);
        } else {
          pagmo::pso_gen pso(static_cast<unsigned>(x.generations), 0.7298, 2.05, 2.05, 0.5, 5u, 2u, 4u, false, seed);
          pso.set_bfe(batch);
          population = pagmo::algorithm{pso}.evolve(population);
        }
      }
      if (x.polish > 0) {
        // Compass search (Kolda, Lewis & Torczon 2003) from the best design so far,
        // in the unit cube: steps from 0.05 down to 1e-4.
        pagmo::population start{problem, 0u, seed};
        start.push_back(population.champion_x(), population.champion_f());
        pagmo::compass_search search(static_cast<unsigned>(x.polish), 0.05, 1e-4, 0.5);
        (void)pagmo::algorithm{search}.evolve(start);
      }
    }
  } catch (const Stopped&) {
    // Stopped between generations: what was evaluated is recorded.
  }
  std::vector<Evaluation> out;
  for (auto& [i, e] : context->all) out.push_back(std::move(e));
  return out;
}

}  // namespace feran
