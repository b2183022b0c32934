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

enum class ExploreMethod { grid, latin_hypercube, sobol };

struct Exploration {
  ExploreMethod method = ExploreMethod::latin_hypercube;
  Index levels = 5;        ///< grid: values per continuous variable
  Index samples = 32;      ///< Latin hypercube and Sobol': number of designs
  std::uint64_t seed = 1;  ///< Latin hypercube
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
  Real seconds = 0;              ///< wall time of this evaluation
  bool interrupted = false;      ///< stopped by a StopToken: not a result, not recorded
};

/// Evaluates the design at unit coordinates @p unit (index @p index): sets the
/// variables, builds the model, computes the quantities, checks the constraints.
/// Never throws for a bad design: the failure is recorded in the result. When @p stop
/// is set during the evaluation, the result is marked interrupted.
Evaluation evaluate_design(const StudySpec& study, Index index, std::span<const Real> unit,
                           const StopToken& stop = {});

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
  explicit ThreadEvaluator(int n_threads = 0, StopToken stop = {}) : n_threads_(n_threads), stop_(std::move(stop)) {}
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
/// @p stop is set (what was evaluated is kept and passed to the sink).
std::vector<Evaluation> run_exploration(const StudySpec& study, BatchEvaluator& evaluator,
                                        const std::vector<Evaluation>& done, const EvaluationSink& sink,
                                        Index batch_size, const StopToken& stop = {});

/// The best feasible design of a single-objective study (lowest index among equals),
/// or nullopt when none is feasible.
std::optional<Index> best_design(const StudySpec& study, std::span<const Evaluation> evaluations);

/// The feasible designs that no other feasible design dominates in the objectives
/// (positions in @p evaluations, in index order).
std::vector<Index> pareto_set(const StudySpec& study, std::span<const Evaluation> evaluations);

}  // namespace feran
