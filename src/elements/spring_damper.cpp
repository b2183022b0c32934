#include <feran/elements/spring_damper.hpp>

#include <array>

#include <fmt/format.h>

#include <algorithm>

namespace feran {

namespace {
Matrix six_by_six(const std::array<SpeedCoefficient, dofs_per_node>& direct, const SpeedCoefficient& yz,
                  const SpeedCoefficient& zy, Real speed, Real frequency) {
  Matrix m = Matrix::Zero(dofs_per_node, dofs_per_node);
  for (int d = 0; d < dofs_per_node; ++d) m(d, d) = direct[static_cast<std::size_t>(d)].at(speed, frequency);
  m(static_cast<Index>(Dof::v), static_cast<Index>(Dof::w)) = yz.at(speed, frequency);
  m(static_cast<Index>(Dof::w), static_cast<Index>(Dof::v)) = zy.at(speed, frequency);
  return m;
}

// [[a, −a], [−a, a]] for two nodes, or a alone for a node-to-ground element.
Matrix relative(const Matrix& a, bool two_nodes) {
  if (!two_nodes) return a;
  Matrix m(2 * dofs_per_node, 2 * dofs_per_node);
  m << a, -a, -a, a;
  return m;
}
}  // namespace

SpringDamper::SpringDamper(Index node_a, std::optional<Index> node_b, SpringDamperCoefficients coeffs)
    : node_a_(node_a), node_b_(node_b), coeffs_(std::move(coeffs)) {}

bool SpringDamper::speed_dependent() const {
  auto varies = [](const SpeedCoefficient& c) { return !c.is_constant(); };
  return std::any_of(coeffs_.k.begin(), coeffs_.k.end(), varies) ||
         std::any_of(coeffs_.c.begin(), coeffs_.c.end(), varies) || varies(coeffs_.kyz) || varies(coeffs_.kzy) ||
         varies(coeffs_.cyz) || varies(coeffs_.czy);
}

bool SpringDamper::frequency_dependent() const {
  auto varies = [](const SpeedCoefficient& c) { return c.frequency_dependent(); };
  return std::any_of(coeffs_.k.begin(), coeffs_.k.end(), varies) ||
         std::any_of(coeffs_.c.begin(), coeffs_.c.end(), varies) || varies(coeffs_.kyz) || varies(coeffs_.kzy) ||
         varies(coeffs_.cyz) || varies(coeffs_.czy);
}

namespace {
// Calls add(coefficient, name) for each of @p c's coefficients.
template <class F>
void each_coefficient(const SpringDamperCoefficients& c, F&& add) {
  for (std::size_t i = 0; i < spring::count; ++i) {
    const auto index = static_cast<spring::Coefficient>(i);
    add(coefficient(c, index), spring::names[i].name.data());
  }
}
}  // namespace

SpeedCoefficient& coefficient(SpringDamperCoefficients& c, spring::Coefficient i) {
  switch (i) {
    case spring::kyz:
      return c.kyz;
    case spring::kzy:
      return c.kzy;
    case spring::cyz:
      return c.cyz;
    case spring::czy:
      return c.czy;
    default:
      return i < spring::cx ? c.k[i] : c.c[i - spring::cx];
  }
}

const SpeedCoefficient& coefficient(const SpringDamperCoefficients& c, spring::Coefficient i) {
  return coefficient(const_cast<SpringDamperCoefficients&>(c), i);  // NOLINT(cppcoreguidelines-pro-type-const-cast)
}

std::vector<SpeedRange> SpringDamper::frequency_ranges() const {
  std::vector<SpeedRange> out;
  each_coefficient(coeffs_, [&](const SpeedCoefficient& c, const char* name) {
    if (const auto* t = std::get_if<SpeedCoefficient::FrequencyTable>(&c.law()); t && !t->frequencies.empty())
      out.push_back({fmt::format("coefficient '{}'", name), t->frequencies.front(), t->frequencies.back()});
  });
  return out;
}

std::vector<SpeedRange> SpringDamper::speed_ranges() const {
  std::vector<SpeedRange> out;
  each_coefficient(coeffs_, [&](const SpeedCoefficient& c, const char* name) {
    if (const auto* t = std::get_if<SpeedCoefficient::Table>(&c.law()); t && !t->speeds.empty())
      out.push_back({fmt::format("coefficient '{}'", name), t->speeds.front(), t->speeds.back()});
    if (const auto* t = std::get_if<SpeedCoefficient::FrequencyTable>(&c.law()); t && !t->speeds.empty())
      out.push_back({fmt::format("coefficient '{}'", name), t->speeds.front(), t->speeds.back()});
  });
  return out;
}

Matrix SpringDamper::stiffness_6x6(Real speed, std::optional<Real> frequency) const {
  return six_by_six(coeffs_.k, coeffs_.kyz, coeffs_.kzy, speed, frequency.value_or(speed));
}

Matrix SpringDamper::damping_6x6(Real speed, std::optional<Real> frequency) const {
  return six_by_six(coeffs_.c, coeffs_.cyz, coeffs_.czy, speed, frequency.value_or(speed));
}

LocalMatrices SpringDamper::local_matrices(const OperatingPoint& op) const {
  LocalMatrices out;
  for (int d = 0; d < dofs_per_node; ++d) out.dofs.push_back(dofs_per_node * node_a_ + d);
  if (node_b_)
    for (int d = 0; d < dofs_per_node; ++d) out.dofs.push_back(dofs_per_node * *node_b_ + d);
  out.K = relative(stiffness_6x6(op.speed, op.frequency), node_b_.has_value());
  out.C = relative(damping_6x6(op.speed, op.frequency), node_b_.has_value());
  out.loss_factor = coeffs_.loss_factor;
  return out;
}

SpringDamper SpringDamper::with_lateral_stiffness(Real k) const {
  SpringDamperCoefficients c = coeffs_;
  c.k[static_cast<std::size_t>(Dof::v)] = k;
  c.k[static_cast<std::size_t>(Dof::w)] = k;
  c.kyz = 0.0;
  c.kzy = 0.0;
  return {node_a_, node_b_, c};
}

}  // namespace feran
