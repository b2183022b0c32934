#include <feran/forces/finite_bearing_table.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <thread>
#include <tuple>

#include <feran/core/error.hpp>
#include <feran/forces/fluid_film_bearing.hpp>

namespace feran {

namespace {

// The weight (1 − ε)^k = e^{−k·t} taken out of Ψ before interpolating: the film force
// grows like (1 − ε)^{−3/2} to (1 − ε)^{−5/2} as the film closes (rotation, squeeze),
// so the weighted force changes slowly in t everywhere.
constexpr Real weight_exponent = 2.0;

// The bicubic Hermite basis on [0, 1]: values (v0, v1) and slopes (d0, d1), with their
// derivatives.
struct Hermite {
  Real v[2], d[2], dv[2], dd[2];
  explicit Hermite(Real s) {
    const Real s2 = s * s, s3 = s2 * s;
    v[0] = 2 * s3 - 3 * s2 + 1;
    v[1] = -2 * s3 + 3 * s2;
    d[0] = s3 - 2 * s2 + s;
    d[1] = s3 - s2;
    dv[0] = 6 * s2 - 6 * s;
    dv[1] = -6 * s2 + 6 * s;
    dd[0] = 3 * s2 - 4 * s + 1;
    dd[1] = 3 * s2 - 2 * s;
  }
};

// (Ψ, Π) and ∂Ψ/∂e′ of the solver at e′ for a bearing of L/D = @p ld (D = 1, c = 1).
void solve(Real ld, const FiniteBearingGrid& grid, const Eigen::Vector2d& e, Eigen::Vector3d& psi,
           Eigen::Matrix2d& gradient) {
  const JournalBearingGeometry g{.diameter = 1.0, .length = ld, .clearance = 1.0, .viscosity = 1.0};
  // u = Ω·e + 2·J·v = (1, 0) with Ω = 0 and v = (0, −1/2).
  const FilmForce f = finite_bearing_force(g, grid, 0.0, e, Eigen::Vector2d(0.0, -0.5));
  const Real scale = 6.0 * 0.125 * ld;        // 6μR³L/c²
  psi << f.f / scale, f.peak_pressure / 1.5;  // p = (6μR²/c²)·P
  gradient = f.dfdx / scale;
}

// Runs body(k) for k in [0, n) on the machine's threads.
template <class Body>
void parallel_for(int n, const Body& body) {
  const int threads = std::max(1, std::min<int>(n, static_cast<int>(std::thread::hardware_concurrency())));
  std::vector<std::thread> pool;
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
  for (int w = 0; w < threads; ++w)
    pool.emplace_back([&, w] {
      try {
        for (int k = w; k < n; k += threads) body(k);
      } catch (...) {
        errors[static_cast<std::size_t>(w)] = std::current_exception();
      }
    });
  for (auto& t : pool) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace

FiniteBearingTable::FiniteBearingTable(Real ld, const FiniteBearingGrid& grid, Layout layout) : layout_(layout) {
  if (layout.eccentricities < 2 || layout.angles < 4 || !(layout.max_eccentricity > 0 && layout.max_eccentricity < 1))
    throw Error(
        "a finite-bearing table needs at least 2 eccentricities, 4 angles and a largest eccentricity in (0, 1)");
  const int ne = layout.eccentricities, na = layout.angles;
  ht_ = -std::log1p(-layout.max_eccentricity) / (ne - 1);
  ha_ = 2 * pi / na;
  const Real k = weight_exponent;
  // The nodes: Ψ and ∇Ψ from the solver, turned into the weighted polar data.
  nodes_.resize(static_cast<std::size_t>(ne) * static_cast<std::size_t>(na));
  std::vector<Eigen::Matrix2d> gradients(nodes_.size());
  parallel_for(ne * na, [&](int n) {
    const int i = n / na, j = n % na;
    const Real t = i * ht_, eps = -std::expm1(-t), a = j * ha_, w = std::exp(-k * t);
    const Eigen::Vector2d r(std::cos(a), std::sin(a)), q(-r(1), r(0));
    Value psi;
    Eigen::Matrix2d& grad = gradients[static_cast<std::size_t>(n)];
    solve(ld, grid, eps * r, psi, grad);
    Node& node = nodes_[static_cast<std::size_t>(n)];
    Value psi_t, psi_a;  // ∂/∂t (∂Ψ/∂ε·dε/dt) and ∂/∂α; Π's below, by differences
    psi_t << grad * r * std::exp(-t), 0.0;
    psi_a << eps * (grad * q), 0.0;
    node.g = w * psi;
    node.gt = w * (psi_t - k * psi);
    node.ga = w * psi_a;
  });
  // Π's slopes: central differences of the weighted values (one-sided at the ends in t).
  for (int i = 0; i < ne; ++i)
    for (int j = 0; j < na; ++j) {
      Node& here = nodes_[static_cast<std::size_t>(i) * static_cast<std::size_t>(na) + static_cast<std::size_t>(j)];
      const int lo = std::max(i - 1, 0), hi = std::min(i + 1, ne - 1);
      here.gt(2) = (node(hi, j).g(2) - node(lo, j).g(2)) / ((hi - lo) * ht_);
      here.ga(2) = (node(i, j + 1).g(2) - node(i, j - 1).g(2)) / (2 * ha_);
    }
  // The mixed derivative: at ε = 0 exactly (∂/∂α of ∇Ψ·r̂, ∇Ψ being that of one point),
  // elsewhere by central differences of ∂G/∂t around the circle.
  for (int i = 0; i < ne; ++i)
    for (int j = 0; j < na; ++j) {
      Node& here = nodes_[static_cast<std::size_t>(i) * static_cast<std::size_t>(na) + static_cast<std::size_t>(j)];
      here.gta = (node(i, j + 1).gt - node(i, j - 1).gt) / (2 * ha_);
      if (i == 0) {
        const Real a = j * ha_;
        here.gta.head<2>() = gradients[static_cast<std::size_t>(j)] * Eigen::Vector2d(-std::sin(a), std::cos(a));
      }
    }
  // The error at the cells' centres.
  const int cells = (ne - 1) * na;
  std::vector<FilmTableError> errors(static_cast<std::size_t>(cells));
  parallel_for(cells, [&](int n) {
    const int i = n / na, j = n % na;
    const Real t = (i + 0.5) * ht_, eps = -std::expm1(-t), a = (j + 0.5) * ha_;
    const Eigen::Vector2d e = eps * Eigen::Vector2d(std::cos(a), std::sin(a));
    Value psi, psi_table;
    Eigen::Matrix2d grad, grad_table;
    solve(ld, grid, e, psi, grad);
    lookup(e, psi_table, grad_table);
    errors[static_cast<std::size_t>(n)] = {(psi_table - psi).head<2>().norm() / psi.head<2>().norm(),
                                           (grad_table - grad).norm() / grad.norm(),
                                           std::abs(psi_table(2) - psi(2)) / psi(2)};
  });
  for (const auto& e : errors) {
    error_.force = std::max(error_.force, e.force);
    error_.jacobian = std::max(error_.jacobian, e.jacobian);
    error_.peak_pressure = std::max(error_.peak_pressure, e.peak_pressure);
  }
}

void FiniteBearingTable::interpolate(Real t, Real alpha, Value& psi, Value& dpsi_de, Value& dpsi_da) const {
  const Real st = t / ht_, sa = alpha / ha_;
  const int i = std::min(static_cast<int>(st), layout_.eccentricities - 2);
  const int j = static_cast<int>(std::floor(sa));
  const Hermite bt(st - i), ba(sa - j);
  Value g = Value::Zero(), gt = g, ga = g;
  for (int p = 0; p < 2; ++p)
    for (int q = 0; q < 2; ++q) {
      const Node& n = node(i + p, j + q);
      g += bt.v[p] * ba.v[q] * n.g + ht_ * bt.d[p] * ba.v[q] * n.gt + ha_ * bt.v[p] * ba.d[q] * n.ga +
           ht_ * ha_ * bt.d[p] * ba.d[q] * n.gta;
      gt += (bt.dv[p] * ba.v[q] * n.g + ha_ * bt.dv[p] * ba.d[q] * n.ga) / ht_ + bt.dd[p] * ba.v[q] * n.gt +
            ha_ * bt.dd[p] * ba.d[q] * n.gta;
      ga += (bt.v[p] * ba.dv[q] * n.g + ht_ * bt.d[p] * ba.dv[q] * n.gt) / ha_ + bt.v[p] * ba.dd[q] * n.ga +
            ht_ * bt.d[p] * ba.dd[q] * n.gta;
    }
  const Real w = std::exp(weight_exponent * t);  // 1/(1 − ε)^k
  psi = w * g;
  dpsi_de = w * (gt + weight_exponent * g) * std::exp(t);  // ∂Ψ/∂t · dt/dε
  dpsi_da = w * ga;
}

bool FiniteBearingTable::evaluate(const Eigen::Vector2d& e, Eigen::Vector2d& psi, Eigen::Matrix2d& gradient) const {
  Value value;
  if (!lookup(e, value, gradient)) return false;
  psi = value.head<2>();
  return true;
}

bool FiniteBearingTable::lookup(const Eigen::Vector2d& e_in, Value& psi, Eigen::Matrix2d& gradient) const {
  Eigen::Vector2d e = e_in;
  // At the very centre the angle is undefined, though Ψ and its gradient are not:
  // taken at 1e-12 along the first axis.
  if (e.norm() < 1e-12) e = Eigen::Vector2d(1e-12, 0.0);
  const Real eps = e.norm();
  if (eps > layout_.max_eccentricity) return false;
  Real alpha = std::atan2(e(1), e(0));
  if (alpha < 0) alpha += 2 * pi;
  const Real t = -std::log1p(-eps);
  Value dpsi_de, dpsi_da;
  interpolate(t, alpha, psi, dpsi_de, dpsi_da);
  const Eigen::Vector2d r = e / eps, q(-r(1), r(0));
  gradient = dpsi_de.head<2>() * r.transpose() + (dpsi_da.head<2>() / eps) * q.transpose();
  return true;
}

bool FiniteBearingTable::force(const JournalBearingGeometry& g, Real speed, const Eigen::Vector2d& x,
                               const Eigen::Vector2d& v, FilmForce& out) const {
  const Real c = g.clearance, R = 0.5 * g.diameter;
  const Eigen::Matrix2d J{{0.0, -1.0}, {1.0, 0.0}};
  const Eigen::Vector2d e = x / c;
  const Eigen::Vector2d u = speed * e + 2.0 * J * v / c;
  const Real un = u.norm();
  // The frame of u: Q = [û, J·û]; where u vanishes (no film drive) the force does
  // too, and its Jacobian is the limit along e (or the first axis).
  Eigen::Vector2d uh =
      un > 0 ? Eigen::Vector2d(u / un) : (e.norm() > 0 ? Eigen::Vector2d(e.normalized()) : Eigen::Vector2d(1.0, 0.0));
  Eigen::Matrix2d Q;
  Q.col(0) = uh;
  Q.col(1) = J * uh;
  const Eigen::Vector2d ep = Q.transpose() * e;
  Value psi;
  Eigen::Matrix2d grad;
  if (!lookup(ep, psi, grad)) return false;
  const Real scale = 6.0 * g.viscosity * R * R * R * g.length / (c * c);
  // f = S·M(u)·Ψ(Qᵀe), M(u) = |u|·Q; ∂f/∂e = S|u|·Q∇ΨQᵀ,
  // ∂f/∂u = S·(Ψ₁I + Ψ₂J − Q∇Ψ·J·e′·(J·û)ᵀ).
  const Eigen::Matrix2d dfde = scale * un * Q * grad * Q.transpose();
  const Eigen::Matrix2d dfdu =
      scale * (psi(0) * Eigen::Matrix2d::Identity() + psi(1) * J - Q * grad * (J * ep) * (J * uh).transpose());
  out.f = scale * un * (Q * psi.head<2>());
  out.dfdx = (dfde + speed * dfdu) / c;
  out.dfdv = dfdu * 2.0 * J / c;
  out.peak_pressure = std::max(0.0, un * 6.0 * g.viscosity * R * R / (c * c) * psi(2));
  return true;
}

std::shared_ptr<const FiniteBearingTable> FiniteBearingTable::shared(Real ld, const FiniteBearingGrid& grid) {
  static std::mutex mutex;
  static std::map<std::tuple<Real, int, int, int>, std::shared_ptr<const FiniteBearingTable>> tables;
  static std::vector<std::tuple<Real, int, int, int>> built;  // oldest first
  const std::lock_guard lock(mutex);
  const std::tuple key{ld, grid.circumferential, grid.axial, static_cast<int>(grid.cavitation)};
  auto& table = tables[key];
  if (table) return table;
  table = std::make_shared<const FiniteBearingTable>(ld, grid, Layout{});
  if (!table->usable()) {
    const Layout fine{.eccentricities = 2 * Layout{}.eccentricities - 1, .angles = 2 * Layout{}.angles};
    table = std::make_shared<const FiniteBearingTable>(ld, grid, fine);
  }
  auto kept = table;
  built.push_back(key);
  if (built.size() > 32) {
    tables.erase(built.front());  // a table still in use lives on with its users
    built.erase(built.begin());
  }
  return kept;
}

}  // namespace feran
