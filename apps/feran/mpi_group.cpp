#include "mpi_group.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <sched.h>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/core/module.hpp>
#include <feran/core/parallel.hpp>

namespace feran::app {

namespace {

// The functions of apps/feran/mpi/feran_mpi.cpp.
struct MpiModule {
  int (*init)(int*, int*) = nullptr;
  int (*allgather_sizes)(std::int64_t, std::int64_t*) = nullptr;
  int (*allgatherv)(const char*, std::int64_t, const std::int64_t*, int, char*) = nullptr;
  int (*broadcast_size)(std::int64_t*, int) = nullptr;
  int (*broadcast)(char*, std::int64_t, int) = nullptr;
  int (*finalize)() = nullptr;
  void (*abort)(int) = nullptr;
};

template <class F>
void bind_symbol(const LoadedModule& module, const char* name, F& f) {
  f = reinterpret_cast<F>(module_function(module, name));
}

class Mpi : public Communicator {
 public:
  Mpi() {
    // Global: Open MPI's own plug-ins look up its symbols in the global scope.
    module_ = load_module("libferan_mpi.so", true, "feran study under an MPI launcher",
                          "build feran with Open MPI installed (libopenmpi-dev), or run without mpirun");
    bind_symbol(module_, "feran_mpi_init", f_.init);
    bind_symbol(module_, "feran_mpi_allgather_sizes", f_.allgather_sizes);
    bind_symbol(module_, "feran_mpi_allgatherv", f_.allgatherv);
    bind_symbol(module_, "feran_mpi_broadcast_size", f_.broadcast_size);
    bind_symbol(module_, "feran_mpi_broadcast", f_.broadcast);
    bind_symbol(module_, "feran_mpi_finalize", f_.finalize);
    bind_symbol(module_, "feran_mpi_abort", f_.abort);
    if (f_.init(&rank_, &size_) != 0) throw Error("MPI could not be initialised");
  }
  ~Mpi() override {
    // The library stays loaded: Open MPI cannot be unloaded and loaded again.
    if (f_.finalize != nullptr) f_.finalize();
  }
  Mpi(const Mpi&) = delete;
  Mpi& operator=(const Mpi&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::vector<std::string> all_gather(const std::string& mine) override {
    std::vector<std::int64_t> sizes(static_cast<std::size_t>(size_));
    check(f_.allgather_sizes(static_cast<std::int64_t>(mine.size()), sizes.data()), "gather");
    std::int64_t total = 0;
    for (const auto s : sizes) total += s;
    std::string all(static_cast<std::size_t>(total), '\0');
    check(f_.allgatherv(mine.data(), static_cast<std::int64_t>(mine.size()), sizes.data(), size_, all.data()),
          "gather");
    std::vector<std::string> out;
    std::size_t at = 0;
    for (const auto s : sizes) {
      out.push_back(all.substr(at, static_cast<std::size_t>(s)));
      at += static_cast<std::size_t>(s);
    }
    return out;
  }

  std::string broadcast(const std::string& bytes, int root) override {
    std::int64_t n = static_cast<std::int64_t>(bytes.size());
    check(f_.broadcast_size(&n, root), "broadcast");
    std::string out = rank_ == root ? bytes : std::string(static_cast<std::size_t>(n), '\0');
    check(f_.broadcast(out.data(), n, root), "broadcast");
    return out;
  }

  void abort(int code) override { f_.abort(code); }

 private:
  void check(int status, const char* what) const {
    if (status == 2)
      throw Error(fmt::format("MPI {}: more than 2 GiB of results in one batch; use a smaller --batch", what));
    if (status != 0) throw Error(fmt::format("MPI {} failed", what));
  }
  LoadedModule module_;
  MpiModule f_;
  int rank_ = 0, size_ = 1;
};

int env_int(const char* name) {
  const char* v = std::getenv(name);
  return v == nullptr ? 0 : std::atoi(v);
}

}  // namespace

bool launched_by_mpi() {
  // Open MPI's mpirun; PMIx (srun --mpi=pmix, Open MPI 4); PMI-2 (srun --mpi=pmi2, MPICH).
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

std::unique_ptr<Communicator> process_group() {
  if (!launched_by_mpi()) return std::make_unique<SoloCommunicator>();
  return std::make_unique<Mpi>();
}

int threads_per_process(int requested) {
  if (requested > 0) return requested;
  const int cores = resolve_threads(0);
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) {
    const int allowed = CPU_COUNT(&set);
    if (allowed > 0 && allowed < cores) return allowed;  // bound by the launcher
  }
  int local = env_int("OMPI_COMM_WORLD_LOCAL_SIZE");
  if (local <= 0) local = env_int("SLURM_NTASKS_PER_NODE");
  if (local <= 0) local = env_int("MPI_LOCALNRANKS");
  return std::max(1, cores / std::max(1, local));
}

}  // namespace feran::app
