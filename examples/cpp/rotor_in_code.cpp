// A rotor built in code: the first C++ tutorial program of feran.
//
// This program does, from C++, what a model file and the `feran` command do from the
// shell: it describes a rotor as a ModelSpec, builds the Model, computes a Campbell
// diagram with its critical speeds, changes one design parameter by its path, and
// computes the unbalance response. It is read from top to bottom; the comments say
// why each step is there. It is built against the installed library exactly as any
// other project would build it (CMakeLists.txt beside it):
//
//     find_package(feran REQUIRED)
//     target_link_libraries(rotor_in_code PRIVATE feran::feran)
//
// The rotor is the Jeffcott rotor: a disk of mass m at the middle of a massless
// clamped–clamped shaft of length L and diameter d. At mid-span the disk's
// translation and tilt decouple, so its first forward critical speed is exactly
// √(k/m) with the shaft's stiffness k = 192·E·I/L³ (Euler–Bernoulli), whatever the
// disk's polar inertia — a closed form to hold the numbers against.

// @sect3{Include files}
//
// One header per part of the library: the specification and its parameter paths
// (spec/), the builder, and the analysis settings that resolve a request against
// the built-in defaults (analyses/settings.hpp, also used by the command line).
#include <feran/analyses/response/analysis.hpp>
#include <feran/analyses/campbell/analysis.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/spec/build_model.hpp>
#include <feran/spec/parameters.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

using namespace feran;

namespace {

// @sect3{The specification}
//
// A ModelSpec says what a model file says, table for table: materials, shafts made
// of sections, rigid bodies, springs, fixed DOFs, unbalances. Quantities are SI
// (m, kg, N, rad/s). Nothing is checked here; build_model() checks everything and
// reports a problem with a path into the spec, such as
// "shafts[0].sections[1].length".
ModelSpec jeffcott_rotor() {
  ModelSpec spec;
  spec.title = "Jeffcott rotor, built in code";
  // Euler–Bernoulli elements, so that the closed form above applies exactly.
  spec.options.shear_deformation = false;

  // A massless steel shaft: all the mass sits in the disk.
  spec.materials.push_back({.name = "massless steel", .E = 210e9, .G = {}, .nu = 0.3, .rho = 0.0, .loss_factor = 0.0});

  // One shaft of two sections of 250 mm each; naming the nodes lets the other
  // tables refer to them by name ("left", "disk", "right").
  ShaftSpec shaft;
  shaft.name = "shaft";
  shaft.material = "massless steel";
  shaft.start_node = "left";
  for (const char* end : {"disk", "right"})
    shaft.sections.push_back({.length = 0.25,
                              .outer_diameter = 0.012,
                              .inner_diameter = 0.0,
                              .material = {},
                              .elements = 1,
                              .end_node = end});
  spec.shafts.push_back(shaft);

  // The disk: mass, transverse and polar moments of inertia about its node.
  RigidBodySpec disk;
  disk.name = "disk";
  disk.node = std::string("disk");
  disk.mass = 5.0;
  disk.Ja = 0.02;
  disk.Jp = 0.04;
  spec.rigid_bodies.push_back(disk);

  // A squeeze-film damper at the disk: damping only (no stiffness), so that the
  // response at the critical speed stays finite.
  SpringSpec damper;
  damper.name = "damper";
  damper.node = std::string("disk");
  damper.coefficients[spring::cy] = SpeedCoefficient(20.0);  // [N s/m]
  damper.coefficients[spring::cz] = SpeedCoefficient(20.0);
  spec.springs.push_back(damper);

  // Both shaft ends clamped (an empty list of DOFs holds all six).
  spec.fixed.push_back({.node = std::string("left"), .dofs = {}});
  spec.fixed.push_back({.node = std::string("right"), .dofs = {}});

  // 1 g at 50 mm on the disk.
  spec.unbalances.push_back(
      {.name = "unbalance", .node = std::string("disk"), .mass = 1e-3, .radius = 0.05, .phase = 0.0, .lever = 0.0});
  return spec;
}

// @sect3{A Campbell diagram and its first forward critical speed}
//
// The request names what differs from the defaults; analysis_options() fills in
// the rest (the spec's [campbell] table, then the built-in defaults) and checks it
// exactly as it does for `feran campbell`. Critical speeds carry the whirl of their
// mode, so the first forward one is found without guessing from labels.
Real first_forward_critical_speed(const ModelSpec& spec, const Model& model) {
  CampbellSpec request;
  request.stop = 2.0 * pi * 100.0;  // 0 to 100 Hz
  request.points = 51;
  request.modes = 4;
  const CampbellOptions options =
      analysis_options<CampbellAnalysis>(spec, model, request, file_key_name<CampbellAnalysis>());
  const CampbellResult campbell = run_campbell(model, options);
  for (const CriticalSpeed& c : campbell.critical_speeds)
    if (c.whirl == Whirl::forward && c.order == 1) return c.speed;
  return std::nan("");
}

}  // namespace

// @sect3{The main program}
int main() {
  try {
    ModelSpec spec = jeffcott_rotor();

    // build_model() meshes the shaft, numbers the nodes and checks the whole spec.
    Model model = build_model(spec);
    std::printf("%s: %ld nodes, %zu elements, %zu forces\n", spec.title.c_str(), static_cast<long>(model.n_nodes()),
                model.elements.size(), model.forces.size());

    const Real before = first_forward_critical_speed(spec, model);
    std::printf("first forward critical speed: %.4f Hz\n", rad_to_hz(before));

    // @sect4{A design change by parameter path}
    //
    // Every number of a spec has a path; set_parameter() takes the value with its
    // unit, as `feran --set` does. A stiffer shaft: 14 mm instead of 12 mm. Its
    // stiffness grows as d⁴, so the critical speed grows as d².
    set_parameter(spec, "shafts[shaft].sections[0].outer_diameter", "14 mm");
    set_parameter(spec, "shafts[shaft].sections[1].outer_diameter", "14 mm");
    model = build_model(spec);
    const Real after = first_forward_critical_speed(spec, model);
    std::printf("with 14 mm: first forward critical speed: %.4f Hz (ratio %.6f, (14/12)^2 = %.6f)\n", rad_to_hz(after),
                after / before, (14.0 * 14.0) / (12.0 * 12.0));

    // @sect4{The unbalance response}
    //
    // At the critical speed the unbalance force m_u·e·Ω² is resisted by the damper
    // alone: the orbit radius is m_u·e·Ω/c. The response's options take the probes
    // from the unbalanced nodes by default.
    ResponseSpec request;
    request.speed = after;  // the response at one speed
    const HarmonicOptions options =
        analysis_options<ResponseAnalysis>(spec, model, request, [](std::string_view key) { return std::string(key); });
    const HarmonicResult response = run_harmonic_response(model, options);
    if (!response.info.converged()) {
      std::fprintf(stderr, "response failed: %s\n", response.info.message.c_str());
      return 3;
    }
    const Real radius = response.probes.front().orbit.front().major;
    std::printf("orbit radius at the critical speed: %.4f mm (m_u e Omega / c = %.4f mm)\n", 1e3 * radius,
                1e3 * 1e-3 * 0.05 * after / 20.0);
    return 0;
  } catch (const std::exception& e) {
    // Bad input (a bad path, a value build_model() rejects) arrives as feran::Error.
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
