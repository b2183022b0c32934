#pragma once
/// @file
/// Analysis options written as text — on a command line (`--speed 30Hz`) or as
/// keywords of the Python module (`speed="30 Hz"`) — parsed into SI values with the
/// same rules and messages for every caller. @p what names the option in messages
/// ("--start", "start").

#include <string>
#include <utility>
#include <vector>

#include <feran/analyses/modal/modal.hpp>
#include <feran/core/types.hpp>
#include <feran/forces/harmonic_force.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// A speed with its unit ("30Hz", "1800 rpm", "188.5rad/s") in rad/s, within the
/// physical range of a speed; throws Error naming @p what otherwise.
Real parse_speed_text(const std::string& text, const std::string& what);

/// A positive time with its unit ("5s", "0.1ms") in s; throws Error naming @p what.
Real parse_time_text(const std::string& text, const std::string& what);

/// A harmonic force "NODE:DIRECTION:AMPLITUDE[:PHASE]" ("rotor:y:10N",
/// "3:rotating:2N:90deg"): DIRECTION x, y, z, rx, ry, rz (fixed in space), rotating
/// or rotating_moment (turning with the shaft); the amplitude positive, a force or a
/// moment as the direction says.
HarmonicForce parse_force_text(const Model& model, const std::string& text, const std::string& what);

/// The eigen solver named "auto", "dense" or "sparse"; throws Error otherwise.
EigenSolver parse_solver_name(const std::string& name, const std::string& what);

}  // namespace feran
