#include <feran/core/module.hpp>

#include <algorithm>
#include <filesystem>
#include <system_error>

#include <dlfcn.h>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {

// The file that holds this function: the program, or the shared object (Python's
// _feran module) that linked libferan.
std::string directory_of_this_code() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&directory_of_this_code), &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code error;
  auto file = std::filesystem::path(info.dli_fname);
  if (file.is_relative() || file.empty()) {
    // A program's own entry is its name as started; /proc/self/exe is its path.
    file = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) return {};
  }
  return std::filesystem::weakly_canonical(file, error).parent_path().string();
}

}  // namespace

std::vector<std::string> module_directories() {
  std::vector<std::string> dirs;
  const std::string here = directory_of_this_code();
  std::string relative;
  if (!here.empty()) {
    std::error_code error;
    relative =
        std::filesystem::weakly_canonical(std::filesystem::path(here) / FERAN_MODULE_RELATIVE_DIR, error).string();
  }
  for (const std::string& dir :
       {here, relative, std::string(FERAN_MODULE_INSTALL_DIR), std::string(FERAN_MODULE_BUILD_DIR)})
    if (!dir.empty() && std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
  return dirs;
}

LoadedModule load_module(const std::string& name, bool global, const std::string& what, const std::string& remedy) {
  std::vector<std::string> tried;
  std::string reason;
  for (const auto& dir : module_directories()) {
    const std::string path = (std::filesystem::path(dir) / name).string();
    tried.push_back(path);
    if (void* handle = dlopen(path.c_str(), RTLD_NOW | (global ? RTLD_GLOBAL : RTLD_LOCAL)); handle != nullptr)
      return {handle, path};
    const char* e = dlerror();
    if (e != nullptr && reason.empty() && std::filesystem::exists(path)) reason = e;
  }
  throw Error(fmt::format("{} needs its module {}, which could not be loaded ({}{}); {}", what, name,
                          reason.empty() ? "not found as " : reason + "; tried ", fmt::join(tried, " or "), remedy));
}

void* module_function(const LoadedModule& module, const char* symbol) {
  void* f = dlsym(module.handle, symbol);
  if (f == nullptr) throw Error(fmt::format("the module {} has no function {}", module.path, symbol));
  return f;
}

}  // namespace feran
