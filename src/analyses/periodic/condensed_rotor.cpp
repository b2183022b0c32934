#include <feran/analyses/periodic/condensed_rotor.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <feran/analyses/static/equilibrium.hpp>
#include <feran/analyses/transient/modal_basis.hpp>
#include <feran/core/error.hpp>

namespace feran {

namespace {

using RowMajor = Eigen::SparseMatrix<Real, Eigen::RowMajor>;

bool lateral(const DofMap& dofs, Index reduced) {
  const auto d = static_cast<Dof>(dofs.full_dof(reduced) % dofs_per_node);
  return d == Dof::v || d == Dof::w || d == Dof::ry || d == Dof::rz;
}

// What the periodic analysis cannot take, with the reason.
void require_time_domain_model(const Model& model, const Assembler& assembler) {
  if (assembler.frequency_dependent())
    throw Error(
        "periodic orbits: the model has supports whose coefficients depend on the frequency of the motion "
        "(tables by frequency); a periodic orbit moves at several frequencies at once and its stability needs "
        "a model in time: give those supports coefficients by speed");
  if (assembler.constant().Kh.nonZeros() > 0 && Matrix(assembler.constant().Kh).cwiseAbs().maxCoeff() > 0)
    throw Error(
        "periodic orbits: the model has hysteretic damping (a loss factor), which is defined for harmonic motion "
        "only; periodic orbits and their stability need damping in time: give it as viscous damping");
  for (const Force& f : model.forces)
    if (f.own_time_law())
      throw Error(fmt::format(
          "periodic orbits: the force '{}' follows a time law of its own (a frequency of its own or a time table), "
          "not the rotation: with it the motion is not periodic at the rotor speed (or has two base frequencies, a "
          "quasi-periodic motion), which the periodic analysis does not compute; leave it out, or make it "
          "synchronous",
          f.label()));
}

}  // namespace

CondensedRotor::CondensedRotor(const Model& model, std::shared_ptr<const Assembler> assembler,
                               const CondensationOptions& options)
    : model_(model), assembler_(std::move(assembler)), options_(options) {
  if (!assembler_) assembler_ = std::make_shared<const Assembler>(model_);
  collect();
  reduce();
}

CondensedRotor::CondensedRotor(const Model& model, std::shared_ptr<const Assembler> assembler,
                               const CondensedRotor& basis_of)
    : model_(model), assembler_(std::move(assembler)), options_(basis_of.options_) {
  if (!assembler_) assembler_ = std::make_shared<const Assembler>(model_);
  collect();
  if (assembler_->dof_map().n_reduced() != basis_of.basis_.rows() || kept_ != basis_of.kept_ ||
      force_coordinates_ != basis_of.force_coordinates_)
    throw Error(
        "periodic orbits: the parameter changed the model's DOFs or where its nonlinear forces and loads act; a "
        "branch can follow numbers only, not the model's structure");
  modes_ = basis_of.modes_;
  basis_ = basis_of.basis_;
}

void CondensedRotor::collect() {
  require_time_domain_model(model_, *assembler_);
  const DofMap& dofs = assembler_->dof_map();
  const Index n = dofs.n_reduced();
  if (n > modal_basis_max_dofs)
    throw Error(
        fmt::format("periodic orbits: the model has {} DOFs; the condensation's dense eigensolver takes at "
                    "most {}",
                    n, modal_basis_max_dofs));
  const RowMajor T = dofs.transformation();
  const auto columns_of = [&](Index full, std::set<Index>& into) {
    for (RowMajor::InnerIterator it(T, full); it; ++it)
      if (it.value() != 0.0) into.insert(it.col());
  };
  // The DOFs kept: those of the nonlinear forces, then those of the loads' nodes.
  std::set<Index> on_forces, kept;
  for (const Force& f : model_.forces)
    if (f.is_nonlinear()) {
      forces_.push_back(f);
      for (const Index d : f.dofs()) columns_of(d, on_forces);
    }
  kept = on_forces;
  for (const Force& f : model_.forces) {
    forced_ = forced_ || (options_.unbalance && f.has_harmonic());
    if ((options_.unbalance && f.has_harmonic()) || (options_.static_loads && f.has_static()))
      for (const Index node : f.nodes())
        for (const Dof d : {Dof::v, Dof::w, Dof::ry, Dof::rz}) columns_of(global_dof(node, d), kept);
  }
  kept_.assign(kept.begin(), kept.end());
  for (Index i = 0; i < static_cast<Index>(kept_.size()); ++i)
    if (on_forces.count(kept_[static_cast<std::size_t>(i)]) > 0) force_coordinates_.push_back(i);
  // Each force's local DOFs in terms of the force coordinates.
  for (const Force& f : forces_) {
    const std::vector<Index> local = f.dofs();
    Matrix S = Matrix::Zero(static_cast<Index>(local.size()), static_cast<Index>(force_coordinates_.size()));
    for (Index r = 0; r < S.rows(); ++r)
      for (RowMajor::InnerIterator it(T, local[static_cast<std::size_t>(r)]); it; ++it)
        for (Index c = 0; c < S.cols(); ++c)
          if (kept_[static_cast<std::size_t>(force_coordinates_[static_cast<std::size_t>(c)])] == it.col())
            S(r, c) += it.value();
    selectors_.push_back(std::move(S));
  }
  const bool loaded = options_.gravity.squaredNorm() > 0 || options_.static_loads;
  constant_load_ = loaded ? Vector(T.transpose() * static_load_vector(model_, options_.gravity, options_.static_loads))
                          : Vector::Zero(n);
}

void CondensedRotor::reduce() {
  const DofMap& dofs = assembler_->dof_map();
  const Index n = dofs.n_reduced();
  const bool loaded = options_.gravity.squaredNorm() > 0 || options_.static_loads;
  // Craig–Bampton: q_B = η_B; q_I = Ψ·η_B + V·η_m (+ the static deflection with B held).
  const SystemMatrices ref = assembler_->at(options_.reference_speed);
  const Matrix Kd = Matrix(ref.stiffness(options_.reference_speed));
  const Matrix K = 0.5 * (Kd + Kd.transpose()), M = Matrix(ref.M);
  std::vector<Index> interior;
  for (Index i = 0, b = 0; i < n; ++i) {
    if (b < static_cast<Index>(kept_.size()) && kept_[static_cast<std::size_t>(b)] == i)
      ++b;
    else
      interior.push_back(i);
  }
  const auto nb = static_cast<Index>(kept_.size()), ni = static_cast<Index>(interior.size());
  const auto pick = [](const Matrix& A, const std::vector<Index>& rows, const std::vector<Index>& cols) {
    Matrix out(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
    for (Index r = 0; r < out.rows(); ++r)
      for (Index c = 0; c < out.cols(); ++c)
        out(r, c) = A(rows[static_cast<std::size_t>(r)], cols[static_cast<std::size_t>(c)]);
    return out;
  };
  Matrix interior_basis(ni, 0), constraint(ni, nb);
  if (ni > 0) {
    const Matrix Mii = pick(M, interior, interior);
    Matrix Kii = pick(K, interior, interior);
    // Free interior motions (an axial or torsional rigid motion nothing holds) are not
    // touched by lateral DOFs; a shift of 1e-10 of the stiffness' scale lets the solve
    // pass them.
    Kii +=
        (1e-10 * Kii.diagonal().cwiseAbs().maxCoeff() / std::max(Mii.diagonal().cwiseAbs().maxCoeff(), 1e-300)) * Mii;
    const Eigen::LDLT<Matrix> kii(Kii);
    constraint = -kii.solve(pick(K, interior, kept_));
    const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(Kii, Mii);
    if (eig.info() != Eigen::Success) throw Error("periodic orbits: the fixed-interface modes were not found");
    std::vector<Index> chosen;
    for (Index j = 0; j < ni && static_cast<Index>(chosen.size()) < options_.modes; ++j) {
      const auto v = eig.eigenvectors().col(j);
      Real lat = 0.0;
      for (Index r = 0; r < ni; ++r)
        if (lateral(dofs, interior[static_cast<std::size_t>(r)])) lat += v(r) * v(r);
      if (lat > 1e-6 * v.squaredNorm()) chosen.push_back(j);
    }
    modes_ = static_cast<Index>(chosen.size());
    interior_basis.resize(ni, modes_ + 1);
    for (Index j = 0; j < modes_; ++j)
      interior_basis.col(j) = eig.eigenvectors().col(chosen[static_cast<std::size_t>(j)]);
    // The static deflection of the interior under the constant loads with B held, made
    // M-orthogonal to the modes kept (it is in their span when all are kept).
    Index extra = 0;
    if (loaded) {
      Vector fi(ni);
      for (Index r = 0; r < ni; ++r) fi(r) = constant_load_(interior[static_cast<std::size_t>(r)]);
      const Vector r0 = kii.solve(fi);
      Vector r = r0;
      for (Index j = 0; j < modes_; ++j) r -= interior_basis.col(j) * interior_basis.col(j).dot(Mii * r);
      const Real size0 = std::sqrt(std::max(r0.dot(Mii * r0), 0.0)), size = std::sqrt(std::max(r.dot(Mii * r), 0.0));
      if (size0 > 0 && size > 1e-8 * size0) {
        interior_basis.col(modes_) = r / size;
        extra = 1;
      }
    }
    interior_basis.conservativeResize(ni, modes_ + extra);
  }
  basis_ = Matrix::Zero(n, nb + interior_basis.cols());
  for (Index b = 0; b < nb; ++b) basis_(kept_[static_cast<std::size_t>(b)], b) = 1.0;
  for (Index r = 0; r < ni; ++r) {
    basis_.row(interior[static_cast<std::size_t>(r)]).head(nb) = constraint.row(r);
    basis_.row(interior[static_cast<std::size_t>(r)]).tail(interior_basis.cols()) = interior_basis.row(r);
  }
}

PeriodicSystem CondensedRotor::at(Real speed, Real omega, const FourierBasis& fourier) const {
  const SystemMatrices s = assembler_->at(speed);
  const Matrix& P = basis_;
  const Index nr = size(), terms = fourier.terms();
  PeriodicSystem out{.M = P.transpose() * (s.M * P),
                     .C = P.transpose() * (s.damping(speed) * P),
                     .K = P.transpose() * (s.stiffness(speed) * P),
                     .external = Vector::Zero(nr * terms),
                     .force = nullptr,
                     .force_dofs = force_coordinates_};
  out.external.head(nr) = P.transpose() * constant_load_;
  if (forced_ && fourier.harmonics > 0) {
    if (std::abs(omega - speed) > 1e-12 * std::max(std::abs(speed), 1.0))
      throw Error(fmt::format(
          "periodic orbits: the unbalance acts at the rotor speed {:.6g} rad/s, the orbit's base frequency is "
          "{:.6g} rad/s; orbits with two base frequencies (a self-excited whirl meeting the unbalance) are "
          "quasi-periodic and not computed: leave the unbalance out for the whirl alone",
          speed, omega));
    ComplexVector f = ComplexVector::Zero(model_.n_dofs());
    const HarmonicExcitation at_speed{speed, speed, true, true};
    for (const Force& force : model_.forces)
      if (force.has_harmonic()) force.add_harmonic(at_speed, f);
    const ComplexVector fr =
        P.transpose().cast<Complex>() * (assembler_->dof_map().transformation().transpose().cast<Complex>() * f);
    out.external.segment(nr, nr) = fr.real();       // x = Re(F e^{iΩt}): a = Re F
    out.external.segment(2 * nr, nr) = -fr.imag();  // b = −Im F
  }
  if (!forces_.empty()) {
    out.force = [this, speed](Real t, const Vector& x, const Vector& v) {
      const Index nf = x.size();
      NonlinearForceValue total{Vector::Zero(nf), Matrix::Zero(nf, nf), Matrix::Zero(nf, nf)};
      const MotionState state{.t = t, .speed = speed, .acceleration = 0.0, .angle = speed * t, .trajectory = false};
      for (std::size_t i = 0; i < forces_.size(); ++i) {
        const Matrix& S = selectors_[i];
        const NonlinearForceValue f = forces_[i].force(state, S * x, S * v);
        total.f.noalias() += S.transpose() * f.f;
        total.dfdx.noalias() += S.transpose() * f.dfdx * S;
        if (f.dfdv.size() != 0) total.dfdv.noalias() += S.transpose() * f.dfdv * S;
      }
      return total;
    };
  }
  return out;
}

Vector CondensedRotor::static_equilibrium(Real speed) const {
  const Equilibrium e = solve_equilibrium(
      model_, *assembler_, speed,
      {.gravity = options_.gravity, .loads = options_.static_loads, .tolerance = 1e-10, .max_iterations = 60});
  if (!e.info.converged())
    throw Error(fmt::format("periodic orbits: the static equilibrium was not found: {}", e.info.message));
  const Matrix full = assembler_->dof_map().transformation() * basis_;
  return full.colPivHouseholderQr().solve(e.q);
}

Vector CondensedRotor::expand(const Vector& eta) const {
  return assembler_->dof_map().transformation() * (basis_ * eta);
}

}  // namespace feran
