#pragma once
// A batch evaluator for tests of interrupted studies: evaluates on two threads and
// sets a stop flag after a given number of batches, as Ctrl-C would.

#include <atomic>

#include <feran/study/study.hpp>

namespace feran::test {

class StoppingEvaluator : public BatchEvaluator {
 public:
  StoppingEvaluator(std::atomic<bool>& flag, int batches) : flag_(flag), left_(batches) {}
  std::vector<Evaluation> evaluate(const StudySpec& s, const std::vector<std::pair<Index, UnitPoint>>& b) override {
    auto out = inner_.evaluate(s, b);
    if (--left_ == 0) flag_ = true;
    return out;
  }

 private:
  std::atomic<bool>& flag_;
  int left_;
  ThreadEvaluator inner_{2};
};

}  // namespace feran::test
