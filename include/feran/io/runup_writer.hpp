#pragma once
/// @file
/// Output of run-ups: CSV streamed sample by sample, JSON at the end
/// (format in docs/output-format.md).

#include <string>

#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/io/output_files.hpp>
#include <feran/io/result_writer.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// Writes the samples of a run-up as CSV rows, one whole row per sample as it comes,
/// to an output of @p files (streamed, so that memory stays bounded however long the
/// run); the file gets its name when @p files commits.
class RunupCsvWriter {
 public:
  /// Writes the header to output @p output of @p files.
  RunupCsvWriter(OutputFiles& files, int output, const Model& model, const TransientOptions& options);

  void write(const TransientSample& sample);

 private:
  OutputFiles& files_;
  int output_;
  std::string row_;
};

/// JSON text of a run-up (its kept samples, envelopes and run statistics).
std::string runup_json(const TransientResult& result, const TransientOptions& options, const Model& model,
                       const ResultSource& source);

}  // namespace feran
