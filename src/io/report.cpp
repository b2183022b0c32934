#include <feran/io/report.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace feran {

namespace {

std::string source_line(const char* analysis, const ResultSource& source) {
  if (source.title.empty()) return fmt::format("feran {}: {}\n", analysis, source.model_path);
  return fmt::format("feran {}: {} ({})\n", analysis, source.title, source.model_path);
}

std::string speed_text(Real speed) {
  return fmt::format("{:.4g} Hz ({:.6g} rpm)", rad_to_hz(speed), rad_to_hz(speed) * 60.0);
}

// A right-aligned number; "-" when it does not exist. Values that would print as
// "-0.000" print as "0.000".
std::string cell(Real x, const char* format_spec, int width, int decimals) {
  if (!std::isfinite(x)) return fmt::format("{:>{}}", "-", width);
  if (std::abs(x) < 0.5 * std::pow(10.0, -decimals)) x = 0.0;
  return fmt::format(fmt::runtime(fmt::format("{{:>{}{}}}", width, format_spec)), x);
}

}  // namespace

std::string modal_report(const ModalResult& result, const Model& model, const ResultSource& source) {
  std::string out = source_line("modal", source);
  out += fmt::format("speed {}, {} modes, solver {}\n\n", speed_text(result.speed), result.modes.size(),
                     result.info.method);
  (void)model;
  out += fmt::format("{:>4}  {:>14}  {:>12}  {:>10}  {:<9} {:>11}  {:<10} {}\n", "mode", "frequency [Hz]",
                     "damping [%]", "log. decr.", "whirl", "directivity", "type", "note");
  int index = 0;
  for (const Mode& m : result.modes) {
    const char* note = m.rigid_body ? "rigid body" : (!m.oscillatory ? "non-oscillatory" : "");
    out += fmt::format("{:>4}  {}  {}  {}  {:<9} {}  {:<10} {}\n", ++index, cell(m.frequency_hz, ".4f", 14, 4),
                       cell(100.0 * m.damping_ratio, ".3f", 12, 3), cell(m.log_decrement, ".4f", 10, 4),
                       to_string(m.whirl), cell(m.directivity, ".3f", 11, 3), to_string(m.type), note);
  }
  if (!result.info.converged) out += fmt::format("\nwarning: {}\n", result.info.message);
  return out;
}

std::string campbell_report(const CampbellResult& result, const CampbellOptions& options,
                            const Model& model, const ResultSource& source) {
  (void)model;
  std::string out = source_line("campbell", source);
  const std::size_t n = result.speeds.size();
  if (n == 0) return out + "no speed could be solved\n";
  out += fmt::format("{} speeds from {} to {}, {} modes tracked, solver {}, {} eigen solves\n\n", n,
                     speed_text(result.speeds.front()), speed_text(result.speeds.back()),
                     result.modes.size(), result.info.method, result.n_solves);

  // Frequencies at (at most) 11 evenly spread speeds of the grid.
  const std::size_t rows = std::min<std::size_t>(n, 11);
  auto row_index = [&](std::size_t r) { return rows == 1 ? 0 : r * (n - 1) / (rows - 1); };
  auto table = [&](const char* title, auto value, const char* spec) {
    out += fmt::format("{}\n{:>11}", title, "speed [Hz]");
    for (const TrackedMode& m : result.modes) out += fmt::format(" {:>12}", m.label);
    out += '\n';
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t i = row_index(r);
      out += cell(rad_to_hz(result.speeds[i]), ".2f", 11, 2);
      for (const TrackedMode& m : result.modes) {
        out += ' ';
        out += cell(value(m, i), spec, 12, 3);
      }
      out += '\n';
    }
    out += '\n';
  };
  table("Natural frequencies [Hz]", [](const TrackedMode& m, std::size_t i) { return m.frequency_hz[i]; },
        ".3f");
  table("Damping ratios [%]", [](const TrackedMode& m, std::size_t i) { return 100.0 * m.damping_ratio[i]; },
        ".3f");

  std::vector<std::string> orders;
  for (int k : options.orders) orders.push_back(std::to_string(k));
  out += fmt::format("Critical speeds (frequency = k x speed, k = {}):\n", fmt::join(orders, ", "));
  if (result.critical_speeds.empty()) out += "  none in the speed range\n";
  for (const CriticalSpeed& c : result.critical_speeds)
    out += fmt::format("  {:<14} k = {}  at {}\n", result.modes[static_cast<std::size_t>(c.mode)].label,
                       c.order, speed_text(c.speed));
  out += "\nStability threshold: ";
  if (!result.stability_threshold) {
    out += fmt::format("none up to {} (every damping ratio stays >= 0)\n", speed_text(result.speeds.back()));
  } else {
    const StabilityThreshold& t = *result.stability_threshold;
    const std::string& label = result.modes[static_cast<std::size_t>(t.mode)].label;
    if (t.unstable_at_start)
      out += fmt::format("{} is already unstable at the first speed, {}\n", label, speed_text(t.speed));
    else
      out += fmt::format("{}: {} becomes unstable (damping ratio < 0) at {:.4g} Hz natural frequency\n",
                         speed_text(t.speed), label, t.frequency_hz);
  }
  if (!result.info.converged) out += fmt::format("\nwarning: {}\n", result.info.message);
  return out;
}

}  // namespace feran
