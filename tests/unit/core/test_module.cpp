// Modules loaded on demand (core/module.hpp): the optimiser module is found from a
// program that links the library, and a missing module is refused with every path
// tried.
#include <gtest/gtest.h>

#include <string>

#include <feran/core/error.hpp>
#include <feran/core/module.hpp>

namespace feran {
namespace {

TEST(Module, TheOptimiserModuleIsFoundAndHasItsFunctions) {
  const auto module = load_module("libferan_optimise.so", false, "a test", "build it");
  EXPECT_NE(module.handle, nullptr);
  EXPECT_NE(module_function(module, "feran_optimise"), nullptr);
  EXPECT_NE(module_function(module, "feran_optimise_interface"), nullptr);
  try {
    module_function(module, "no_such_function");
    FAIL() << "a missing function was found";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("has no function no_such_function"), std::string::npos) << e.what();
  }
}

TEST(Module, AMissingModuleIsRefusedNamingEveryPathTried) {
  try {
    load_module("libferan_no_such_module.so", false, "the test's analysis", "install it");
    FAIL() << "a missing module was loaded";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("the test's analysis needs its module libferan_no_such_module.so"), std::string::npos) << m;
    EXPECT_NE(m.find("not found as "), std::string::npos) << m;
    for (const auto& dir : module_directories()) EXPECT_NE(m.find(dir), std::string::npos) << dir << " in " << m;
    EXPECT_NE(m.find("; install it"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace feran
