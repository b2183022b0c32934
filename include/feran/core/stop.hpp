#pragma once
/// @file
/// A request to stop a long analysis early: a signal, a button, a study's deadline.

#include <atomic>

namespace feran {

/// Asks a long analysis to stop. The analyses look at it at their clean points —
/// before each speed of a sweep, before each step of a run-up — and then end with
/// SolverStatus::interrupted, the results so far kept and consistent (whole points,
/// whole samples). Copies share the flag, which the caller owns and sets (a signal
/// handler may: a lock-free atomic); the default token never asks.
class StopToken {
 public:
  StopToken() = default;
  explicit StopToken(const std::atomic<bool>& flag) : flag_(&flag) {}
  bool requested() const noexcept { return flag_ != nullptr && flag_->load(std::memory_order_relaxed); }

 private:
  const std::atomic<bool>* flag_ = nullptr;
};

}  // namespace feran
