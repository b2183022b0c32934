#pragma once
/// @file
/// The model specification: a plain value that says what a model file says.
///
/// A ModelSpec mirrors the model file (docs/model-format.md) table for table and key
/// for key, with every quantity already in SI units (m, kg, s, N, rad, rad/s;
/// frequencies in Hz). Names of choices ("lumped", "rotating_force", "-z") are kept
/// as the words the file uses. Nothing here is checked: build_model() (build_model.hpp)
/// does all meshing, numbering and validation, and is the only way to a Model. Specs
/// copy and compare with ==; read_model_spec() makes one from TOML, write_toml()
/// writes one back, and parameter paths (parameters.hpp) get and set its numbers.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/speed_coefficient.hpp>
#include <feran/spec/node_ref.hpp>
#include <feran/spec/entries/rigid_bodies.hpp>
#include <feran/spec/entries/springs.hpp>
#include <feran/spec/entries/rotating_dampers.hpp>
#include <feran/spec/entries/friction.hpp>
#include <feran/spec/entries/journal_bearings.hpp>
#include <feran/spec/entries/annular_seals.hpp>
#include <feran/spec/entries/rolling_bearings.hpp>
#include <feran/spec/entries/rigid_links.hpp>
#include <feran/spec/entries/fixed.hpp>
#include <feran/spec/entries/unbalances.hpp>
#include <feran/spec/entries/forces.hpp>
#include <feran/spec/entries/static_loads.hpp>
#include <feran/spec/entries/drive.hpp>

namespace feran {

/// [options]: model-wide options.
struct OptionsSpec {
  bool shear_deformation = true;             ///< Timoshenko (true) or Euler–Bernoulli shafts
  std::string gyroscopic = "consistent";     ///< "consistent" or "lumped"
  Real shaft_damping = 0.0;                  ///< β [s] of rotating shafts: C_i = β K
  std::vector<std::string> free_motions;     ///< "axial", "torsion", "lateral"
  bool rotary_inertia = true;                ///< rotary inertia ρI of shaft sections
  std::string shear_coefficient = "cowper";  ///< "cowper" or "hutchinson"
  std::optional<Real> kappa;                 ///< a fixed shear coefficient (overrides the formula)
  Real rayleigh_alpha = 0.0;                 ///< non-rotating damping α·M of shafts [1/s]
  Real rayleigh_beta = 0.0;                  ///< non-rotating damping β·K of shafts [s]
  bool operator==(const OptionsSpec&) const = default;
};

/// [[materials]]: an isotropic material. Exactly one of G and nu is given.
struct MaterialSpec {
  std::string name;
  Real E = 0.0;            ///< Young's modulus [Pa]
  std::optional<Real> G;   ///< shear modulus [Pa]
  std::optional<Real> nu;  ///< Poisson's ratio
  Real rho = 0.0;          ///< density [kg/m³]
  Real loss_factor = 0.0;  ///< hysteretic loss factor η
  bool operator==(const MaterialSpec&) const = default;
};

/// [[shafts.sections]]: a length of circular section, uniform or tapered (diameters
/// linear from the start to the end), meshed into elements.
struct SectionSpec {
  Real length = 0.0;                       ///< [m]
  Real outer_diameter = 0.0;               ///< [m], at the start
  Real inner_diameter = 0.0;               ///< [m], 0 for a solid section
  std::optional<Real> outer_diameter_end;  ///< [m] at the end; default outer_diameter
  std::optional<Real> inner_diameter_end;  ///< [m] at the end; default inner_diameter
  Real axial_force = 0.0;                  ///< constant axial force [N], tension positive
  std::string material;                    ///< empty: the shaft's material
  int elements = 1;                        ///< number of shaft elements
  std::string end_node;                    ///< name of the section's last node (may be empty)
  bool operator==(const SectionSpec&) const = default;
};

/// [[shafts]]: a shaft along x made of sections; it creates nodes.
struct ShaftSpec {
  std::string name;
  Real x = 0.0;  ///< axial position of the first node [m]
  bool rotating = true;
  std::string material;                ///< default material of the sections (may be empty)
  std::string start_node;              ///< name of the first node (may be empty)
  std::optional<Real> rayleigh_alpha;  ///< this shaft's α [1/s]; default [options]
  std::optional<Real> rayleigh_beta;   ///< this shaft's β [s]; default [options]
  std::vector<SectionSpec> sections;
  bool operator==(const ShaftSpec&) const = default;
};

/// [[nodes]]: a node that no shaft creates (stator, housing, a lumped rotor).
struct NodeSpec {
  Real x = 0.0;  ///< [m]
  std::string name;
  std::optional<std::int64_t> number;  ///< not given: the next free number
  bool rotating = false;
  bool operator==(const NodeSpec&) const = default;
};

/// [modal]: defaults of a modal analysis.
struct ModalSpec {
  std::optional<Real> speed;  ///< [rad/s]
  std::optional<int> modes;
  std::optional<std::string> solver;  ///< "auto", "dense" or "sparse"
  std::optional<bool> shapes;         ///< the mode shapes in the JSON
  bool operator==(const ModalSpec&) const = default;
};

/// [campbell]: defaults of a Campbell diagram.
struct CampbellSpec {
  std::optional<Real> start, stop;  ///< [rad/s]
  std::optional<int> points, modes;
  std::vector<int> orders;
  std::optional<std::string> solver;  ///< "auto", "dense" or "sparse"
  bool operator==(const CampbellSpec&) const = default;
};

/// [response]: defaults of a steady-state response.
struct ResponseSpec {
  /// A speed sweep: first and last rotor speed [rad/s] and the number of points.
  std::optional<Real> start, stop;
  std::optional<int> points;
  /// The rotor speed [rad/s] of a frequency sweep, or alone the response at one speed.
  std::optional<Real> speed;
  /// A frequency sweep: first and last excitation frequency [rad/s] and their number.
  std::optional<Real> freq_start, freq_stop;
  std::optional<int> freq_points;
  std::vector<NodeRef> probes;
  /// Harmonic forces added for the analysis, "NODE:DIRECTION:AMPLITUDE[:PHASE]".
  std::vector<std::string> forces;
  std::optional<Real> loss_factor;
  std::optional<std::string> stations;  ///< "all", "summary" or "none"
  std::optional<bool> unbalance;        ///< include the model's unbalances
  std::optional<bool> stability;        ///< judge the rotor's stability at each point
  bool operator==(const ResponseSpec&) const = default;
};

/// [static]: gravity and the speed of a static analysis.
struct StaticSpec {
  std::optional<std::string> gravity;  ///< "+x", "-x", "+y", "-y", "+z", "-z" or "none"
  std::optional<Real> g;               ///< [m/s²]
  std::optional<Real> speed;           ///< [rad/s]
  std::optional<bool> loads;           ///< include the [[static_loads]]
  std::optional<bool> stability;       ///< judge whether the equilibrium is stable
  bool operator==(const StaticSpec&) const = default;
};

/// [runup]: the speed profile (one of three forms) and defaults of a run-up.
struct RunupSpec {
  std::optional<Real> speed;                          ///< constant speed [rad/s]
  std::optional<Real> from, to, ramp_time;            ///< linear ramp [rad/s, rad/s, s]
  std::vector<std::pair<Real, Real>> table;           ///< (time [s], speed [rad/s]) points
  std::optional<Real> duration, dt, output_interval;  ///< [s]
  std::optional<std::string> integrator;
  std::optional<Real> rel_tol, abs_tol;
  std::optional<int> modes;
  std::vector<NodeRef> probes;
  std::vector<std::string> springs;  ///< names of [[springs]] entries
  std::optional<bool> gravity;       ///< apply [static] gravity as a constant force
  std::optional<bool> static_loads;  ///< apply the [[static_loads]] as constant forces
  std::optional<std::string> start;  ///< "rest", "equilibrium" or "steady"
  std::optional<bool> drive;         ///< torque-driven by [drive] from the profile's first speed
  // The integrators' settings (integrators/integrator.hpp, IntegratorSettings).
  std::optional<Real> newton_tol;
  std::optional<int> newton_max_iter;
  std::optional<bool> allow_unstable;    ///< rk3: warn instead of refusing a step above its limit
  std::optional<std::string> jacobian;   ///< W-methods: "exact" or "linear"
  std::optional<int> jacobian_interval;  ///< W-methods: steps between Jacobians
  std::optional<Real> blowup;            ///< [m] a displacement that ends the run as diverged
  std::optional<bool> samples;           ///< keep every sample in the result
  bool operator==(const RunupSpec&) const = default;
};

/// [api684]: the operating range and settings of the API 617 / API 684 analyses.
struct Api684Spec {
  std::optional<Real> min_speed, max_speed;  ///< the operating range [rad/s]
  std::optional<Real> stop;                  ///< last speed of the unbalance responses [rad/s]
  std::optional<int> points, modes;
  std::optional<std::string> unbalance;  ///< "4W/N" or "model"
  std::optional<Real> unbalance_multiple;
  std::vector<NodeRef> probes;
  std::vector<std::string> bearings;      ///< names of [[springs]] entries
  std::optional<Real> map_low, map_high;  ///< [N/m]
  std::optional<int> map_points, map_criticals;
  std::optional<NodeRef> stability_node;
  std::optional<Real> anticipated_q;  ///< [N/m]
  std::optional<bool> map;            ///< the undamped critical speed map
  std::optional<bool> stability;      ///< the level I stability analysis
  bool operator==(const Api684Spec&) const = default;
};

/// [orbits]: the periodic orbits (harmonic balance) over a speed range, or over a
/// parameter path at a fixed speed, and their settings.
struct OrbitsSpec {
  std::optional<Real> from, to;                             ///< the speed range [rad/s]
  std::optional<std::string> parameter;                     ///< a parameter path continued instead of the speed
  std::optional<std::string> parameter_from, parameter_to;  ///< its range, values with units
  std::optional<Real> speed;                                ///< the fixed speed of a parameter branch [rad/s]
  std::optional<std::string> branch;                        ///< "auto", "forced", "whirl" or "equilibrium"
  std::optional<std::string> direction;                     ///< a forced branch: "up", "down" or "both"
  std::optional<std::string> start_at;  ///< the parameter's value where a run finds the orbit to start from
  std::optional<Real> settle;           ///< that run's longest simulated time [s]
  std::optional<int> harmonics, samples, modes, points;
  std::vector<NodeRef> probes;
  std::optional<bool> gravity;       ///< apply [static] gravity as a constant force
  std::optional<bool> static_loads;  ///< apply the [[static_loads]]
  bool operator==(const OrbitsSpec&) const = default;
};

/// A whole model file.
struct ModelSpec {
  std::string title;
  OptionsSpec options;
  std::vector<MaterialSpec> materials;
  std::vector<ShaftSpec> shafts;
  std::vector<NodeSpec> nodes;
  std::vector<RigidBodySpec> rigid_bodies;
  std::vector<SpringSpec> springs;
  std::vector<RotatingDamperSpec> rotating_dampers;
  std::vector<FrictionSpec> friction;
  std::vector<JournalBearingSpec> journal_bearings;
  std::vector<RollingBearingSpec> rolling_bearings;
  std::vector<AnnularSealSpec> annular_seals;
  std::vector<RigidLinkSpec> rigid_links;
  std::vector<FixedSpec> fixed;
  std::vector<UnbalanceSpec> unbalances;
  std::vector<ForceSpec> forces;
  std::vector<StaticLoadSpec> static_loads;
  ModalSpec modal;
  CampbellSpec campbell;
  ResponseSpec response;
  StaticSpec static_;  ///< the [static] table ("static" is a C++ keyword)
  RunupSpec runup;
  Api684Spec api684;
  OrbitsSpec orbits;
  DriveSpec drive;
  bool operator==(const ModelSpec&) const = default;
};

}  // namespace feran
