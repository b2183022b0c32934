// Google Benchmark kernels: the inner pieces of feran's analyses on the Friswell 5.9.1
// rotor (bench/models, written by make_models.py) meshed with 6 to 501 elements.
// See bench/README.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>

#include <Eigen/SparseLU>
#include <string>

#include <feran/core/parallel.hpp>
#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/integrators/integrator.hpp>
#include <feran/analyses/transient/rotor_system.hpp>
#include <feran/assembly/assembler.hpp>
#include <feran/core/banded_lu.hpp>
#include <feran/forces/finite_bearing_table.hpp>
#include <feran/forces/fluid_film_bearing.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/analyses/periodic/orbits.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>

#include "test_models.hpp"

namespace feran {
namespace {

const Real speed_4000rpm = 4000.0 * 2.0 * pi / 60.0;

// The model with @p n_elements shaft elements, read once.
const Model& model(Index n_elements) {
  static std::map<Index, ModelFile> files;
  auto it = files.find(n_elements);
  if (it == files.end())
    it = files
             .emplace(n_elements, read_model_file(std::string(FERAN_BENCH_MODELS) + "/friswell_5_9_1_" +
                                                  std::to_string(n_elements) + ".toml"))
             .first;
  return it->second.model;
}

void sizes(benchmark::internal::Benchmark* b) {
  for (Index n : {6, 48, 99, 201, 501}) b->Arg(n);
}
// The banded kernels also at 5001 elements (30 006 DOF).
void band_sizes(benchmark::internal::Benchmark* b) {
  for (Index n : {6, 48, 99, 201, 501, 5001}) b->Arg(n);
}

// This CPU's double-precision rate (AVX2 FMA, one core), for the bounds of the
// banded kernels' counters: measured 46–49 GFLOP/s (docs/performance.md).
constexpr double flops_per_second = 47.5e9;

void dofs_counter(benchmark::State& state, const Assembler& a) {
  state.counters["dofs"] = static_cast<double>(a.dof_map().n_reduced());
}

// One shaft element's M, C, G, K (12 × 12).
void BM_ElementMatrices(benchmark::State& state) {
  const Element& beam = model(6).elements.front();
  for (auto _ : state) benchmark::DoNotOptimize(beam.local_matrices(OperatingPoint{speed_4000rpm}));
}
BENCHMARK(BM_ElementMatrices);

// Assembly of the global sparse matrices in reduced coordinates.
void BM_Assembly(benchmark::State& state) {
  const Model& m = model(state.range(0));
  for (auto _ : state) {
    const Assembler a(m);
    benchmark::DoNotOptimize(a.constant().K.nonZeros());
    dofs_counter(state, a);
  }
}
BENCHMARK(BM_Assembly)->Apply(sizes)->Unit(benchmark::kMicrosecond);

// One modal solve at 4000 rpm (the solver built once, outside the loop).
void modal_solve(benchmark::State& state, EigenSolver solver_kind, Index n_modes, bool oscillatory_only) {
  ModalOptions opt;
  opt.solver = solver_kind;
  opt.n_modes = n_modes;
  opt.oscillatory_only = oscillatory_only;
  opt.shapes = false;
  const ModalSolver solver(model(state.range(0)), opt);
  dofs_counter(state, solver.assembler());
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(speed_4000rpm));
}

// All modes by dense QR of the state matrix (the reference solver).
void BM_ModalDenseAll(benchmark::State& state) { modal_solve(state, EigenSolver::dense, 0, false); }
BENCHMARK(BM_ModalDenseAll)->Arg(6)->Arg(48)->Unit(benchmark::kMicrosecond);

// The 16 lowest oscillatory modes by dense QR (what a Campbell diagram of 12 modes asks).
void BM_ModalDenseSelected(benchmark::State& state) { modal_solve(state, EigenSolver::dense, 16, true); }
BENCHMARK(BM_ModalDenseSelected)->Arg(6)->Arg(48)->Unit(benchmark::kMicrosecond);

// The 12 lowest modes by shift-invert Arnoldi.
void BM_ModalSparse(benchmark::State& state) { modal_solve(state, EigenSolver::sparse, 12, false); }
BENCHMARK(BM_ModalSparse)->Apply(sizes)->Unit(benchmark::kMillisecond);

// Unbalance response: a sweep of 10 speeds on one thread; items are speeds.
void BM_HarmonicResponse(benchmark::State& state) {
  const Model& m = model(state.range(0));
  HarmonicOptions opt;
  for (int i = 1; i <= 10; ++i) opt.speeds.push_back(0.1 * i * speed_4000rpm);
  opt.probes = {m.n_nodes() / 2};
  opt.n_threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(run_harmonic_response(m, opt));
  state.SetItemsProcessed(state.iterations() * 10);
}
BENCHMARK(BM_HarmonicResponse)->Apply(sizes)->Unit(benchmark::kMillisecond);

// One time step of an integrator at constant speed (after start()). rk3 is explicit:
// its step must stay below the stability limit, so it takes a much shorter one.
void BM_TimeStep(benchmark::State& state, const std::string& name) {
  const Model& m = model(state.range(0));
  RotorSystem sys(m, SpeedProfile::constant(speed_4000rpm));
  IntegratorSettings settings;
  settings.dt = name == "rk3" ? 0.5 / sys.highest_frequency() : 1e-4;
  settings.allow_unstable_step = true;
  const auto integrator = make_integrator(name, settings);
  State s;
  s.x = Vector::Zero(sys.size());
  s.v = Vector::Zero(sys.size());
  integrator->start(sys, s);
  Real dt = settings.dt;
  for (auto _ : state) {
    const StepReport r = integrator->step(sys, s, dt);
    if (!r.ok) state.SkipWithError(r.message.c_str());
    if (integrator->adaptive()) dt = r.dt_next;
  }
  state.counters["dofs"] = static_cast<double>(sys.size());
}
BENCHMARK_CAPTURE(BM_TimeStep, trapezoidal, std::string("trapezoidal"))->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_TimeStep, rk3, std::string("rk3"))->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_TimeStep, wolfbrandt, std::string("wolfbrandt"))->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_TimeStep, ros34pw2, std::string("ros34pw2"))->Apply(sizes)->Unit(benchmark::kMicrosecond);

// One trapezoidal step on a speed ramp (0 → 4000 rpm in 10 s): the speed changes at
// every step, and the step refreshes its banded tangent at t_{n+1} (one exact solve)
// — against BM_TimeStep/trapezoidal at constant speed.
void BM_TimeStepRamp(benchmark::State& state) {
  const Model& m = model(state.range(0));
  RotorSystem sys(m, SpeedProfile::ramp(0.0, speed_4000rpm, 10.0));
  IntegratorSettings settings;
  settings.dt = 1e-4;
  const auto integrator = make_integrator("trapezoidal", settings);
  State s;
  s.x = Vector::Zero(sys.size());
  s.v = Vector::Zero(sys.size());
  integrator->start(sys, s);
  Index iterations = 0, steps = 0;
  for (auto _ : state) {
    const StepReport r = integrator->step(sys, s, settings.dt);
    if (!r.ok) state.SkipWithError(r.message.c_str());
    iterations += r.iterations;
    ++steps;
  }
  state.counters["dofs"] = static_cast<double>(sys.size());
  state.counters["iterations_per_step"] =
      steps > 0 ? static_cast<double>(iterations) / static_cast<double>(steps) : 0.0;
}
BENCHMARK(BM_TimeStepRamp)->Apply(sizes)->Unit(benchmark::kMicrosecond);

// The banded LU of a step's tangent S = c_a·M + c_v·D + K at 4000 rpm (Δt = 0.1 ms):
// factorisation, and one solve with the factors.
SparseMatrix step_tangent(const Model& m) {
  const Assembler a(m);
  const SystemMatrices s = a.at(speed_4000rpm);
  const Real dt = 1e-4;
  SparseMatrix S = (4.0 / (dt * dt)) * s.M + (2.0 / dt) * s.damping(speed_4000rpm) + s.stiffness(speed_4000rpm);
  S.makeCompressed();
  return S;
}

void BM_BandedFactor(benchmark::State& state) {
  const SparseMatrix S = step_tangent(model(state.range(0)));
  BandedLU lu;
  // Split as a run's tangent is (RotorSystem): a band per uncoupled set of unknowns.
  if (!lu.partition(S.rows(), {&S}, 64)) state.SkipWithError("bandwidth above 64");
  const std::vector<Index> where = lu.positions(S);
  for (auto _ : state) {
    lu.set_zero();
    lu.add(1.0, S, where);
    if (!lu.factorize()) state.SkipWithError("a small pivot");
  }
  state.counters["dofs"] = static_cast<double>(S.rows());
  state.counters["half_bandwidth"] = static_cast<double>(lu.bandwidth());
  state.counters["blocks"] = static_cast<double>(lu.blocks());
}
BENCHMARK(BM_BandedFactor)->Apply(band_sizes)->Unit(benchmark::kMicrosecond);

void BM_BandedSolve(benchmark::State& state) {
  const SparseMatrix S = step_tangent(model(state.range(0)));
  BandedLU lu;
  if (!lu.partition(S.rows(), {&S}, 64)) state.SkipWithError("bandwidth above 64");
  lu.set_zero();
  lu.add(1.0, S);
  if (!lu.factorize()) state.SkipWithError("a small pivot");
  const Vector b = Vector::Ones(S.rows());
  Vector x;
  for (auto _ : state) {
    x = b;
    lu.solve_in_place(x);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["dofs"] = static_cast<double>(S.rows());
  // The bound: reading the factors (each component's n·(2b + 1) values) once.
  state.counters["factor_bytes"] = static_cast<double>(lu.values().size() * 8);
}
BENCHMARK(BM_BandedSolve)->Apply(band_sizes)->Unit(benchmark::kMicrosecond);

// Four tangents factorised at once, one in each lane (a ramp's next four steps):
// the time of the four, against BM_BandedFactor's one.
void BM_BandedFactorLanes(benchmark::State& state) {
  const SparseMatrix S = step_tangent(model(state.range(0)));
  BandedLU lu;
  if (!lu.partition(S.rows(), {&S}, 64)) state.SkipWithError("bandwidth above 64");
  lu.set_zero();
  lu.add(1.0, S);
  const std::vector<Real> A = lu.values();
  for (auto _ : state)
    if (lu.factorize_lanes(A, {0.0, 1e-3, 2e-3, 3e-3}, A, {}) != (1u << BandedLU::lanes) - 1)
      state.SkipWithError("a small pivot");
  state.counters["dofs"] = static_cast<double>(S.rows());
  state.counters["per_matrix_us"] = benchmark::Counter(static_cast<double>(state.iterations()) * BandedLU::lanes,
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BandedFactorLanes)->Apply(band_sizes)->Unit(benchmark::kMicrosecond);

// A solve with one lane's factors (their entries four apart).
void BM_BandedSolveLane(benchmark::State& state) {
  const SparseMatrix S = step_tangent(model(state.range(0)));
  BandedLU lu;
  if (!lu.partition(S.rows(), {&S}, 64)) state.SkipWithError("bandwidth above 64");
  lu.set_zero();
  lu.add(1.0, S);
  if (lu.factorize_lanes(lu.values(), {0.0, 1e-3, 2e-3, 3e-3}, lu.values(), {}) != (1u << BandedLU::lanes) - 1)
    state.SkipWithError("a small pivot");
  const Vector b = Vector::Ones(S.rows());
  Vector x;
  for (auto _ : state) {
    x = b;
    lu.solve_in_place(x, 2);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["dofs"] = static_cast<double>(S.rows());
}
BENCHMARK(BM_BandedSolveLane)->Apply(band_sizes)->Unit(benchmark::kMicrosecond);

// A response point's dynamic stiffness K + iω(C + ΩG) − ω²M at Ω = ω = 4000 rpm, as
// run_harmonic_response assembles it.
ComplexBandedLU::ComplexSparse dynamic_stiffness(const Model& m) {
  const Assembler a(m);
  const SystemMatrices s = a.at(speed_4000rpm);
  const Real w = speed_4000rpm;
  ComplexBandedLU::ComplexSparse A = s.stiffness(w).cast<Complex>() + Complex(0, w) * s.damping(w).cast<Complex>() -
                                     Complex(w * w) * s.M.cast<Complex>();
  A.makeCompressed();
  return A;
}

// Its factorisation: banded with partial pivoting (core/banded_lu.hpp), against the
// flops bound 8·n·b² (complex multiply–adds of the elimination without row
// interchanges) and that of the interchanges it made, at flops_per_second.
void BM_ResponseFactorBanded(benchmark::State& state) {
  const auto A = dynamic_stiffness(model(state.range(0)));
  ComplexBandedLU lu;
  if (!lu.analyse(A, 64)) state.SkipWithError("bandwidth above 64");
  for (auto _ : state)
    if (!lu.factorize(A)) state.SkipWithError("singular");
  const double n = static_cast<double>(A.rows()), b = static_cast<double>(lu.bandwidth());
  state.counters["dofs"] = n;
  state.counters["bound_us"] = 8 * n * b * b / flops_per_second * 1e6;
  // The flops of this matrix's elimination: the row interchanges widen each step's
  // update from b to up to 2b columns (LAPACK's ju).
  double flops = 0;
  for (Index j = 0, ju = 0; j < A.rows(); ++j) {
    const Index m = std::min<Index>(lu.bandwidth(), A.rows() - 1 - j);
    ju = std::max<Index>(ju, std::min<Index>(lu.pivots()[static_cast<std::size_t>(j)] + lu.bandwidth(), A.rows() - 1));
    flops += 8.0 * static_cast<double>(m * (ju - j));
  }
  state.counters["pivoted_bound_us"] = flops / flops_per_second * 1e6;
}
BENCHMARK(BM_ResponseFactorBanded)->Apply(band_sizes)->Unit(benchmark::kMicrosecond);

// The same by Eigen's supernodal sparse LU (the pattern analysed once), as before.
void BM_ResponseFactorSparse(benchmark::State& state) {
  const auto A = dynamic_stiffness(model(state.range(0)));
  Eigen::SparseLU<ComplexBandedLU::ComplexSparse, Eigen::COLAMDOrdering<int>> lu;
  lu.analyzePattern(A);
  for (auto _ : state) lu.factorize(A);
  state.counters["dofs"] = static_cast<double>(A.rows());
}
BENCHMARK(BM_ResponseFactorSparse)->Apply(band_sizes)->Unit(benchmark::kMicrosecond);

// The finite-length bearing's film force with its Jacobian (example 06's bearing,
// L/D = 0.5, 72 × 8 cells, Reynolds' condition) at 64 states of a whirling journal,
// ε from 0.1 to 0.9: by the solver (argument 0) and from the table (1; built before
// the timing).
void BM_FiniteBearingForce(benchmark::State& state) {
  const JournalBearingGeometry g{.diameter = 0.04, .length = 0.02, .clearance = 40e-6, .viscosity = 0.02};
  FiniteBearingGrid grid;
  grid.evaluation = state.range(0) == 0 ? FilmEvaluation::exact : FilmEvaluation::table;
  if (state.range(0) == 1) (void)FiniteBearingTable::shared(0.5, grid);
  const Real speed = 600.0;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> states;
  for (int k = 0; k < 64; ++k) {
    const Real eps = 0.1 + 0.8 * (k % 9) / 8.0, a = 0.7 * k;
    const Eigen::Vector2d x = eps * g.clearance * Eigen::Vector2d(std::cos(a), std::sin(a));
    states.emplace_back(x, 0.3 * speed * Eigen::Vector2d(-x(1), x(0)) + 0.05 * speed * x);
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const auto& [x, v] = states[k++ % states.size()];
    benchmark::DoNotOptimize(film_force(g, FilmTheory::finite_length, speed, x, v, grid));
  }
}
BENCHMARK(BM_FiniteBearingForce)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// A flexible rotor of 100 lateral DOFs on two short journal bearings: a steel shaft
// Ø 40 mm, 0.8 m, 24 elements (axial and torsional DOFs held), a 20 kg disk at mid-span,
// bearings D 40 mm, L 12 mm, c 50 µm, μ 0.02 Pa s; gravity −y. Its equilibrium loses
// stability at a Hopf point near 559 rad/s (subcritical; the whip's fold near 506 rad/s).
Model whirl_rotor() {
  Model m;
  const int n_el = 24;
  const Index first = test::add_shaft(m, 0.0, 0.8, n_el, 0.04, test::steel());
  for (Index i = 0; i < m.n_nodes(); ++i) test::fix(m, i, {Dof::u, Dof::rx});
  test::add_body(m, first + n_el / 2, 20.0, 0.05, 0.1);
  const JournalBearingGeometry g{.diameter = 0.04, .length = 0.012, .clearance = 5e-5, .viscosity = 0.02};
  for (const Index node : {first, first + n_el})
    m.forces.emplace_back(
        FluidFilmBearing{.node_a = node, .node_b = {}, .geometry = g, .theory = FilmTheory::short_bearing, .grid = {}});
  m.gravity = Eigen::Vector3d(0, -9.81, 0);
  return m;
}

// whirl_rotor() condensed as the periodic analysis does (8 fixed-interface modes: 13
// coordinates).
CondensedRotor condensed_whirl_rotor(const Model& m) {
  return {m,
          nullptr,
          {.modes = 8, .gravity = m.gravity, .static_loads = true, .unbalance = false, .reference_speed = 300.0}};
}

// Its whirl branch: the equilibrium from 100 to 3000 rad/s with its Hopf point, and 200
// self-excited orbits from it (8 harmonics, 64 samples, set in @p s) with Hill's
// multipliers and the fold located.
OrbitBranch whirl_branch(const CondensedRotor& rotor, OrbitSettings& s) {
  s.continuation.p_min = 100.0;
  s.continuation.p_max = 3000.0;
  const OrbitBranch eq = equilibrium_branch(rotor, s);
  s.fourier = {.harmonics = 8, .samples = 64};
  s.continuation.max_points = 200;
  return hopf_branch(rotor, eq.bifurcations.at(0), s);
}

// The whirl branch of whirl_rotor() by harmonic balance, as the periodic analysis
// finds it, the condensation included.
void BM_WhirlBranch(benchmark::State& state) {
  const Model m = whirl_rotor();
  Index orbits = 0;
  for (auto _ : state) {
    const CondensedRotor rotor = condensed_whirl_rotor(m);
    OrbitSettings s;
    orbits = static_cast<Index>(whirl_branch(rotor, s).orbits.size());
  }
  state.counters["orbits"] = static_cast<double>(orbits);
}
BENCHMARK(BM_WhirlBranch)->Iterations(1)->Unit(benchmark::kSecond);

// One run-up of whirl_rotor() that reaches one of those orbits: at constant 600 rad/s,
// on the branch's stable stretch (the Hopf point is at 559 rad/s, the fold at
// 506 rad/s), from the equilibrium disturbed by a nanometre, trapezoidal rule at 10 µs,
// for 7.5 s — about the time the journal's orbit takes to come within 1 % of the
// branch's orbit there (over 7.15–7.25 s it is 1.06 % off, over 7.4–7.5 s 0.16 %: the
// counter off_orbit; the growth from a nanometre takes 6.5 s, the settling the rest at
// |μ| = 0.980 per period). At 620 rad/s it takes 5.5 s, at 580 rad/s more than 12 s;
// between the fold and the Hopf point a run-up from the equilibrium never reaches the
// orbit, and the unstable orbits cannot be reached at all. Reaching the branch's 200
// orbits so takes 200 such runs.
void BM_RunupToWhirlOrbit(benchmark::State& state) {
  const Model m = whirl_rotor();
  const Real speed = 600.0;
  TransientOptions options;
  options.profile = SpeedProfile::constant(speed);
  options.duration = 7.5;
  options.integrator = "trapezoidal";
  options.settings.dt = 1e-5;
  options.output_interval = 1e-4;
  options.probes = {0};
  options.gravity = m.gravity;
  options.start = RunupStart::equilibrium;
  options.initial_velocity = Vector::Zero(m.n_dofs());
  options.initial_velocity(global_dof(12, Dof::v)) = 1e-6;
  TransientResult r;
  for (auto _ : state) r = run_transient(m, options);
  // Untimed: how far the run's last 0.1 s (five periods) is from the branch's orbit at
  // the speed, in half the first journal's peak-to-peak y.
  const CondensedRotor rotor = condensed_whirl_rotor(m);
  OrbitSettings s;
  const std::vector<SteadyState> at = states_at(rotor, whirl_branch(rotor, s), speed, s);
  if (at.size() != 1) return state.SkipWithError("the branch does not cross 600 rad/s once");
  Real lo = 1.0, hi = -1.0, run_lo = 1.0, run_hi = -1.0;
  Vector x, v;
  for (int j = 0; j < 720; ++j) {
    orbit_state(rotor, at[0], s.fourier, 2 * pi * j / 720.0, x, v);
    lo = std::min(lo, x(global_dof(0, Dof::v)));
    hi = std::max(hi, x(global_dof(0, Dof::v)));
  }
  for (const TransientSample& sample : r.samples)
    if (sample.t >= options.duration - 0.1) {
      run_lo = std::min(run_lo, sample.probes[0][1]);
      run_hi = std::max(run_hi, sample.probes[0][1]);
    }
  state.counters["off_orbit"] = std::abs((run_hi - run_lo) / (hi - lo) - 1.0);
}
BENCHMARK(BM_RunupToWhirlOrbit)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace feran

// As the feran program does: a threaded OpenBLAS would spin threads of its own inside
// the small dense solves (seen as half the time in sched_yield), so use one thread.
int main(int argc, char** argv) {
  feran::single_threaded_blas();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
