#pragma once
/// @file
/// A minimal parallel loop for independent work items (speed sweeps).

#include <functional>

#include <feran/core/types.hpp>

namespace feran {

/// Asks a threaded OpenBLAS, when it is the LAPACK in use, for one thread. feran runs
/// the points of a sweep and the designs of a study on threads of its own; OpenBLAS's
/// threads inside each small dense solve only compete with them, and spin for a while
/// after each call (a Campbell study on two cores ran six times slower with them).
/// Also shuts OpenBLAS's thread server down, joining the threads it started when it
/// loaded. Programs linking the library call it once at start (the command line, the
/// Python module and the tests do). Looked up at run time: other BLAS builds lack it.
void single_threaded_blas();

/// Number of threads a sweep uses when asked for @p requested: the hardware
/// concurrency for 0, else @p requested. Throws feran::Error for a negative count or
/// more than max_threads.
int resolve_threads(int requested);

/// The most threads a sweep may be asked for (as the command line's --threads).
inline constexpr int max_threads = 1024;

/// Calls @p body(i, worker) for i = 0 … n−1 on up to @p n_threads threads
/// (0: the hardware concurrency); worker ∈ [0, n_threads) identifies the calling
/// thread, so that each can use its own workspace. Items are handed out in order,
/// one at a time, so uneven items balance. The first exception thrown by a body is
/// rethrown after all threads have stopped; items not yet started are skipped.
/// With one thread (or n ≤ 1) everything runs on the calling thread. Threads the
/// system refuses to start are done without: their items go to the others.
void parallel_for(Index n, int n_threads, const std::function<void(Index i, int worker)>& body);

}  // namespace feran
