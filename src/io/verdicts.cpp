#include "verdicts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

namespace feran::detail {

namespace {

using nlohmann::json;

// A section the report ran: present and without an error.
const json* section(const json& data, const char* name) {
  if (!data.contains(name)) return nullptr;
  const json& s = data.at(name);
  if (!s.is_object() || s.contains("error")) return nullptr;
  return &s;
}

std::string section_error(const json& data, const char* name) {
  if (data.contains(name) && data.at(name).is_object() && data.at(name).contains("error"))
    return data.at(name).at("error").get<std::string>();
  return {};
}

bool number(const json& j) { return j.is_number(); }

class Speeds {
 public:
  explicit Speeds(std::string unit) : unit_(std::move(unit)) {}
  std::string operator()(double rpm) const {
    return unit_ == "Hz" ? fmt::format("{:.4g} Hz", rpm / 60) : fmt::format("{:.5g} rpm", rpm);
  }

 private:
  std::string unit_;
};

Verdict not_checked(std::string check, std::string reason) {
  return {std::move(check), "not checked", nullptr, "", std::move(reason)};
}

Verdict stability(const json& data, const Speeds& speed) {
  const std::string check = "stability in the operating range";
  const json* campbell = section(data, "campbell");
  const json* threshold =
      campbell && campbell->contains("stability_threshold") && campbell->at("stability_threshold").is_object()
          ? &campbell->at("stability_threshold")
          : nullptr;
  if (const json* api = section(data, "api684"); api && api->contains("operating_stability")) {
    const json& v = api->at("operating_stability");
    double worst = -std::numeric_limits<double>::infinity();
    for (const json& g : v.at("growth_rate_per_s"))
      if (number(g)) worst = std::max(worst, g.get<double>());
    return {check, v.at("passes").get<bool>() ? "pass" : "FAIL", std::isfinite(worst) ? json(worst) : json(nullptr),
            "1/s (largest growth rate)", v.at("reason").get<std::string>()};
  }
  if (!data.contains("operating") || !data.at("operating").is_object()) {
    std::string reason = "no operating range: give [api684] min_speed and max_speed";
    if (threshold)
      reason += fmt::format(" (the Campbell diagram finds the rotor unstable from {}, {})",
                            speed(threshold->at("speed_rpm").get<double>()), threshold->at("mode").get<std::string>());
    return {check, "not checked", threshold ? threshold->at("speed_rpm") : json(nullptr), threshold ? "rpm" : "",
            reason};
  }
  const double high = data.at("operating").at("max_rpm").get<double>();
  if (!campbell) return not_checked(check, "the Campbell diagram failed: " + section_error(data, "campbell"));
  if (threshold && threshold->at("speed_rpm").get<double>() <= high)
    return {check, "FAIL", threshold->at("speed_rpm"), "rpm",
            fmt::format("the Campbell diagram's stability threshold, {} ({}), lies below the maximum continuous "
                        "speed {}",
                        speed(threshold->at("speed_rpm").get<double>()), threshold->at("mode").get<std::string>(),
                        speed(high))};
  const double last = campbell->at("speeds_hz").back().get<double>() * 60;
  if (last < high)
    return not_checked(check, fmt::format("the Campbell diagram stops at {}, below the maximum continuous speed {}: "
                                          "the rest of the range was not analysed",
                                          speed(last), speed(high)));
  return {check, "pass", threshold ? threshold->at("speed_rpm") : json(nullptr), threshold ? "rpm" : "",
          threshold
              ? fmt::format("the stability threshold, {}, lies above the maximum continuous speed {}",
                            speed(threshold->at("speed_rpm").get<double>()), speed(high))
              : fmt::format("no mode loses its damping up to {} (the Campbell diagram's last speed)", speed(last))};
}

// The peaks judged against the operating range: API 684's unbalance cases when they
// ran, else the report's own response.
struct Peak {
  double speed_rpm = 0, af = std::numeric_limits<double>::quiet_NaN(), actual = 0;
  std::optional<double> required;
  std::optional<bool> passes;
  bool unstable = false;
  std::string where;
};

std::vector<Peak> peaks(const json& data, std::string& source) {
  std::vector<Peak> out;
  auto read = [&](const json& p, std::string where) {
    Peak k;
    k.speed_rpm = p.at("speed_rpm").get<double>();
    if (number(p.at("amplification_factor"))) k.af = p.at("amplification_factor").get<double>();
    k.actual = p.at("actual_margin").get<double>();
    if (number(p.at("required_margin"))) k.required = p.at("required_margin").get<double>();
    if (p.at("passes").is_boolean()) k.passes = p.at("passes").get<bool>();
    k.unstable = p.value("unstable", false);
    k.where = std::move(where);
    out.push_back(std::move(k));
  };
  if (const json* api = section(data, "api684"); api && !api->at("cases").empty()) {
    source = "the API 684 unbalance cases";
    for (const json& c : api->at("cases"))
      for (const json& probe : c.at("probes"))
        for (const json& p : probe.at("peaks"))
          read(p,
               fmt::format("{}, {}", c.at("name").get<std::string>(),
                           probe.value("name", std::string()).empty() ? fmt::format("node {}", probe.at("node").dump())
                                                                      : probe.at("name").get<std::string>()));
    return out;
  }
  if (const json* response = section(data, "response"); response && response->contains("peaks")) {
    source = "the unbalance response";
    const json& probes = response->at("probes");
    for (const json& p : response->at("peaks")) {
      const json& probe = probes.at(p.at("probe").get<std::size_t>());
      read(p, probe.value("name", std::string()).empty() ? fmt::format("node {}", probe.at("node").dump())
                                                         : probe.at("name").get<std::string>());
    }
  }
  return out;
}

std::vector<Verdict> margins(const json& data, const Speeds& speed) {
  const std::string separation = "separation margins", amplification = "amplification factors";
  if (!data.contains("operating") || !data.at("operating").is_object())
    return {not_checked(separation, "no operating range: give [api684] min_speed and max_speed"),
            not_checked(amplification, "no operating range: give [api684] min_speed and max_speed")};
  std::string source;
  const std::vector<Peak> all = peaks(data, source);
  if (source.empty()) {
    const std::string why = section_error(data, "response").empty()
                                ? "no unbalance response: the model has no unbalance or harmonic force"
                                : "the unbalance response failed: " + section_error(data, "response");
    return {not_checked(separation, why), not_checked(amplification, why)};
  }
  const double low = data.at("operating").at("min_rpm").get<double>();
  const double high = data.at("operating").at("max_rpm").get<double>();
  std::vector<Verdict> out;
  // Separation: the judged peak with the least surplus of margin (a failing one first).
  const Peak* worst = nullptr;
  int judged = 0;
  auto surplus = [](const Peak& p) { return p.unstable ? -1e300 : p.actual - p.required.value_or(0.0); };
  for (const Peak& p : all) {
    if (!p.passes) continue;
    ++judged;
    if (!worst || surplus(p) < surplus(*worst)) worst = &p;
  }
  if (!worst) {
    out.push_back({separation, "pass", nullptr, "",
                   fmt::format("no resonance peak that can be judged in {} ({} peaks without half-power points)",
                               source, all.size())});
  } else if (!*worst->passes) {
    out.push_back({separation, "FAIL", 100 * worst->actual, "%",
                   worst->unstable
                       ? fmt::format("the peak at {} ({}) lies where the rotor is unstable: no steady state",
                                     speed(worst->speed_rpm), worst->where)
                       : fmt::format("the peak at {} ({}, amplification factor {:.3g}) is {:.1f} % from the operating "
                                     "range; API 684 requires {:.1f} %",
                                     speed(worst->speed_rpm), worst->where, worst->af, 100 * worst->actual,
                                     100 * worst->required.value_or(0.0))});
  } else {
    out.push_back({separation, "pass", 100 * worst->actual, "%",
                   fmt::format("{} peaks of {} judged; the closest to its limit, at {} ({}), is {:.1f} % from the "
                               "range where {:.1f} % is required",
                               judged, source, speed(worst->speed_rpm), worst->where, 100 * worst->actual,
                               100 * worst->required.value_or(0.0))});
  }
  // Amplification: a resonance with AF ≥ 2.5 inside the operating range fails.
  const Peak* largest = nullptr;
  const Peak* inside = nullptr;
  for (const Peak& p : all) {
    if (std::isnan(p.af)) continue;
    if (!largest || p.af > largest->af) largest = &p;
    if (p.af >= 2.5 && p.speed_rpm >= low && p.speed_rpm <= high && (!inside || p.af > inside->af)) inside = &p;
  }
  if (!largest)
    out.push_back({amplification, "pass", nullptr, "",
                   fmt::format("no resonance peak with an amplification factor in {}", source)});
  else if (inside)
    out.push_back({amplification, "FAIL", inside->af, "",
                   fmt::format("a resonance with amplification factor {:.3g} (≥ 2.5) at {} ({}) lies inside the "
                               "operating range",
                               inside->af, speed(inside->speed_rpm), inside->where)});
  else
    out.push_back({amplification, "pass", largest->af, "",
                   fmt::format("no resonance with amplification factor ≥ 2.5 inside the operating range; the "
                               "largest, {:.3g}, at {} ({})",
                               largest->af, speed(largest->speed_rpm), largest->where)});
  return out;
}

std::vector<Verdict> bearings(const json& data, const Speeds& speed) {
  const std::string loads = "bearing loads", film = "minimum film thickness";
  const json* statics = section(data, "static");
  if (!statics) {
    const std::string why = section_error(data, "static").empty()
                                ? "no static analysis in this report"
                                : "the static analysis failed: " + section_error(data, "static");
    return {not_checked(loads, why), not_checked(film, why)};
  }
  const std::string at =
      fmt::format("at the static equilibrium at {}{}", speed(statics->at("speed_hz").get<double>() * 60),
                  statics->contains("stability") && statics->at("stability").value("unstable", false) == true
                      ? ", which is unstable"
                      : "");
  // Each bearing's use of its limit: specific load (journals) or contact stress
  // (balls); the most used decides.
  double worst_use = -1, worst_value = 0, worst_limit = 0;
  std::string worst_name, worst_unit, worst_what;
  double thinnest_margin = std::numeric_limits<double>::infinity(), thinnest = 0, thinnest_limit = 0;
  std::string thinnest_name;
  int journals = 0, rolling = 0;
  for (const json& s : statics->at("supports")) {
    if (!s.contains("operating")) continue;
    const json& o = s.at("operating");
    const std::string name = s.value("label", std::string("bearing"));
    auto consider = [&](const char* value, const char* limit, double scale, const char* unit, const char* what) {
      if (!o.contains(value) || !number(o.at(value)) || !o.contains(limit) || !number(o.at(limit))) return;
      const double v = o.at(value).get<double>(), l = o.at(limit).get<double>();
      if (v / l > worst_use)
        worst_use = v / l, worst_value = v * scale, worst_limit = l * scale, worst_name = name, worst_unit = unit,
        worst_what = what;
    };
    if (o.contains("specific_load_pa")) {
      ++journals;
      consider("specific_load_pa", "specific_load_limit_pa", 1e-6, "MPa", "unit load W/(L·D)");
      if (number(o.at("min_film_thickness_m")) && number(o.at("min_film_limit_m"))) {
        const double h = o.at("min_film_thickness_m").get<double>(), l = o.at("min_film_limit_m").get<double>();
        if (h / l < thinnest_margin) thinnest_margin = h / l, thinnest = h, thinnest_limit = l, thinnest_name = name;
      }
    } else if (o.contains("max_contact_stress_pa")) {
      ++rolling;
      consider("max_contact_stress_pa", "contact_stress_limit_pa", 1e-6, "MPa", "largest Hertz contact stress");
    }
  }
  std::vector<Verdict> out;
  if (journals + rolling == 0)
    out.push_back(not_checked(loads,
                              "the rotor rests on springs, not on journal or rolling bearings: no bearing "
                              "model gives loads to judge"));
  else if (worst_use < 0)
    out.push_back(not_checked(loads,
                              "no bearing gives a limit to judge its load by (roller bearings: the contact "
                              "stress is not modelled)"));
  else
    out.push_back({loads, worst_use <= 1 ? "pass" : "FAIL", worst_value, worst_unit,
                   fmt::format("{}: {} {:.4g} {} against the limit {:.4g} {} ({}) {}", worst_name, worst_what,
                               worst_value, worst_unit, worst_limit, worst_unit,
                               worst_what[0] == 'u' ? "Trumpler, 300 psi" : "ISO 76, permanent dents beyond it", at)});
  if (journals == 0)
    out.push_back(not_checked(film, "no journal bearing"));
  else if (!std::isfinite(thinnest_margin))
    out.push_back(not_checked(film, "no journal bearing gives its film thickness"));
  else
    out.push_back({film, thinnest_margin >= 1 ? "pass" : "FAIL", thinnest * 1e6, "µm",
                   fmt::format("{}: {:.4g} µm against Trumpler's lower limit 5.08 µm + 4e-5·D = {:.4g} µm {}",
                               thinnest_name, thinnest * 1e6, thinnest_limit * 1e6, at)});
  return out;
}

}  // namespace

std::vector<Verdict> report_verdicts(const json& data, const std::string& speed_unit) {
  const Speeds speed(speed_unit);
  std::vector<Verdict> out{stability(data, speed)};
  for (Verdict& v : margins(data, speed)) out.push_back(std::move(v));
  for (Verdict& v : bearings(data, speed)) out.push_back(std::move(v));
  // A report stopped on request judged part of its range: a failure found stands, a
  // pass does not.
  if (!data.value("complete", true))
    for (Verdict& v : out)
      if (v.status == "pass")
        v = not_checked(v.check, "the report was stopped on request before its analyses were complete; " + v.reason);
  return out;
}

json verdicts_json(const std::vector<Verdict>& verdicts) {
  json out = json::array();
  for (const Verdict& v : verdicts)
    out.push_back(
        {{"check", v.check}, {"status", v.status}, {"value", v.value}, {"unit", v.unit}, {"reason", v.reason}});
  return out;
}

std::string verdicts_text(const std::vector<Verdict>& verdicts) {
  std::string out;
  for (const Verdict& v : verdicts) out += fmt::format("  {:<34} {:<12} {}\n", v.check, v.status, v.reason);
  return out;
}

}  // namespace feran::detail
