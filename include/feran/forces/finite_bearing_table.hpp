#pragma once
/// @file
/// The finite-length bearing's film force tabulated once per bearing shape, for
/// run-ups and studies: the discrete Reynolds solution (finite_bearing.hpp) depends,
/// after scaling, on two numbers only, over which it is interpolated by bicubic
/// Hermite polynomials with an error measured against the solver when the table is
/// built. Theory: docs/theory/fluid_film_bearings.md, "The tabulated finite bearing".

#include <memory>

#include <Eigen/Core>

#include <feran/core/types.hpp>
#include <feran/forces/finite_bearing.hpp>

namespace feran {

struct JournalBearingGeometry;
struct FilmForce;

/// The largest relative errors of a table, measured against the Reynolds solver at
/// the centre of each of its cells (where a Hermite interpolant's error is largest).
struct FilmTableError {
  Real force = 0.0;          ///< max |Ψ_table − Ψ|/|Ψ|
  Real jacobian = 0.0;       ///< max ‖∇Ψ_table − ∇Ψ‖/‖∇Ψ‖ (Frobenius)
  Real peak_pressure = 0.0;  ///< max relative error of the largest nodal pressure
};

/// The dimensionless film force Ψ(e′) of one bearing shape (L/D, grid, cavitation):
/// the force on a journal at e′ = x/c whose film is driven by u = (1, 0), where
/// u = Ω·x/c + 2·J·v/c (J: +90°) is all the Reynolds equation's right-hand side
/// depends on. Tabulated over the eccentricity ε = |e′| ≤ max_eccentricity (nodes
/// uniform in t = −ln(1 − ε), so that they crowd where the film closes) and the angle
/// of e′ (uniform, periodic); the weighted force (1 − ε)²·Ψ is interpolated by
/// bicubic Hermite polynomials from the solver's values and exact first derivatives,
/// the mixed derivative by central differences: fourth-order in the node spacing for
/// the force, third-order for its Jacobian (the interpolant's own derivative).
class FiniteBearingTable {
 public:
  struct Layout {
    int eccentricities = 41;       ///< nodes in ε, from 0 to max_eccentricity
    int angles = 48;               ///< nodes around the circle
    Real max_eccentricity = 0.95;  ///< beyond it the solver is called
  };

  /// Builds the table: (eccentricities × angles) + (eccentricities − 1) × angles
  /// solutions of the Reynolds equation (the nodes, then the cells' centres for the
  /// error).
  FiniteBearingTable(Real length_over_diameter, const FiniteBearingGrid& grid, Layout layout);

  /// Ψ and ∂Ψ/∂e′ at @p e; false when |e| is beyond the table.
  bool evaluate(const Eigen::Vector2d& e, Eigen::Vector2d& psi, Eigen::Matrix2d& gradient) const;

  /// The film force and its Jacobian from the table, as finite_bearing_force() gives
  /// them, with the largest film pressure (tabulated too, its slopes by differences);
  /// false, @p out untouched, when the journal is beyond the table's eccentricity.
  bool force(const JournalBearingGeometry& g, Real speed, const Eigen::Vector2d& x, const Eigen::Vector2d& v,
             FilmForce& out) const;

  const FilmTableError& error() const { return error_; }
  /// The bound on error().force within which film_force() uses the table: 1 %.
  static constexpr Real force_bound = 1e-2;
  bool usable() const { return error_.force <= force_bound; }
  const Layout& layout() const { return layout_; }

  /// The table of a bearing shape, built on first use and kept for the process (one
  /// table serves every bearing of the same L/D, grid and cavitation; thread-safe;
  /// the 32 last built are kept). The default layout, and should its error exceed the
  /// bound, one with twice the nodes each way; when that fails too, usable() is false.
  static std::shared_ptr<const FiniteBearingTable> shared(Real length_over_diameter, const FiniteBearingGrid& grid);

 private:
  // (1 − ε)²·(Ψ₁, Ψ₂, Π) and their derivatives in t, α, t and α; Π the largest
  // nodal pressure P for the unit drive.
  using Value = Eigen::Vector3d;
  struct Node {
    Value g, gt, ga, gta;
  };
  const Node& node(int i, int j) const {
    const int angle = ((j % layout_.angles) + layout_.angles) % layout_.angles;
    return nodes_[static_cast<std::size_t>(i) * static_cast<std::size_t>(layout_.angles) +
                  static_cast<std::size_t>(angle)];
  }
  // (Ψ, Π) and their derivatives in ε and α at (t, α).
  void interpolate(Real t, Real alpha, Value& psi, Value& dpsi_de, Value& dpsi_da) const;
  // (Ψ, Π) and ∂Ψ/∂e′ at e′; false beyond the table.
  bool lookup(const Eigen::Vector2d& e, Value& psi, Eigen::Matrix2d& gradient) const;

  Layout layout_;
  Real ht_ = 0.0, ha_ = 0.0;
  std::vector<Node> nodes_;
  FilmTableError error_;
};

}  // namespace feran
