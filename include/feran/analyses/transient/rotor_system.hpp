#pragma once
/// @file
/// A feran model as a SecondOrderSystem for the time integrators.

#include <array>
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <feran/integrators/second_order_system.hpp>
#include <feran/analyses/transient/speed_profile.hpp>
#include <feran/core/banded_lu.hpp>
#include <feran/assembly/assembler.hpp>
#include <feran/assembly/sparse_sum.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// M q'' = f(t) + f_nl(t, q, q', Ω) − (C(Ω) + C_i + Ω G) q' − (K(Ω) + Ω K_i) q in
/// reduced coordinates, with Ω = Ω(t) from a speed profile. f(t) holds the
/// unbalances, m·r·(Ω² − jΩ')·e^{j(φ + phase)} with φ = ∫Ω dt (plus their lever
/// moments), the model's harmonic forces at the angle φ, and optionally a constant
/// load (gravity, the static loads). Speed-dependent coefficients follow Ω(t).
///
/// Driven by a Drive instead, the rotation angle φ and the speed Ω = φ' are one more
/// unknown (the last): (J_drive + J_rotor + Σm r²)·Ω' − sᵀq'' = T(Ω) − T_resisting(Ω) −
/// Σ T_bearings, with s(φ) = ∂f_unbalance/∂Ω' the unbalances' coupling (exact for a
/// point mass: the kinetic energy of m at the eccentricity r), and the lateral
/// equations gain s·Ω'. The coupled accelerations are found exactly in rhs() by a
/// bordered solve with M (z = M⁻¹s is a combination of two fixed vectors), so that the
/// integrators see the constant mass diag(M, J) (docs/theory/time_integration.md).
class RotorSystem final : public SecondOrderSystem {
 public:
  /// @p model must outlive the system. @p constant_load: over all unconstrained DOFs
  /// (global_dof order), or empty. With @p drive (copied) the speed is a state and
  /// @p profile is not used. @p assembled: @p model's assembly when the caller has it
  /// (ModelFile::assembler), else the system assembles the model itself.
  RotorSystem(const Model& model, SpeedProfile profile, Vector constant_load = {}, const Drive* drive = nullptr,
              std::shared_ptr<const Assembler> assembled = nullptr);

  Index size() const override { return driven_ ? n_ + 1 : n_; }
  /// The model's reduced unknowns (size() without the drive's angle).
  Index model_size() const { return n_; }
  bool driven() const { return driven_; }
  /// The polar inertia the drive accelerates: drive + rotating parts + Σ m r² [kg m²].
  Real driven_inertia() const { return inertia_; }
  /// The speed at (t, v): the profile's, or the drive's state v(n).
  Real speed(Real t, const Vector& v) const { return driven_ ? v(n_) : profile_.speed(t); }
  /// Where and how fast the rotor is at (t, x, v) (the integrated state; a driven run's
  /// angle is x(n), its acceleration the last one computed), on a trajectory.
  MotionState motion(Real t, const Vector& x, const Vector& v) const {
    if (driven_) return {t, v(n_), acceleration_, x(n_), true};
    return {t, profile_.speed(t), profile_.acceleration(t), profile_.angle(t), true};
  }
  void rhs(Real t, const Vector& x, const Vector& v, Vector& r) override;
  void mass_times(const Vector& u, Vector& y) const override;
  void solve_mass(const Vector& r, Vector& a) override;
  void set_jacobian(Real t, const Vector& x, const Vector& v, bool exact) override;
  void stiffness_times(const Vector& u, Vector& y) const override {
    tangent_values();
    y.noalias() = KT_ * u;
  }
  void damping_times(const Vector& u, Vector& y) const override {
    tangent_values();
    y.noalias() = DT_ * u;
  }
  bool factor_tangent(Real c_x, Real c_v, Real c_a) override;
  void solve_tangent(const Vector& rhs, Vector& delta) override;
  /// Without nonlinear forces the system is linear in (x, v), and the Jacobian is
  /// exact at every time whose speed equals the speed it was set at.
  bool tangent_exact_at(Real t) const override {
    return !driven_ && forces_.empty() && profile_.speed(t) == jacobian_speed_;
  }
  /// A tangent factorised banded (the last factorisation), without a drive.
  bool refresh_pays_at(Real t) const override {
    static_cast<void>(t);
    return !driven_ && banded_factors_;
  }
  Real highest_frequency() override;

  const DofMap& dof_map() const { return assembler_->dof_map(); }
  const Assembler& assembler() const { return *assembler_; }
  const SpeedProfile& profile() const { return profile_; }
  /// Displacements (or velocities) of all unconstrained DOFs (of the model's part of a
  /// driven state).
  Vector expand(const Vector& reduced) const {
    return assembler_->dof_map().expand(reduced.size() == n_ ? reduced : Vector(reduced.head(n_)));
  }

 private:
  /// Nonlinear force @p i at the state; an Error it throws is rethrown naming the force.
  /// (The last evaluation at the same state is returned again, not recomputed.)
  const NonlinearForceValue& evaluate(std::size_t i, const MotionState& state, const Vector& x, const Vector& v) const;
  void update_speed(Real speed) const;
  /// D_T and K_T of a linear model, set_jacobian() having left them for later: its
  /// banded factorisation needs neither (factor_tangent()), only the W-methods'
  /// products and the sparse LU do.
  void tangent_values() const;
  /// True when the tangent is c_a·M + c_v·(C + C_i + Ω·G) + c_x·(K + Ω·K_i) plus the
  /// speed-dependent elements' terms: no drive, no nonlinear force.
  bool linear() const { return !driven_ && forces_.empty(); }
  void external_forces(const MotionState& state, Vector& f_full) const;
  /// r of the model's equations at displacements @p x, velocities @p v (model size):
  /// external forces at @p external, nonlinear ones at @p nonlinear.
  void model_rhs(const MotionState& external, const MotionState& nonlinear, const Vector& x, const Vector& v,
                 Vector& r);
  /// The model's damping and stiffness tangents at @p state into DT_, KT_.
  void model_jacobian(const MotionState& state, const Vector& x, const Vector& v, bool exact);
  void set_up_drive(const Drive& drive);
  /// The terms of D_T and K_T without the forces (for damping_sum_, stiffness_sum_).
  std::vector<const SparseMatrix*> damping_terms() const;
  std::vector<const SparseMatrix*> stiffness_terms() const;

  const Model& model_;
  std::shared_ptr<const Assembler> assembler_;
  SpeedProfile profile_;
  Vector constant_load_;                  // over all unconstrained DOFs; empty: none
  SparseMatrix M_, C_, K_, G_, Ci_, Ki_;  // speed-independent parts
  SparseMatrix Cc_;                       // C_ + Ci_
  Vector work_;                           // rhs() scratch
  mutable SystemMatrices variable_;       // speed-dependent parts at cached_speed_
  mutable Real cached_speed_;
  Eigen::SimplicialLDLT<SparseMatrix> mass_;
  std::vector<Force> forces_;            ///< the model's nonlinear forces
  std::vector<SparseMatrix> selectors_;  // per force: rows of T for its DOFs
  mutable SparseMatrix DT_, KT_;
  mutable bool tangent_pending_ = false;      // a linear model's D_T, K_T not yet set at jacobian_speed_
  SparseSum damping_sum_, stiffness_sum_;     // D_T, K_T in place (the forces' entries included, zero)
  std::vector<SparseMatrix> force_patterns_;  // per force: the pattern of Sᵀ·J·S
  // Per force: (local row p, local column q, position in D_T's and K_T's values,
  // weight S(p, r)·S(q, c)) for each contribution of its Jacobian blocks.
  struct ForceScatter {
    Index p, q, in_damping, in_stiffness;
    Real weight;
  };
  std::vector<std::vector<ForceScatter>> force_scatter_;
  // The last evaluation of each force, reused at the same state (a step's first
  // iteration evaluates the forces for the Jacobian and the residual at one state).
  struct ForceCache {
    MotionState state;
    Vector x, v;
    NonlinearForceValue value;
    bool valid = false;
  };
  mutable std::vector<ForceCache> force_cache_;
  mutable Vector xl_, vl_;  // a force's local displacements and velocities (evaluate())
  /// The coefficients of damping_terms() and stiffness_terms() at @p speed.
  std::vector<Real> tangent_coefficients(Real speed) const;
  Real jacobian_speed_;  // the speed of DT_, KT_ (NaN before the first)
  // The tangent's factors: banded (BandedLU, without pivoting) while the pattern's
  // half-bandwidth is at most max_band and the pivots allow it, else a sparse LU.
  static constexpr Index max_band = 64;
  BandedLU band_;
  Index band_pattern_ = -1;                         // nonzeros of the patterns the band was sized for
  bool band_fits_ = false;                          // their half-bandwidth is at most max_band
  bool banded_factors_ = false;                     // the last factorisation is band_'s
  std::vector<std::vector<Index>> band_positions_;  // of M_, DT_, KT_ in band_
  // A linear model's tangent in the band's storage, kept: its constant part
  // c_a·M + c_v·(C + C_i) + c_x·K and its speed part c_v·G + c_x·K_i for the
  // coefficients band_coefficients_, so that a step on a speed ramp sets the band as
  // one combination of the two (plus the speed-dependent elements) before factorising.
  std::vector<Real> band_constant_, band_speed_;
  std::array<Real, 3> band_coefficients_{};   // (c_x, c_v, c_a) of band_constant_, band_speed_
  std::vector<Index> variable_positions_[2];  // of variable_.C and variable_.K in band_
  Index variable_pattern_ = -1;
  // On a speed ramp the next steps' tangents are factorised four at a time, one in each
  // lane of band_ (BandedLU::factorize_lanes), at the speeds of the times that follow
  // this one at the spacing of the last two factorisations: a later step whose speed
  // is one of them (to round-off) solves with that lane's factors.
  Real jacobian_time_ = 0.0;                                     // the time of DT_, KT_
  Real factored_time_ = std::numeric_limits<Real>::quiet_NaN();  // of the last factorisation
  std::array<Real, BandedLU::lanes> lane_speeds_{};
  unsigned lanes_good_ = 0;  // a bit for each lane factorised for band_coefficients_
  unsigned lanes_used_ = 0;  // a bit for each lane a step solved with
  int lane_ = -1;            // the lane the last factorisation is, −1: band_'s single matrix
  int lane_pause_ = 0;       // factorisations left before predicting again (after a miss)
  std::vector<BandedLU::LaneAddition> lane_additions_;
  /// The lane factorised at @p speed (to round-off) for the coefficients kept, or −1.
  int lane_at(Real speed) const;
  /// Factorises band_'s lanes at @p speed and the next predicted speeds; false when
  /// lane 0 (at @p speed) does not factorise.
  bool factor_lanes(Real speed, Real spacing, Real c_x, Real c_v);
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  Index pattern_nonzeros_ = -1;
  Vector f_full_;
  Index n_ = 0;  // the model's reduced unknowns

  // A driven run (see the class comment).
  bool driven_ = false;
  Drive drive_;
  Real inertia_ = 0.0;                     // J_drive + J_rotor + Σ m r²
  Vector S0_, S90_, Z0_, Z90_, C0_, C90_;  // s(φ) = cos φ S0 + sin φ S90, z = M⁻¹s; c: the Ω² part
  std::vector<std::size_t> drag_;          // indices in forces_ with a drag torque
  std::vector<Index> border_rows_;         // rows of the speed column of the tangent
  Real acceleration_ = 0.0;                // the last Ω' (for nonlinear forces' MotionState)
  SparseMatrix mass_ext_;                  // diag(M, J) of the tangent
  Vector xq_, vq_, rq_;                    // scratch of the model part
};

}  // namespace feran
