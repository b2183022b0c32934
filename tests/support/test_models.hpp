#pragma once
// Small programmatic model builders shared by the tests. Each builds a Model the
// same way the model reader does, without going through a file.

#include <cmath>
#include <optional>
#include <string>

#include <feran/elements/rigid_body.hpp>
#include <feran/elements/rotating_damper.hpp>
#include <feran/elements/spring_damper.hpp>
#include <feran/elements/timoshenko_beam.hpp>
#include <feran/forces/coulomb_friction.hpp>
#include <feran/forces/fluid_film_bearing.hpp>
#include <feran/forces/harmonic_force.hpp>
#include <feran/forces/static_load.hpp>
#include <feran/forces/unbalance.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/model/model.hpp>

namespace feran::test {

inline Index add_node(Model& m, Real x, bool rotating = true, std::string name = {}) {
  Node n;
  n.number = static_cast<int>(m.nodes.size()) + 1;
  n.name = std::move(name);
  n.x = x;
  n.rotating = rotating;
  m.nodes.push_back(n);
  return m.n_nodes() - 1;
}

inline Material steel(Real E = 211e9, Real G = 81.2e9, Real rho = 7810) { return Material{"steel", E, G, rho}; }

// A uniform shaft from x0 of n_el elements, nodes appended; returns the first node.
// Its elements get @p opt (shear deformation, gyroscopic form, rotating damping β).
inline Index add_shaft(Model& m, Real x0, Real length, int n_el, Real d_out, const Material& mat, Real d_in = 0.0,
                       const BeamOptions& opt = {}) {
  const Index first = add_node(m, x0);
  Index prev = first;
  const Real le = length / n_el;
  for (int e = 0; e < n_el; ++e) {
    const Index next = add_node(m, x0 + le * (e + 1));
    m.elements.emplace_back(TimoshenkoBeam(prev, next, le, CircularSection{d_out, d_in}, mat, opt));
    prev = next;
  }
  return first;
}

inline void add_body(Model& m, Index node, Real mass, Real Ja, Real Jp, Real offset = 0.0, bool rotating = true) {
  m.elements.emplace_back(RigidBody(node, RigidBodyProperties{mass, Ja, Jp, offset}, rotating));
}

inline void add_isotropic_bearing(Model& m, Index node, Real k, Real c = 0.0, std::optional<Index> to = std::nullopt) {
  SpringDamperCoefficients sc;
  sc.k[static_cast<std::size_t>(Dof::v)] = k;
  sc.k[static_cast<std::size_t>(Dof::w)] = k;
  sc.c[static_cast<std::size_t>(Dof::v)] = c;
  sc.c[static_cast<std::size_t>(Dof::w)] = c;
  m.elements.emplace_back(SpringDamper(node, to, sc));
}

inline void fix(Model& m, Index node, std::initializer_list<Dof> dofs) {
  FixedDofs f;
  f.node = node;
  for (Dof d : dofs) f.dofs[static_cast<std::size_t>(d)] = true;
  m.fixed.push_back(f);
}

inline void fix_all(Model& m, Index node) { fix(m, node, {Dof::u, Dof::v, Dof::w, Dof::rx, Dof::ry, Dof::rz}); }

// Jeffcott rotor: a point mass m (tiny tilt inertia, tilts fixed) on an isotropic
// spring k with external damping c_a and, when c_i > 0, a rotating damper c_i to the
// shaft axis.
inline Model jeffcott(Real m, Real k, Real ca, Real ci) {
  Model model;
  const Index n = add_node(model, 0.0, true, "disk");
  add_body(model, n, m, 1e-3, 1e-3);
  add_isotropic_bearing(model, n, k, ca);
  if (ci > 0) model.elements.emplace_back(RotatingDamper(n, std::nullopt, {ci, 0, 0, 0}));
  fix(model, n, {Dof::u, Dof::rx, Dof::ry, Dof::rz});
  return model;
}

// The run-up tests' Jeffcott rotor: a point mass of 9.1 kg on 1.6e5 N/m
// (ω_n = 132.6 rad/s) with external damping c_a, rotating damping c_i, an unbalance
// of @p unbalance kg at 50 mm and Coulomb friction of amplitude @p friction N between
// rotor and shaft (regularised over a sliding speed ε_t = 1e-5 m/s), each when > 0.
inline constexpr Real runup_mass = 9.1, runup_stiffness = 1.6e5;
inline Model runup_jeffcott(Real ca, Real ci, Real unbalance = 0.0, Real friction = 0.0) {
  Model model = jeffcott(runup_mass, runup_stiffness, ca, ci);
  const Index n = 0;
  if (unbalance > 0) model.forces.emplace_back(Unbalance{n, unbalance, 0.05, 0.0, 0.0}, "u");
  if (friction > 0) {
    CoulombFriction f;
    f.node_a = n;
    f.force_amplitude = friction;
    f.epsilon_t = 1e-5;
    model.forces.emplace_back(f);
  }
  return model;
}

// The friction-whirl run of the run-up tests: 3 s at the constant speed 2·ω_n of
// runup_jeffcott(), starting from v = 0.1 mm, sampled every millisecond at node 0.
inline TransientOptions friction_whirl_run(const Model& model, Real dt) {
  TransientOptions t;
  t.profile = SpeedProfile::constant(2.0 * std::sqrt(runup_stiffness / runup_mass));
  t.duration = 3.0;
  t.settings.dt = dt;
  t.output_interval = 1e-3;
  t.probes = {0};
  t.initial_displacement = Vector::Zero(model.n_dofs());
  t.initial_displacement(global_dof(0, Dof::v)) = 1e-4;
  return t;
}

// Friswell, Penny, Garvey & Lees (2010), Example 5.9.1: steel shaft 1.5 m, Ø 50 mm,
// six Timoshenko elements; disks Ø 280 × 70 mm at 0.5 m and Ø 350 × 70 mm at 1.0 m
// (bore = shaft diameter); isotropic bearings 1 MN/m at both ends. Axial and
// torsional motion are held at the first bearing (the book's model is lateral only).
inline Model friswell_5_9_1(int n_el = 6, const BeamOptions& opt = {}) {
  Model m;
  const Material mat = steel();
  add_shaft(m, 0.0, 1.5, n_el, 0.05, mat, 0.0, opt);
  auto node_at = [&](Real x) {
    for (Index i = 0; i < m.n_nodes(); ++i)
      if (std::abs(m.nodes[static_cast<std::size_t>(i)].x - x) < 1e-9) return i;
    return Index{-1};
  };
  add_body(m, node_at(0.5), 0, 0, 0);
  m.elements.back() = RigidBody(node_at(0.5), RigidBody::disk(7810, 0.28, 0.05, 0.07), true);
  m.elements.emplace_back(RigidBody(node_at(1.0), RigidBody::disk(7810, 0.35, 0.05, 0.07), true));
  add_isotropic_bearing(m, node_at(0.0), 1e6);
  add_isotropic_bearing(m, node_at(1.5), 1e6);
  fix(m, 0, {Dof::u, Dof::rx});
  return m;
}

// Friswell et al. (2010), Example 5.5.1: D = 100 mm, L = 30 mm, c = 0.1 mm, μ = 0.1 Pa s.
inline constexpr JournalBearingGeometry friswell_5_5_1_bearing{
    .diameter = 0.1, .length = 0.03, .clearance = 1e-4, .viscosity = 0.1};

// A rigid rotor of mass 2m on two identical journal bearings at x = ±a (a = 0.2 m):
// node 0 at the centre carries the body and leads nodes 1 and 2 (the journals) by a
// rigid link; its axial and torsional DOFs are fixed; gravity −9.81 m/s² along y. The
// cylindrical motion (v, w of node 0) has mass m per bearing; the conical motion is
// made much stiffer (J_A small) so that it stays stable well beyond the cylindrical
// threshold.
inline Model rigid_rotor_in_journal_bearings(Real m_per_bearing, FilmTheory theory,
                                             const JournalBearingGeometry& geometry = friswell_5_5_1_bearing,
                                             const FiniteBearingGrid& grid = {}) {
  constexpr Real a = 0.2;
  Model model;
  model.nodes = {{1, "centre", 0.0, true}, {2, "left", -a, true}, {3, "right", a, true}};
  const Real mass = 2 * m_per_bearing;
  model.elements.emplace_back(
      RigidBody(0, {.mass = mass, .transverse_inertia = 0.05 * mass * a * a, .polar_inertia = 0.02 * mass * a * a},
                true),
      "rotor");
  model.links.push_back({0, {1, 2}});
  FixedDofs fixed{.node = 0, .dofs = {}};
  fixed.dofs[static_cast<std::size_t>(Dof::u)] = fixed.dofs[static_cast<std::size_t>(Dof::rx)] = true;
  model.fixed.push_back(fixed);
  model.forces.emplace_back(
      FluidFilmBearing{.node_a = 1, .node_b = {}, .geometry = geometry, .theory = theory, .grid = grid}, "left");
  model.forces.emplace_back(
      FluidFilmBearing{.node_a = 2, .node_b = {}, .geometry = geometry, .theory = theory, .grid = grid}, "right");
  model.gravity = Eigen::Vector3d(0, -9.81, 0);
  return model;
}

}  // namespace feran::test
