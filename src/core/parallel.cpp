#include <feran/core/parallel.hpp>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include <dlfcn.h>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

void single_threaded_blas() {
  using SetThreads = void (*)(int);
  if (void* f = dlsym(RTLD_DEFAULT, "openblas_set_num_threads")) reinterpret_cast<SetThreads>(f)(1);
  // The worker threads started when the library loaded spin for about 0.1 s before
  // they sleep; shutting the thread server down joins them at once.
  using Shutdown = int (*)();
  if (void* f = dlsym(RTLD_DEFAULT, "blas_thread_shutdown_")) reinterpret_cast<Shutdown>(f)();
}

int resolve_threads(int requested) {
  if (requested < 0 || requested > max_threads)
    throw Error(fmt::format("threads: 0 (all cores) or a count from 1 to {}, got {}", max_threads, requested));
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

void parallel_for(Index n, int n_threads, const std::function<void(Index i, int worker)>& body) {
  const int threads = static_cast<int>(std::min<Index>(resolve_threads(n_threads), std::max<Index>(n, 1)));
  if (threads <= 1) {
    for (Index i = 0; i < n; ++i) body(i, 0);
    return;
  }
  std::atomic<Index> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&](int worker) {
    for (Index i = next++; i < n && !failed; i = next++) {
      try {
        body(i, worker);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads - 1));
  // The system may refuse a thread (a limit on processes or memory): the items are
  // then shared by those that started, instead of the program ending.
  try {
    for (int w = 1; w < threads; ++w) pool.emplace_back(work, w);
  } catch (const std::system_error&) {
  }
  work(0);
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace feran
