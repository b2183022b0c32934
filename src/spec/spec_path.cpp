#include <feran/spec/spec_path.hpp>

#include <fmt/format.h>

namespace feran::spec {

std::string child(std::string_view path, std::string_view key) {
  if (path.empty()) return std::string(key);
  return fmt::format("{}.{}", path, key);
}

std::string element(std::string_view path, std::size_t index) { return fmt::format("{}[{}]", path, index); }

std::string parent_path(std::string_view path) {
  const std::size_t cut = path.find_last_of(".[");
  if (cut == std::string_view::npos) return {};
  return std::string(path.substr(0, cut));
}

}  // namespace feran::spec
