#pragma once
// The processes a run of the command belongs to: an MPI job's when an MPI launcher
// (mpirun, srun) started it, else this process alone.

#include <memory>

#include <feran/study/distributed.hpp>

namespace feran::app {

/// Whether an MPI launcher started this process (its environment says so).
bool launched_by_mpi();

/// The MPI job's processes when launched_by_mpi(), through the MPI module
/// libferan_mpi.so beside the program (or in its installed place), MPI initialised;
/// else this process alone. Throws feran::Error when the module cannot be loaded.
std::unique_ptr<Communicator> process_group();

/// Threads one process uses when asked for @p requested (0: its share of the cores):
/// the cores this process may run on when the launcher bound it to some, else the
/// machine's cores divided among the job's processes on this machine.
int threads_per_process(int requested);

}  // namespace feran::app
