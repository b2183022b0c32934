#pragma once
/// @file
/// Linear spring–damper between a node and ground or between two nodes.

#include <array>
#include <optional>
#include <string_view>

#include <feran/core/types.hpp>
#include <feran/model/element.hpp>
#include <feran/model/speed_coefficient.hpp>

namespace feran {

/// Coefficients of a spring–damper, each possibly dependent on speed and on the
/// frequency of the motion.
/// Direct terms per DOF direction (indexed by Dof: x, y, z, rx, ry, rz), and the
/// cross-coupled lateral terms: the force on node a along y is
/// −(k_yy·Δv + k_yz·Δw) − (c_yy·Δv' + c_yz·Δw'), Δ = q_a − q_b.
struct SpringDamperCoefficients {
  std::array<SpeedCoefficient, dofs_per_node> k{};  ///< [N/m] or [N m/rad]
  std::array<SpeedCoefficient, dofs_per_node> c{};  ///< [N s/m] or [N m s/rad]
  SpeedCoefficient kyz, kzy;                        ///< [N/m]
  SpeedCoefficient cyz, czy;                        ///< [N s/m]
  Real loss_factor = 0.0;                           ///< hysteretic loss factor η of the stiffness (harmonic analyses)
};

/// The coefficients of a spring–damper by index, and the one table of their names (the
/// keys of a model file's [[springs]], parameter paths, messages): the direct
/// stiffnesses kx … krz, the cross-coupled stiffnesses kyz, kzy, the direct dampings
/// cx … crz and the cross-coupled dampings cyz, czy.
namespace spring {
enum Coefficient : std::size_t { kx, ky, kz, krx, kry, krz, kyz, kzy, cx, cy, cz, crx, cry, crz, cyz, czy, count };
struct CoefficientName {
  std::string_view name;
  bool damping;     ///< a damping (else a stiffness)
  bool rotational;  ///< about an axis (else along one)
  bool direct;      ///< a direct term (else cross-coupled: may be negative)
  std::string_view doc;
};
inline constexpr std::array<CoefficientName, count> names = {{
    {"kx", false, false, true, "direct stiffness along x"},
    {"ky", false, false, true, "direct stiffness along y"},
    {"kz", false, false, true, "direct stiffness along z"},
    {"krx", false, true, true, "direct stiffness about x (torsion)"},
    {"kry", false, true, true, "direct stiffness about y"},
    {"krz", false, true, true, "direct stiffness about z"},
    {"kyz", false, false, false, "cross-coupled stiffness, force along y from w; may be negative"},
    {"kzy", false, false, false, "cross-coupled stiffness, force along z from v; may be negative"},
    {"cx", true, false, true, "direct damping along x"},
    {"cy", true, false, true, "direct damping along y"},
    {"cz", true, false, true, "direct damping along z"},
    {"crx", true, true, true, "direct damping about x (torsion)"},
    {"cry", true, true, true, "direct damping about y"},
    {"crz", true, true, true, "direct damping about z"},
    {"cyz", true, false, false, "cross-coupled damping, force along y from w'; may be negative"},
    {"czy", true, false, false, "cross-coupled damping, force along z from v'; may be negative"},
}};
}  // namespace spring

/// Coefficient @p i of @p c (spring::names[i]).
SpeedCoefficient& coefficient(SpringDamperCoefficients& c, spring::Coefficient i);
const SpeedCoefficient& coefficient(const SpringDamperCoefficients& c, spring::Coefficient i);

/// Spring–damper from @p node_a to @p node_b, or to ground when node_b is empty.
/// Matrices: docs/theory/spring_damper.md.
class SpringDamper {
 public:
  SpringDamper(Index node_a, std::optional<Index> node_b, SpringDamperCoefficients coeffs);

  LocalMatrices local_matrices(const OperatingPoint& op) const;
  std::string_view kind() const { return "spring_damper"; }
  bool speed_dependent() const;
  /// True when a coefficient depends on the frequency of the motion (ability,
  /// model/element.hpp).
  bool frequency_dependent() const;

  Index node_a() const { return node_a_; }
  const std::optional<Index>& node_b() const { return node_b_; }
  Connection connection() const { return {node_a_, node_b_}; }
  const SpringDamperCoefficients& coefficients() const { return coeffs_; }
  /// Ability (model/element.hpp): the same spring–damper with k_yy = k_zz = @p k [N/m]
  /// and no cross-coupled stiffness, its other coefficients kept.
  SpringDamper with_lateral_stiffness(Real k) const;
  /// 6×6 stiffness and damping of the relative motion at speed @p speed for motion at
  /// @p frequency [rad/s] (empty: synchronous, frequency = speed).
  Matrix stiffness_6x6(Real speed, std::optional<Real> frequency = std::nullopt) const;
  Matrix damping_6x6(Real speed, std::optional<Real> frequency = std::nullopt) const;
  /// The force it transmits (ability of connecting elements, model/element.hpp).
  Transmission transmission(Real speed, std::optional<Real> frequency = std::nullopt) const {
    return {node_a_, node_b_, stiffness_6x6(speed, frequency), damping_6x6(speed, frequency), coeffs_.loss_factor, {}};
  }
  /// The speed ranges of its tabulated coefficients (ability, model/element.hpp).
  std::vector<SpeedRange> speed_ranges() const;
  /// The frequency ranges of its frequency tables (ability, model/element.hpp).
  std::vector<SpeedRange> frequency_ranges() const;

 private:
  Index node_a_;
  std::optional<Index> node_b_;
  SpringDamperCoefficients coeffs_;
};

}  // namespace feran
