// The compiled part of the Python module feran: one bind_<area>.cpp per area of the
// library, each adding its classes and functions to the module, and the analyses of
// analyses/list.hpp from their faces (analysis_binding.hpp; docs/python.md).
#include <feran/analyses/list.hpp>
#include <feran/core/parallel.hpp>

#include <pybind11/pybind11.h>

#include "analysis_binding.hpp"
#include "bindings.hpp"

PYBIND11_MODULE(_feran, m) {
  m.doc() = "feran: finite-element rotor dynamics (the compiled part; use the package feran)";
  // As the command line does (and for Python threads running analyses side by side).
  feran::single_threaded_blas();
  feran::python::bind_model(m);
  feran::python::bind_study(m);
  feran::python::bind_report(m);
  // The analyses of analyses/list.hpp, each from its face; the package gives each
  // function its signature from the options described here.
  pybind11::dict options;
  feran::Analyses::for_each([&]<class A>() { feran::python::bind_analysis<A>(m, options); });
  m.attr("_analysis_options") = options;
}
