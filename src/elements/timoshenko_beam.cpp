#include <feran/elements/timoshenko_beam.hpp>

#include <cmath>

#include <feran/elements/plane_layout.hpp>

namespace feran {

TimoshenkoBeam::TimoshenkoBeam(Index node_a, Index node_b, Real length, CircularSection section,
                               Material material, BeamOptions options)
    : node_a_(node_a),
      node_b_(node_b),
      length_(length),
      section_(section),
      material_(std::move(material)),
      options_(options) {}

Real TimoshenkoBeam::shear_parameter() const {
  if (!options_.shear_deformation) return 0.0;
  const Real nu = material_.poisson();
  const Real kappa = options_.shear == ShearCoefficient::given        ? options_.kappa
                     : options_.shear == ShearCoefficient::hutchinson ? section_.hutchinson_shear_coefficient(nu)
                                                                      : section_.cowper_shear_coefficient(nu);
  return 12.0 * material_.E * section_.second_moment() /
         (kappa * material_.G * section_.area() * length_ * length_);
}

Matrix TimoshenkoBeam::bending_stiffness() const {
  const Real L = length_, phi = shear_parameter();
  const Real f = material_.E * section_.second_moment() / ((1.0 + phi) * L * L * L);
  Matrix k(4, 4);
  k << 12, 6 * L, -12, 6 * L,                                   //
      6 * L, (4 + phi) * L * L, -6 * L, (2 - phi) * L * L,      //
      -12, -6 * L, 12, -6 * L,                                  //
      6 * L, (2 - phi) * L * L, -6 * L, (4 + phi) * L * L;
  return f * k;
}

Matrix TimoshenkoBeam::bending_translational_mass() const {
  const Real L = length_, p = shear_parameter();
  const Real m1 = 312 + 588 * p + 280 * p * p;
  const Real m2 = (44 + 77 * p + 35 * p * p) * L;
  const Real m3 = 108 + 252 * p + 140 * p * p;
  const Real m4 = -(26 + 63 * p + 35 * p * p) * L;
  const Real m5 = (8 + 14 * p + 7 * p * p) * L * L;
  const Real m6 = -(6 + 14 * p + 7 * p * p) * L * L;
  Matrix m(4, 4);
  m << m1, m2, m3, m4,  //
      m2, m5, -m4, m6,  //
      m3, -m4, m1, -m2,  //
      m4, m6, -m2, m5;
  return material_.rho * section_.area() * L / (840.0 * (1 + p) * (1 + p)) * m;
}

Matrix TimoshenkoBeam::bending_rotary_mass() const {
  const Real L = length_, p = shear_parameter();
  const Real m7 = 36;
  const Real m8 = (3 - 15 * p) * L;
  const Real m9 = (4 + 5 * p + 10 * p * p) * L * L;
  const Real m10 = (-1 - 5 * p + 5 * p * p) * L * L;
  Matrix m(4, 4);
  m << m7, m8, -m7, m8,   //
      m8, m9, -m8, m10,   //
      -m7, -m8, m7, -m8,  //
      m8, m10, -m8, m9;
  return material_.rho * section_.second_moment() / (30.0 * (1 + p) * (1 + p) * L) * m;
}

LocalMatrices TimoshenkoBeam::local_matrices(const OperatingPoint& /*op*/) const {
  const Real L = length_;
  const Real E = material_.E, Gm = material_.G, rho = material_.rho;
  const Real A = section_.area(), Ip = section_.polar_moment();
  constexpr int n = 2 * dofs_per_node;

  LocalMatrices out;
  out.dofs.resize(n);
  for (int d = 0; d < dofs_per_node; ++d) {
    out.dofs[static_cast<std::size_t>(d)] = dofs_per_node * node_a_ + d;
    out.dofs[static_cast<std::size_t>(d + dofs_per_node)] = dofs_per_node * node_b_ + d;
  }
  out.K = Matrix::Zero(n, n);
  out.M = Matrix::Zero(n, n);
  out.loss_factor = options_.loss_factor;

  // Axial (u) and torsion (rx): two-node bars with linear shape functions.
  auto add_bar = [](Matrix& target, int dof, Real stiff, Real mass_factor, Matrix& mass) {
    const int a = dof, b = dof + dofs_per_node;
    target(a, a) += stiff;
    target(b, b) += stiff;
    target(a, b) -= stiff;
    target(b, a) -= stiff;
    mass(a, a) += 2.0 * mass_factor;
    mass(b, b) += 2.0 * mass_factor;
    mass(a, b) += mass_factor;
    mass(b, a) += mass_factor;
  };
  add_bar(out.K, static_cast<int>(Dof::u), E * A / L, rho * A * L / 6.0, out.M);
  add_bar(out.K, static_cast<int>(Dof::rx), Gm * Ip / L, rho * Ip * L / 6.0, out.M);

  const Matrix kb = bending_stiffness();
  const Matrix mr = bending_rotary_mass();
  detail::add_to_both_planes(kb, out.K);
  detail::add_to_both_planes(
      options_.rotary_inertia ? Matrix(bending_translational_mass() + mr) : bending_translational_mass(), out.M);
  if (options_.rayleigh_alpha != 0.0 || options_.rayleigh_beta != 0.0)
    out.C = options_.rayleigh_alpha * out.M + options_.rayleigh_beta * out.K;

  if (options_.rotating) {
    out.G = Matrix::Zero(n, n);
    if (options_.gyroscopic == GyroscopicForm::consistent) {
      // ∫ρ I_p N_rᵀ N_r dx = (I_p/I)·(rotary-inertia matrix).
      detail::add_plane_coupling(mr * (Ip / section_.second_moment()), out.G);
    } else {
      // Polar inertia ρ I_p L lumped half to each node, as a thin disk.
      Matrix b = Matrix::Zero(4, 4);
      b(1, 1) = b(3, 3) = rho * Ip * L / 2.0;
      detail::add_plane_coupling(b, out.G);
    }
    if (options_.damping_beta > 0.0) {
      out.Ci = options_.damping_beta * out.K;
      out.Ki = Matrix::Zero(n, n);
      detail::add_plane_coupling(options_.damping_beta * kb, out.Ki);
    }
  }
  return out;
}

}  // namespace feran
