#pragma once
// Lookups into a Campbell result by the papers' mode names ("forward 1": the first
// forward mode, whirl_name()), shared by the paper tests.

#include <limits>
#include <stdexcept>
#include <string>

#include <feran/analyses/campbell/campbell.hpp>

namespace feran::test {

/// The tracked mode named @p name by its whirl; throws when there is none.
inline const TrackedMode& mode(const CampbellResult& r, const std::string& name) {
  for (std::size_t i = 0; i < r.modes.size(); ++i)
    if (whirl_name(r, static_cast<Index>(i)) == name) return r.modes[i];
  throw std::runtime_error("no mode " + name);
}

/// The first-order critical speed [Hz] of the mode named @p name by its whirl; NaN
/// when none.
inline Real critical_hz(const CampbellResult& r, const std::string& name) {
  for (const CriticalSpeed& c : r.critical_speeds)
    if (whirl_name(r, c.mode) == name && c.order == 1) return rad_to_hz(c.speed);
  return std::numeric_limits<Real>::quiet_NaN();
}

}  // namespace feran::test
