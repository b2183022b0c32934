// make_integrator and integrator_names: each integrator name mapped to a factory.
// A new integrator adds one line to the table below.
#include <functional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include <feran/integrators/integrator.hpp>
#include <feran/integrators/newmark.hpp>
#include <feran/integrators/rk3.hpp>
#include <feran/integrators/w_method.hpp>
#include <feran/core/error.hpp>

namespace feran {

namespace {

using Factory = std::function<std::unique_ptr<Integrator>(const IntegratorSettings&)>;

const std::vector<std::pair<std::string, Factory>>& registry() {
  static const std::vector<std::pair<std::string, Factory>> table{
      {"trapezoidal",
       [](const IntegratorSettings& s) {
         return std::make_unique<Newmark>(s, NewmarkParameters::average_acceleration());
       }},
      {"rk3", [](const IntegratorSettings& s) { return std::make_unique<Rk3>(s); }},
      {"wolfbrandt",
       [](const IntegratorSettings& s) { return std::make_unique<WMethod>(WTableau::wolfbrandt(), s, false); }},
      {"ros34pw2",
       [](const IntegratorSettings& s) { return std::make_unique<WMethod>(WTableau::ros34pw2(), s, true); }},
  };
  return table;
}

}  // namespace

std::unique_ptr<Integrator> make_integrator(const std::string& name, const IntegratorSettings& settings) {
  for (const auto& [known, factory] : registry())
    if (known == name) return factory(settings);
  std::string known_names;
  for (const std::string& n : integrator_names()) {
    if (!known_names.empty()) known_names += ", ";
    known_names += n;
  }
  throw Error(fmt::format("unknown integrator '{}' (known: {})", name, known_names));
}

std::vector<std::string> integrator_names() {
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

}  // namespace feran
