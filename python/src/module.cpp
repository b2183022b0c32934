// The compiled part of the Python module feran: one bind_<area>.cpp per area of the
// library, each adding its classes and functions to the module (docs/python.md).
#include <dlfcn.h>

#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(_feran, m) {
  m.doc() = "feran: finite-element rotor dynamics (the compiled part; use the package feran)";
  // As the command line does: feran's sweeps run on threads of their own, and a
  // threaded OpenBLAS inside each small dense solve only competes with them (and with
  // Python threads running analyses side by side). Looked up at run time: other BLAS
  // builds lack the function.
  using SetThreads = void (*)(int);
  if (void* f = dlsym(RTLD_DEFAULT, "openblas_set_num_threads")) reinterpret_cast<SetThreads>(f)(1);
  feran::python::bind_model(m);
  feran::python::bind_modal(m);
  feran::python::bind_campbell(m);
  feran::python::bind_response(m);
  feran::python::bind_static(m);
  feran::python::bind_runup(m);
}
