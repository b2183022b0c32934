// A study spread over a group of processes, here played by threads exchanging bytes
// through shared memory: the same evaluations as one process, bit for bit, whatever
// the group's size; a stop asked of one member ends every member at the same batch;
// evaluations survive packing exactly and malformed bytes are refused.
#include <barrier>
#include <cmath>
#include <limits>
#include <thread>

#include <gtest/gtest.h>

#include <feran/core/error.hpp>
#include <feran/io/study_reader.hpp>
#include <feran/study/distributed.hpp>

namespace feran::test_distributed {
namespace {

// The members of a group of threads: each all_gather and broadcast is a barrier.
struct Shared {
  explicit Shared(int n) : size(n), slots(static_cast<std::size_t>(n)), sync(n) {}
  int size;
  std::vector<std::string> slots;
  std::barrier<> sync;
};

class ThreadGroup : public Communicator {
 public:
  ThreadGroup(Shared& shared, int rank) : shared_(shared), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return shared_.size; }
  std::vector<std::string> all_gather(const std::string& mine) override {
    shared_.slots[static_cast<std::size_t>(rank_)] = mine;
    shared_.sync.arrive_and_wait();
    auto all = shared_.slots;
    shared_.sync.arrive_and_wait();
    return all;
  }
  std::string broadcast(const std::string& bytes, int root) override {
    if (rank_ == root) shared_.slots[static_cast<std::size_t>(root)] = bytes;
    shared_.sync.arrive_and_wait();
    auto out = shared_.slots[static_cast<std::size_t>(root)];
    shared_.sync.arrive_and_wait();
    return out;
  }

 private:
  Shared& shared_;
  int rank_;
};

// Runs @p body(group, rank) on @p n member threads; returns each member's result.
template <class Body>
auto on_members(int n, Body body) {
  Shared shared(n);
  std::vector<decltype(body(std::declval<Communicator&>(), 0))> out(static_cast<std::size_t>(n));
  std::vector<std::thread> members;
  for (int r = 0; r < n; ++r)
    members.emplace_back([&, r] {
      ThreadGroup group(shared, r);
      out[static_cast<std::size_t>(r)] = body(group, r);
    });
  for (auto& t : members) t.join();
  return out;
}

// Everything but the wall time.
void expect_same(const std::vector<Evaluation>& a, const std::vector<Evaluation>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].index, b[i].index);
    EXPECT_EQ(a[i].unit, b[i].unit) << i;
    EXPECT_EQ(a[i].values, b[i].values) << i;
    EXPECT_EQ(a[i].quantities, b[i].quantities) << i;  // exactly: the same arithmetic
    EXPECT_EQ(a[i].evaluated, b[i].evaluated);
    EXPECT_EQ(a[i].feasible, b[i].feasible);
    EXPECT_EQ(a[i].message, b[i].message);
    EXPECT_EQ(a[i].clipped, b[i].clipped);
  }
}

StudySpec grid_study() {
  auto study = read_study_file(FERAN_TEST_MODELS "/studies/bearing_damping_grid.toml").study;
  study.explore.levels = 11;
  return study;
}

TEST(DistributedStudy, EvaluationsSurvivePackingExactly) {
  Evaluation a;
  a.index = 41;
  a.unit = {0.1, 1.0 / 3.0};
  a.values = {1e-300, -0.0};
  a.quantities = {std::numeric_limits<Real>::denorm_min(), 6.02214076e23};
  a.evaluated = a.feasible = true;
  a.message = "line one\nline \"two\" \xce\xb6";
  a.clipped = {"", "a lower bound: the range ends"};
  a.seconds = 0.125;
  Evaluation b;
  b.index = 42;
  b.interrupted = true;
  const std::vector<Evaluation> both{a, b};
  const auto back = unpack_evaluations(pack_evaluations(both));
  expect_same(back, both);
  EXPECT_EQ(back[0].seconds, 0.125);
  EXPECT_TRUE(back[1].interrupted);
  EXPECT_FALSE(back[0].interrupted);
  EXPECT_TRUE(std::signbit(back[0].values[1]));
  EXPECT_TRUE(unpack_evaluations(pack_evaluations({})).empty());

  const std::string bytes = pack_evaluations(both);
  EXPECT_THROW(unpack_evaluations("FEV2" + bytes.substr(4)), Error);
  EXPECT_THROW(unpack_evaluations(bytes.substr(0, bytes.size() - 1)), Error);
  EXPECT_THROW(unpack_evaluations(bytes + "x"), Error);
  // A count far beyond the bytes (a corrupted length) is refused, not allocated.
  std::string huge = bytes;
  huge[4 + 8 + 8 + 7] = '\x7f';
  EXPECT_THROW(unpack_evaluations(huge), Error);
}

TEST(DistributedStudy, AnyGroupSizeGivesTheEvaluationsOfOneProcess) {
  const auto study = grid_study();
  ThreadEvaluator solo(1);
  const auto reference = run_exploration(study, solo, {}, {}, 4);
  ASSERT_EQ(reference.size(), 11u);
  for (const int n : {1, 2, 3}) {
    const auto results = on_members(n, [&](Communicator& group, int) {
      ThreadEvaluator local(1);
      DistributedEvaluator evaluator(group, local);
      return run_exploration(study, evaluator, {}, {}, 4, evaluator.stop_token());
    });
    for (const auto& r : results) expect_same(r, reference);
  }
}

TEST(DistributedStudy, AnOptimiserRunsTheSameOnEveryMember) {
  auto study = read_study_file(FERAN_TEST_MODELS "/studies/bearing_damping_optimise.toml").study;
  study.explore.generations = 2;
  study.explore.polish = 6;
  ThreadEvaluator solo(2);
  const auto reference = run_optimisation(study, solo, {}, {});
  ASSERT_GT(reference.size(), 2 * static_cast<std::size_t>(study.explore.population));
  const auto results = on_members(3, [&](Communicator& group, int) {
    ThreadEvaluator local(1);
    DistributedEvaluator evaluator(group, local);
    return run_optimisation(study, evaluator, {}, {}, evaluator.stop_token());
  });
  for (const auto& r : results) expect_same(r, reference);
}

TEST(DistributedStudy, AStopAskedOfOneMemberEndsAllAtTheSameBatch) {
  const auto study = grid_study();
  std::atomic<bool> asked{true};
  const auto results = on_members(3, [&](Communicator& group, int rank) {
    // Member 1 is asked to stop before the first batch (as a signal would: its
    // evaluations and the group see it); its share comes back interrupted, the
    // others' share is kept, and no member starts a second batch.
    const StopToken stop = rank == 1 ? StopToken(asked) : StopToken();
    ThreadEvaluator local(1, stop);
    DistributedEvaluator evaluator(group, local, stop);
    auto all = run_exploration(study, evaluator, {}, {}, 6, evaluator.stop_token());
    EXPECT_TRUE(evaluator.stopped());
    return all;
  });
  for (const auto& r : results) {
    std::vector<Index> indices;
    for (const auto& e : r) indices.push_back(e.index);
    EXPECT_EQ(indices, (std::vector<Index>{0, 2, 3, 5}));  // batch 0–5 less member 1's 1 and 4
  }
}

TEST(DistributedStudy, MembersAgreeOrNameTheOneThatFailed) {
  const auto messages = on_members(3, [&](Communicator& group, int rank) {
    std::string why;
    const bool ok = all_agree(group, rank != 2, rank == 2 ? "cannot read s.toml" : "", &why);
    return ok ? std::string("ok") : why;
  });
  for (const auto& m : messages) EXPECT_EQ(m, "process 2: cannot read s.toml");
  const auto fine = on_members(2, [&](Communicator& group, int) { return all_agree(group, true, "") ? 1 : 0; });
  for (const int ok : fine) EXPECT_EQ(ok, 1);
}

}  // namespace
}  // namespace feran::test_distributed
