#pragma once
/// @file
/// The element interface: a concept with optional abilities and a type-erased,
/// copyable Element value.
///
/// An element is a small value type that returns its matrices at an operating
/// point. Besides, it may have abilities that analyses and writers ask for instead of
/// asking for its type (detected at compile time, as pagmo detects has_gradient):
///
///   transmission(Real speed) -> Transmission   it connects two nodes (or a node and
///                                              the ground) and transmits a force to
///                                              report: spring–dampers, bearings
///   connection() -> Connection                 the nodes it connects, known without
///                                              evaluating it (analyses find the bearings
///                                              by it; without it, transmission(0) tells)
///   shaft_segment() -> ShaftSegment            it is a piece of shaft whose section
///                                              forces and stresses are reported
///   speed_ranges() -> std::vector<SpeedRange>  it has tabulated data over speed
///                                              ranges (analyses warn beyond them)
///   frequency_dependent() -> bool              its matrices depend on the frequency
///                                              of the motion (OperatingPoint::frequency):
///                                              seals, squeeze films, support structures
///   frequency_ranges() -> std::vector<SpeedRange>  the frequency ranges of its tables
///   transmission(Real speed, std::optional<Real> frequency) -> Transmission
///                                              what it transmits for motion at a
///                                              frequency (else transmission(speed))
///   dofs() -> std::vector<Index>               its DOFs without evaluating its matrices
///                                              (an element whose matrices need work,
///                                              or exist only at some speeds)
///   operating_data(Real speed)                 the operating state at @p speed of the
///     -> std::vector<OperatingValue>           support it stands for (a bearing
///                                              linearised about its equilibrium)
///   with_lateral_stiffness(Real k) -> E        it is a bearing whose lateral direct
///                                              stiffness can be set, the rest kept: the
///                                              same element with k_yy = k_zz = k and no
///                                              cross-coupled stiffness (the critical
///                                              speed map's sweep of bearing stiffness)
///   mass_properties() -> MassProperties        it is a lumped rigid mass at a node:
///                                              its mass and inertias (drawings,
///                                              summaries)
///
/// To add an element: a header and a source in elements/, its spec type and field
/// table (spec/), its build step, a test, and its matrices in docs/theory/.

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
#include <feran/model/section.hpp>

namespace feran {

/// An element's contribution to M q'' + (C + C_i + Ω G) q' + (K + Ω K_i) q = f.
/// Matrices are square of size dofs.size(); an empty matrix (0×0) means zero.
/// G and K_i are per unit speed: the assembly multiplies them by Ω.
struct LocalMatrices {
  std::vector<Index> dofs;  ///< global (unconstrained) DOF numbers, see global_dof()
  Matrix M;                 ///< mass
  Matrix C;                 ///< non-rotating (external) viscous damping
  Matrix K;                 ///< stiffness
  Matrix G;                 ///< gyroscopic, skew-symmetric, per unit speed
  Matrix Ci;                ///< rotating (internal) viscous damping
  Matrix Ki;                ///< circulatory stiffness of rotating damping, skew, per unit speed
  /// Hysteretic loss factor η: harmonic analyses add j·η·K to the dynamic stiffness.
  Real loss_factor = 0.0;
};

/// What a connecting element transmits at a speed: with Δq = q_a − q_b (q_b = 0 for
/// the ground) its force on node a is −(K·Δq + C·Δq' + M·Δq''), and K·Δq + C·Δq' +
/// M·Δq'' is reported as the force it transmits to node b or the ground. K and C are 6×6 in the DOF order
/// u, v, w, rx, ry, rz.
struct Transmission {
  Index node_a = 0;
  std::optional<Index> node_b;  ///< empty: the ground
  Matrix K;                     ///< [N/m, N m/rad]
  Matrix C;                     ///< [N s/m, N m s/rad]
  Real loss_factor = 0.0;       ///< hysteretic loss factor η of K (harmonic analyses)
  /// Added mass [kg, kg m²] of a fluid element (an annular seal): its force on node a
  /// has −M·Δq'' too. Empty: none.
  Matrix M;
};

/// The nodes a connecting element joins: node_a to node_b, or to the ground.
struct Connection {
  Index node_a = 0;
  std::optional<Index> node_b;  ///< empty: the ground
};

/// A two-node piece of shaft with a circular cross-section: where section forces
/// and stresses are reported.
struct ShaftSegment {
  Index node_a = 0;  ///< at the smaller x
  Index node_b = 0;
  CircularSection section;    ///< at node a
  CircularSection section_b;  ///< at node b (equal to section unless tapered)
  /// The section at end @p end (0: node a, 1: node b).
  const CircularSection& section_at_end(int end) const { return end == 0 ? section : section_b; }
};

/// A speed range over which an element has data (a tabulated coefficient): outside
/// it the data's last value is held.
struct SpeedRange {
  std::string what;  ///< e.g. "coefficient 'ky'"
  Real low = 0.0;    ///< [rad/s]
  Real high = 0.0;   ///< [rad/s]
};

/// A lumped rigid mass at a node, as drawings and summaries show it.
struct MassProperties {
  Index node = 0;
  Real mass = 0.0;                ///< [kg]
  Real transverse_inertia = 0.0;  ///< about a transverse axis through the node [kg m²]
  Real polar_inertia = 0.0;       ///< about the x axis [kg m²]
  Real offset = 0.0;              ///< axial position of the centre of mass from the node [m]
  bool rotating = false;
};

/// What an element type must provide.
template <class E>
concept ElementType = std::copyable<E> && requires(const E& e, const OperatingPoint& op) {
  { e.local_matrices(op) } -> std::same_as<LocalMatrices>;
  { e.kind() } -> std::convertible_to<std::string_view>;
  { e.speed_dependent() } -> std::convertible_to<bool>;
};

template <class E>
concept HasTransmission = requires(const E& e, Real speed) {
  { e.transmission(speed) } -> std::same_as<Transmission>;
};
template <class E>
concept HasFrequencyTransmission = requires(const E& e, Real speed, std::optional<Real> frequency) {
  { e.transmission(speed, frequency) } -> std::same_as<Transmission>;
};
template <class E>
concept HasFrequencyDependence = requires(const E& e) {
  { e.frequency_dependent() } -> std::convertible_to<bool>;
  { e.frequency_ranges() } -> std::same_as<std::vector<SpeedRange>>;
};
template <class E>
concept HasSpeedRanges = requires(const E& e) {
  { e.speed_ranges() } -> std::same_as<std::vector<SpeedRange>>;
};
template <class E>
concept HasShaftSegment = requires(const E& e) {
  { e.shaft_segment() } -> std::same_as<ShaftSegment>;
};

template <class E>
concept HasConnection = requires(const E& e) {
  { e.connection() } -> std::same_as<Connection>;
};

template <class E>
concept HasOperatingState = requires(const E& e, Real speed) {
  { e.operating_data(speed) } -> std::same_as<std::vector<OperatingValue>>;
};
template <class E>
concept HasLateralStiffness = requires(const E& e, Real k) {
  { e.with_lateral_stiffness(k) } -> std::same_as<E>;
};
template <class E>
concept HasMassProperties = requires(const E& e) {
  { e.mass_properties() } -> std::same_as<MassProperties>;
};
template <class E>
concept HasDofs = requires(const E& e) {
  { e.dofs() } -> std::same_as<std::vector<Index>>;
};

/// A type-erased element with value semantics (copies are deep).
class Element {
 public:
  /// Wraps @p e; @p label is the user's name for it (may be empty).
  template <class E>
  requires(!std::same_as<std::remove_cvref_t<E>, Element> && ElementType<E>)
      Element(E e, std::string label = {})  // NOLINT(google-explicit-constructor)
      : self_(std::make_unique<Holder<E>>(std::move(e))), label_(std::move(label)) {}

  Element(const Element& other) : self_(other.self_->clone()), label_(other.label_) {}
  Element& operator=(const Element& other) {
    if (this != &other) {
      self_ = other.self_->clone();
      label_ = other.label_;
    }
    return *this;
  }
  Element(Element&&) noexcept = default;
  Element& operator=(Element&&) noexcept = default;
  ~Element() = default;

  /// Local matrices at operating point @p op.
  LocalMatrices local_matrices(const OperatingPoint& op) const { return self_->local_matrices(op); }
  /// Its global DOFs (those of local_matrices()).
  std::vector<Index> dofs() const { return self_->dofs(); }
  /// Element kind, e.g. "shaft", "rigid_body", "spring_damper".
  std::string_view kind() const { return self_->kind(); }
  /// True when any matrix other than G and K_i's speed factor depends on speed.
  bool speed_dependent() const { return self_->speed_dependent(); }
  /// The user's name for the element (may be empty).
  const std::string& label() const { return label_; }
  /// True when its matrices depend on the frequency of the motion.
  bool frequency_dependent() const { return self_->frequency_dependent(); }
  /// What it transmits at @p speed [rad/s] for motion at @p frequency [rad/s] (empty:
  /// synchronous), if it is a connecting element.
  std::optional<Transmission> transmission(Real speed, std::optional<Real> frequency = std::nullopt) const {
    return self_->transmission(speed, frequency);
  }
  /// The nodes it connects, if it is a connecting element.
  std::optional<Connection> connection() const { return self_->connection(); }
  /// The speed ranges of its tabulated data (empty for elements without tables).
  std::vector<SpeedRange> speed_ranges() const { return self_->speed_ranges(); }
  /// The frequency ranges of its frequency tables [rad/s] (empty for most elements).
  std::vector<SpeedRange> frequency_ranges() const { return self_->frequency_ranges(); }
  /// Its shaft segment, if it is a piece of shaft.
  std::optional<ShaftSegment> shaft_segment() const { return self_->shaft_segment(); }
  /// The operating state at @p speed [rad/s] of the support it stands for, if it
  /// stands for one (a bearing linearised about its equilibrium).
  std::optional<std::vector<OperatingValue>> operating_data(Real speed) const { return self_->operating_data(speed); }
  /// The same bearing with lateral direct stiffness @p k [N/m] and no cross-coupled
  /// stiffness, its other coefficients kept; empty without the ability.
  std::optional<Element> with_lateral_stiffness(Real k) const {
    std::unique_ptr<Concept> changed = self_->with_lateral_stiffness(k);
    if (!changed) return std::nullopt;
    return Element(std::move(changed), label_);
  }
  /// Its mass and inertias, if it is a lumped rigid mass.
  std::optional<MassProperties> mass_properties() const { return self_->mass_properties(); }

  /// The wrapped element if it is an E, else nullptr (for inspection: analyses and
  /// writers ask for abilities instead).
  template <class E>
  const E* target() const {
    if (self_->type() != typeid(E)) return nullptr;
    return static_cast<const E*>(self_->data());
  }

 private:
  struct Concept;
  Element(std::unique_ptr<Concept> self, std::string label) : self_(std::move(self)), label_(std::move(label)) {}

  struct Concept {
    virtual ~Concept() = default;
    virtual std::unique_ptr<Concept> clone() const = 0;
    virtual LocalMatrices local_matrices(const OperatingPoint& op) const = 0;
    virtual std::vector<Index> dofs() const = 0;
    virtual std::string_view kind() const = 0;
    virtual bool speed_dependent() const = 0;
    virtual bool frequency_dependent() const = 0;
    virtual std::vector<SpeedRange> frequency_ranges() const = 0;
    virtual std::optional<Transmission> transmission(Real speed, std::optional<Real> frequency) const = 0;
    virtual std::optional<ShaftSegment> shaft_segment() const = 0;
    virtual std::optional<Connection> connection() const = 0;
    virtual std::vector<SpeedRange> speed_ranges() const = 0;
    virtual std::optional<std::vector<OperatingValue>> operating_data(Real speed) const = 0;
    virtual std::optional<MassProperties> mass_properties() const = 0;
    virtual std::unique_ptr<Concept> with_lateral_stiffness(Real k) const = 0;
    virtual const std::type_info& type() const = 0;
    virtual const void* data() const = 0;
  };
  template <class E>
  struct Holder final : Concept {
    explicit Holder(E e) : value(std::move(e)) {}
    std::unique_ptr<Concept> clone() const override { return std::make_unique<Holder>(value); }
    LocalMatrices local_matrices(const OperatingPoint& op) const override { return value.local_matrices(op); }
    std::vector<Index> dofs() const override {
      if constexpr (HasDofs<E>)
        return value.dofs();
      else
        return value.local_matrices({}).dofs;
    }
    std::string_view kind() const override { return value.kind(); }
    bool speed_dependent() const override { return value.speed_dependent(); }
    bool frequency_dependent() const override {
      if constexpr (HasFrequencyDependence<E>)
        return value.frequency_dependent();
      else
        return false;
    }
    std::vector<SpeedRange> frequency_ranges() const override {
      if constexpr (HasFrequencyDependence<E>)
        return value.frequency_ranges();
      else
        return {};
    }
    std::optional<Transmission> transmission(Real speed, std::optional<Real> frequency) const override {
      if constexpr (HasFrequencyTransmission<E>)
        return value.transmission(speed, frequency);
      else if constexpr (HasTransmission<E>)
        return value.transmission(speed);
      else
        return std::nullopt;
    }
    std::optional<Connection> connection() const override {
      if constexpr (HasConnection<E>)
        return value.connection();
      else if constexpr (HasTransmission<E> || HasFrequencyTransmission<E>) {
        const std::optional<Transmission> t = transmission(0.0, std::nullopt);  // its nodes, by evaluating it
        return Connection{t->node_a, t->node_b};
      } else
        return std::nullopt;
    }
    std::vector<SpeedRange> speed_ranges() const override {
      if constexpr (HasSpeedRanges<E>)
        return value.speed_ranges();
      else
        return {};
    }
    std::optional<ShaftSegment> shaft_segment() const override {
      if constexpr (HasShaftSegment<E>)
        return value.shaft_segment();
      else
        return std::nullopt;
    }
    std::optional<std::vector<OperatingValue>> operating_data(Real speed) const override {
      if constexpr (HasOperatingState<E>)
        return value.operating_data(speed);
      else
        return std::nullopt;
    }
    std::optional<MassProperties> mass_properties() const override {
      if constexpr (HasMassProperties<E>)
        return value.mass_properties();
      else
        return std::nullopt;
    }
    std::unique_ptr<Concept> with_lateral_stiffness(Real k) const override {
      if constexpr (HasLateralStiffness<E>)
        return std::make_unique<Holder<E>>(value.with_lateral_stiffness(k));
      else
        return nullptr;
    }
    const std::type_info& type() const override { return typeid(E); }
    const void* data() const override { return &value; }
    E value;
  };

  std::unique_ptr<Concept> self_;
  std::string label_;
};

}  // namespace feran
