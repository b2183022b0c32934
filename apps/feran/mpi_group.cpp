#include "mpi_group.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include <dlfcn.h>
#include <sched.h>

#include <fmt/format.h>

#include <feran/core/error.hpp>
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

constexpr const char* module_name = "libferan_mpi.so";

std::string program_directory() {
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::string() : exe.parent_path().string();
}

template <class F>
void bind_symbol(void* handle, const char* name, F& f, const std::string& path) {
  void* symbol = dlsym(handle, name);
  if (symbol == nullptr) throw Error(fmt::format("the MPI module {} has no function {}", path, name));
  f = reinterpret_cast<F>(symbol);
}

class Mpi : public Communicator {
 public:
  Mpi() {
    std::vector<std::string> tried;
    std::string reason;
    for (const std::string& dir : {program_directory(), std::string(FERAN_MPI_MODULE_DIR)}) {
      if (dir.empty()) continue;
      const std::string path = (std::filesystem::path(dir) / module_name).string();
      tried.push_back(path);
      // Global: Open MPI's own plug-ins look up its symbols in the global scope.
      handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
      if (handle_ != nullptr) {
        path_ = path;
        break;
      }
      if (const char* e = dlerror(); e != nullptr && std::filesystem::exists(path)) reason = e;
    }
    if (handle_ == nullptr)
      throw Error(fmt::format("an MPI launcher started feran, but its MPI module could not be loaded ({}{}); "
                              "build feran with Open MPI installed (libopenmpi-dev), or run without mpirun",
                              reason.empty() ? "not found as " : reason + "; tried ",
                              fmt::join(tried, " or ")));
    bind_symbol(handle_, "feran_mpi_init", f_.init, path_);
    bind_symbol(handle_, "feran_mpi_allgather_sizes", f_.allgather_sizes, path_);
    bind_symbol(handle_, "feran_mpi_allgatherv", f_.allgatherv, path_);
    bind_symbol(handle_, "feran_mpi_broadcast_size", f_.broadcast_size, path_);
    bind_symbol(handle_, "feran_mpi_broadcast", f_.broadcast, path_);
    bind_symbol(handle_, "feran_mpi_finalize", f_.finalize, path_);
    bind_symbol(handle_, "feran_mpi_abort", f_.abort, path_);
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
    check(f_.allgatherv(mine.data(), static_cast<std::int64_t>(mine.size()), sizes.data(), size_, all.data()), "gather");
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
    if (status == 2) throw Error(fmt::format("MPI {}: more than 2 GiB of results in one batch; use a smaller --batch", what));
    if (status != 0) throw Error(fmt::format("MPI {} failed", what));
  }
  void* handle_ = nullptr;
  std::string path_;
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
