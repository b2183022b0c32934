#pragma once
/// @file
/// Modal analysis at one speed: complex eigenvalues and mode shapes of
/// M q'' + (C + C_i + Ω G) q' + (K + Ω K_i) q = 0.

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <feran/assembly/assembler.hpp>
#include <feran/analyses/common/operating_state.hpp>
#include <feran/analyses/common/solver_info.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

namespace detail {
struct StateEigenpairs;
}  // namespace detail

/// How a mode's nodes whirl in the y–z plane (spin is about +x).
enum class Whirl {
  forward,   ///< every node's orbit turns with the spin
  backward,  ///< every node's orbit turns against the spin
  mixed,     ///< some nodes turn forward, others backward
  planar,    ///< straight-line orbits (e.g. anisotropic supports at rest)
  none       ///< no lateral motion (axial or torsional mode)
};

/// Dominant motion of a mode, by kinetic-energy fraction.
enum class ModeType { lateral, axial, torsional, coupled };

/// How the rotor deforms in a lateral mode: it moves nearly as a rigid body on its
/// supports, translating (cylindrical: a bearing or oil-film whirl mode) or tilting
/// (conical), or it bends. See Mode::bending.
enum class ModeShape { none, cylindrical, conical, bending };

const char* to_string(Whirl w);
const char* to_string(ModeType t);
const char* to_string(ModeShape s);

/// One eigenpair, represented by the eigenvalue with Im p ≥ 0.
struct Mode {
  Complex eigenvalue;      ///< p = −δ + iω [1/s]
  Real frequency_hz = 0;   ///< damped natural frequency ω/2π [Hz]
  Real damping_ratio = 0;  ///< D = −Re p/|p| (negative: unstable); NaN when p = 0
  /// Logarithmic decrement 2π·δ/ω; NaN for a non-oscillatory mode.
  Real log_decrement = std::numeric_limits<Real>::quiet_NaN();
  Whirl whirl = Whirl::none;
  /// Amplitude-weighted directivity Σ(r_f² − r_b²)/Σ(r_f² + r_b²): +1 forward circles,
  /// 0 straight lines, −1 backward circles (r_f, r_b: forward and backward circular
  /// components of each node's orbit). NaN for axial and torsional modes.
  Real directivity = 0;
  ModeType type = ModeType::lateral;
  /// The fraction of the rotor's lateral motion (v, w at its rotating nodes, in the
  /// least-squares sense) that no straight line along it holds: 0 for a rotor moving
  /// as a rigid body, towards 1 as it bends. NaN without lateral motion.
  Real bending = std::numeric_limits<Real>::quiet_NaN();
  /// bending < 0.1: cylindrical or conical (whichever of translation and tilt holds
  /// more of the straight line's motion); else bending. None for axial, torsional.
  ModeShape shape_kind = ModeShape::none;
  bool rigid_body = false;  ///< no elastic deformation (strain energy ≈ 0)
  bool oscillatory = true;  ///< Im p > 0; false for real (overdamped or rigid) eigenvalues
  /// Shape over all unconstrained DOFs (global_dof order), scaled so that its largest
  /// component is 1 (real). Empty when shapes were not requested.
  ComplexVector shape;
  /// Shape in reduced coordinates, unit 2-norm (for correlating modes).
  ComplexVector reduced_shape;
};

/// Which eigen solver to use.
enum class EigenSolver {
  automatic,  ///< all modes: dense up to ModalOptions::dense_limit; otherwise each block by a cost model
  dense,      ///< all modes: Hessenberg-QR of the state matrix (LAPACK dgeev)
  sparse      ///< lowest modes: shift-invert Arnoldi (Spectra) on a sparse LU
};
/// The words that name the solvers in options ("auto", "dense", "sparse").
inline constexpr std::string_view eigen_solver_names[] = {"auto", "dense", "sparse"};

struct ModalOptions {
  /// Number of modes wanted, the lowest by |p|. 0: all (dense) or 12 (sparse).
  Index n_modes = 0;
  EigenSolver solver = EigenSolver::automatic;
  /// Reduced DOF count up to which automatic selects the dense solver when all modes
  /// are asked for (n_modes = 0). With n_modes given (or above this size, 12 modes),
  /// automatic chooses for each decoupled block the solver a cost model expects to be
  /// faster (docs/theory/modal_analysis.md, "Choosing the solver").
  Index dense_limit = 400;
  /// Real shift σ [rad/s] for shift-invert; NaN: automatic (slightly below zero).
  Real shift = std::numeric_limits<Real>::quiet_NaN();
  /// Compute full mode shapes (Mode::shape).
  bool shapes = true;
  /// Keep only oscillatory modes (Im p > 0), n_modes of them, and a repeated pair at
  /// the cut whole (what a Campbell diagram follows). Rigid-body and overdamped modes
  /// are dropped.
  bool oscillatory_only = false;
  /// Solve the lateral motion of an axisymmetric rotor in complex forward/backward
  /// coordinates (half the order; detected per decoupled block, see
  /// docs/theory/modal_analysis.md). false: always the real form (for comparison).
  bool complex_form = true;
  /// Solve undamped blocks in their symmetric forms (docs/theory/modal_analysis.md):
  /// dense, a conservative gyroscopic block (no damping, no circulatory stiffness, no
  /// rigid-body mode; e.g. an undamped rotor at any speed) as a Hermitian-definite
  /// problem, its eigenvalues exactly on the imaginary axis; sparse, a block without
  /// damping and gyroscopic terms by symmetric Lanczos on K and M. false: always the
  /// general QR and state-space Arnoldi.
  bool hermitian_form = true;
};

/// The modes of a model at one speed: the n_modes smallest by |p|, listed by frequency.
struct ModalResult {
  Real speed = 0;  ///< [rad/s]
  std::vector<Mode> modes;
  SolverInfo info;
  /// The lateral motion was axisymmetric and solved in complex (forward/backward)
  /// coordinates: one half-size complex problem instead of the real one.
  bool complex_form = false;
  /// Some coefficient depends on the frequency of the motion: each mode was iterated
  /// until the coefficients it sees are those at its own damped frequency.
  bool frequency_dependent = false;
  /// The most eigen solves one mode needed to settle on its own frequency (0 when no
  /// coefficient depends on frequency).
  Index frequency_iterations = 0;
  /// With ModalOptions::oscillatory_only: the largest real positive eigenvalue of a
  /// mode that is not rigid-body motion [1/s] (divergence: a negative stiffness, a
  /// shaft beyond its buckling load), among the eigenvalues the solver computed (all
  /// of them in a dense solve), although such a mode is not listed; 0: none.
  Real divergence = 0;
  /// Per support (Force::supports()), its operating state at the equilibrium at this
  /// speed: one point.
  std::vector<OperatingSeries> operating;
};

/// Modal solver for one model: assembles the speed-independent matrices once and
/// solves at any number of speeds. Groups of DOFs that no matrix entry couples (e.g.
/// axial, torsional and lateral motion of a straight rotor; the two bending planes at
/// rest) are solved separately, which is cheaper and keeps the repeated eigenvalues of
/// an isotropic rotor at rest apart. A group that no speed-dependent term touches
/// (no gyroscopic or circulatory entry, no speed-dependent element: typically the
/// axial and torsional motion) is solved once and its modes reused at every speed.
/// Supports (fluid-film bearings) enter as their tangent stiffness and damping about
/// the static equilibrium at each speed (linearised(), analyses/static/equilibrium.hpp);
/// solve() then throws Error at speed 0. Coefficients that depend on the frequency of
/// the motion (frequency tables) are taken at each mode's own damped frequency ω = Im p:
/// starting from the modes with synchronous coefficients (ω = Ω), the i-th lowest
/// frequency f_i(ω) is iterated to its fixed point ω = f_i(ω) by the secant method
/// (docs/theory/modal_analysis.md, "Frequency-dependent coefficients").
/// solve() may be called from several threads.
class ModalSolver {
 public:
  explicit ModalSolver(const Model& model, ModalOptions options = {});
  /// The same with @p model already assembled (e.g. ModelFile::assembler, by the
  /// reader's check): the assembly is reused, not repeated. Null: assembled here (and
  /// always for a model with supports, whose linearisation that assembly lacks).
  ModalSolver(const Model& model, ModalOptions options, std::shared_ptr<const Assembler> assembled);
  /// Modes at speed @p speed [rad/s].
  ModalResult solve(Real speed) const;
  const ModalOptions& options() const { return options_; }
  /// Changes the number of modes wanted (see ModalOptions::n_modes).
  void set_n_modes(Index n_modes) { options_.n_modes = n_modes; }
  const Assembler& assembler() const { return *assembler_; }
  /// The supports' operating state at the equilibria at @p speeds [rad/s] about which
  /// solve() linearises them (Force::operating_data(); empty without supports).
  std::vector<OperatingSeries> operating_at(const std::vector<Real>& speeds) const;

 private:
  // dense or sparse for every block, or each decoupled block by the cost model
  // (src/analyses/modal/solver_choice.hpp).
  enum class Choice { dense, sparse, by_cost };
  Choice choice() const;
  /// The modes with every coefficient taken at frequency @p frequency (empty: synchronous).
  ModalResult solve_at(Real speed, std::optional<Real> frequency) const;
  /// The modes each at its own frequency (frequency-dependent coefficients).
  ModalResult solve_self_consistent(Real speed) const;
  // The steps of solve_at (modal.cpp).
  struct Block;  // one decoupled block of (M, D, K)
  /// The eigenpairs of every decoupled block, in vectors over all reduced DOFs.
  detail::StateEigenpairs eigenpairs(const SparseMatrix& M, const SparseMatrix& D, const SparseMatrix& K,
                                     bool& any_complex) const;
  Block block(const std::vector<Index>& dofs, std::vector<Index>& local, const SparseMatrix& M, const SparseMatrix& D,
              const SparseMatrix& K) const;
  /// A block's lowest modes by Arnoldi; the first (largest) block sets @p cutoff.
  detail::StateEigenpairs lowest_by_arnoldi(const Block& b, bool first, Real& cutoff) const;
  /// A block's lowest @p count modes by the solver that applies, cached when constant.
  detail::StateEigenpairs block_modes(const Block& b, Index count, bool arnoldi) const;
  /// The modes of the eigenpairs: rigid-body zeros once, divergence, type, whirl, shape.
  void add_modes(const detail::StateEigenpairs& pairs, const SystemMatrices& sys, ModalResult& result) const;
  void describe(Mode& mode, const ComplexVector& phi, const ComplexVector& Mphi) const;
  /// The lowest modes by |p| (a repeated pair kept whole), listed by frequency.
  void keep_lowest(ModalResult& result) const;
  Real zero_tol() const;  // |p| below which an eigenvalue is zero
  Index wanted() const;   // modes wanted (12 by default unless the dense solver gives all)

  ModalOptions options_;
  std::shared_ptr<const Model> linear_;  // linearised(model) with supports, else null
  std::shared_ptr<const Assembler> assembler_;
  std::vector<Force> supports_;                      // the model's supports (solve() refuses speed 0 with them)
  std::vector<OperatingSeries> operating_;           // operating_series(model): names, no points
  std::vector<std::pair<Index, Real>> rotor_nodes_;  // the rotating nodes and their x, for Mode::bending
  Real lambda_max_ = 1.0;                            // estimate of the largest K/M ratio (scale for tolerances)
  std::vector<char> speed_touched_;                  // per reduced DOF: some speed-dependent entry touches it
  // Per reduced DOF: the reduced DOF it pairs with in complex coordinates (v with w,
  // ry with rz at the same node) for the first of a pair, −1 for the second, −2 for
  // a DOF that cannot pair (axial, torsional, or its partner not a reduced DOF).
  std::vector<Index> twin_;
  struct BlockCache;  // the modes of speed-independent DOF groups
  std::shared_ptr<BlockCache> cache_;
};

/// Complex modal assurance criterion |aᴴb|²/(|a|²|b|²).
Real mac(const ComplexVector& a, const ComplexVector& b);

/// Convenience: modes of @p model at speed @p speed [rad/s] (@p assembled as for
/// ModalSolver).
ModalResult run_modal(const Model& model, Real speed, const ModalOptions& options = {},
                      std::shared_ptr<const Assembler> assembled = nullptr);

}  // namespace feran
