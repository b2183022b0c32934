#include <feran/core/error.hpp>

#include <fmt/format.h>

namespace feran {

namespace {
std::string format_location(const SourceLocation& w, const std::string& message) {
  if (w.line > 0) return fmt::format("{}:{}:{}: {}", w.file, w.line, w.column, message);
  if (!w.file.empty()) return fmt::format("{}: {}", w.file, message);
  return message;
}
}  // namespace

ModelError::ModelError(SourceLocation where, const std::string& message)
    : Error(format_location(where, message)), where_(std::move(where)), message_(message) {}

SpecError::SpecError(std::string path, const std::string& message)
    : Error(path.empty() ? message : fmt::format("{}: {}", path, message)), path_(std::move(path)), message_(message) {}

}  // namespace feran
