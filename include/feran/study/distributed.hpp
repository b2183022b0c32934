#pragma once
/// @file
/// A study's evaluations spread over several processes (MPI ranks, or any other group
/// that can exchange bytes): each batch is shared out, each process evaluates its
/// part on its own threads, and every process gets the whole batch back, so that the
/// optimiser or the sampler runs the same on each and asks for the same next batch.
///
/// The results do not depend on the number of processes or threads: a design's
/// result depends only on its index and point, and the batch comes back in its order.

#include <atomic>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <feran/core/stop.hpp>
#include <feran/study/study.hpp>

namespace feran {

/// A group of processes that exchange bytes: collective operations, each called by
/// every member in the same order.
class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Each member's @p mine, in rank order, on every member.
  virtual std::vector<std::string> all_gather(const std::string& mine) = 0;
  /// @p bytes of member @p root, on every member (the others' argument is ignored).
  virtual std::string broadcast(const std::string& bytes, int root) = 0;
  /// Ends every member with exit code @p code, for an error on one member after
  /// which the others would wait for it forever; does nothing in a group of one.
  virtual void abort(int /*code*/) {}
};

/// The group of one process: the study runs as it would without a group.
class SoloCommunicator : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<std::string> all_gather(const std::string& mine) override { return {mine}; }
  std::string broadcast(const std::string& bytes, int) override { return bytes; }
};

/// Evaluations as bytes, exactly (doubles bit for bit), and back; unpack throws
/// feran::Error for bytes that are not a packed list.
std::string pack_evaluations(std::span<const Evaluation> evaluations);
std::vector<Evaluation> unpack_evaluations(const std::string& bytes);

/// Whether every member's @p ok is true; when one is not, the first such member's
/// @p message (prefixed by "process R: " when R is not 0) in @p first_message.
bool all_agree(Communicator& group, bool ok, const std::string& message, std::string* first_message = nullptr);

/// Evaluates each batch over the members of a group: item i of a batch on member
/// i mod size, with that member's @p local evaluator; then the whole batch is
/// gathered on every member. After each batch the members also agree on stopping:
/// when any member's @p stop is set, stop_token() is set on all of them, so that
/// every member leaves the study at the same batch. evaluate() is collective.
class DistributedEvaluator : public BatchEvaluator {
 public:
  DistributedEvaluator(Communicator& group, BatchEvaluator& local, StopToken stop = {})
      : group_(group), local_(local), stop_(stop), stopped_(std::make_unique<std::atomic<bool>>(false)) {}
  std::vector<Evaluation> evaluate(const StudySpec& study,
                                   const std::vector<std::pair<Index, UnitPoint>>& batch) override;
  /// Set on every member once any member was asked to stop (between batches).
  StopToken stop_token() const { return StopToken(*stopped_); }
  bool stopped() const { return stopped_->load(); }

 private:
  Communicator& group_;
  BatchEvaluator& local_;
  StopToken stop_;
  std::unique_ptr<std::atomic<bool>> stopped_;
};

}  // namespace feran
