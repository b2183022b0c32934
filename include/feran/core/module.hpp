#pragma once
/// \file
/// Parts of feran loaded only by the commands that need them (the optimisers of
/// design studies with pagmo2, the MPI engine with Open MPI): each is a shared module
/// found at run time, so that the program and the Python package neither link nor
/// pay the start-up of the libraries behind it (docs/performance.md).
#include <string>
#include <vector>

namespace feran {

/// A module loaded by load_module(); it stays loaded until the process ends.
struct LoadedModule {
  void* handle = nullptr;
  std::string path;
};

/// The directories searched for a module, in order: the one holding the code that
/// calls (the feran program, Python's _feran module or a program linking libferan),
/// LIBDIR/feran relative to it (a program installed under another prefix), the
/// configured prefix's LIBDIR/feran and the build tree.
std::vector<std::string> module_directories();

/// Loads the module file `name` (e.g. "libferan_optimise.so") from the first of
/// module_directories() that has it; `global` makes its symbols visible to modules it
/// loads in turn (Open MPI's plug-ins need that). Throws Error naming every path tried
/// and, where a file was found but not loaded, the loader's reason; `what` says what
/// the module is for, `remedy` what to do.
LoadedModule load_module(const std::string& name, bool global, const std::string& what, const std::string& remedy);

/// The function `symbol` of a loaded module; throws Error naming the module when it
/// has none.
void* module_function(const LoadedModule& module, const char* symbol);

}  // namespace feran
