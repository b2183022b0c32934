#pragma once
/// @file
/// Nonlinear forces f_nl(t, q, q', Ω) (paper eq. 1): a concept and a type-erased,
/// copyable NonlinearForce value. A new force (a rub, a clearance) is one new file:
/// a type with dofs(), force() and kind(), plus one line in nonlinear_forces().

#include <concepts>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// Where and how fast the rotor is when a nonlinear force is evaluated.
struct MotionState {
  Real t = 0.0;
  Real speed = 0.0;  ///< Ω [rad/s]
};

/// A force on a few DOFs and its Jacobian blocks ∂f/∂x and ∂f/∂v (local, on dofs()).
struct NonlinearForceValue {
  Vector f;
  Matrix dfdx;
  Matrix dfdv;
};

template <class F>
concept NonlinearForceType = std::copyable<F> && requires(const F& f, const MotionState& s, const Vector& x) {
  { f.dofs() } -> std::convertible_to<std::vector<Index>>;                 // global (unconstrained) DOFs
  { f.force(s, x, x) } -> std::same_as<NonlinearForceValue>;             // x, v on dofs()
  { f.kind() } -> std::convertible_to<std::string_view>;
};

/// Type-erased nonlinear force with value semantics.
class NonlinearForce {
 public:
  template <class F>
    requires(!std::same_as<std::remove_cvref_t<F>, NonlinearForce> && NonlinearForceType<F>)
  NonlinearForce(F f, std::string label = {})  // NOLINT(google-explicit-constructor)
      : self_(std::make_unique<Holder<F>>(std::move(f))), label_(std::move(label)) {}
  NonlinearForce(const NonlinearForce& o) : self_(o.self_->clone()), label_(o.label_) {}
  NonlinearForce& operator=(const NonlinearForce& o) {
    if (this != &o) self_ = o.self_->clone(), label_ = o.label_;
    return *this;
  }
  NonlinearForce(NonlinearForce&&) noexcept = default;
  NonlinearForce& operator=(NonlinearForce&&) noexcept = default;
  ~NonlinearForce() = default;

  std::vector<Index> dofs() const { return self_->dofs(); }
  /// Force and Jacobian at local displacements @p x and velocities @p v (on dofs()).
  NonlinearForceValue force(const MotionState& s, const Vector& x, const Vector& v) const {
    return self_->force(s, x, v);
  }
  std::string_view kind() const { return self_->kind(); }
  const std::string& label() const { return label_; }

 private:
  struct Concept {
    virtual ~Concept() = default;
    virtual std::unique_ptr<Concept> clone() const = 0;
    virtual std::vector<Index> dofs() const = 0;
    virtual NonlinearForceValue force(const MotionState&, const Vector&, const Vector&) const = 0;
    virtual std::string_view kind() const = 0;
  };
  template <class F>
  struct Holder final : Concept {
    explicit Holder(F f) : value(std::move(f)) {}
    std::unique_ptr<Concept> clone() const override { return std::make_unique<Holder>(value); }
    std::vector<Index> dofs() const override { return value.dofs(); }
    NonlinearForceValue force(const MotionState& s, const Vector& x, const Vector& v) const override {
      return value.force(s, x, v);
    }
    std::string_view kind() const override { return value.kind(); }
    F value;
  };
  std::unique_ptr<Concept> self_;
  std::string label_;
};

/// The nonlinear forces a model defines (today: its Coulomb friction elements).
std::vector<NonlinearForce> nonlinear_forces(const Model& model);

}  // namespace feran
