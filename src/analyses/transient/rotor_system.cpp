#include <feran/analyses/transient/rotor_system.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/forces/unbalance.hpp>

namespace feran {

RotorSystem::RotorSystem(const Model& model, SpeedProfile profile, Vector constant_load, const Drive* drive,
                         std::shared_ptr<const Assembler> assembled)
    : model_(model),
      assembler_(assembled ? std::move(assembled) : std::make_shared<const Assembler>(model)),
      profile_(std::move(profile)),
      constant_load_(std::move(constant_load)),
      cached_speed_(std::numeric_limits<Real>::quiet_NaN()),
      jacobian_speed_(std::numeric_limits<Real>::quiet_NaN()) {
  const SystemMatrices& c = assembler_->constant();
  M_ = c.M, C_ = c.C, K_ = c.K, G_ = c.G, Ci_ = c.Ci, Ki_ = c.Ki;
  M_.makeCompressed();
  Cc_ = C_ + Ci_;
  Cc_.prune(0.0);
  mass_.compute(M_);
  if (mass_.info() != Eigen::Success) throw Error("transient: the mass matrix is not positive definite");
  // The rows of T for a force's DOFs map reduced coordinates to its local ones.
  const Eigen::SparseMatrix<Real, Eigen::RowMajor> Tr = assembler_->dof_map().transformation();
  for (const Force& f : model.forces) {
    if (!f.is_nonlinear()) continue;
    const std::vector<Index> dofs = f.dofs();
    SparseMatrix sel(static_cast<Index>(dofs.size()), Tr.cols());
    std::vector<Eigen::Triplet<Real>> trip;
    for (std::size_t i = 0; i < dofs.size(); ++i)
      for (Eigen::SparseMatrix<Real, Eigen::RowMajor>::InnerIterator it(Tr, dofs[i]); it; ++it)
        trip.emplace_back(static_cast<Index>(i), it.col(), it.value());
    sel.setFromTriplets(trip.begin(), trip.end());
    selectors_.push_back(sel);
    forces_.push_back(f);
  }
  f_full_.resize(model.n_dofs());
  n_ = M_.rows();
  update_speed(profile_.speed(0.0));
  // The forces' Jacobians land in D_T and K_T at the entries of Sᵀ·1·S.
  for (const SparseMatrix& S : selectors_) {
    const Matrix ones = Matrix::Ones(S.rows(), S.rows());
    SparseMatrix pattern = S.transpose() * ones.sparseView(0.0, 0.0) * S;
    for (Index k = 0; k < pattern.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(pattern, k); it; ++it) it.valueRef() = 1.0;
    pattern.makeCompressed();
    force_patterns_.push_back(std::move(pattern));
  }
  damping_sum_ = SparseSum(damping_terms());
  stiffness_sum_ = SparseSum(stiffness_terms());
  // Sᵀ·J·S entry (r, c) = Σ S(p, r)·J(p, q)·S(q, c); D_T and K_T share one union
  // pattern only when their terms do, so each gets its positions.
  for (const SparseMatrix& S : selectors_) {
    std::vector<ForceScatter> scatter;
    const Eigen::SparseMatrix<Real, Eigen::RowMajor> Sr = S;
    for (Index p = 0; p < Sr.rows(); ++p)
      for (Eigen::SparseMatrix<Real, Eigen::RowMajor>::InnerIterator a(Sr, p); a; ++a)
        for (Index q = 0; q < Sr.rows(); ++q)
          for (Eigen::SparseMatrix<Real, Eigen::RowMajor>::InnerIterator b(Sr, q); b; ++b)
            scatter.push_back({p, q, damping_sum_.position(a.col(), b.col()), stiffness_sum_.position(a.col(), b.col()),
                               a.value() * b.value()});
    force_scatter_.push_back(std::move(scatter));
  }
  force_cache_.resize(forces_.size());
  if (drive != nullptr) set_up_drive(*drive);
}

std::vector<const SparseMatrix*> RotorSystem::damping_terms() const {
  std::vector<const SparseMatrix*> terms{&Cc_, &G_};
  if (assembler_->speed_dependent()) terms.push_back(&variable_.C);
  for (const SparseMatrix& P : force_patterns_) terms.push_back(&P);
  return terms;
}

std::vector<const SparseMatrix*> RotorSystem::stiffness_terms() const {
  std::vector<const SparseMatrix*> terms{&K_, &Ki_};
  if (assembler_->speed_dependent()) terms.push_back(&variable_.K);
  for (const SparseMatrix& P : force_patterns_) terms.push_back(&P);
  return terms;
}

std::vector<Real> RotorSystem::tangent_coefficients(Real speed) const {
  std::vector<Real> c{1.0, speed};
  if (assembler_->speed_dependent()) c.push_back(1.0);
  c.resize(c.size() + force_patterns_.size(), 0.0);  // the forces' entries: zero, then scattered
  return c;
}

void RotorSystem::set_up_drive(const Drive& drive) {
  driven_ = true;
  drive_ = drive;
  const SparseMatrix Tt = assembler_->dof_map().transformation().transpose();
  // The unbalances' coupling: their force is Ω²·c(φ) + Ω'·s(φ), each a combination of
  // its values at φ = 0 and φ = 90° (the force turns with e^{iφ}).
  Real unbalance_inertia = 0.0;
  const auto unbalance_part = [&](Real speed, Real acceleration, Real angle) {
    Vector f = Vector::Zero(model_.n_dofs());
    for (const Force& force : model_.forces)
      if (force.synchronous_inertia()) force.add_transient({0.0, speed, acceleration, angle}, f);
    return Vector(Tt * f);
  };
  for (const Force& force : model_.forces) unbalance_inertia += force.synchronous_inertia().value_or(0.0);
  S0_ = unbalance_part(0.0, 1.0, 0.0);
  S90_ = unbalance_part(0.0, 1.0, pi / 2);
  C0_ = unbalance_part(1.0, 0.0, 0.0);
  C90_ = unbalance_part(1.0, 0.0, pi / 2);
  Z0_ = mass_.solve(S0_);
  Z90_ = mass_.solve(S90_);
  // The rotating parts' polar inertia: each element's mass on the torsion DOFs (rx) of
  // rotating nodes, summed (1ᵀM_rx·1: a rigid rotation of them all).
  Real rotor_inertia = 0.0;
  for (const Element& e : model_.elements) {
    const LocalMatrices lm = e.local_matrices(OperatingPoint{});
    if (lm.M.size() == 0) continue;
    std::vector<Index> rx;
    for (std::size_t i = 0; i < lm.dofs.size(); ++i) {
      const Index node = lm.dofs[i] / dofs_per_node;
      if (lm.dofs[i] % dofs_per_node == static_cast<Index>(Dof::rx) &&
          model_.nodes[static_cast<std::size_t>(node)].rotating)
        rx.push_back(static_cast<Index>(i));
    }
    for (const Index a : rx)
      for (const Index b : rx) rotor_inertia += lm.M(a, b);
  }
  inertia_ = drive.inertia + rotor_inertia + unbalance_inertia;
  if (!(inertia_ > 0))
    throw Error(
        "runup: a driven run needs a polar inertia to accelerate: give the drive an 'inertia' or the rotor "
        "rotating parts with mass");
  for (std::size_t i = 0; i < forces_.size(); ++i)
    if (forces_[i].has_drag_torque()) drag_.push_back(i);
  // The speed column of the tangent: rows where G, K_i or the unbalances act.
  std::vector<bool> row(static_cast<std::size_t>(n_), false);
  for (const SparseMatrix* m : {&G_, &Ki_})
    for (Index k = 0; k < m->outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(*m, k); it; ++it) row[static_cast<std::size_t>(it.row())] = true;
  for (Index i = 0; i < n_; ++i)
    if (C0_(i) != 0 || C90_(i) != 0) row[static_cast<std::size_t>(i)] = true;
  for (Index i = 0; i < n_; ++i)
    if (row[static_cast<std::size_t>(i)]) border_rows_.push_back(i);
  std::vector<Eigen::Triplet<Real>> trip;
  for (Index k = 0; k < M_.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(M_, k); it; ++it) trip.emplace_back(it.row(), it.col(), it.value());
  trip.emplace_back(n_, n_, inertia_);
  mass_ext_.resize(n_ + 1, n_ + 1);
  mass_ext_.setFromTriplets(trip.begin(), trip.end());
}

void RotorSystem::mass_times(const Vector& u, Vector& y) const {
  if (!driven_) {
    y.noalias() = M_ * u;
    return;
  }
  y.resize(n_ + 1);
  y.head(n_).noalias() = M_ * u.head(n_);
  y(n_) = inertia_ * u(n_);
}

void RotorSystem::solve_mass(const Vector& r, Vector& a) {
  if (!driven_) {
    a = mass_.solve(r);
    return;
  }
  a.resize(n_ + 1);
  a.head(n_) = mass_.solve(Vector(r.head(n_)));
  a(n_) = r(n_) / inertia_;
}

void RotorSystem::update_speed(Real speed) const {
  if (!assembler_->speed_dependent() || speed == cached_speed_) return;
  assembler_->variable_values(speed, variable_);
  cached_speed_ = speed;
}

void RotorSystem::external_forces(const MotionState& state, Vector& f) const {
  f.setZero();
  for (const Force& force : model_.forces) force.add_transient(state, f);
  if (constant_load_.size() > 0) f += constant_load_;
}

void RotorSystem::rhs(Real t, const Vector& x, const Vector& v, Vector& r) {
  if (!driven_) {
    const MotionState state{t, profile_.speed(t), profile_.acceleration(t), profile_.angle(t), true};
    model_rhs(state, state, x, v, r);
    return;
  }
  const Real W = v(n_), phi = x(n_);
  xq_ = x.head(n_);
  vq_ = v.head(n_);
  // The unbalances' Ω' part is the border below: the external forces see Ω' = 0.
  const MotionState nonlinear{t, W, acceleration_, phi, true};
  model_rhs({t, W, 0.0, phi, true}, nonlinear, xq_, vq_, rq_);
  Real torque = drive_.net_torque(W);
  for (const std::size_t i : drag_)
    torque -= forces_[i].drag_torque(nonlinear, selectors_[i] * xq_, selectors_[i] * vq_);
  const Real c = std::cos(phi), s = std::sin(phi);
  // (J − sᵀz)·Ω' = T + zᵀr_q, then M q'' = r_q + s·Ω'.
  const Real szz = c * c * S0_.dot(Z0_) + c * s * (S0_.dot(Z90_) + S90_.dot(Z0_)) + s * s * S90_.dot(Z90_);
  const Real a = (torque + c * Z0_.dot(rq_) + s * Z90_.dot(rq_)) / (inertia_ - szz);
  acceleration_ = a;
  r.resize(n_ + 1);
  r.head(n_) = rq_ + (a * c) * S0_ + (a * s) * S90_;
  r(n_) = inertia_ * a;
}

void RotorSystem::model_rhs(const MotionState& external, const MotionState& nonlinear, const Vector& x, const Vector& v,
                            Vector& r) {
  const Real W = external.speed;
  update_speed(W);
  external_forces(external, f_full_);
  // Products accumulate in place (noalias): no temporaries in the step loop.
  r.noalias() = assembler_->dof_map().transformation().transpose() * f_full_;
  r.noalias() -= K_ * x;
  r.noalias() -= Cc_ * v;
  work_.noalias() = G_ * v;
  work_.noalias() += Ki_ * x;
  r -= W * work_;
  if (assembler_->speed_dependent()) {
    r.noalias() -= variable_.C * v;
    r.noalias() -= variable_.K * x;
  }
  for (std::size_t i = 0; i < forces_.size(); ++i) r += selectors_[i].transpose() * evaluate(i, nonlinear, x, v).f;
}

const NonlinearForceValue& RotorSystem::evaluate(std::size_t i, const MotionState& state, const Vector& x,
                                                 const Vector& v) const {
  ForceCache& cache = force_cache_[i];
  xl_.noalias() = selectors_[i] * x;
  vl_.noalias() = selectors_[i] * v;
  if (cache.valid && cache.state == state && cache.x == xl_ && cache.v == vl_) return cache.value;
  try {
    cache.valid = false;
    cache.value = forces_[i].force(state, xl_, vl_);
    cache.state = state;
    cache.x = xl_;
    cache.v = vl_;
    cache.valid = true;
    return cache.value;
  } catch (const Error& e) {
    // Name the force: "journal bearing 'A': the journal has reached the bearing: …".
    std::string kind(forces_[i].kind());
    std::replace(kind.begin(), kind.end(), '_', ' ');
    const std::string& label = forces_[i].label();
    throw Error(label.empty() ? fmt::format("{}: {}", kind, e.what())
                              : fmt::format("{} '{}': {}", kind, label, e.what()));
  }
}

void RotorSystem::set_jacobian(Real t, const Vector& x, const Vector& v, bool exact) {
  if (!driven_) {
    model_jacobian({t, profile_.speed(t), profile_.acceleration(t), profile_.angle(t), true}, x, v, exact);
    return;
  }
  const Real W = v(n_), phi = x(n_);
  xq_ = x.head(n_);
  vq_ = v.head(n_);
  model_jacobian({t, W, acceleration_, phi, true}, xq_, vq_, exact);
  // Bordered by the speed: −∂r_q/∂Ω = G q' + K_i q − 2Ω c(φ) (the speed-dependent
  // coefficients' and the forces' own dependence on Ω left out: an approximation the
  // W-methods and Newton's iteration accept), and −∂T/∂Ω on the diagonal.
  const Vector column = G_ * vq_ + Ki_ * xq_ - (2 * W) * (std::cos(phi) * C0_ + std::sin(phi) * C90_);
  std::vector<Eigen::Triplet<Real>> trip;
  const auto extend = [&](SparseMatrix& m, bool with_border) {
    trip.clear();
    for (Index k = 0; k < m.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(m, k); it; ++it) trip.emplace_back(it.row(), it.col(), it.value());
    if (with_border) {
      for (const Index i : border_rows_) trip.emplace_back(i, n_, column(i));
      trip.emplace_back(n_, n_, -drive_.net_slope(W));
    }
    m.resize(n_ + 1, n_ + 1);  // (resize empties m; its entries are in trip)
    m.setFromTriplets(trip.begin(), trip.end());
  };
  extend(DT_, true);
  extend(KT_, false);
}

void RotorSystem::model_jacobian(const MotionState& state, const Vector& x, const Vector& v, bool exact) {
  const Real W = state.speed;
  update_speed(W);
  jacobian_speed_ = W;
  jacobian_time_ = state.t;
  if (linear()) {
    // Set when something asks for them (tangent_values()); the banded factorisation
    // combines its kept parts instead.
    tangent_pending_ = true;
    return;
  }
  // D_T = C + C_i + Ω·G (+ the speed-dependent elements' C) − Sᵀ·∂f/∂v·S, K_T = K + Ω·K_i
  // (+ their K) − Sᵀ·∂f/∂x·S, in place in one pattern: a run sets them at every step.
  const std::vector<Real> c = tangent_coefficients(W);
  damping_sum_.evaluate(c, damping_terms(), DT_);
  stiffness_sum_.evaluate(c, stiffness_terms(), KT_);
  if (forces_.empty() || !exact) return;  // without: the forces' entries stay zero
  Real* d = DT_.valuePtr();
  Real* k = KT_.valuePtr();
  for (std::size_t i = 0; i < forces_.size(); ++i) {
    const NonlinearForceValue& f = evaluate(i, state, x, v);
    for (const ForceScatter& s : force_scatter_[i]) {
      d[s.in_damping] -= s.weight * f.dfdv(s.p, s.q);
      k[s.in_stiffness] -= s.weight * f.dfdx(s.p, s.q);
    }
  }
}

void RotorSystem::tangent_values() const {
  if (!tangent_pending_) return;
  update_speed(jacobian_speed_);
  const std::vector<Real> c = tangent_coefficients(jacobian_speed_);
  damping_sum_.evaluate(c, damping_terms(), DT_);
  stiffness_sum_.evaluate(c, stiffness_terms(), KT_);
  tangent_pending_ = false;
}

bool RotorSystem::factor_tangent(Real c_x, Real c_v, Real c_a) {
  lane_ = -1;
  // A driven run's speed row and column border the whole matrix: sparse LU.
  if (!driven_) {
    if (band_pattern_ < 0) tangent_values();  // the patterns (set once) for the band's size
    const Index nonzeros = M_.nonZeros() + DT_.nonZeros() + KT_.nonZeros();
    if (nonzeros != band_pattern_) {
      // A band for each set of unknowns no entry couples (lateral, axial, torsional).
      band_fits_ = band_.partition(n_, {&M_, &DT_, &KT_}, max_band);
      band_positions_.clear();
      if (band_fits_) {
        // D_T and K_T keep their patterns (SparseSum, the forces' entries included):
        // where their entries land in the band is found once.
        band_positions_ = {band_.positions(M_), band_.positions(DT_), band_.positions(KT_)};
      }
      band_pattern_ = nonzeros;
      band_constant_.clear();
    }
    if (band_fits_ && linear()) {
      // The kept constant and speed parts for these coefficients (set again when Δt
      // changes), combined at the tangent's speed; then the speed-dependent elements.
      const std::array<Real, 3> coefficients{c_x, c_v, c_a};
      if (band_constant_.empty() || coefficients != band_coefficients_) {
        band_.set_zero();
        band_.add(c_a, M_);
        band_.add(c_v, Cc_);
        band_.add(c_x, K_);
        band_constant_ = band_.values();
        band_.set_zero();
        band_.add(c_v, G_);
        band_.add(c_x, Ki_);
        band_speed_ = band_.values();
        band_coefficients_ = coefficients;
        lanes_good_ = lanes_used_ = 0;
      }
      lane_ = lane_at(jacobian_speed_);
      if (lane_ >= 0) {
        lanes_used_ |= 1u << lane_;
        factored_time_ = jacobian_time_;
        banded_factors_ = true;
        return true;
      }
      // A ramp: the speed changed since the last factorisation, whose time gives the
      // spacing of the steps to come. Where the last lanes went unused (steps of
      // changing size), the next 16 factorisations are single.
      const Real spacing = jacobian_time_ - factored_time_;
      if (lanes_good_ != 0 && (lanes_used_ & ~1u) == 0) {
        lane_pause_ = 16;
        lanes_good_ = 0;
      }
      factored_time_ = jacobian_time_;
      if (lane_pause_ > 0) {
        --lane_pause_;
      } else if (spacing > 0.0 && std::isfinite(spacing) && factor_lanes(jacobian_speed_, spacing, c_x, c_v)) {
        lane_ = 0;
        banded_factors_ = true;
        return true;
      }
      band_.set_combination(band_constant_, jacobian_speed_, band_speed_);
      if (assembler_->speed_dependent()) {
        update_speed(jacobian_speed_);
        if (variable_.C.nonZeros() + variable_.K.nonZeros() != variable_pattern_) {
          variable_positions_[0] = band_.positions(variable_.C);
          variable_positions_[1] = band_.positions(variable_.K);
          variable_pattern_ = variable_.C.nonZeros() + variable_.K.nonZeros();
        }
        band_.add(c_v, variable_.C, variable_positions_[0]);
        band_.add(c_x, variable_.K, variable_positions_[1]);
      }
      banded_factors_ = band_.factorize();
      if (banded_factors_) return true;
    } else if (band_fits_) {
      band_.set_zero();
      band_.add(c_a, M_, band_positions_[0]);
      band_.add(c_v, DT_, band_positions_[1]);
      band_.add(c_x, KT_, band_positions_[2]);
      banded_factors_ = band_.factorize();
      if (banded_factors_) return true;
    }
  }
  banded_factors_ = false;
  tangent_values();
  SparseMatrix S = c_a * (driven_ ? mass_ext_ : M_) + c_v * DT_ + c_x * KT_;
  S.makeCompressed();
  if (S.nonZeros() != pattern_nonzeros_) {
    lu_.analyzePattern(S);
    pattern_nonzeros_ = S.nonZeros();
  }
  lu_.factorize(S);
  return lu_.info() == Eigen::Success;
}

int RotorSystem::lane_at(Real speed) const {
  // The lanes' speeds come from times a few units of round-off away from the step's
  // own (t + j·h against the integrator's sums of Δt): a lane within 4ε of the speed
  // is its tangent to round-off, as the factorisation itself is.
  for (int l = 0; l < BandedLU::lanes; ++l)
    if ((lanes_good_ >> l & 1u) != 0 && std::abs(lane_speeds_[static_cast<std::size_t>(l)] - speed) <=
                                            4 * std::numeric_limits<Real>::epsilon() * std::abs(speed))
      return l;
  return -1;
}

bool RotorSystem::factor_lanes(Real speed, Real spacing, Real c_x, Real c_v) {
  lanes_good_ = 0;  // the speeds below are not yet the lanes' factors
  for (int l = 0; l < BandedLU::lanes; ++l)
    lane_speeds_[static_cast<std::size_t>(l)] = l == 0 ? speed : profile_.speed(jacobian_time_ + l * spacing);
  lane_additions_.clear();
  if (assembler_->speed_dependent()) {
    // The speed-dependent elements' entries at each lane's speed, merged by position.
    for (int l = 0; l < BandedLU::lanes; ++l) {
      update_speed(lane_speeds_[static_cast<std::size_t>(l)]);
      if (variable_.C.nonZeros() + variable_.K.nonZeros() != variable_pattern_) {
        variable_positions_[0] = band_.positions(variable_.C);
        variable_positions_[1] = band_.positions(variable_.K);
        variable_pattern_ = variable_.C.nonZeros() + variable_.K.nonZeros();
        if (l > 0) return false;  // the pattern changed with the speed: one at a time
      }
      std::size_t e = 0;
      for (int part = 0; part < 2; ++part) {
        const SparseMatrix& S = part == 0 ? variable_.C : variable_.K;
        const Real c = part == 0 ? c_v : c_x;
        const std::vector<Index>& at = variable_positions_[part];
        for (std::size_t i = 0; i < at.size(); ++i, ++e) {
          if (l == 0) lane_additions_.push_back({at[i], {}});
          lane_additions_[e].value[static_cast<std::size_t>(l)] = c * S.valuePtr()[i];
        }
      }
    }
    update_speed(speed);
    std::stable_sort(
        lane_additions_.begin(), lane_additions_.end(),
        [](const BandedLU::LaneAddition& a, const BandedLU::LaneAddition& b) { return a.position < b.position; });
  }
  lanes_good_ = band_.factorize_lanes(band_constant_, lane_speeds_, band_speed_, lane_additions_);
  lanes_used_ = 1u;
  if ((lanes_good_ & 1u) == 0) lanes_good_ = 0;
  return lanes_good_ != 0;
}

void RotorSystem::solve_tangent(const Vector& rhs, Vector& delta) {
  if (banded_factors_) {
    delta = rhs;
    if (lane_ >= 0)
      band_.solve_in_place(delta, lane_);
    else
      band_.solve_in_place(delta);
    return;
  }
  delta = lu_.solve(rhs);
}

Real RotorSystem::highest_frequency() {
  // Power iteration on M⁻¹K_s (K_s the symmetric stiffness at the current speed):
  // 60 iterations from a fixed start vector, then 10 % margin, since the iteration
  // approaches the largest eigenvalue from below.
  SparseMatrix K = K_;
  if (assembler_->speed_dependent()) K += variable_.K;
  const SparseMatrix Ks = 0.5 * (K + SparseMatrix(K.transpose()));
  Vector u = Vector::LinSpaced(n_, 1.0, 2.0);
  Real lambda = 0.0;
  for (int it = 0; it < 60; ++it) {
    Vector w = mass_.solve(Ks * u);
    const Real norm = w.norm();
    if (norm == 0.0) break;
    lambda = u.dot(M_ * w) / u.dot(M_ * u);
    u = w / norm;
  }
  return 1.1 * std::sqrt(std::max(lambda, 0.0));
}

}  // namespace feran
