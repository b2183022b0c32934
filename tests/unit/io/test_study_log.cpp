// The study's record on disk: an interrupted study, its last line cut short as a
// crash would leave it, continues with resume to exactly the result of an
// uninterrupted run, every design once; and the record refuses to be overwritten or
// continued by a different study.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <set>

#include <unistd.h>

#include <gtest/gtest.h>

#include "stopping_evaluator.hpp"

#include <feran/core/error.hpp>
#include <feran/io/study_log.hpp>
#include <feran/io/study_reader.hpp>

namespace feran::test_study_log {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

using test::StoppingEvaluator;

TEST(StudyLog, AnInterruptedStudyResumesToTheUninterruptedResult) {
  const auto file = read_study_file(FERAN_TEST_MODELS "/studies/bearing_damping_grid.toml");
  const auto& study = file.study;
  const fs::path dir = fs::temp_directory_path() / ("feran_study_log_" + std::to_string(::getpid()));
  fs::remove_all(dir);

  ThreadEvaluator plain(2);
  const auto reference = run_exploration(study, plain, {}, {}, 10);

  {  // The first run stops after 3 batches of 10.
    std::atomic<bool> flag{false};
    StoppingEvaluator evaluator(flag, 3);
    StudyLog log(dir.string(), study, false);
    const auto part = run_exploration(
        study, evaluator, log.done(), [&](std::span<const Evaluation> e) { log.append(e); }, 10, StopToken(flag));
    EXPECT_EQ(part.size(), 30u);
  }
  EXPECT_EQ(lines_of(dir / "evaluations.jsonl").size(), 30u);
  EXPECT_EQ(lines_of(dir / "evaluations.csv").size(), 31u);  // with its header
  // A crash while writing leaves half a line.
  std::ofstream(dir / "evaluations.jsonl", std::ios::app) << R"({"evaluated":true,"feasible":tr)";
  std::ofstream(dir / "evaluations.csv", std::ios::app) << "30,1234";

  // Without resume the directory is refused.
  EXPECT_THROW(StudyLog(dir.string(), study, false), Error);
  {
    StudyLog log(dir.string(), study, true);
    EXPECT_EQ(log.done().size(), 30u);  // the cut line dropped
    const auto all = run_exploration(
        study, plain, log.done(), [&](std::span<const Evaluation> e) { log.append(e); }, 10);
    ASSERT_EQ(all.size(), reference.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
      EXPECT_EQ(all[i].index, reference[i].index);
      EXPECT_EQ(all[i].values, reference[i].values);  // read back bit for bit
      EXPECT_EQ(all[i].quantities, reference[i].quantities);
    }
    log.finish(all, true);
  }
  // Every design once in each file, in the same order in both.
  const auto jsonl = lines_of(dir / "evaluations.jsonl");
  const auto csv = lines_of(dir / "evaluations.csv");
  ASSERT_EQ(jsonl.size(), 201u);
  ASSERT_EQ(csv.size(), 202u);
  std::set<Index> seen;
  for (std::size_t i = 0; i < jsonl.size(); ++i) {
    const auto e = evaluation_from_json(study, jsonl[i]);
    EXPECT_TRUE(seen.insert(e.index).second) << "design " << e.index << " twice";
    EXPECT_EQ(csv[i + 1].substr(0, csv[i + 1].find(',')), std::to_string(e.index));
  }
  EXPECT_TRUE(fs::exists(dir / "best.toml"));
  EXPECT_TRUE(fs::exists(dir / "summary.json"));

  // A different study may not continue these results.
  StudySpec other = study;
  other.variables[0].upper = 20000;
  EXPECT_THROW(StudyLog(dir.string(), other, true), Error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace feran::test_study_log
