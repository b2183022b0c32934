#include <feran/elements/timoshenko_beam.hpp>

#include <array>
#include <cmath>

#include <feran/core/quadrature.hpp>
#include <feran/elements/plane_layout.hpp>

namespace feran {

namespace {

/// The interdependent shape functions of one bending plane at ξ and their
/// x-derivatives (docs/theory/shaft_element.md).
struct PlaneShapes {
  Eigen::Matrix<Real, 1, 4> t, r, dt, dr;
};

PlaneShapes plane_shapes(Real xi, Real L, Real p) {
  const Real s = 1.0 / (1.0 + p), x2 = xi * xi, x3 = x2 * xi;
  PlaneShapes n;
  n.t << 1 - 3 * x2 + 2 * x3 + p * (1 - xi), L * (xi - 2 * x2 + x3 + p / 2 * (xi - x2)), 3 * x2 - 2 * x3 + p * xi,
      L * (-x2 + x3 - p / 2 * (xi - x2));
  n.r << 6 / L * (x2 - xi), 1 - 4 * xi + 3 * x2 + p * (1 - xi), 6 / L * (xi - x2), -2 * xi + 3 * x2 + p * xi;
  n.dt << (-6 * xi + 6 * x2 - p) / L, 1 - 4 * xi + 3 * x2 + p / 2 * (1 - 2 * xi), (6 * xi - 6 * x2 + p) / L,
      -2 * xi + 3 * x2 - p / 2 * (1 - 2 * xi);
  n.dr << 6 / (L * L) * (2 * xi - 1), (-4 + 6 * xi - p) / L, 6 / (L * L) * (1 - 2 * xi), (-2 + 6 * xi + p) / L;
  n.t *= s;
  n.r *= s;
  n.dt *= s;
  n.dr *= s;
  return n;
}

/// Points of the element rule: 6 Gauss points integrate degree 11 exactly (the
/// integrands of a tapered element are of degree ≤ 8 in ξ).
const GaussLegendre& element_rule() {
  static const GaussLegendre rule = gauss_legendre(6);
  return rule;
}

}  // namespace

TimoshenkoBeam::TimoshenkoBeam(Index node_a, Index node_b, Real length, CircularSection section, Material material,
                               BeamOptions options)
    : TimoshenkoBeam(node_a, node_b, length, section, section, std::move(material), options) {}

TimoshenkoBeam::TimoshenkoBeam(Index node_a, Index node_b, Real length, CircularSection section_a,
                               CircularSection section_b, Material material, BeamOptions options)
    : node_a_(node_a),
      node_b_(node_b),
      length_(length),
      section_(section_a),
      section_b_(section_b),
      material_(std::move(material)),
      options_(options) {}

CircularSection TimoshenkoBeam::section_at(Real xi) const {
  return {section_.outer_diameter + xi * (section_b_.outer_diameter - section_.outer_diameter),
          section_.inner_diameter + xi * (section_b_.inner_diameter - section_.inner_diameter)};
}

Real TimoshenkoBeam::shear_coefficient(const CircularSection& section) const {
  const Real nu = material_.poisson();
  return options_.shear == ShearCoefficient::given        ? options_.kappa
         : options_.shear == ShearCoefficient::hutchinson ? section.hutchinson_shear_coefficient(nu)
                                                          : section.cowper_shear_coefficient(nu);
}

Real TimoshenkoBeam::shear_parameter() const {
  if (!options_.shear_deformation) return 0.0;
  const CircularSection s = tapered() ? section_at(0.5) : section_;
  return 12.0 * material_.E * s.second_moment() / (shear_coefficient(s) * material_.G * s.area() * length_ * length_);
}

template <class F>
Matrix TimoshenkoBeam::integrate(F&& integrand) const {
  const GaussLegendre& rule = element_rule();
  const Real L = length_, p = shear_parameter();
  Matrix out = Matrix::Zero(4, 4);
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const Real xi = 0.5 * (rule.nodes[i] + 1.0);
    out += (0.5 * rule.weights[i] * L) * integrand(section_at(xi), plane_shapes(xi, L, p));
  }
  return out;
}

Matrix TimoshenkoBeam::geometric_stiffness() const {
  return integrate([](const CircularSection&, const PlaneShapes& n) -> Matrix { return n.dt.transpose() * n.dt; });
}

Matrix TimoshenkoBeam::bending_stiffness() const {
  if (tapered()) {
    const Real E = material_.E, Gm = material_.G;
    const bool shear = options_.shear_deformation;
    return integrate([&](const CircularSection& s, const PlaneShapes& n) -> Matrix {
      Matrix k = E * s.second_moment() * n.dr.transpose() * n.dr;
      if (shear) {
        const Eigen::Matrix<Real, 1, 4> gamma = n.dt - n.r;
        k += shear_coefficient(s) * Gm * s.area() * gamma.transpose() * gamma;
      }
      return k;
    });
  }
  const Real L = length_, phi = shear_parameter();
  const Real f = material_.E * section_.second_moment() / ((1.0 + phi) * L * L * L);
  Matrix k(4, 4);
  k << 12, 6 * L, -12, 6 * L,                               //
      6 * L, (4 + phi) * L * L, -6 * L, (2 - phi) * L * L,  //
      -12, -6 * L, 12, -6 * L,                              //
      6 * L, (2 - phi) * L * L, -6 * L, (4 + phi) * L * L;
  return f * k;
}

Matrix TimoshenkoBeam::bending_translational_mass() const {
  if (tapered())
    return integrate([&](const CircularSection& s, const PlaneShapes& n) -> Matrix {
      return material_.rho * s.area() * n.t.transpose() * n.t;
    });
  const Real L = length_, p = shear_parameter();
  const Real m1 = 312 + 588 * p + 280 * p * p;
  const Real m2 = (44 + 77 * p + 35 * p * p) * L;
  const Real m3 = 108 + 252 * p + 140 * p * p;
  const Real m4 = -(26 + 63 * p + 35 * p * p) * L;
  const Real m5 = (8 + 14 * p + 7 * p * p) * L * L;
  const Real m6 = -(6 + 14 * p + 7 * p * p) * L * L;
  Matrix m(4, 4);
  m << m1, m2, m3, m4,   //
      m2, m5, -m4, m6,   //
      m3, -m4, m1, -m2,  //
      m4, m6, -m2, m5;
  return material_.rho * section_.area() * L / (840.0 * (1 + p) * (1 + p)) * m;
}

Matrix TimoshenkoBeam::bending_rotary_mass() const {
  if (tapered())
    return integrate([&](const CircularSection& s, const PlaneShapes& n) -> Matrix {
      return material_.rho * s.second_moment() * n.r.transpose() * n.r;
    });
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
  constexpr int n = 2 * dofs_per_node;
  // Axial and torsion bars: stiffness (·)∫A dx/L² (E, G I_p), consistent mass
  // ρ∫(·)N_aN_b dx with the linear N_a = 1 − ξ, N_b = ξ: {aa, ab, bb}. Closed forms for
  // a uniform element, Gauss–Legendre for a tapered one.
  std::array<Real, 3> area_mass{}, polar_mass{};
  Real mean_area = section_.area(), mean_polar = section_.polar_moment();
  if (tapered()) {
    const GaussLegendre& rule = element_rule();
    mean_area = mean_polar = 0.0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      const Real xi = 0.5 * (rule.nodes[i] + 1.0), w = 0.5 * rule.weights[i];
      const CircularSection s = section_at(xi);
      const std::array<Real, 3> shape{(1 - xi) * (1 - xi), xi * (1 - xi), xi * xi};
      for (std::size_t k = 0; k < 3; ++k) {
        area_mass[k] += w * rho * s.area() * L * shape[k];
        polar_mass[k] += w * rho * s.polar_moment() * L * shape[k];
      }
      mean_area += w * s.area();
      mean_polar += w * s.polar_moment();
    }
  } else {
    const Real ma = rho * mean_area * L / 6.0, mp = rho * mean_polar * L / 6.0;
    area_mass = {2.0 * ma, ma, 2.0 * ma};
    polar_mass = {2.0 * mp, mp, 2.0 * mp};
  }

  LocalMatrices out;
  out.dofs.resize(n);
  for (int d = 0; d < dofs_per_node; ++d) {
    out.dofs[static_cast<std::size_t>(d)] = dofs_per_node * node_a_ + d;
    out.dofs[static_cast<std::size_t>(d) + dofs_per_node] = dofs_per_node * node_b_ + d;
  }
  out.K = Matrix::Zero(n, n);
  out.M = Matrix::Zero(n, n);
  out.loss_factor = options_.loss_factor;

  // Axial (u) and torsion (rx): two-node bars with linear shape functions.
  auto add_bar = [](Matrix& target, int dof, Real stiff, const std::array<Real, 3>& mass_terms, Matrix& mass) {
    const int a = dof, b = dof + dofs_per_node;
    target(a, a) += stiff;
    target(b, b) += stiff;
    target(a, b) -= stiff;
    target(b, a) -= stiff;
    mass(a, a) += mass_terms[0];
    mass(b, b) += mass_terms[2];
    mass(a, b) += mass_terms[1];
    mass(b, a) += mass_terms[1];
  };
  add_bar(out.K, static_cast<int>(Dof::u), E * mean_area / L, area_mass, out.M);
  add_bar(out.K, static_cast<int>(Dof::rx), Gm * mean_polar / L, polar_mass, out.M);

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
      // ∫ρ I_p N_rᵀ N_r dx = 2·(rotary-inertia matrix), since I_p = 2I.
      detail::add_plane_coupling(2.0 * mr, out.G);
    } else {
      // Polar inertia ρ∫I_p dx lumped to the nodes (half each when uniform), as thin disks.
      Matrix b = Matrix::Zero(4, 4);
      if (tapered()) {
        b(1, 1) = polar_mass[0] + polar_mass[1];
        b(3, 3) = polar_mass[1] + polar_mass[2];
      } else {
        b(1, 1) = b(3, 3) = rho * mean_polar * L / 2.0;
      }
      detail::add_plane_coupling(b, out.G);
    }
    if (options_.damping_beta > 0.0) {
      out.Ci = options_.damping_beta * out.K;
      out.Ki = Matrix::Zero(n, n);
      detail::add_plane_coupling(options_.damping_beta * kb, out.Ki);
    }
  }
  // The geometric stiffness of the axial force, after the damping matrices: it is not
  // the material's, so neither proportional damping nor rotating damping sees it.
  if (options_.axial_force != 0.0) detail::add_to_both_planes(options_.axial_force * geometric_stiffness(), out.K);
  return out;
}

}  // namespace feran
