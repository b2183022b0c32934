#pragma once
/// @file
/// A design study: a base model, design variables, quantities, objectives and
/// constraints, and a way to explore (a grid, a Latin hypercube, a Sobol' sequence).
///
/// Each design is evaluated on its own (a copy of the base model with the variables
/// set, built, analysed) and gets an index: the same study gives the same designs
/// with the same indices, whatever evaluates them (threads, processes) and in
/// whatever order they finish. A design that cannot be built or analysed is recorded
/// with its message and counts as infeasible; it never stops the study.

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <feran/core/stop.hpp>
#include <feran/core/types.hpp>
#include <feran/spec/model_spec.hpp>
#include <feran/study/design.hpp>
#include <feran/study/quantity.hpp>
#include <feran/study/sampling.hpp>

namespace feran {

enum class Sense { minimise, maximise };

struct Objective {
  Index quantity = 0;  ///< index into StudySpec::quantities
  Sense sense = Sense::minimise;
};

/// quantity ≤ at_most and/or quantity ≥ at_least (SI units).
struct Constraint {
  Index quantity = 0;
  std::optional<Real> at_most, at_least;
};

enum class ExploreMethod {
  grid,             ///< every combination of levels
  latin_hypercube,  ///< a Latin hypercube sample
  sobol,            ///< the Sobol' sequence
  optimise,         ///< one objective: a global method, then a local polish (pagmo2)
  pareto,           ///< several objectives: NSGA-II's Pareto set (pagmo2)
};

/// "grid", "latin_hypercube", "sobol", "optimise", "pareto" (as a study file names them).
std::string_view to_string(ExploreMethod method);

/// The global method of an optimisation.
enum class GlobalAlgorithm {
  pso,   ///< particle swarm, generational (pagmo2 pso_gen; Poli, Kennedy & Blackwell 2007)
  gaco,  ///< extended ant colony optimisation (pagmo2 gaco; Schlüter, Egea & Banga 2009)
};

struct Exploration {
  ExploreMethod method = ExploreMethod::latin_hypercube;
  Index levels = 5;        ///< grid: values per continuous variable
  Index samples = 32;      ///< Latin hypercube and Sobol': number of designs
  std::uint64_t seed = 1;  ///< Latin hypercube and the optimisers
  GlobalAlgorithm algorithm = GlobalAlgorithm::pso;
  Index population = 16;   ///< optimisers: designs per generation (NSGA-II: a multiple of 4, ≥ 8)
  Index generations = 20;  ///< optimisers: generations after the first population
  Index polish = 0;        ///< optimise: evaluations of the local polish (compass search); 0: none
};

struct StudySpec {
  std::string title;
  std::string model_path;  ///< the base model's file, as the study names it (for outputs)
  ModelSpec base;          ///< the base model with the study's settings applied
  std::vector<DesignVariable> variables;
  std::vector<QuantitySpec> quantities;
  std::vector<Objective> objectives;
  std::vector<Constraint> constraints;
  Exploration explore;
};

/// One evaluated design.
struct Evaluation {
  Index index = 0;
  std::vector<Real> unit;        ///< coordinates in the unit cube
  std::vector<Real> values;      ///< the variables' values (SI)
  std::vector<Real> quantities;  ///< SI; empty when the design failed
  bool evaluated = false;        ///< every quantity was computed
  bool feasible = false;         ///< evaluated and every constraint holds
  std::string message;           ///< why it failed, or which constraint it violates
  /// Per quantity (empty when the design failed): why its value is only a bound,
  /// clipped by the range an analysis covered ("" when it is exact).
  std::vector<std::string> clipped;
  Real seconds = 0;          ///< wall time of this evaluation
  bool interrupted = false;  ///< stopped by a StopToken: not a result, not recorded
};

/// Evaluates the design at unit coordinates @p unit (index @p index): sets the
/// variables, builds the model, computes the quantities, checks the constraints.
/// Never throws for a bad design: the failure is recorded in the result. When @p stop
/// is set during the evaluation, the result is marked interrupted.
Evaluation evaluate_design(const StudySpec& study, Index index, std::span<const Real> unit, const StopToken& stop = {});

/// The designs the study's exploration visits, in index order.
std::vector<UnitPoint> exploration_points(const StudySpec& study);

/// Evaluates batches of designs: the seam between a study and the machinery that
/// runs it (threads here; processes under MPI elsewhere).
class BatchEvaluator {
 public:
  virtual ~BatchEvaluator() = default;
  /// Evaluates each (index, point) and returns the evaluations in the same order.
  virtual std::vector<Evaluation> evaluate(const StudySpec& study,
                                           const std::vector<std::pair<Index, UnitPoint>>& batch) = 0;
};

/// Evaluates a batch on @p n_threads threads (0: all cores), one design per thread.
class ThreadEvaluator : public BatchEvaluator {
 public:
  explicit ThreadEvaluator(int n_threads = 0, StopToken stop = {}) : n_threads_(n_threads), stop_(stop) {}
  std::vector<Evaluation> evaluate(const StudySpec& study,
                                   const std::vector<std::pair<Index, UnitPoint>>& batch) override;

 private:
  int n_threads_;
  StopToken stop_;
};

/// Called with each batch's evaluations as it completes (to append them to disk).
using EvaluationSink = std::function<void(std::span<const Evaluation>)>;

/// Runs the exploration: every point not already in @p done (by index) is evaluated
/// by @p evaluator in batches of @p batch_size, each batch passed to @p sink. Returns
/// all evaluations, @p done included, in index order. Stops between batches when
/// @p stop is set (what was evaluated is kept and passed to the sink). An optimiser
/// (ExploreMethod::optimise, pareto) runs through run_optimisation().
std::vector<Evaluation> run_exploration(const StudySpec& study, BatchEvaluator& evaluator,
                                        const std::vector<Evaluation>& done, const EvaluationSink& sink,
                                        Index batch_size, const StopToken& stop = {});

/// Runs the study's optimiser (ExploreMethod::optimise or pareto) with pagmo2, its
/// generations evaluated as batches by @p evaluator and passed to @p sink. Designs get
/// indices in the order the optimiser asks for them; for a fixed seed that order is
/// always the same, so evaluations in @p done (a resumed study) are taken from there
/// instead of recomputed, after checking that the optimiser asked for the same point.
/// The problem the optimiser sees lives in the unit cube: each objective (negated when
/// maximised) for a feasible design; for an infeasible or failed one 1e30·(1 + v),
/// v the sum of the constraints' relative violations (10³ for a failed design), so that
/// every feasible design is better than every infeasible one and the less violated
/// better among those. Returns all evaluations, @p done included, in index order.
std::vector<Evaluation> run_optimisation(const StudySpec& study, BatchEvaluator& evaluator,
                                         const std::vector<Evaluation>& done, const EvaluationSink& sink,
                                         const StopToken& stop = {});

/// The evaluations a study plans: the sampler's points, or for an optimiser its
/// population times (generations + 1) plus the polish (an upper bound).
Index planned_evaluations(const StudySpec& study);

/// The best feasible design of a single-objective study (lowest index among equals),
/// or nullopt when none is feasible.
std::optional<Index> best_design(const StudySpec& study, std::span<const Evaluation> evaluations);

/// The feasible designs that no other feasible design dominates in the objectives
/// (positions in @p evaluations, in index order); of designs with equal objectives
/// only the first.
std::vector<Index> pareto_set(const StudySpec& study, std::span<const Evaluation> evaluations);

/// At most @p count members of @p front (positions in @p evaluations), evenly spread
/// along the first objective (its ends kept), in order of it.
std::vector<Index> spread_along_front(const StudySpec& study, std::span<const Evaluation> evaluations,
                                      std::vector<Index> front, Index count);

}  // namespace feran
