#pragma once
/// @file
/// The files one command writes: every path checked before the analysis runs, each
/// written to a temporary file of its own in the target's directory and renamed, all
/// of them or none (format of the contents in docs/output-format.md).

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace feran {

/// The outputs of one command. add() checks a path and reserves it; the contents are
/// given with write() (whole) or append() (streamed as the analysis runs); commit()
/// writes them all and gives each its name. An OutputFiles destroyed before commit()
/// removes every temporary file it made and leaves every target as it was.
///
/// Where a path leads:
/// - a regular file, or a name not yet taken, in an existing directory: a temporary
///   file PATH.part-XXXXXX (unique, so concurrent runs and a user's own files are
///   never shared) is made next to it at add() and renamed over it at commit(); a
///   replaced file keeps its permissions, a new one gets 0666 less the umask;
/// - a symbolic link: the same for the file it points to (the link stays);
/// - standard output or error (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N):
///   written to that descriptor as it is (a pipe, a terminal, a file opened for
///   appending), at commit();
/// - any other file that is not regular (a device, a FIFO): written in place, at
///   commit() (a streamed output: as it comes).
///
/// Refused, with the option, the path and why: a directory, a missing directory, a
/// directory the program cannot write to, the model file or another input
/// (add_input) itself (however reached: through links or another name), a path that
/// an earlier output also writes (except /dev/null).
class OutputFiles {
 public:
  /// @p model_path is the file the command reads, which no output may replace.
  explicit OutputFiles(std::string model_path);
  /// Another file the command reads (@p what names it in messages: "the report
  /// configuration"), which no output may replace either: checked against the
  /// outputs added before and after. Throws feran::Error naming the output's option.
  void add_input(std::string path, std::string what);
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// Checks and reserves @p path for the output given by @p option ("--json"), or
  /// does nothing for an empty path. A @p streamed output is written as append()
  /// gives it (memory stays bounded); the others are kept until commit(). Returns
  /// the output's number; throws feran::Error.
  int add(std::string option, std::string path, bool streamed = false);
  /// Whether output @p id names a file (add() was given a path).
  bool wanted(int id) const;
  /// The whole content of output @p id (not streamed).
  void write(int id, std::string content);
  /// More of streamed output @p id. A write error is kept and reported by commit().
  void append(int id, std::string_view text);
  /// Writes every output and gives each its name: first all temporary files are
  /// completed, then the outputs written in place are written (a failure in either
  /// removes every temporary file and throws, no regular target touched), and last
  /// each temporary file is renamed. Throws feran::Error naming the file and the
  /// system's reason.
  void commit();

 private:
  struct Output;
  struct Input {
    std::string path, what;
  };
  std::vector<Input> inputs_;
  std::vector<std::unique_ptr<Output>> outputs_;
  bool committed_ = false;
};

/// Removes the temporary files of every OutputFiles that has not committed. Only
/// async-signal-safe calls: a signal handler may call it before the process ends.
void remove_temporary_outputs() noexcept;

}  // namespace feran
