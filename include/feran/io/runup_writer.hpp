#pragma once
/// @file
/// Output of run-ups: CSV streamed sample by sample, JSON at the end
/// (format in docs/output-format.md).

#include <fstream>
#include <string>

#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/io/result_writer.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// Writes the samples of a run-up to a CSV file as they come, so that memory stays
/// bounded however long the run. The file is written as PATH.part and renamed by
/// finish(); without finish() (an exception) the partial file is removed.
class RunupCsvWriter {
 public:
  RunupCsvWriter(const std::string& path, const Model& model, const TransientOptions& options);
  ~RunupCsvWriter();
  RunupCsvWriter(const RunupCsvWriter&) = delete;
  RunupCsvWriter& operator=(const RunupCsvWriter&) = delete;

  void write(const TransientSample& sample);
  /// Closes the file and gives it its final name.
  void finish();

 private:
  std::string path_;
  std::ofstream out_;
  bool finished_ = false;
};

/// JSON text of a run-up (its kept samples, envelopes and run statistics).
std::string runup_json(const TransientResult& result, const TransientOptions& options, const Model& model,
                       const ResultSource& source);

}  // namespace feran
