/* The interface between feran's design studies (study/optimise.cpp) and their
   optimisers, pagmo2's, built into the module libferan_optimise.so (optimise_module.cpp)
   and loaded only when a study optimises: a C interface of plain numbers and one
   callback, so that no C++ object or exception crosses between the two. */
#ifndef FERAN_OPTIMISE_MODULE_H
#define FERAN_OPTIMISE_MODULE_H

#ifdef __cplusplus
extern "C" {
#endif

/* Changes whenever this interface does: a module of another version (an older
   installed copy) is refused instead of called. */
#define FERAN_OPTIMISE_INTERFACE 1

/* The global method of "optimise"; "pareto" is always NSGA-II. */
enum feran_optimise_method { feran_optimise_pso = 0, feran_optimise_gaco = 1, feran_optimise_nsga2 = 2 };

/* What a callback or the optimiser returns. */
enum feran_optimise_status {
  feran_optimise_done = 0,
  feran_optimise_stopped = 1, /* the study was asked to stop: what was evaluated is kept */
  feran_optimise_failed = 2,  /* the callback failed; the caller kept its reason */
  feran_optimise_error = 3    /* the optimiser refused or failed; its message is returned */
};

struct feran_optimise_problem {
  long dimension;  /* variables, each in [0, 1] */
  long objectives; /* 1 for "optimise", 2 or more for "pareto" */
  int method;      /* enum feran_optimise_method */
  long population;
  long generations;
  long polish; /* compass-search evaluations after the global method ("optimise") */
  unsigned seed;
  void* context; /* handed back to batch_fitness */
  /* The fitness of n points (n × dimension numbers, point after point) into
     n × objectives numbers, each minimised; returns a feran_optimise_status. */
  int (*batch_fitness)(void* context, const double* points, long n, double* fitness);
};

/* FERAN_OPTIMISE_INTERFACE as the module was built. */
int feran_optimise_interface(void);

/* Runs the optimiser; on feran_optimise_error writes a message of at most
   capacity − 1 characters into message. */
int feran_optimise(const struct feran_optimise_problem* problem, char* message, long capacity);

#ifdef __cplusplus
}
#endif

#endif
