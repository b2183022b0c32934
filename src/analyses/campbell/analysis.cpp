// The Campbell diagram's room: its options ([campbell]), their defaults and checks, its
// JSON, CSV and terminal writers and its study quantities (analyses/campbell/analysis.hpp).
#include <feran/analyses/campbell/analysis.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/harmonic/api684.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/core/error.hpp>
#include <feran/core/text.hpp>
#include <feran/io/option_text.hpp>
#include <feran/spec/fields.hpp>
#include <feran/study/design_analyses.hpp>

#include "../../io/result_text.hpp"

namespace feran {

using Json = nlohmann::json;
using namespace detail;  // NOLINT(google-build-using-namespace): the writers' shared vocabulary (result_text.hpp)

namespace spec {

template <>
const FieldTable<CampbellSpec>& fields_of<CampbellSpec>() {
  using S = CampbellSpec;
  using K = FieldKind;
  static const FieldTable<S> table = {
      {.key = "start",
       .kind = K::quantity,
       .member = &S::start,
       .doc = "first speed",
       .quantity = Quantity::speed,
       .bound = {Bound::Kind::non_negative},
       .unit = "Hz"},
      {.key = "stop",
       .kind = K::quantity,
       .member = &S::stop,
       .doc = "last speed; > `start` when both are given",
       .quantity = Quantity::speed,
       .bound = {Bound::Kind::non_negative},
       .unit = "Hz",
       .default_text = "required (here or as an option)"},
      {.key = "points",
       .kind = K::integer,
       .member = &S::points,
       .doc = "number of speeds",
       .bound = {Bound::Kind::at_least, 2, max_sweep_points},
       .short_name = "p"},
      {.key = "modes",
       .kind = K::integer,
       .member = &S::modes,
       .doc = "number of modes to track",
       .bound = {Bound::Kind::at_least, 1},
       .short_name = "n"},
      {.key = "orders",
       .kind = K::integer_list,
       .member = &S::orders,
       .doc = "each ≥ 1; excitation orders k of the lines f = k·Ω, kept as given",
       .bound = {Bound::Kind::at_least, 1},
       .short_name = "k"},
      {.key = "solver",
       .kind = K::choice,
       .member = &S::solver,
       .doc = "eigen solver at each speed, as `[modal]` `solver`",
       .choices = eigen_solver_names},
  };
  return table;
}

}  // namespace spec

const CampbellSpec& CampbellAnalysis::defaults() {
  static const CampbellSpec d{.start = 0.0,
                              .stop = std::nullopt,
                              .points = defaults::campbell_points,
                              .modes = defaults::campbell_modes,
                              .orders = {1},
                              .solver = "auto"};
  return d;
}

CampbellOptions CampbellAnalysis::settings(const Model&, const CampbellSpec&, const CampbellSpec& resolved,
                                           const OptionName& named) {
  if (!resolved.stop)
    throw Error(fmt::format("campbell: give the last speed with {0} (e.g. {0} 80Hz) or in the model's [campbell] table",
                            named("stop")));
  if (!(*resolved.stop > *resolved.start)) throw Error("campbell: the last speed must be above the first");
  CampbellOptions options;
  const int n = *resolved.points;
  options.speeds.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    options.speeds[static_cast<std::size_t>(i)] = *resolved.start + (*resolved.stop - *resolved.start) * i / (n - 1);
  options.n_modes = *resolved.modes;
  options.orders = resolved.orders;
  options.modal.solver = parse_solver_name(*resolved.solver, "solver");
  return options;
}

CampbellResult CampbellAnalysis::run(const Model& model, const CampbellOptions& options, const RunContext& context) {
  CampbellOptions o = options;
  o.n_threads = context.threads;
  o.stop = context.stop;
  return run_campbell(model, o, context.assembler);
}

std::vector<std::string> CampbellAnalysis::warnings(const Model& model, const CampbellOptions& options,
                                                    const CampbellResult& result) {
  // Frequency tables are read at the tracked modes' frequencies.
  std::vector<Real> frequencies;
  for (const TrackedMode& m : result.modes)
    frequencies.insert(frequencies.end(), m.frequency_hz.begin(), m.frequency_hz.end());
  const auto span = frequency_span(frequencies);
  return range_warnings(model, options.speeds.front(), options.speeds.back(), span);
}

std::string CampbellAnalysis::json(const Outcome<CampbellAnalysis>& o) {
  const CampbellResult& result = o.result;
  const CampbellOptions& options = o.options;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  Json j = header("campbell", source);
  std::vector<Real> hz;
  for (Real s : result.speeds) hz.push_back(rad_to_hz(s));
  j["complete"] = result.info.converged() && result.speeds.size() == options.speeds.size();
  j["speeds_hz"] = numbers(hz);
  j["orders"] = options.orders;
  j["solver"] = solver_json(result.info);
  j["n_solves"] = result.n_solves;
  Json modes = Json::array();
  for (const TrackedMode& m : result.modes) {
    Json whirl_at = Json::array();
    for (Whirl w : m.whirl_at) whirl_at.push_back(to_string(w));
    modes.push_back({{"label", m.label},
                     {"whirl", to_string(m.whirl)},
                     {"type", to_string(m.type)},
                     {"shape", to_string(m.shape_kind)},
                     {"bending", numbers(m.bending)},
                     {"frequency_hz", numbers(m.frequency_hz)},
                     {"damping_ratio", numbers(m.damping_ratio)},
                     {"log_decrement", numbers(m.log_decrement)},
                     {"directivity", numbers(m.directivity)},
                     {"whirl_at", whirl_at},
                     {"correlation", numbers(m.correlation)}});
  }
  j["modes"] = modes;
  Json critical = Json::array();
  for (const CriticalSpeed& c : result.critical_speeds)
    critical.push_back({{"speed_hz", rad_to_hz(c.speed)},
                        {"speed_rpm", rad_to_hz(c.speed) * 60.0},
                        {"mode", result.modes[static_cast<std::size_t>(c.mode)].label},
                        {"order", c.order},
                        {"frequency_hz", c.frequency_hz},
                        {"whirl", to_string(c.whirl)}});
  j["critical_speeds"] = critical;
  if (result.stability_threshold) {
    const StabilityThreshold& t = *result.stability_threshold;
    j["stability_threshold_hz"] = rad_to_hz(t.speed);
    j["stability_threshold"] = {
        {"speed_hz", rad_to_hz(t.speed)},           {"speed_rpm", rad_to_hz(t.speed) * 60.0},
        {"mode", threshold_label(result, t)},       {"frequency_hz", t.frequency_hz},
        {"unstable_at_start", t.unstable_at_start}, {"kind", t.divergence ? "divergence" : "flutter"}};
  } else {
    j["stability_threshold_hz"] = nullptr;
    j["stability_threshold"] = nullptr;
  }
  j["supports"] = detail::operating_json(result.operating, model);
  return detail::json_text(j, 2);
}

std::string CampbellAnalysis::csv(const Outcome<CampbellAnalysis>& o) {
  const CampbellResult& result = o.result;
  const Model& model = o.model();
  std::ostringstream out;
  out << "speed_hz,speed_rpm";
  for (const TrackedMode& m : result.modes)
    out << ',' << detail::csv_column(m.label, "_frequency_hz") << ',' << detail::csv_column(m.label, "_damping_ratio");
  out << detail::operating_csv_header(result.operating, model) << '\n';
  for (std::size_t i = 0; i < result.speeds.size(); ++i) {
    out << csv_number(rad_to_hz(result.speeds[i])) << ',' << csv_number(rad_to_hz(result.speeds[i]) * 60);
    for (const TrackedMode& m : result.modes)
      out << ',' << csv_number(m.frequency_hz[i]) << ',' << csv_number(m.damping_ratio[i]);
    out << detail::operating_csv_row(result.operating, i) << '\n';
  }
  return out.str();
}

std::string CampbellAnalysis::terminal(const Outcome<CampbellAnalysis>& o) {
  const CampbellResult& result = o.result;
  const CampbellOptions& options = o.options;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  std::string out = source_line("campbell", source);
  const std::size_t n = result.speeds.size();
  if (n == 0) return out + "no speed could be solved\n";
  out += fmt::format("{} speeds from {} to {}, {} modes tracked, solver {}, {} eigen solves\n\n", n,
                     speed_text(result.speeds.front(), source.speed_unit),
                     speed_text(result.speeds.back(), source.speed_unit), result.modes.size(),
                     to_string(result.info.method), result.n_solves);

  // Frequencies at (at most) 11 evenly spread speeds of the grid.
  const std::size_t rows = std::min<std::size_t>(n, 11);
  auto row_index = [&](std::size_t r) { return rows == 1 ? 0 : r * (n - 1) / (rows - 1); };
  auto table = [&](const char* title, auto value, const char* spec) {
    out += fmt::format("{}\n{:>11}", title, speed_header(source.speed_unit));
    // Each column as wide as its label ("backward cylindrical 1"), at least 12.
    const auto width = [](const TrackedMode& m) {
      return std::max<int>(12, static_cast<int>(printable(m.label).size()));
    };
    for (const TrackedMode& m : result.modes) out += fmt::format(" {:>{}}", printable(m.label), width(m));
    out += '\n';
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t i = row_index(r);
      out += source.speed_unit == "rpm" ? cell(speed_value(result.speeds[i], "rpm"), ".1f", 11, 1)
                                        : cell(rad_to_hz(result.speeds[i]), ".2f", 11, 2);
      for (const TrackedMode& m : result.modes) {
        out += ' ';
        out += cell(value(m, i), spec, width(m), 3);
      }
      out += '\n';
    }
    out += '\n';
  };
  const std::string& unit = source.speed_unit;
  table(
      fmt::format("Natural frequencies [{}]", frequency_unit(unit)).c_str(),
      [&](const TrackedMode& m, std::size_t i) { return frequency_value(m.frequency_hz[i], unit); },
      unit == "rpm" ? ".1f" : ".3f");
  table(
      "Damping ratios [%]", [](const TrackedMode& m, std::size_t i) { return 100.0 * m.damping_ratio[i]; }, ".3f");

  std::vector<std::string> orders;
  for (int k : options.orders) orders.push_back(std::to_string(k));
  out += fmt::format("Critical speeds (frequency = k x speed, k = {}):\n", fmt::join(orders, ", "));
  if (result.critical_speeds.empty()) out += "  none in the speed range\n";
  for (const CriticalSpeed& c : result.critical_speeds)
    out += fmt::format("  {:<24} k = {}  at {}\n", result.modes[static_cast<std::size_t>(c.mode)].label, c.order,
                       speed_text(c.speed, source.speed_unit));
  out += "\nStability threshold: ";
  if (!result.stability_threshold) {
    out += fmt::format("none up to {} (every damping ratio stays >= 0)\n",
                       speed_text(result.speeds.back(), source.speed_unit));
  } else {
    const StabilityThreshold& t = *result.stability_threshold;
    const std::string label = threshold_label(result, t);
    if (t.unstable_at_start)
      out +=
          fmt::format("{} is already unstable at the first speed, {}\n", label, speed_text(t.speed, source.speed_unit));
    else if (t.divergence)
      out += fmt::format(
          "{}: a real eigenvalue turns positive (divergence: the stiffness loses its positivity, "
          "a negative support stiffness or an axial load beyond buckling)\n",
          speed_text(t.speed, source.speed_unit));
    else
      out += fmt::format("{}: {} becomes unstable (damping ratio < 0) at {} natural frequency\n",
                         speed_text(t.speed, source.speed_unit), label, frequency_text(t.frequency_hz, unit));
  }
  out += operating_tables(result.operating, model, "at the equilibrium", speed_header(source.speed_unit),
                          [&](std::size_t k) { return speed_number(result.speeds[k], source.speed_unit); });
  if (!result.info.converged()) out += fmt::format("\nwarning: {}\n", result.info.message);
  return out;
}

// ---- study quantities ----------------------------------------------------------------

namespace {

// The critical speeds a quantity selects, in increasing order, within [low, high].
std::vector<Real> selected_criticals(const CampbellResult& c, const QuantitySpec& q, Real low, Real high) {
  std::vector<Real> out;
  for (const auto& x : c.critical_speeds) {
    const auto& mode = c.modes[static_cast<std::size_t>(x.mode)];
    if (mode.type != ModeType::lateral || x.order != q.order || !selected(x.whirl, q.whirl)) continue;
    if (x.speed >= low && x.speed <= high) out.push_back(x.speed);
  }
  std::sort(out.begin(), out.end());
  return out;
}

Real smallest_damping(const CampbellResult& c, const QuantitySpec& q, Real low, Real high, bool log_decrement) {
  Real smallest = std::numeric_limits<Real>::infinity();
  for (const auto& mode : c.modes) {
    if (mode.type != ModeType::lateral) continue;
    for (std::size_t k = 0; k < c.speeds.size(); ++k) {
      if (c.speeds[k] < low || c.speeds[k] > high || !selected(mode.whirl_at[k], q.whirl)) continue;
      const Real d = log_decrement ? mode.log_decrement[k] : mode.damping_ratio[k];
      if (std::isfinite(d)) smallest = std::min(smallest, d);
    }
  }
  if (!std::isfinite(smallest))
    throw Error(fmt::format("no {}lateral mode between {} and {}", whirl_word(q.whirl), rpm(low), rpm(high)));
  return smallest;
}

Real critical_speed(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const CampbellResult& c = a.result<CampbellAnalysis>();
  const Real low = q.low.value_or(c.speeds.front()), high = q.high.value_or(c.speeds.back());
  const auto criticals = selected_criticals(c, q, low, high);
  if (static_cast<int>(criticals.size()) < q.n)
    throw Error(fmt::format("no {} {}critical speed of order {} between {} and {} (found {})", ordinal(q.n),
                            whirl_word(q.whirl), q.order, rpm(low), rpm(high), criticals.size()));
  return criticals[static_cast<std::size_t>(q.n - 1)];
}

Real campbell_separation_margin(DesignAnalyses& a, const QuantitySpec& q, std::string& clipped) {
  const CampbellResult& c = a.result<CampbellAnalysis>();
  const Real low = q.low.value_or(c.speeds.front()), high = q.high.value_or(c.speeds.back());
  // Critical speeds beyond the analysed range are unknown but at least as far
  // away as its ends: the margin of the ends bounds theirs.
  Real margin = std::min(separation_margin(low, q.operating_low, q.operating_high),
                         separation_margin(high, q.operating_low, q.operating_high));
  if (low <= 0) margin = separation_margin(high, q.operating_low, q.operating_high);
  Real nearest = std::numeric_limits<Real>::infinity();
  for (const Real s : selected_criticals(c, q, low, high))
    nearest = std::min(nearest, separation_margin(s, q.operating_low, q.operating_high));
  if (!(nearest <= margin))
    clipped = fmt::format(
        "a lower bound: no {}critical speed of order {} between {} and {} lies nearer the "
        "operating range than the range's {}; widen the Campbell range to find the margin",
        whirl_word(q.whirl), q.order, rpm(low), rpm(high), low > 0 ? "ends" : "end");
  return std::min(margin, nearest);
}

template <bool log_decrement>
Real min_damping(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const CampbellResult& c = a.result<CampbellAnalysis>();
  return smallest_damping(c, q, q.low.value_or(c.speeds.front()), q.high.value_or(c.speeds.back()), log_decrement);
}

Real stability_threshold(DesignAnalyses& a, const QuantitySpec&, std::string& clipped) {
  const CampbellResult& c = a.result<CampbellAnalysis>();
  // None in the range: the threshold lies above it; its end is a lower bound.
  if (c.stability_threshold) return c.stability_threshold->speed;
  clipped = fmt::format(
      "a lower bound: the rotor is stable up to the Campbell range's end, {}; widen the range to "
      "find the threshold",
      rpm(c.speeds.back()));
  return c.speeds.back();
}

template <bool smallest>
Real bearing_value(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  // Over the Campbell diagram's speeds within the range: each bearing's state at
  // the equilibrium about which the diagram linearises it.
  const CampbellResult& c = a.result<CampbellAnalysis>();
  const Real low = q.low.value_or(c.speeds.front()), high = q.high.value_or(c.speeds.back());
  std::vector<BearingValues> bearings;
  for (const OperatingSeries& s : c.operating) {
    BearingValues& b = bearings.emplace_back();
    b.label = a.model().forces[static_cast<std::size_t>(s.force)].label();
    b.quantities = s.quantities;
    const std::vector<Real> values = s.series(q.value);
    for (std::size_t k = 0; k < values.size(); ++k)
      if (c.speeds[k] >= low && c.speeds[k] <= high) b.values.push_back(values[k]);
  }
  return extreme_bearing_value(q, smallest, bearings, fmt::format(" between {} and {}", rpm(low), rpm(high)));
}

}  // namespace

const std::vector<QuantityRow>& CampbellAnalysis::quantities() {
  static const std::vector<QuantityRow> rows = {
      {.name = "critical_speed",
       .doc = "the n-th critical speed of a whirl and order in a speed range",
       .analysis = name,
       .unit = Quantity::speed,
       .evaluate = critical_speed},
      {.name = "separation_margin",
       .doc = "smallest relative distance of the critical speeds from the operating range",
       .analysis = name,
       .evaluate = campbell_separation_margin,
       .needs_operating = true},
      {.name = "min_damping_ratio",
       .doc = "smallest damping ratio of the lateral modes over a speed range",
       .analysis = name,
       .evaluate = min_damping<false>,
       .any_whirl = true},
      {.name = "min_log_decrement",
       .doc = "smallest logarithmic decrement over a speed range",
       .analysis = name,
       .evaluate = min_damping<true>,
       .any_whirl = true},
      {.name = "stability_threshold",
       .doc = "lowest speed where a mode's damping turns negative",
       .analysis = name,
       .unit = Quantity::speed,
       .evaluate = stability_threshold},
      {.name = "min_bearing_value",
       .doc = "smallest value of a bearing's operating quantity over the Campbell speeds",
       .analysis = name,
       .evaluate = bearing_value<true>,
       .bearing_value = true},
      {.name = "max_bearing_value",
       .doc = "largest value of it",
       .analysis = name,
       .evaluate = bearing_value<false>,
       .bearing_value = true},
  };
  return rows;
}

}  // namespace feran
