#include <feran/io/option_text.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/core/units.hpp>
#include <feran/io/node_reference.hpp>
#include <feran/spec/request.hpp>

namespace feran {

Real parse_speed_text(const std::string& text, const std::string& what) {
  return spec::detail::quantity_text(text, Quantity::speed, what);
}

Real parse_time_text(const std::string& text, const std::string& what) {
  try {
    const Real t = parse_quantity(text, Quantity::time);
    if (!(t > 0)) throw Error("must be positive");
    return t;
  } catch (const Error& e) {
    throw Error(fmt::format("{} '{}': {} (a time such as 5s or 0.1ms)", what, text, e.what()));
  }
}

HarmonicForce parse_force_text(const Model& model, const std::string& text, const std::string& what) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == ':') {
      parts.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  if (parts.size() < 3 || parts.size() > 4)
    throw Error(
        fmt::format("{} '{}': expected NODE:DIRECTION:AMPLITUDE[:PHASE], e.g. rotor:y:10N or "
                    "rotor:rotating:2N:90deg",
                    what, text));
  HarmonicForce f;
  f.node = find_node_reference(model, parts[0], what);
  const std::string& dir = parts[1];
  static const std::pair<const char*, Dof> dirs[] = {{"x", Dof::u},   {"y", Dof::v},   {"z", Dof::w},
                                                     {"rx", Dof::rx}, {"ry", Dof::ry}, {"rz", Dof::rz}};
  bool moment = false;
  if (dir == "rotating") {
    f.type = HarmonicForce::Kind::rotating_force;
  } else if (dir == "rotating_moment") {
    f.type = HarmonicForce::Kind::rotating_moment;
    moment = true;
  } else {
    const auto* it = std::find_if(std::begin(dirs), std::end(dirs), [&](const auto& p) { return dir == p.first; });
    if (it == std::end(dirs))
      throw Error(
          fmt::format("{} '{}': direction '{}' is not one of x, y, z, rx, ry, rz, rotating, "
                      "rotating_moment",
                      what, text, dir));
    f.direction = it->second;
    moment = f.direction == Dof::rx || f.direction == Dof::ry || f.direction == Dof::rz;
  }
  try {
    f.amplitude = parse_quantity(parts[2], moment ? Quantity::moment : Quantity::force);
    if (parts.size() == 4) f.phase = parse_quantity(parts[3], Quantity::angle);
  } catch (const Error& e) {
    throw Error(fmt::format("{} '{}': {}", what, text, e.what()));
  }
  if (!(f.amplitude > 0)) throw Error(fmt::format("{} '{}': the amplitude must be positive", what, text));
  return f;
}

EigenSolver parse_solver_name(const std::string& name, const std::string& what) {
  if (name == "auto") return EigenSolver::automatic;
  if (name == "dense") return EigenSolver::dense;
  if (name == "sparse") return EigenSolver::sparse;
  throw Error(fmt::format("{} '{}': expected auto, dense or sparse", what, name));
}

}  // namespace feran
