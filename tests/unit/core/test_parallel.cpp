#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include <feran/core/parallel.hpp>

namespace feran::test_parallel {
namespace {

TEST(ParallelFor, EveryItemOnceWithAValidWorker) {
  for (int threads : {1, 2, 3}) {
    std::vector<std::atomic<int>> hits(100);
    std::atomic<bool> bad_worker{false};
    parallel_for(100, threads, [&](Index i, int worker) {
      ++hits[static_cast<std::size_t>(i)];
      if (worker < 0 || worker >= threads) bad_worker = true;
    });
    for (const auto& h : hits) EXPECT_EQ(h.load(), 1) << threads << " threads";
    EXPECT_FALSE(bad_worker);
  }
}

TEST(ParallelFor, NoItems) {
  int calls = 0;
  parallel_for(0, 2, [&](Index, int) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelFor, RethrowsTheBodysException) {
  EXPECT_THROW(parallel_for(50, 2,
                            [](Index i, int) {
                              if (i == 7) throw std::runtime_error("item 7");
                            }),
               std::runtime_error);
}

TEST(ParallelFor, ResolvesThreadCount) {
  EXPECT_EQ(resolve_threads(3), 3);
  EXPECT_GE(resolve_threads(0), 1);
}

}  // namespace
}  // namespace feran::test_parallel
