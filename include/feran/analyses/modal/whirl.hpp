#pragma once
/// @file
/// Whirl direction of a complex mode shape and the forward/backward split of
/// repeated eigenvalues.

#include <feran/analyses/modal/modal.hpp>
#include <feran/core/types.hpp>

namespace feran {

struct WhirlResult {
  Whirl whirl = Whirl::none;
  Real directivity = 0;  ///< see Mode::directivity
};

/// Classifies a mode shape given over all unconstrained DOFs (6 per node, motion
/// q(t) = Re(shape·e^{iωt}) with ω > 0). Each node's orbit is split into a forward
/// circle of radius r_f = |V + iW|/2 and a backward one r_b = |V − iW|/2 (V, W the
/// complex v and w amplitudes). Nodes whose orbit is below 5 % of the largest are
/// ignored (near nodal points the direction is arbitrary); a node whose per-node
/// directivity (r_f − r_b)/(r_f + r_b) is within ±0.05 counts as planar. When the
/// mode has no translation the tilt vector (rz, −ry) is used instead.
WhirlResult classify_whirl(const ComplexVector& shape);

struct ShapeResult {
  Real bending = std::numeric_limits<Real>::quiet_NaN();  ///< see Mode::bending
  ModeShape kind = ModeShape::none;
};

/// How the rotor deforms in @p shape (all unconstrained DOFs, 6 per node), judged
/// on the translations v, w of @p nodes (index, axial position x): each direction's
/// amplitudes are fitted by a straight line a + b·(x − x̄) (complex a, b, least
/// squares, nodes weighted alike); bending = Σ|residual|²/Σ|amplitude|² over both
/// directions. A mode with bending < 0.1 is rigid: cylindrical when the translation
/// part n·|a|² outweighs the tilt part |b|²·Σ(x − x̄)², conical otherwise. One node:
/// cylindrical. No lateral motion: none.
ShapeResult classify_shape(const ComplexVector& shape, const std::vector<std::pair<Index, Real>>& nodes);

/// Hermitian whirl form s(x, y) = Σ_nodes (i/2)(conj(x_v)·y_w − conj(x_w)·y_v), for
/// which s(φ, φ) = Σ Im(V·conj(W)) = Σ(r_f² − r_b²): positive for forward whirl.
ComplexMatrix whirl_form(const ComplexMatrix& shapes);
/// Hermitian lateral-amplitude form n(x, y) = Σ_nodes conj(x_v)·y_v + conj(x_w)·y_w.
ComplexMatrix lateral_form(const ComplexMatrix& shapes);

}  // namespace feran
