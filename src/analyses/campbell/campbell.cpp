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

namespace {

// A Campbell diagram in named steps: the grid's eigen solves side by side
// (solve_grid()), the modes tracked through them in order (start_tracks(), track()),
// each sign change found on the way (find_brackets()) refined afterwards
// (refine_brackets(), divergence_onset()), then the critical speeds, the threshold and
// the labels (finish(), label_modes()).
class CampbellSweep {
 public:
  CampbellSweep(const Model& model, const CampbellOptions& options, std::shared_ptr<const Assembler> assembled)
      : options_(options),
        n_track_(static_cast<std::size_t>(std::max<Index>(options.n_modes, 1))),
        // Candidates beyond the tracked modes let modes enter from above.
        n_cand_(n_track_ + 4),
        solver_(model, modal_options(options, n_cand_), std::move(assembled)) {}

  CampbellResult run() {
    std::vector<ModalResult> grid = solve_grid();
    for (std::size_t i = 0; i < options_.speeds.size(); ++i)
      if (!track(i, std::move(grid[i]))) break;
    refine_brackets();
    divergence_onset();
    finish();
    return std::move(result_);
  }

 private:
  static ModalOptions modal_options(const CampbellOptions& options, std::size_t n_cand) {
    ModalOptions mo = options.modal;
    mo.shapes = false;
    mo.n_modes = static_cast<Index>(n_cand);
    mo.oscillatory_only = true;
    return mo;
  }

  ModalResult solve(Real speed) const {
    ++n_refinement_solves_;
    return solver_.solve(speed);
  }

  // All grid speeds first, in parallel; tracking then walks through them in order.
  std::vector<ModalResult> solve_grid() const {
    std::vector<ModalResult> grid(options_.speeds.size());
    parallel_for(static_cast<Index>(grid.size()), options_.n_threads, [&](Index i, int) {
      ModalResult& r = grid[static_cast<std::size_t>(i)];
      if (options_.stop.requested())
        r.info.fail(SolverStatus::interrupted, "stopped on request");
      else
        r = solver_.solve(options_.speeds[static_cast<std::size_t>(i)]);
    });
    return grid;
  }

  static void record(TrackedMode& tm, const Mode* m, Real corr) {
    tm.frequency_hz.push_back(m ? m->frequency_hz : missing_value);
    tm.damping_ratio.push_back(m ? m->damping_ratio : missing_value);
    tm.log_decrement.push_back(m ? m->log_decrement : missing_value);
    tm.directivity.push_back(m ? m->directivity : missing_value);
    tm.whirl_at.push_back(m ? m->whirl : Whirl::none);
    tm.bending.push_back(m ? m->bending : missing_value);
    tm.shape_at.push_back(m ? m->shape_kind : ModeShape::none);
    tm.correlation.push_back(corr);
  }

  // Divergence: a real eigenvalue that is positive (ModalResult::divergence, beyond
  // round-off of the largest eigenvalue), at the first grid speed where it appears.
  static bool divergent(const ModalResult& r) {
    Real largest = 0;
    for (const Mode& m : r.modes) largest = std::max(largest, magnitude(m.eigenvalue));
    return r.divergence > 1e-9 * std::max(largest, r.divergence);
  }

  // Grid speed @p i's modes taken into the tracks; false (the sweep ends there, said in
  // the result's info) when its solve was stopped or failed.
  bool track(std::size_t i, ModalResult r) {
    const Real speed = options_.speeds[i];
    ++result_.n_solves;
    if (result_.info.method == SolverMethod::none) result_.info = r.info;
    if (r.info.status == SolverStatus::interrupted) {
      result_.info.fail(SolverStatus::interrupted,
                        fmt::format("stopped on request before {:.6g} Hz", rad_to_hz(speed)));
      return false;
    }
    if (!r.info.converged()) {
      result_.info = r.info;
      result_.info.message = "eigen solve failed at " + std::to_string(rad_to_hz(speed)) + " Hz: " + r.info.message;
      return false;
    }
    if (divergent(r) && !first_divergent_) first_divergent_ = i;
    std::vector<Mode> cands = oscillatory_modes(std::move(r), i == 0 ? n_track_ : n_cand_);
    result_.speeds.push_back(speed);
    if (i == 0)
      start_tracks(speed, cands);
    else
      assign(i, cands);
    return true;
  }

  // The first speed's modes are the tracks.
  void start_tracks(Real speed, std::vector<Mode>& cands) {
    for (Mode& m : cands) {
      TrackedMode tm;
      tm.type = m.type;
      record(tm, &m, 1.0);
      result_.modes.push_back(std::move(tm));
      Track t;
      t.speed_last = speed;
      t.p_last = m.eigenvalue;
      t.shape = std::move(m.reduced_shape);
      tracks_.push_back(std::move(t));
    }
    for (std::size_t j = 0; j < tracks_.size(); ++j)
      if (result_.modes[j].damping_ratio[0] < -options_.damping_tolerance)
        thresholds_.push_back({speed, static_cast<Index>(j), result_.modes[j].frequency_hz[0], true});
  }

  // The optimal assignment of the tracked modes to grid speed @p i's candidates
  // (padded when short), each track continued and its interval searched for brackets.
  void assign(std::size_t i, std::vector<Mode>& cands) {
    const Real speed = options_.speeds[i];
    const auto n_rows = static_cast<Index>(tracks_.size());
    const Index n_cols = std::max<Index>(n_rows, static_cast<Index>(cands.size()));
    Matrix c = Matrix::Constant(n_rows, n_cols, 1e6);
    for (Index a = 0; a < n_rows; ++a)
      for (Index b = 0; b < static_cast<Index>(cands.size()); ++b)
        c(a, b) = cost(tracks_[static_cast<std::size_t>(a)], speed, cands[static_cast<std::size_t>(b)]);
    const std::vector<Index> assigned = optimal_assignment(c);
    for (std::size_t j = 0; j < tracks_.size(); ++j) {
      const Index col = assigned[j];
      TrackedMode& tm = result_.modes[j];
      if (col < 0 || col >= static_cast<Index>(cands.size())) {
        record(tm, nullptr, missing_value);
        continue;
      }
      Mode& m = cands[static_cast<std::size_t>(col)];
      const Track before = tracks_[j];
      record(tm, &m, mac(before.shape, m.reduced_shape));
      Track& t = tracks_[j];
      t.p_prev = t.p_last;
      t.speed_prev = t.speed_last;
      t.has_prev = true;
      t.p_last = m.eigenvalue;
      t.speed_last = speed;
      t.shape = std::move(m.reduced_shape);
      if (!std::isnan(tm.frequency_hz[i - 1])) find_brackets(i, j, before, t);
    }
  }

  // On the interval before grid speed @p i, track @p j's sign changes: of f − k·Ω/2π
  // (critical speeds) and of the damping ratio plus the tolerance (stability).
  void find_brackets(std::size_t i, std::size_t j, const Track& before, const Track& t) {
    const TrackedMode& tm = result_.modes[j];
    const Real s0 = options_.speeds[i - 1], speed = options_.speeds[i];
    if (lateral_family(tm.type))
      for (int k : options_.orders) {
        const Real g0 = tm.frequency_hz[i - 1] - k * rad_to_hz(s0);
        const Real g1 = tm.frequency_hz[i] - k * rad_to_hz(speed);
        if (!((g0 > 0 && g1 <= 0) || (g0 < 0 && g1 >= 0))) continue;
        brackets_.push_back({static_cast<Index>(j), k, before, t, g0, g1,
                             whirl_sense(tm.whirl_at[i], tm.directivity[i]), tm.frequency_hz[i]});
      }
    const Real d0 = tm.damping_ratio[i - 1] + options_.damping_tolerance;
    const Real d1 = tm.damping_ratio[i] + options_.damping_tolerance;
    if (d0 >= 0 && d1 < 0)
      brackets_.push_back({static_cast<Index>(j), 0, before, t, d0, d1, tm.whirl_at[i], tm.frequency_hz[i]});
  }

  // The candidate at a trial speed between grid speeds a and b that continues the
  // track whose states there are @p ta and @p tb.
  std::optional<Mode> match_between(const Track& ta, const Track& tb, Real speed) const {
    ModalResult r = solve(speed);
    if (!r.info.converged()) return std::nullopt;
    std::vector<Mode> cands = oscillatory_modes(std::move(r), n_cand_);
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
  }

  // Every bracket refined by Brent's method, each trial speed a fresh eigen solve; the
  // brackets are independent, so they run in parallel.
  void refine_brackets() {
    std::vector<std::optional<CriticalSpeed>> criticals(brackets_.size());
    std::vector<std::optional<StabilityThreshold>> crossings(brackets_.size());
    std::atomic<Index> n_skipped{0};
    parallel_for(static_cast<Index>(brackets_.size()), options_.n_threads, [&](Index bi, int) {
      if (options_.stop.requested()) {
        ++n_skipped;
        return;
      }
      const Bracket& br = brackets_[static_cast<std::size_t>(bi)];
      const Real s0 = br.a.speed_last, s1 = br.b.speed_last;
      Whirl w = br.whirl;
      Real freq = br.frequency_hz;
      auto f = [&](Real s) {
        const std::optional<Mode> mm = match_between(br.a, br.b, s);
        if (!mm) return missing_value;
        w = whirl_sense(mm->whirl, mm->directivity);
        freq = mm->frequency_hz;
        return br.order > 0 ? mm->frequency_hz - br.order * rad_to_hz(s)
                            : mm->damping_ratio + options_.damping_tolerance;
      };
      const RootResult root = brent_root(f, s0, s1, br.g0, br.g1, options_.speed_tolerance);
      const Real s = std::isnan(root.fx) ? s0 + (s1 - s0) * br.g0 / (br.g0 - br.g1) : root.x;
      if (br.order > 0)
        criticals[static_cast<std::size_t>(bi)] = CriticalSpeed{s, br.order * rad_to_hz(s), br.mode, br.order, w};
      else
        crossings[static_cast<std::size_t>(bi)] = StabilityThreshold{s, br.mode, freq, false};
    });
    if (n_skipped > 0 && result_.info.converged())
      result_.info.fail(SolverStatus::interrupted,
                        fmt::format("stopped on request while refining critical speeds and thresholds: {} of {} "
                                    "not refined, and left out",
                                    n_skipped.load(), brackets_.size()));
    for (std::size_t b = 0; b < brackets_.size(); ++b) {
      if (criticals[b]) result_.critical_speeds.push_back(*criticals[b]);
      if (crossings[b]) crossings_.push_back(*crossings[b]);
    }
  }

  // The onset of a divergence, by bisection between the last grid speed without it and
  // the first with it (no eigenvalue continues through it: the real one is born at
  // p = 0).
  void divergence_onset() {
    if (!first_divergent_ || options_.stop.requested()) return;
    const std::size_t i = *first_divergent_;
    StabilityThreshold t{options_.speeds[i], -1, 0.0, i == 0, true};
    if (i > 0) {
      Real low = options_.speeds[i - 1], high = options_.speeds[i];
      while (high - low > options_.speed_tolerance && !options_.stop.requested()) {
        const Real mid = 0.5 * (low + high);
        if (mid <= low || mid >= high) break;
        const ModalResult r = solve(mid);
        if (!r.info.converged()) break;
        (divergent(r) ? high : low) = mid;
      }
      t.speed = high;  // where it was seen: never above the onset by more than the bracket
    }
    thresholds_.push_back(t);
  }

  // The critical speeds in order, the lowest threshold, the labels and the supports'
  // state at the grid speeds' equilibria, which the solves found and kept.
  void finish() {
    result_.n_solves += n_refinement_solves_;
    thresholds_.insert(thresholds_.end(), crossings_.begin(), crossings_.end());  // after a divergence's onset
    std::sort(result_.critical_speeds.begin(), result_.critical_speeds.end(),
              [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.speed < b.speed; });
    if (!thresholds_.empty())
      result_.stability_threshold =
          *std::min_element(thresholds_.begin(), thresholds_.end(),
                            [](const StabilityThreshold& a, const StabilityThreshold& b) { return a.speed < b.speed; });
    label_modes();
    result_.operating = solver_.operating_at(result_.speeds);
  }

  // Labels: the sense in which a mode whirls at most speeds of the sweep (a nearly
  // straight-line orbit counts by the sign of its directivity) and the shape it has at
  // the first speed (cylindrical, conical, bending), numbered by frequency at the first
  // speed within each family; planar only when it whirls at no speed.
  void label_modes() {
    std::map<std::string, int> counters;
    for (TrackedMode& tm : result_.modes) {
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
      if (tm.type == ModeType::axial || tm.type == ModeType::torsional) {
        family = tm.type == ModeType::axial ? "axial" : "torsional";
        tm.whirl = Whirl::none;
        tm.shape_kind = ModeShape::none;
      } else {
        family = to_string(tm.whirl);
        if (tm.shape_kind != ModeShape::none) family += std::string(" ") + to_string(tm.shape_kind);
      }
      tm.label = family + " " + std::to_string(++counters[family]);
    }
  }

  const CampbellOptions& options_;
  const std::size_t n_track_, n_cand_;
  const ModalSolver solver_;
  mutable std::atomic<Index> n_refinement_solves_{0};
  CampbellResult result_;
  std::vector<Track> tracks_;
  std::vector<StabilityThreshold> thresholds_;
  std::vector<StabilityThreshold> crossings_;  // the damping ratio's, refined
  std::vector<Bracket> brackets_;
  std::optional<std::size_t> first_divergent_;
};

}  // namespace

CampbellResult run_campbell(const Model& model, const CampbellOptions& options,
                            std::shared_ptr<const Assembler> assembled) {
  return CampbellSweep(model, options, std::move(assembled)).run();
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
