#pragma once
/// @file
/// The force interface: a concept with optional abilities and a type-erased,
/// copyable Force value, the counterpart of Element for what acts on a model
/// (unbalances, harmonic forces, static loads, friction, nonlinear bearings).
///
/// A force type must say what it is (kind()) and where it acts (nodes(): the load
/// locations a reduced run keeps static corrections for). Everything else is an
/// ability the type has when it has the member, detected at compile time as pagmo
/// detects has_gradient; an analysis asks the Force whether it has one:
///
///   add_harmonic(const HarmonicExcitation&, ComplexVector& f)  steady-state response
///   add_transient(const MotionState&, Vector& f)               run-ups (external forces)
///   add_static(Vector& f)                                      static analysis
///   dofs() and force(const MotionState&, x, v)                 a nonlinear force f(x, v)
///                                                              with its Jacobian
///   supports() (with the above)                                it carries the rotor: the
///                                                              static analysis finds the
///                                                              equilibrium with it, the
///                                                              linear analyses use its
///                                                              tangent about that
///                                                              equilibrium and the model
///                                                              check counts it as holding
///                                                              its DOFs (fluid-film bearings;
///                                                              not friction)
///   needs_speed() (with supports())                            it carries load only while
///                                                              the rotor turns (an oil film):
///                                                              analyses refuse speed 0
///   drag_torque(const MotionState&, x, v) (with force())       it resists the rotation with a
///                                                              torque [N m] (an oil film's
///                                                              friction): torque-driven
///                                                              run-ups load the drive with it
///   operating_data(const MotionState&, x, v) (with force())    the numbers of its operating
///                                                              state an engineer checks (a
///                                                              journal bearing's eccentricity
///                                                              ratio, film thickness, …):
///                                                              OperatingValue list
///   clearance() (with supports())                              the radial clearance [m] its
///                                                              journal moves in: responses
///                                                              give each orbit as a fraction
///                                                              of it
///   own_time_law()                                             its load follows a time law of
///                                                              its own (a frequency of its own,
///                                                              a time table), not the rotation:
///                                                              the steady-state analyses leave
///                                                              it out (true), the periodic one
///                                                              refuses it
///   synchronous_inertia()                                      a mass turning with the rotor
///                                                              at an eccentricity (an
///                                                              unbalance): its m·e² [kg m²],
///                                                              which a torque-driven drive
///                                                              also accelerates; its load is
///                                                              the rotor speed's (default
///                                                              probes, API 684's placement)
///
/// Vectors are over all unconstrained DOFs (global_dof order); add_* add into them.
/// To add a force: a type in forces/ with kind(), nodes() and its abilities, its
/// spec type and field table (spec/), and its build step. No analysis changes.

#include <concepts>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include <feran/core/operating_point.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// One point of a steady-state analysis: the motion is x(t) = Re(X·e^{iωt}).
struct HarmonicExcitation {
  Real speed = 0.0;         ///< rotor speed Ω [rad/s]
  Real frequency = 0.0;     ///< excitation frequency ω [rad/s]; ω = Ω in a speed sweep
  bool synchronous = true;  ///< a speed sweep (ω = Ω); false: a frequency sweep
  bool unbalance = true;    ///< unbalances take part (they act only at ω = Ω)
};

/// Where and how fast the rotor is when a time-dependent force is evaluated.
struct MotionState {
  Real t = 0.0;             ///< [s]
  Real speed = 0.0;         ///< Ω [rad/s]
  Real acceleration = 0.0;  ///< Ω' [rad/s²]
  Real angle = 0.0;         ///< rotation angle φ = ∫Ω dt [rad]
  /// The caller evaluates the force along a trajectory, thousands of times (run-ups):
  /// a force may then answer from a table it builds once, within a stated error (the
  /// finite-length journal bearing does, forces/finite_bearing_table.hpp).
  bool trajectory = false;
  bool operator==(const MotionState&) const = default;
};

/// A nonlinear force on a few DOFs and its Jacobian blocks ∂f/∂x and ∂f/∂v (local,
/// on dofs()).
struct NonlinearForceValue {
  Vector f;
  Matrix dfdx;
  Matrix dfdv;
};

/// What every force type provides.
template <class F>
concept ForceType = std::copyable<F> && requires(const F& f) {
  { f.kind() } -> std::convertible_to<std::string_view>;
  { f.nodes() } -> std::convertible_to<std::vector<Index>>;
};

/// The optional abilities.
template <class F>
concept HasHarmonicLoad = requires(const F& f, const HarmonicExcitation& e, ComplexVector& v) {
  f.add_harmonic(e, v);
};
template <class F>
concept HasTransientLoad = requires(const F& f, const MotionState& s, Vector& v) {
  f.add_transient(s, v);
};
template <class F>
concept HasStaticLoad = requires(const F& f, Vector& v) {
  f.add_static(v);
};
template <class F>
concept HasNonlinearForce = requires(const F& f, const MotionState& s, const Vector& x) {
  { f.dofs() } -> std::convertible_to<std::vector<Index>>;
  { f.force(s, x, x) } -> std::same_as<NonlinearForceValue>;
};

template <class F>
concept HasSupport = HasNonlinearForce<F> && requires(const F& f) {
  { f.supports() } -> std::same_as<bool>;
};
/// A support that carries load only while the rotor turns (an oil film).
template <class F>
concept NeedsSpeed = requires(const F& f) {
  { f.needs_speed() } -> std::same_as<bool>;
};

/// A force that resists the shaft's rotation with a torque (an oil film's friction).
template <class F>
concept HasDragTorque = requires(const F& f, const MotionState& s, const Vector& x) {
  { f.drag_torque(s, x, x) } -> std::same_as<Real>;
};

/// A support that reports its operating state (a journal bearing's film, a rolling
/// bearing's most loaded element).
template <class F>
concept HasOperatingData = requires(const F& f, const MotionState& s, const Vector& x) {
  { f.operating_data(s, x, x) } -> std::same_as<std::vector<OperatingValue>>;
};

/// A support whose journal moves within a radial clearance (a journal bearing's film,
/// a rolling bearing's internal clearance).
template <class F>
concept HasClearance = requires(const F& f) {
  { f.clearance() } -> std::convertible_to<Real>;
};

/// A load with a time law of its own (a frequency of its own, a time table).
template <class F>
concept HasOwnTimeLaw = requires(const F& f) {
  { f.own_time_law() } -> std::same_as<bool>;
};

/// A mass turning with the rotor at an eccentricity (an unbalance).
template <class F>
concept HasSynchronousInertia = requires(const F& f) {
  { f.synchronous_inertia() } -> std::convertible_to<Real>;
};

/// A type-erased force with value semantics (copies are deep).
class Force {
 public:
  /// Wraps @p f; @p label is the user's name for it (may be empty).
  template <class F>
  requires(!std::same_as<std::remove_cvref_t<F>, Force> && ForceType<F>)
      Force(F f, std::string label = {})  // NOLINT(google-explicit-constructor)
      : self_(std::make_unique<Holder<F>>(std::move(f))), label_(std::move(label)) {}

  Force(const Force& other) : self_(other.self_->clone()), label_(other.label_) {}
  Force& operator=(const Force& other) {
    if (this != &other) {
      self_ = other.self_->clone();
      label_ = other.label_;
    }
    return *this;
  }
  Force(Force&&) noexcept = default;
  Force& operator=(Force&&) noexcept = default;
  ~Force() = default;

  /// "unbalance", "harmonic_force", "static_load", "coulomb_friction", …
  std::string_view kind() const { return self_->kind(); }
  /// The user's name for the force (may be empty).
  const std::string& label() const { return label_; }
  /// The nodes the force acts at.
  std::vector<Index> nodes() const { return self_->nodes(); }

  bool has_harmonic() const { return self_->has_harmonic(); }
  /// Adds the complex amplitudes at @p e into @p f (nothing without the ability).
  void add_harmonic(const HarmonicExcitation& e, ComplexVector& f) const { self_->add_harmonic(e, f); }
  bool has_transient() const { return self_->has_transient(); }
  /// Adds the force at @p s into @p f (nothing without the ability).
  void add_transient(const MotionState& s, Vector& f) const { self_->add_transient(s, f); }
  bool has_static() const { return self_->has_static(); }
  /// Adds the constant load into @p f (nothing without the ability).
  void add_static(Vector& f) const { self_->add_static(f); }
  bool is_nonlinear() const { return self_->is_nonlinear(); }
  /// True for a nonlinear force that carries the rotor (see the abilities above).
  bool supports() const { return self_->supports(); }
  /// True for a support that carries load only while the rotor turns (an oil film).
  bool needs_speed() const { return self_->needs_speed(); }
  bool has_drag_torque() const { return self_->has_drag_torque(); }
  /// The torque [N m] with which it resists the rotation at local displacements @p x
  /// and velocities @p v (on dofs()); 0 without the ability.
  Real drag_torque(const MotionState& s, const Vector& x, const Vector& v) const { return self_->drag_torque(s, x, v); }
  /// Its operating state at local displacements @p x and velocities @p v (on dofs());
  /// empty without the ability.
  std::vector<OperatingValue> operating_data(const MotionState& s, const Vector& x, const Vector& v) const {
    return self_->operating_data(s, x, v);
  }
  /// The radial clearance its journal moves in [m]; empty without the ability.
  std::optional<Real> clearance() const { return self_->clearance(); }
  /// The m·e² [kg m²] of a mass turning with the rotor (an unbalance); empty for others.
  std::optional<Real> synchronous_inertia() const { return self_->synchronous_inertia(); }
  /// True for a load that follows a time law of its own, not the rotation (run-ups only).
  bool own_time_law() const { return self_->own_time_law(); }
  /// The global DOFs of a nonlinear force (empty for others).
  std::vector<Index> dofs() const { return self_->dofs(); }
  /// Force and Jacobian of a nonlinear force at local displacements @p x and
  /// velocities @p v (on dofs()); empty for others.
  NonlinearForceValue force(const MotionState& s, const Vector& x, const Vector& v) const {
    return self_->force(s, x, v);
  }

  /// The wrapped force if it is an F, else nullptr (for inspection: analyses ask for
  /// abilities instead).
  template <class F>
  const F* target() const {
    if (self_->type() != typeid(F)) return nullptr;
    return static_cast<const F*>(self_->data());
  }

 private:
  struct Concept {
    virtual ~Concept() = default;
    virtual std::unique_ptr<Concept> clone() const = 0;
    virtual std::string_view kind() const = 0;
    virtual std::vector<Index> nodes() const = 0;
    virtual bool has_harmonic() const = 0;
    virtual void add_harmonic(const HarmonicExcitation& e, ComplexVector& f) const = 0;
    virtual bool has_transient() const = 0;
    virtual void add_transient(const MotionState& s, Vector& f) const = 0;
    virtual bool has_static() const = 0;
    virtual void add_static(Vector& f) const = 0;
    virtual bool is_nonlinear() const = 0;
    virtual bool supports() const = 0;
    virtual bool needs_speed() const = 0;
    virtual bool has_drag_torque() const = 0;
    virtual Real drag_torque(const MotionState&, const Vector&, const Vector&) const = 0;
    virtual std::vector<OperatingValue> operating_data(const MotionState&, const Vector&, const Vector&) const = 0;
    virtual std::optional<Real> clearance() const = 0;
    virtual std::optional<Real> synchronous_inertia() const = 0;
    virtual bool own_time_law() const = 0;
    virtual std::vector<Index> dofs() const = 0;
    virtual NonlinearForceValue force(const MotionState&, const Vector&, const Vector&) const = 0;
    virtual const std::type_info& type() const = 0;
    virtual const void* data() const = 0;
  };
  template <class F>
  struct Holder final : Concept {
    explicit Holder(F f) : value(std::move(f)) {}
    std::unique_ptr<Concept> clone() const override { return std::make_unique<Holder>(value); }
    std::string_view kind() const override { return value.kind(); }
    std::vector<Index> nodes() const override { return value.nodes(); }
    bool has_harmonic() const override { return HasHarmonicLoad<F>; }
    void add_harmonic(const HarmonicExcitation& e, ComplexVector& f) const override {
      if constexpr (HasHarmonicLoad<F>) value.add_harmonic(e, f);
    }
    bool has_transient() const override { return HasTransientLoad<F>; }
    void add_transient(const MotionState& s, Vector& f) const override {
      if constexpr (HasTransientLoad<F>) value.add_transient(s, f);
    }
    bool has_static() const override { return HasStaticLoad<F>; }
    void add_static(Vector& f) const override {
      if constexpr (HasStaticLoad<F>) value.add_static(f);
    }
    bool is_nonlinear() const override { return HasNonlinearForce<F>; }
    bool supports() const override {
      if constexpr (HasSupport<F>)
        return value.supports();
      else
        return false;
    }
    bool needs_speed() const override {
      if constexpr (NeedsSpeed<F>)
        return value.needs_speed();
      else
        return false;
    }
    bool has_drag_torque() const override { return HasDragTorque<F>; }
    Real drag_torque(const MotionState& s, const Vector& x, const Vector& v) const override {
      if constexpr (HasDragTorque<F>)
        return value.drag_torque(s, x, v);
      else
        return 0.0;
    }
    std::vector<OperatingValue> operating_data(const MotionState& s, const Vector& x, const Vector& v) const override {
      if constexpr (HasOperatingData<F>)
        return value.operating_data(s, x, v);
      else
        return {};
    }
    std::optional<Real> clearance() const override {
      if constexpr (HasClearance<F>)
        return static_cast<Real>(value.clearance());
      else
        return std::nullopt;
    }
    std::optional<Real> synchronous_inertia() const override {
      if constexpr (HasSynchronousInertia<F>)
        return static_cast<Real>(value.synchronous_inertia());
      else
        return std::nullopt;
    }
    bool own_time_law() const override {
      if constexpr (HasOwnTimeLaw<F>)
        return value.own_time_law();
      else
        return false;
    }
    std::vector<Index> dofs() const override {
      if constexpr (HasNonlinearForce<F>)
        return value.dofs();
      else
        return {};
    }
    NonlinearForceValue force(const MotionState& s, const Vector& x, const Vector& v) const override {
      if constexpr (HasNonlinearForce<F>)
        return value.force(s, x, v);
      else
        return {};
    }
    const std::type_info& type() const override { return typeid(F); }
    const void* data() const override { return &value; }
    F value;
  };

  std::unique_ptr<Concept> self_;
  std::string label_;
};

/// An unbalance: a mass turning with the rotor (the synchronous_inertia() ability).
inline bool is_unbalance(const Force& f) { return f.synchronous_inertia().has_value(); }
/// A harmonic load that is not an unbalance: it excites at its own or the swept
/// frequency (harmonic forces and moments).
inline bool is_harmonic_force(const Force& f) { return f.has_harmonic() && !is_unbalance(f); }

}  // namespace feran
