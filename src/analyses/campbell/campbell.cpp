#include <feran/analyses/campbell/campbell.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include <feran/core/assignment.hpp>
#include <feran/core/parallel.hpp>
#include <feran/core/root_finding.hpp>
#include <feran/core/tolerances.hpp>

namespace feran {

namespace {

constexpr Real missing_value = std::numeric_limits<Real>::quiet_NaN();

// The modes a Campbell diagram follows: the @p count oscillatory ones nearest the
// origin (a rigid-body mode at p = 0 has no frequency line to follow; overdamped
// modes far out on the real axis are not among the lowest), by frequency.
std::vector<Mode> oscillatory_modes(ModalResult&& r, std::size_t count) {
  std::vector<Mode> out;
  for (Mode& m : r.modes)
    if (m.oscillatory) out.push_back(std::move(m));
  std::stable_sort(out.begin(), out.end(),
                   [](const Mode& a, const Mode& b) { return abs2(a.eigenvalue) < abs2(b.eigenvalue); });
  if (out.size() > count) {
    // Keep a repeated pair whole (isotropic rotors at rest).
    std::size_t n = count;
    while (n < out.size() && magnitude(out[n].eigenvalue - out[n - 1].eigenvalue) <=
                                 tolerance::repeated_eigenvalue * magnitude(out[n].eigenvalue))
      ++n;
    out.resize(n);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Mode& a, const Mode& b) { return a.frequency_hz < b.frequency_hz; });
  return out;
}

// Where a tracked mode was at the last speed(s): the basis of the prediction.
struct Track {
  Real speed_last = 0, speed_prev = 0;
  Complex p_last, p_prev;
  bool has_prev = false;
  ComplexVector shape;
};

Complex predict(const Track& t, Real speed) {
  if (!t.has_prev || t.speed_last == t.speed_prev) return t.p_last;
  return t.p_last + (t.p_last - t.p_prev) * ((speed - t.speed_last) / (t.speed_last - t.speed_prev));
}

// Matching cost: shape dissimilarity (1 − MAC) plus the relative distance of the
// eigenvalue from its prediction.
Real cost(const Track& t, Real speed, const Mode& c) {
  const Complex pred = predict(t, speed);
  const Real scale = std::max({magnitude(pred), magnitude(c.eigenvalue), 1e-12});
  return (1.0 - mac(t.shape, c.reduced_shape)) + magnitude(pred - c.eigenvalue) / scale;
}

bool lateral_family(ModeType t) { return t == ModeType::lateral || t == ModeType::coupled; }

// The sense in which a mode whirls: its orbit classification, except that a nearly
// straight-line orbit (planar by the 5 % threshold of classify_whirl) still whirls
// forward or backward by the sign of its directivity unless that vanishes.
Whirl whirl_sense(Whirl classified, Real directivity) {
  if (classified != Whirl::planar || !(std::abs(directivity) > tolerance::planar_directivity)) return classified;
  return directivity > 0 ? Whirl::forward : Whirl::backward;
}

// A sign change on the grid interval (speed_a, speed_b) of track @p mode, refined
// after the sweep: of f − order·Ω/2π (a critical speed) or, with order 0, of the
// damping ratio (the stability threshold).
struct Bracket {
  Index mode = 0;
  int order = 0;
  Track a, b;
  Real g0 = 0, g1 = 0;
  Whirl whirl = Whirl::none;  // at speed b, kept if the refinement fails
  Real frequency_hz = 0;      // at speed b, likewise
};

}  // namespace

CampbellResult run_campbell(const Model& model, const CampbellOptions& options,
                            std::shared_ptr<const Assembler> assembled) {
  CampbellResult result;
  ModalOptions mo = options.modal;
  mo.shapes = false;
  const std::size_t n_track = static_cast<std::size_t>(std::max<Index>(options.n_modes, 1));
  // Candidates beyond the tracked modes let modes enter from above.
  const std::size_t n_cand = n_track + 4;
  mo.n_modes = static_cast<Index>(n_cand);
  mo.oscillatory_only = true;
  const ModalSolver solver(model, mo, std::move(assembled));
  std::atomic<Index> n_refinement_solves{0};
  auto solve = [&](Real speed) {
    ++n_refinement_solves;
    return solver.solve(speed);
  };
  // All grid speeds first, in parallel; tracking then walks through them in order.
  std::vector<ModalResult> grid(options.speeds.size());
  parallel_for(static_cast<Index>(grid.size()), options.n_threads, [&](Index i, int) {
    ModalResult& r = grid[static_cast<std::size_t>(i)];
    if (options.stop.requested())
      r.info.fail(SolverStatus::interrupted, "stopped on request");
    else
      r = solver.solve(options.speeds[static_cast<std::size_t>(i)]);
  });

  std::vector<Track> tracks;
  auto record = [&](TrackedMode& tm, const Mode* m, Real corr) {
    tm.frequency_hz.push_back(m ? m->frequency_hz : missing_value);
    tm.damping_ratio.push_back(m ? m->damping_ratio : missing_value);
    tm.log_decrement.push_back(m ? m->log_decrement : missing_value);
    tm.directivity.push_back(m ? m->directivity : missing_value);
    tm.whirl_at.push_back(m ? m->whirl : Whirl::none);
    tm.bending.push_back(m ? m->bending : missing_value);
    tm.shape_at.push_back(m ? m->shape_kind : ModeShape::none);
    tm.correlation.push_back(corr);
  };

  // The candidate at a trial speed between grid speeds a and b that continues track
  // @p j, whose states at a and b are @p ta and @p tb.
  auto match_between = [&](const Track& ta, const Track& tb, Real speed) -> std::optional<Mode> {
    ModalResult r = solve(speed);
    if (!r.info.converged()) return std::nullopt;
    std::vector<Mode> cands = oscillatory_modes(std::move(r), n_cand);
    Track interp = ta;
    interp.p_prev = ta.p_last;
    interp.speed_prev = ta.speed_last;
    interp.p_last = tb.p_last;
    interp.speed_last = tb.speed_last;
    interp.has_prev = true;
    Real best = std::numeric_limits<Real>::infinity();
    std::optional<Mode> out;
    for (Mode& c : cands) {
      Track ref = interp;
      ref.shape = std::abs(speed - ta.speed_last) < std::abs(speed - tb.speed_last) ? ta.shape : tb.shape;
      const Real value = cost(ref, speed, c);
      if (value < best) best = value, out = std::move(c);
    }
    return out;
  };

  std::vector<StabilityThreshold> thresholds;
  std::vector<Bracket> brackets;
  // Divergence: a real eigenvalue that is positive (ModalResult::divergence, beyond
  // round-off of the largest eigenvalue), at the first grid speed where it appears.
  const auto divergent = [](const ModalResult& r) {
    Real largest = 0;
    for (const Mode& m : r.modes) largest = std::max(largest, magnitude(m.eigenvalue));
    return r.divergence > 1e-9 * std::max(largest, r.divergence);
  };
  std::optional<std::size_t> first_divergent;
  for (std::size_t i = 0; i < options.speeds.size(); ++i) {
    const Real speed = options.speeds[i];
    ModalResult r = std::move(grid[i]);
    ++result.n_solves;
    if (result.info.method == SolverMethod::none) result.info = r.info;
    if (r.info.status == SolverStatus::interrupted) {
      result.info.fail(SolverStatus::interrupted, fmt::format("stopped on request before {:.6g} Hz", rad_to_hz(speed)));
      break;
    }
    if (!r.info.converged()) {
      result.info = r.info;
      result.info.message = "eigen solve failed at " + std::to_string(rad_to_hz(speed)) + " Hz: " + r.info.message;
      break;
    }
    if (divergent(r) && !first_divergent) first_divergent = i;
    std::vector<Mode> cands = oscillatory_modes(std::move(r), i == 0 ? n_track : n_cand);
    result.speeds.push_back(speed);

    if (i == 0) {
      for (Mode& m : cands) {
        TrackedMode tm;
        tm.type = m.type;
        record(tm, &m, 1.0);
        result.modes.push_back(std::move(tm));
        Track t;
        t.speed_last = speed;
        t.p_last = m.eigenvalue;
        t.shape = std::move(m.reduced_shape);
        tracks.push_back(std::move(t));
      }
      for (std::size_t j = 0; j < tracks.size(); ++j)
        if (result.modes[j].damping_ratio[0] < -options.damping_tolerance)
          thresholds.push_back({speed, static_cast<Index>(j), result.modes[j].frequency_hz[0], true});
      continue;
    }

    // Optimal assignment of tracked modes to candidates (padding when short).
    const auto n_rows = static_cast<Index>(tracks.size());
    const Index n_cols = std::max<Index>(n_rows, static_cast<Index>(cands.size()));
    Matrix c = Matrix::Constant(n_rows, n_cols, 1e6);
    for (Index a = 0; a < n_rows; ++a)
      for (Index b = 0; b < static_cast<Index>(cands.size()); ++b)
        c(a, b) = cost(tracks[static_cast<std::size_t>(a)], speed, cands[static_cast<std::size_t>(b)]);
    const std::vector<Index> assigned = optimal_assignment(c);

    for (std::size_t j = 0; j < tracks.size(); ++j) {
      const Index col = assigned[j];
      TrackedMode& tm = result.modes[j];
      if (col < 0 || col >= static_cast<Index>(cands.size())) {
        record(tm, nullptr, missing_value);
        continue;
      }
      Mode& m = cands[static_cast<std::size_t>(col)];
      Track before = tracks[j];
      record(tm, &m, mac(before.shape, m.reduced_shape));
      Track& t = tracks[j];
      t.p_prev = t.p_last;
      t.speed_prev = t.speed_last;
      t.has_prev = true;
      t.p_last = m.eigenvalue;
      t.speed_last = speed;
      t.shape = std::move(m.reduced_shape);
      if (std::isnan(tm.frequency_hz[i - 1])) continue;

      // Critical speeds: sign changes of f − k·Ω/2π on this interval.
      const Real s0 = options.speeds[i - 1];
      if (lateral_family(tm.type))
        for (int k : options.orders) {
          const Real g0 = tm.frequency_hz[i - 1] - k * rad_to_hz(s0);
          const Real g1 = tm.frequency_hz[i] - k * rad_to_hz(speed);
          if (!((g0 > 0 && g1 <= 0) || (g0 < 0 && g1 >= 0))) continue;
          brackets.push_back({static_cast<Index>(j), k, before, t, g0, g1,
                              whirl_sense(tm.whirl_at[i], tm.directivity[i]), tm.frequency_hz[i]});
        }

      // Stability: the damping ratio drops below −tolerance on this interval.
      const Real d0 = tm.damping_ratio[i - 1] + options.damping_tolerance;
      const Real d1 = tm.damping_ratio[i] + options.damping_tolerance;
      if (d0 >= 0 && d1 < 0)
        brackets.push_back({static_cast<Index>(j), 0, before, t, d0, d1, tm.whirl_at[i], tm.frequency_hz[i]});
    }
  }

  // Refine every bracket by Brent's method, each trial speed a fresh eigen solve;
  // the brackets are independent, so they run in parallel.
  std::vector<std::optional<CriticalSpeed>> criticals(brackets.size());
  std::vector<std::optional<StabilityThreshold>> crossings(brackets.size());
  std::atomic<Index> n_skipped{0};
  parallel_for(static_cast<Index>(brackets.size()), options.n_threads, [&](Index bi, int) {
    if (options.stop.requested()) {
      ++n_skipped;
      return;
    }
    const Bracket& br = brackets[static_cast<std::size_t>(bi)];
    const Real s0 = br.a.speed_last, s1 = br.b.speed_last;
    Whirl w = br.whirl;
    Real freq = br.frequency_hz;
    auto f = [&](Real s) {
      const std::optional<Mode> mm = match_between(br.a, br.b, s);
      if (!mm) return missing_value;
      w = whirl_sense(mm->whirl, mm->directivity);
      freq = mm->frequency_hz;
      return br.order > 0 ? mm->frequency_hz - br.order * rad_to_hz(s) : mm->damping_ratio + options.damping_tolerance;
    };
    const RootResult root = brent_root(f, s0, s1, br.g0, br.g1, options.speed_tolerance);
    const Real s = std::isnan(root.fx) ? s0 + (s1 - s0) * br.g0 / (br.g0 - br.g1) : root.x;
    if (br.order > 0)
      criticals[static_cast<std::size_t>(bi)] = CriticalSpeed{s, br.order * rad_to_hz(s), br.mode, br.order, w};
    else
      crossings[static_cast<std::size_t>(bi)] = StabilityThreshold{s, br.mode, freq, false};
  });
  // The onset of a divergence, by bisection between the last grid speed without it
  // and the first with it (no eigenvalue continues through it: the real one is born
  // at p = 0).
  if (first_divergent && !options.stop.requested()) {
    const std::size_t i = *first_divergent;
    StabilityThreshold t{options.speeds[i], -1, 0.0, i == 0, true};
    if (i > 0) {
      Real low = options.speeds[i - 1], high = options.speeds[i];
      while (high - low > options.speed_tolerance && !options.stop.requested()) {
        const Real mid = 0.5 * (low + high);
        if (mid <= low || mid >= high) break;
        const ModalResult r = solve(mid);
        if (!r.info.converged()) break;
        (divergent(r) ? high : low) = mid;
      }
      t.speed = high;  // where it was seen: never above the onset by more than the bracket
    }
    thresholds.push_back(t);
  }
  result.n_solves += n_refinement_solves;
  if (n_skipped > 0 && result.info.converged())
    result.info.fail(SolverStatus::interrupted,
                     fmt::format("stopped on request while refining critical speeds and thresholds: {} of {} "
                                 "not refined, and left out",
                                 n_skipped.load(), brackets.size()));
  for (std::size_t b = 0; b < brackets.size(); ++b) {
    if (criticals[b]) result.critical_speeds.push_back(*criticals[b]);
    if (crossings[b]) thresholds.push_back(*crossings[b]);
  }

  std::sort(result.critical_speeds.begin(), result.critical_speeds.end(),
            [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.speed < b.speed; });
  if (!thresholds.empty())
    result.stability_threshold =
        *std::min_element(thresholds.begin(), thresholds.end(),
                          [](const StabilityThreshold& a, const StabilityThreshold& b) { return a.speed < b.speed; });

  // Labels: the sense in which a mode whirls at most speeds of the sweep (a nearly
  // straight-line orbit counts by the sign of its directivity) and the shape it has at
  // the first speed (cylindrical, conical, bending), numbered by frequency at the first
  // speed within each family; planar only when it whirls at no speed.
  std::map<std::string, int> counters;
  for (TrackedMode& tm : result.modes) {
    int forward = 0, backward = 0, mixed = 0;
    for (std::size_t i = 0; i < tm.whirl_at.size(); ++i) {
      const Whirl w = whirl_sense(tm.whirl_at[i], tm.directivity[i]);
      forward += w == Whirl::forward;
      backward += w == Whirl::backward;
      mixed += w == Whirl::mixed;
    }
    tm.whirl = forward == 0 && backward == 0 && mixed == 0 ? Whirl::planar
               : forward >= backward && forward >= mixed   ? Whirl::forward
               : backward >= mixed                         ? Whirl::backward
                                                           : Whirl::mixed;
    // The shape at the first speed, where the labels are numbered (an oil-whirl mode,
    // rigid in its films at low speed, keeps its name when it later bends the shaft
    // far above the first bending mode).
    tm.shape_kind = ModeShape::none;
    for (const ModeShape s : tm.shape_at)
      if (s != ModeShape::none) {
        tm.shape_kind = s;
        break;
      }
    std::string family;
    switch (tm.type) {
      case ModeType::axial:
        family = "axial";
        tm.whirl = Whirl::none;
        tm.shape_kind = ModeShape::none;
        break;
      case ModeType::torsional:
        family = "torsional";
        tm.whirl = Whirl::none;
        tm.shape_kind = ModeShape::none;
        break;
      default:
        family = to_string(tm.whirl);
        if (tm.shape_kind != ModeShape::none) family += std::string(" ") + to_string(tm.shape_kind);
    }
    tm.label = family + " " + std::to_string(++counters[family]);
  }
  // The supports' state at the grid speeds' equilibria, which the solves found and kept.
  result.operating = solver.operating_at(result.speeds);
  return result;
}

std::string whirl_name(const CampbellResult& result, Index mode) {
  const auto family = [](const TrackedMode& m) -> std::string {
    return m.type == ModeType::axial ? "axial" : m.type == ModeType::torsional ? "torsional" : to_string(m.whirl);
  };
  const TrackedMode& target = result.modes.at(static_cast<std::size_t>(mode));
  int count = 0;
  for (Index i = 0; i <= mode; ++i) count += family(result.modes[static_cast<std::size_t>(i)]) == family(target);
  return family(target) + " " + std::to_string(count);
}

std::string threshold_label(const CampbellResult& result, const StabilityThreshold& threshold) {
  if (threshold.divergence || threshold.mode < 0 || threshold.mode >= static_cast<Index>(result.modes.size()))
    return "divergence (a real eigenvalue)";
  return result.modes[static_cast<std::size_t>(threshold.mode)].label;
}

}  // namespace feran
