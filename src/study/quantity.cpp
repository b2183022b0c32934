#include <feran/study/quantity.hpp>

#include <feran/analyses/list.hpp>
#include <feran/study/design_analyses.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/analyses/harmonic/api684.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>
#include <feran/spec/parameters.hpp>

namespace feran {

bool selected(Whirl w, WhirlSelection s) {
  switch (s) {
    case WhirlSelection::forward:
      return w == Whirl::forward;
    case WhirlSelection::backward:
      return w == Whirl::backward;
    case WhirlSelection::any:
      return w != Whirl::none;
  }
  return false;
}

std::string_view whirl_word(WhirlSelection s) {
  switch (s) {
    case WhirlSelection::forward:
      return "forward ";
    case WhirlSelection::backward:
      return "backward ";
    case WhirlSelection::any:
      return "";
  }
  return "";
}

std::string ordinal(int n) {
  const int tens = n % 100, units = n % 10;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                       : units == 1               ? "st"
                       : units == 2               ? "nd"
                       : units == 3               ? "rd"
                                                  : "th";
  return fmt::format("{}{}", n, suffix);
}

std::vector<NodeRef> quantity_probes(const Model& model, std::span<const QuantitySpec> quantities,
                                     std::string_view analysis) {
  std::vector<NodeRef> probes;
  std::vector<Index> nodes;
  for (const QuantitySpec& q : quantities) {
    if (!q.probe || row_of(q).analysis != analysis) continue;
    const Index node = node_index(model, *q.probe);
    if (std::find(nodes.begin(), nodes.end(), node) != nodes.end()) continue;
    nodes.push_back(node);
    probes.push_back(*q.probe);
  }
  return probes;
}

std::string rpm(Real speed) { return approximate_quantity(speed, Quantity::speed, "rpm"); }

Real extreme_bearing_value(const QuantitySpec& q, bool smallest, const std::vector<BearingValues>& bearings,
                           const std::string& where) {
  if (bearings.empty()) throw Error("the model has no journal or rolling bearing");
  Real best = std::numeric_limits<Real>::quiet_NaN();
  bool named = false;
  for (const BearingValues& b : bearings) {
    if (q.bearing && *q.bearing != b.label) continue;
    named = true;
    if (std::find(b.quantities.begin(), b.quantities.end(), q.value) == b.quantities.end())
      throw Error(fmt::format("bearing '{}' has no operating quantity '{}'; it has {}", b.label, q.value,
                              fmt::join(b.quantities, ", ")));
    for (const Real v : b.values)
      if (std::isfinite(v) && (std::isnan(best) || (smallest ? v < best : v > best))) best = v;
  }
  if (!named) {
    std::vector<std::string> labels;
    for (const BearingValues& b : bearings) labels.push_back(b.label);
    throw Error(fmt::format("no bearing named '{}'; the bearings are {}", *q.bearing, fmt::join(labels, ", ")));
  }
  if (std::isnan(best)) throw Error(fmt::format("no value of '{}'{}", q.value, where));
  return best * (q.value.ends_with("_deg") ? pi / 180 : 1.0);
}

DesignAnalyses::DesignAnalyses(const ModelSpec& spec, const Model& model, std::span<const QuantitySpec> quantities,
                               StopToken stop)
    : spec_(spec), model_(model), stop_(stop), quantities_(quantities) {}

namespace {

// ---- the rows of no analysis -----------------------------------------------------------

Real rotor_mass(DesignAnalyses& a, const QuantitySpec&, std::string&) { return rotating_mass(a.model()); }

Real parameter(DesignAnalyses& a, const QuantitySpec& q, std::string&) { return get_parameter(a.spec(), q.path).value; }

Real function(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  if (!q.function || !*q.function)
    throw Error(
        "no function is given for it (a quantity of kind \"function\" is computed by code, e.g. feran.Study's "
        "quantities)");
  return (*q.function)(a.spec(), a.model());
}

using Q = Quantity;

// The rows of no analysis.
const std::vector<QuantityRow>& own_rows() {
  static const std::vector<QuantityRow> rows = {
      {.name = "rotor_mass", .doc = "mass of the rotating parts", .unit = Q::mass, .evaluate = rotor_mass},
      {.name = "parameter",
       .doc = "a number of the design's model, by its parameter path",
       .evaluate = parameter,
       .parameter = true},
      {.name = "function",
       .doc = "a function given in code (the Python package's feran.Study)",
       .evaluate = function,
       .code_only = true},
  };
  return rows;
}

}  // namespace

const std::vector<QuantityRow>& quantity_rows() {
  static const std::vector<QuantityRow> rows = [] {
    std::vector<QuantityRow> all = own_rows();
    // The rows of the analyses in their folders, before parameter and function.
    std::vector<QuantityRow> rooms;
    Analyses::for_each([&]<class A>() {
      if constexpr (requires { A::quantities(); })
        for (const QuantityRow& r : A::quantities()) rooms.push_back(r);
    });
    all.insert(all.end() - 2, rooms.begin(), rooms.end());
    return all;
  }();
  return rows;
}

const QuantityRow* quantity_row(std::string_view name) {
  for (const QuantityRow& r : quantity_rows())
    if (r.name == name) return &r;
  return nullptr;
}

const QuantityRow& row_of(const QuantitySpec& q) {
  if (const QuantityRow* r = quantity_row(q.kind)) return *r;
  throw Error(fmt::format("unknown quantity kind '{}'", q.kind));
}

std::optional<Quantity> operating_value_unit(std::string_view name) {
  if (name.ends_with("_nm")) return Quantity::moment;
  if (name.ends_with("_pa")) return Quantity::pressure;
  if (name.ends_with("_deg")) return Quantity::angle;
  if (name.ends_with("_m")) return Quantity::length;
  if (name.ends_with("_n")) return Quantity::force;
  return std::nullopt;
}

std::optional<Quantity> quantity_unit(const QuantitySpec& q) {
  const QuantityRow& row = row_of(q);
  if (row.bearing_value) return operating_value_unit(q.value);
  return row.parameter ? q.value_kind : row.unit;
}

std::vector<Real> evaluate_quantities(const ModelSpec& spec, const Model& model,
                                      std::span<const QuantitySpec> quantities, const StopToken& stop,
                                      std::vector<std::string>* clipped) {
  DesignAnalyses analyses(spec, model, quantities, stop);
  std::vector<Real> values;
  values.reserve(quantities.size());
  if (clipped) clipped->assign(quantities.size(), std::string());
  for (const auto& q : quantities) {
    try {
      std::string note;
      values.push_back(row_of(q).evaluate(analyses, q, note));
      if (clipped) (*clipped)[values.size() - 1] = std::move(note);
    } catch (const Error& e) {
      throw Error(fmt::format("quantity '{}': {}", q.name, e.what()));
    }
  }
  return values;
}

}  // namespace feran
