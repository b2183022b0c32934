#pragma once
/// @file
/// Scalar, index and matrix aliases used throughout feran.

#include <cmath>
#include <complex>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace feran {

/// Floating-point type of all physical quantities (SI units everywhere).
using Real = double;
/// Index type for vectors, matrices and DOF numbers.
using Index = Eigen::Index;
using Complex = std::complex<Real>;

/// |z|² and |z| computed directly: std::abs of a complex number is a hypot call (safe
/// against overflow beyond 1e154, which no eigenvalue or amplitude comes near) and
/// several times slower where many are compared.
inline Real abs2(Complex z) { return z.real() * z.real() + z.imag() * z.imag(); }
inline Real magnitude(Complex z) { return std::sqrt(abs2(z)); }

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;
using ComplexVector = Eigen::VectorXcd;
using ComplexMatrix = Eigen::MatrixXcd;
/// Column-major sparse matrix used for the assembled global matrices.
using SparseMatrix = Eigen::SparseMatrix<Real>;

/// Number of degrees of freedom of every node.
inline constexpr int dofs_per_node = 6;

/// Local DOF of a node, in storage order: u (along x), v (along y), w (along z),
/// rx (torsion θx), ry (θy), rz (θz). Bending in the x–y plane uses v and rz,
/// in the x–z plane w and ry, with rz = +dv/dx and ry = −dw/dx (right-handed).
enum class Dof : int { u = 0, v = 1, w = 2, rx = 3, ry = 4, rz = 5 };

/// Global (unconstrained) DOF number of local DOF @p d of node @p node.
constexpr Index global_dof(Index node, Dof d) { return dofs_per_node * node + static_cast<Index>(d); }

/// Short name of a local DOF ("u", "v", "w", "rx", "ry", "rz").
const char* dof_name(Dof d);

inline constexpr Real pi = 3.141592653589793238462643383279502884;
/// The default gravitational acceleration [m/s²] (when a model gives none).
inline constexpr Real standard_gravity = 9.81;
/// Converts a speed in Hz (revolutions per second) to rad/s.
constexpr Real hz_to_rad(Real hz) { return 2.0 * pi * hz; }
/// Converts a speed in rad/s to Hz.
constexpr Real rad_to_hz(Real rad) { return rad / (2.0 * pi); }

}  // namespace feran
