// The optimisers of a study, from pagmo2 (Biscani & Izzo 2020), run in the module
// libferan_optimise.so (pagmo/optimise_module.cpp), loaded on the first optimisation:
// the study as a problem in the unit cube whose batch fitness goes through the
// study's evaluator.
#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <utility>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/core/module.hpp>
#include <feran/study/study.hpp>

#include "pagmo/optimise_module.h"

namespace feran {

namespace {

constexpr Real infeasible_scale = 1e30;
constexpr Real failed_violation = 1e3;

// What the optimiser's callbacks share: the evaluator, the next index, the
// evaluations so far.
struct Context {
  const StudySpec* study = nullptr;
  BatchEvaluator* evaluator = nullptr;
  const EvaluationSink* sink = nullptr;
  StopToken stop;
  Index next = 0;
  std::map<Index, Evaluation> all;
  std::exception_ptr failure;  // what the callback threw
};

Real relative_excess(Real value, Real bound) {
  const Real scale = std::max(std::abs(bound), Real(1e-300));
  return std::max(Real(0), value - bound) / scale;
}

std::vector<Real> fitness_of(const StudySpec& study, const Evaluation& e) {
  std::vector<Real> f;
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

// The module's callback: the fitness of a batch of points, each given the next index;
// a point already evaluated (a resumed study) must be the one the optimiser asks for
// now. Exceptions stay on this side: kept in the context, reported as failed.
int batch_fitness(void* opaque, const double* points, long n, double* fitness) {
  auto& c = *static_cast<Context*>(opaque);
  try {
    const auto& study = *c.study;
    const std::size_t dim = study.variables.size();
    std::vector<Index> index(static_cast<std::size_t>(n));
    std::vector<std::pair<Index, UnitPoint>> todo;
    for (std::size_t k = 0; k < index.size(); ++k) {
      UnitPoint p(points + k * dim, points + (k + 1) * dim);
      index[k] = c.next++;
      if (const auto at = c.all.find(index[k]); at != c.all.end()) {
        if (at->second.unit != p)
          throw Error(
              fmt::format("the resumed optimisation asked for another design {} than the recorded one: "
                          "the study or the program changed; start it afresh in another directory",
                          index[k]));
        continue;
      }
      todo.emplace_back(index[k], std::move(p));
    }
    if (!todo.empty()) {
      if (c.stop.requested()) return feran_optimise_stopped;
      auto results = c.evaluator->evaluate(study, todo);
      const bool stopped =
          std::any_of(results.begin(), results.end(), [](const Evaluation& e) { return e.interrupted; });
      std::erase_if(results, [](const Evaluation& e) { return e.interrupted; });
      if (*c.sink) (*c.sink)(results);
      for (auto& e : results) c.all.emplace(e.index, std::move(e));
      if (stopped || c.stop.requested()) return feran_optimise_stopped;
    }
    for (const Index i : index)
      for (const Real f : fitness_of(study, c.all.at(i))) *fitness++ = f;
    return feran_optimise_done;
  } catch (...) {
    c.failure = std::current_exception();
    return feran_optimise_failed;
  }
}

using OptimiseFunction = int (*)(const feran_optimise_problem*, char*, long);

// Loaded once, on the first optimisation of the process.
OptimiseFunction optimiser() {
  static std::once_flag once;
  static OptimiseFunction f = nullptr;
  std::call_once(once, [] {
    const auto module = load_module("libferan_optimise.so", false, "an optimising study (\"optimise\", \"pareto\")",
                                    "build feran with pagmo2 installed (libpagmo-dev, scripts/setup.sh) and install it "
                                    "with cmake --install, or use a grid, latin or sobol study");
    const auto version = reinterpret_cast<int (*)()>(module_function(module, "feran_optimise_interface"))();
    if (version != FERAN_OPTIMISE_INTERFACE)
      throw Error(
          fmt::format("the optimiser module {} is of another feran (interface {}, this program's {}); "
                      "install this feran again (cmake --install)",
                      module.path, version, FERAN_OPTIMISE_INTERFACE));
    f = reinterpret_cast<OptimiseFunction>(module_function(module, "feran_optimise"));
  });
  return f;
}

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
  Context context;
  context.study = &study;
  context.evaluator = &evaluator;
  context.sink = &sink;
  context.stop = stop;
  for (const auto& e : done) context.all.emplace(e.index, e);

  feran_optimise_problem problem{};
  problem.dimension = static_cast<long>(study.variables.size());
  problem.objectives = static_cast<long>(study.objectives.size());
  problem.method =
      pareto ? feran_optimise_nsga2 : (x.algorithm == GlobalAlgorithm::gaco ? feran_optimise_gaco : feran_optimise_pso);
  problem.population = static_cast<long>(x.population);
  problem.generations = static_cast<long>(x.generations);
  problem.polish = pareto ? 0 : static_cast<long>(x.polish);
  problem.seed = static_cast<unsigned>(x.seed);
  problem.context = &context;
  problem.batch_fitness = &batch_fitness;
  char message[1024] = {};
  const int status = optimiser()(&problem, message, sizeof message);
  if (status == feran_optimise_failed && context.failure) std::rethrow_exception(context.failure);
  if (status == feran_optimise_error) throw Error(fmt::format("the optimiser (pagmo2) failed: {}", message));
  // Stopped between generations: what was evaluated is recorded.
  std::vector<Evaluation> out;
  for (auto& [i, e] : context.all) out.push_back(std::move(e));
  return out;
}

}  // namespace feran
