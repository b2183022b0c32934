#pragma once
/// @file
/// Exception types for bad input. Numerical non-convergence is not an exception:
/// it is recorded in a result's SolverInfo.

#include <stdexcept>
#include <string>

namespace feran {

/// Position in an input file (1-based line and column; 0 when unknown).
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// Base of every error feran reports for bad input or bad options.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An error in a model file. what() reads "file:line:column: message".
class ModelError : public Error {
 public:
  ModelError(SourceLocation where, const std::string& message);
  /// Where in the model file the problem is.
  const SourceLocation& where() const { return where_; }
  /// The message without the location prefix.
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

/// An error in a model specification (ModelSpec), located by a path into it such as
/// "shafts[1].sections[2].length" (indices from 0; "" for the model as a whole).
/// what() reads "path: message". The model reader turns it into a ModelError at the
/// file, line and column where that part of the spec was written.
class SpecError : public Error {
 public:
  SpecError(std::string path, const std::string& message);
  /// Where in the spec the problem is.
  const std::string& path() const { return path_; }
  /// The message without the path.
  const std::string& message() const { return message_; }

 private:
  std::string path_;
  std::string message_;
};

/// An error in the structure of a model that has no single place in a file
/// (thrown by the library; the model reader attaches a location and rethrows it
/// as a ModelError). @p node is the index of a node involved, or -1.
class ModelStructureError : public Error {
 public:
  ModelStructureError(const std::string& message, long node = -1) : Error(message), node_(node) {}
  long node() const { return node_; }

 private:
  long node_;
};

}  // namespace feran
