#pragma once
// Lookups into a Campbell result by mode label, shared by the paper tests.

#include <limits>
#include <stdexcept>
#include <string>

#include <feran/analyses/modal/campbell.hpp>

namespace feran::test {

/// The tracked mode labelled @p label; throws when there is none.
inline const TrackedMode& mode(const CampbellResult& r, const std::string& label) {
  for (const TrackedMode& m : r.modes)
    if (m.label == label) return m;
  throw std::runtime_error("no mode " + label);
}

/// The first-order critical speed [Hz] of the mode labelled @p label; NaN when none.
inline Real critical_hz(const CampbellResult& r, const std::string& label) {
  for (const CriticalSpeed& c : r.critical_speeds)
    if (r.modes[static_cast<std::size_t>(c.mode)].label == label && c.order == 1) return rad_to_hz(c.speed);
  return std::numeric_limits<Real>::quiet_NaN();
}

}  // namespace feran::test
