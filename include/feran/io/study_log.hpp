#pragma once
/// @file
/// The record of a study on disk (docs/output-format.md, "Studies"): a directory
/// with the study's description (study.json), every evaluation as a JSON line
/// (evaluations.jsonl) and as a CSV row (evaluations.csv), appended as batches
/// complete and flushed to the disk, so that an interrupted study loses nothing that
/// was finished; and, at the end, summary.json and the model file of each optimum.

#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include <feran/study/study.hpp>

namespace feran {

/// The names of the files a study writes in its output directory, besides the models
/// of its optima (best.toml, pareto-INDEX.toml).
namespace study_files {
inline constexpr const char* study = "study.json";
inline constexpr const char* evaluations = "evaluations.jsonl";
inline constexpr const char* evaluations_csv = "evaluations.csv";
inline constexpr const char* summary = "summary.json";
}  // namespace study_files

class StudyLog {
 public:
  /// Opens @p directory for @p study (created if missing). Without @p resume the
  /// directory must not hold evaluations already; with it, the evaluations there are
  /// read back (a line cut short by a crash is dropped, and the CSV rewritten to
  /// match), after checking that they belong to the same study. The files the study
  /// reads, @p inputs (its study file and model file), must not be among those it
  /// writes there (however reached: through links or another name). Throws
  /// feran::Error.
  StudyLog(std::string directory, const StudySpec& study, bool resume, const std::vector<std::string>& inputs = {});
  ~StudyLog();
  StudyLog(const StudyLog&) = delete;
  StudyLog& operator=(const StudyLog&) = delete;

  /// The evaluations read back on resume, in index order.
  const std::vector<Evaluation>& done() const { return done_; }
  /// Appends @p evaluations to both files and flushes them to the disk.
  void append(std::span<const Evaluation> evaluations);
  /// Writes summary.json and the models of the best design or the Pareto set
  /// (best.toml, pareto-INDEX.toml); returns the paths of the model files written.
  std::vector<std::string> finish(std::span<const Evaluation> all, bool complete);

  const std::string& directory() const { return directory_; }

 private:
  std::string directory_;
  const StudySpec& study_;
  std::vector<Evaluation> done_;
  std::FILE* jsonl_ = nullptr;
  std::FILE* csv_ = nullptr;
};

/// The JSON line of one evaluation (the format of evaluations.jsonl).
std::string evaluation_json(const StudySpec& study, const Evaluation& e);
/// The evaluation read back from its JSON line; throws feran::Error for a malformed one.
Evaluation evaluation_from_json(const StudySpec& study, const std::string& line);
/// The study's description (study.json): what must match for --resume.
std::string study_json(const StudySpec& study);

}  // namespace feran
