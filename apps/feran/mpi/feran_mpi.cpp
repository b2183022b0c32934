// The MPI module of the feran command (libferan_mpi.so): the few MPI calls a study
// distributed over processes needs, behind a C interface (mpi_group.cpp loads it).
// The command loads it only when an MPI launcher (mpirun, srun) started it, so that
// its other runs neither load MPI's libraries nor need them installed. Each function
// returns 0 on success; MPI's default error handler ends the whole job on a
// communication error.
#include <climits>
#include <cstdint>
#include <vector>

#include <mpi.h>

extern "C" {

int feran_mpi_init(int* rank, int* size) {
  int provided = 0;
  // Only the main thread calls MPI; the evaluations' threads never do.
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) return 1;
  if (MPI_Comm_rank(MPI_COMM_WORLD, rank) != MPI_SUCCESS) return 1;
  return MPI_Comm_size(MPI_COMM_WORLD, size) != MPI_SUCCESS;
}

// Every process's byte count, one entry of @p sizes per process.
int feran_mpi_allgather_sizes(std::int64_t mine, std::int64_t* sizes) {
  return MPI_Allgather(&mine, 1, MPI_INT64_T, sizes, 1, MPI_INT64_T, MPI_COMM_WORLD) != MPI_SUCCESS;
}

// Every process's bytes, concatenated in rank order into @p out (the sum of sizes).
// 2: more than 2 GiB in all (MPI's counts are int).
int feran_mpi_allgatherv(const char* mine, std::int64_t n, const std::int64_t* sizes, int size, char* out) {
  std::vector<int> counts(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
  std::int64_t at = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    if (sizes[r] < 0 || sizes[r] > INT_MAX - at) return 2;
    counts[r] = static_cast<int>(sizes[r]);
    offsets[r] = static_cast<int>(at);
    at += sizes[r];
  }
  return MPI_Allgatherv(mine, static_cast<int>(n), MPI_CHAR, out, counts.data(), offsets.data(), MPI_CHAR,
                        MPI_COMM_WORLD) != MPI_SUCCESS;
}

int feran_mpi_broadcast_size(std::int64_t* n, int root) {
  return MPI_Bcast(n, 1, MPI_INT64_T, root, MPI_COMM_WORLD) != MPI_SUCCESS;
}

int feran_mpi_broadcast(char* bytes, std::int64_t n, int root) {
  if (n < 0 || n > INT_MAX) return 2;
  return MPI_Bcast(bytes, static_cast<int>(n), MPI_CHAR, root, MPI_COMM_WORLD) != MPI_SUCCESS;
}

int feran_mpi_finalize() { return MPI_Finalize() != MPI_SUCCESS; }

void feran_mpi_abort(int code) { MPI_Abort(MPI_COMM_WORLD, code); }

}  // extern "C"
