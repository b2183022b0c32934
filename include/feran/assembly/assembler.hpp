#pragma once
/// @file
/// Assembly of the global matrices in reduced coordinates.

#include <optional>

#include <feran/assembly/dof_map.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// Global matrices of M q'' + (C + C_i + Ω G) q' + (K + Ω K_i) q = f in reduced
/// coordinates (after fixed DOFs and rigid links). C and K hold the speed-dependent
/// spring–damper coefficients evaluated at the speed they were assembled for;
/// G and K_i are per unit speed.
struct SystemMatrices {
  SparseMatrix M, C, K, G, Ci, Ki;
  /// Σ η_e·K_e over elements with a hysteretic loss factor (harmonic analyses add j·Kh).
  SparseMatrix Kh;

  /// D(Ω) = C + C_i + Ω·G.
  SparseMatrix damping(Real speed) const;
  /// K(Ω) + Ω·K_i.
  SparseMatrix stiffness(Real speed) const;
};

/// Assembles a model's matrices. The speed-independent part is assembled once, at
/// construction; at() adds the speed-dependent elements for each speed.
class Assembler {
 public:
  explicit Assembler(const Model& model);

  const DofMap& dof_map() const { return dofs_; }
  /// Matrices at speed @p speed for motion at frequency @p frequency [rad/s] (empty:
  /// synchronous, frequency = speed; it matters only to frequency-dependent elements).
  SystemMatrices at(Real speed, std::optional<Real> frequency = std::nullopt) const;
  /// True when some element's matrices depend on speed (beyond G and K_i) or on the
  /// frequency of the motion.
  bool speed_dependent() const { return !speed_dependent_elements_.empty(); }
  /// True when some element's matrices depend on the frequency of the motion (seals,
  /// squeeze films, support structures given by frequency tables).
  bool frequency_dependent() const { return frequency_dependent_; }
  /// The speed-independent part (assembled once).
  const SystemMatrices& constant() const { return constant_; }
  /// Only the speed-dependent elements' contribution at @p speed and @p frequency, as
  /// for at() (zero matrices of the right size when there are none).
  SystemMatrices variable_at(Real speed, std::optional<Real> frequency = std::nullopt) const;
  /// The same values as variable_at(@p speed), written in place into @p out: the first
  /// call sizes @p out with a sparsity pattern that holds every entry the
  /// speed-dependent elements can touch (explicit zeros included); later calls only
  /// evaluate the elements and scatter their values, without allocating. For
  /// time integration, where the speed changes at every step: frequency-dependent
  /// elements see synchronous motion (frequency = speed).
  void variable_values(Real speed, SystemMatrices& out) const;

 private:
  void build_variable_scatter();

  DofMap dofs_;
  /// Row r of the transformation T (full DOF r in terms of the reduced DOFs): its
  /// (reduced DOF, weight) entries; empty for a fixed DOF.
  std::vector<std::vector<std::pair<Index, Real>>> rows_;
  SystemMatrices constant_;
  std::vector<Element> speed_dependent_elements_;  // those that depend on speed or frequency
  bool frequency_dependent_ = false;
  /// Where a local entry of a speed-dependent element lands in the pattern of
  /// variable_values(): entry `local` (column-major in the element's matrices) adds
  /// `weight`·value to `value` of the reduced matrices' value arrays.
  struct Scatter {
    Index local, value;
    Real weight;
  };
  std::vector<std::vector<Scatter>> variable_scatter_;  // per speed-dependent element
  std::vector<std::size_t> variable_dof_counts_;        // local DOFs per element
  SparseMatrix variable_pattern_;
};

}  // namespace feran
