// The optimisers of a study, from pagmo2 (Biscani & Izzo 2020), in a module of their
// own (libferan_optimise.so) that feran loads only when a study optimises: loading
// pagmo and the libraries it needs costs about 80 ms, which every command paid while
// the library linked it. The study is a pagmo problem in the unit cube whose batch
// fitness is the caller's callback (optimise_module.h).
#include "optimise_module.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <string>
#include <utility>

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/compass_search.hpp>
#include <pagmo/algorithms/gaco.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/algorithms/pso_gen.hpp>
#include <pagmo/batch_evaluators/member_bfe.hpp>
#include <pagmo/bfe.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

namespace {

// Thrown through pagmo when the callback says stop or failed.
struct Interrupted {
  int status;
};

struct StudyProblem {
  const feran_optimise_problem* p = nullptr;

  pagmo::vector_double fitness(const pagmo::vector_double& x) const { return batch_fitness(x); }

  pagmo::vector_double batch_fitness(const pagmo::vector_double& dvs) const {
    const auto dim = static_cast<std::size_t>(p->dimension);
    const std::size_t n = dvs.size() / dim;
    pagmo::vector_double f(n * static_cast<std::size_t>(p->objectives));
    const int status = p->batch_fitness(p->context, dvs.data(), static_cast<long>(n), f.data());
    if (status != feran_optimise_done) throw Interrupted{status};
    return f;
  }

  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    const auto dim = static_cast<std::size_t>(p->dimension);
    return {pagmo::vector_double(dim, 0.0), pagmo::vector_double(dim, 1.0)};
  }
  pagmo::vector_double::size_type get_nobj() const {
    return static_cast<pagmo::vector_double::size_type>(p->objectives);
  }
  std::string get_name() const { return "feran study"; }
};

void evolve(const feran_optimise_problem& p) {
  pagmo::problem problem{StudyProblem{&p}};
  const pagmo::bfe batch{pagmo::member_bfe{}};
  const unsigned seed = p.seed;
  pagmo::population population{problem, batch, static_cast<pagmo::population::size_type>(p.population), seed};
  const auto generations = static_cast<unsigned>(p.generations);
  if (p.method == feran_optimise_nsga2) {
    pagmo::nsga2 nsga2(generations, 0.95, 10., 0.01, 50., seed);
    nsga2.set_bfe(batch);
    population = pagmo::algorithm{nsga2}.evolve(population);
    return;
  }
  if (generations > 0) {
    if (p.method == feran_optimise_gaco) {
      pagmo::gaco gaco(generations, static_cast<unsigned>(std::min<long>(p.population, 63)), 1.0, 0.0, 0.01, 1u, 7u,
                       100000u, 100000u, 0.0, false, seed);
      gaco.set_bfe(batch);
      population = pagmo::algorithm{gaco}.evolve(population);
    } else {
      pagmo::pso_gen pso(generations, 0.7298, 2.05, 2.05, 0.5, 5u, 2u, 4u, false, seed);
      pso.set_bfe(batch);
      population = pagmo::algorithm{pso}.evolve(population);
    }
  }
  if (p.polish > 0) {
    // Compass search (Kolda, Lewis & Torczon 2003) from the best design so far, in
    // the unit cube: steps from 0.05 down to 1e-4.
    pagmo::population start{problem, 0u, seed};
    start.push_back(population.champion_x(), population.champion_f());
    pagmo::compass_search search(static_cast<unsigned>(p.polish), 0.05, 1e-4, 0.5);
    (void)pagmo::algorithm{search}.evolve(start);
  }
}

int error(const char* what, char* message, long capacity) {
  if (message != nullptr && capacity > 0) {
    const auto n = std::min<std::size_t>(std::strlen(what), static_cast<std::size_t>(capacity - 1));
    std::memcpy(message, what, n);
    message[n] = '\0';
  }
  return feran_optimise_error;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int feran_optimise_interface() { return FERAN_OPTIMISE_INTERFACE; }

extern "C" __attribute__((visibility("default"))) int feran_optimise(const feran_optimise_problem* problem,
                                                                     char* message, long capacity) {
  try {
    evolve(*problem);
    return feran_optimise_done;
  } catch (const Interrupted& i) {
    return i.status;
  } catch (const std::exception& e) {
    return error(e.what(), message, capacity);
  } catch (...) {
    return error("an unknown error in pagmo2", message, capacity);
  }
}
