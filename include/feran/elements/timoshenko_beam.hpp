#pragma once
/// @file
/// Two-node 12-DOF shaft element: Timoshenko bending with Cowper's shear
/// coefficient, linear axial, Saint-Venant torsion; consistent mass with rotary
/// inertia; consistent or lumped gyroscopic matrix; optional stiffness-proportional
/// rotating (material) damping; uniform or tapered (conical: both diameters linear
/// along the element); optional geometric stiffness of a constant axial force.
/// Matrices: docs/theory/shaft_element.md.

#include <string_view>

#include <feran/core/types.hpp>
#include <feran/model/element.hpp>
#include <feran/model/material.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// How the shear coefficient κ of a Timoshenko element is found.
enum class ShearCoefficient {
  cowper,      ///< Cowper (1966), J. Appl. Mech. 33:335–340
  hutchinson,  ///< Hutchinson (2001), J. Appl. Mech. 68:87–92
  given        ///< BeamOptions::kappa
};

/// Options of a shaft element.
struct BeamOptions {
  bool shear_deformation = true;
  GyroscopicForm gyroscopic = GyroscopicForm::consistent;
  bool rotating = true;     ///< a non-rotating beam has no G and no rotating damping
  Real damping_beta = 0.0;  ///< stiffness-proportional rotating damping β [s]
  Real loss_factor = 0.0;   ///< hysteretic loss factor η (harmonic analyses only)
  /// Rotary inertia ρI of the cross-sections in the mass matrix (a Rayleigh or
  /// Timoshenko beam); without it only the translational inertia ρA remains. The
  /// gyroscopic matrix (polar inertia ρI_p) is kept either way.
  bool rotary_inertia = true;
  ShearCoefficient shear = ShearCoefficient::cowper;
  Real kappa = 0.0;  ///< the shear coefficient when shear is ShearCoefficient::given
  /// Non-rotating (external) proportional damping C = α·M + β·K of the element,
  /// α [1/s] and β [s]; distinct from the rotating damping damping_beta.
  Real rayleigh_alpha = 0.0;
  Real rayleigh_beta = 0.0;
  /// Constant axial force in the element [N], tension positive: adds the geometric
  /// stiffness P∫N_t'ᵀN_t' dx to both bending planes (tension stiffens, compression
  /// softens down to buckling).
  Real axial_force = 0.0;
};

/// Timoshenko shaft element between nodes @p node_a (at x) and @p node_b (at x + L).
class TimoshenkoBeam {
 public:
  TimoshenkoBeam(Index node_a, Index node_b, Real length, CircularSection section, Material material,
                 BeamOptions options);
  /// A tapered element: @p section_a at node a, @p section_b at node b, outer and inner
  /// diameters linear in between.
  TimoshenkoBeam(Index node_a, Index node_b, Real length, CircularSection section_a, CircularSection section_b,
                 Material material, BeamOptions options);

  LocalMatrices local_matrices(const OperatingPoint& op) const;
  std::string_view kind() const { return "shaft"; }
  bool speed_dependent() const { return false; }

  Index node_a() const { return node_a_; }
  Index node_b() const { return node_b_; }
  Real length() const { return length_; }
  /// The section at node a (the whole element's when it is uniform).
  const CircularSection& section() const { return section_; }
  /// The section at node b.
  const CircularSection& section_b() const { return section_b_; }
  bool tapered() const { return !(section_ == section_b_); }
  /// The section at ξ = (x − x_a)/L ∈ [0, 1].
  CircularSection section_at(Real xi) const;
  const Material& material() const { return material_; }
  const BeamOptions& options() const { return options_; }
  /// Where its section forces and stresses are reported (ability, model/element.hpp).
  ShaftSegment shaft_segment() const { return {node_a_, node_b_, section_, section_b_}; }
  /// Shear parameter Φ = 12EI/(κGAL²), or 0 without shear deformation; of the
  /// mid-length section for a tapered element (its shape functions').
  Real shear_parameter() const;

  /// 4×4 bending stiffness in one plane, DOFs (d1, s1, d2, s2) with s = dd/dx.
  Matrix bending_stiffness() const;
  /// 4×4 geometric stiffness in one plane per unit axial force, ∫N_t'ᵀN_t' dx [1/m].
  Matrix geometric_stiffness() const;
  /// 4×4 translational (ρA) mass in one plane.
  Matrix bending_translational_mass() const;
  /// 4×4 rotary-inertia (ρI) mass in one plane.
  Matrix bending_rotary_mass() const;

 private:
  /// κ of @p section by the options' rule.
  Real shear_coefficient(const CircularSection& section) const;
  /// ∫₀¹ f(ξ, N_t, N_r, N_t', N_r') L dξ of 4×4 products, by Gauss–Legendre over the
  /// element (exact for the polynomial integrands of a tapered element).
  template <class F>
  Matrix integrate(F&& integrand) const;

  Index node_a_, node_b_;
  Real length_;
  CircularSection section_, section_b_;
  Material material_;
  BeamOptions options_;
};

}  // namespace feran
