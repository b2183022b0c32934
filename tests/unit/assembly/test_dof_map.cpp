#include <gtest/gtest.h>

#include <feran/assembly/dof_map.hpp>
#include <feran/core/error.hpp>

#include "test_models.hpp"

namespace feran::test_dof_map {
namespace {

TEST(DofMap, FixedDofsAreRemoved) {
  Model m;
  test::add_node(m, 0.0);
  test::add_node(m, 1.0);
  test::fix(m, 0, {Dof::u, Dof::rx});
  const DofMap d(m);
  EXPECT_EQ(d.n_full(), 12);
  EXPECT_EQ(d.n_reduced(), 10);
  EXPECT_EQ(d.reduced_dof(global_dof(0, Dof::u)), -1);
  EXPECT_EQ(d.full_dof(0), global_dof(0, Dof::v));
  // Every reduced DOF maps back to itself.
  for (Index r = 0; r < d.n_reduced(); ++r) EXPECT_EQ(d.reduced_dof(d.full_dof(r)), r);
}

// A follower 0.3 m from its leader moves with it as a rigid body: for a small
// leader rotation rz the follower translates by +0.3·rz along y, for ry by −0.3·ry
// along z (ry = −dw/dx), and shares the rotations.
TEST(DofMap, RigidLinkUsesLeverKinematics) {
  Model m;
  const Index a = test::add_node(m, 0.2), b = test::add_node(m, 0.5);
  m.links.push_back({a, {b}});
  const DofMap d(m);
  ASSERT_EQ(d.n_reduced(), 6);
  Vector q = Vector::Zero(6);
  q(static_cast<Index>(Dof::v)) = 1e-3;
  q(static_cast<Index>(Dof::rz)) = 2e-3;
  q(static_cast<Index>(Dof::ry)) = 5e-3;
  q(static_cast<Index>(Dof::u)) = 7e-3;
  const Vector full = d.expand(q);
  EXPECT_NEAR(full(global_dof(b, Dof::v)), 1e-3 + 0.3 * 2e-3, 1e-15);
  EXPECT_NEAR(full(global_dof(b, Dof::w)), -0.3 * 5e-3, 1e-15);
  EXPECT_EQ(full(global_dof(b, Dof::u)), 7e-3);
  EXPECT_EQ(full(global_dof(b, Dof::ry)), 5e-3);
  EXPECT_EQ(full(global_dof(b, Dof::rz)), 2e-3);
}

TEST(DofMap, ChainedLinksResolveToTheFirstLeader) {
  Model m;
  const Index a = test::add_node(m, 0.0), b = test::add_node(m, 1.0), c = test::add_node(m, 3.0);
  m.links.push_back({b, {c}});
  m.links.push_back({a, {b}});
  const DofMap d(m);
  ASSERT_EQ(d.n_reduced(), 6);
  Vector q = Vector::Zero(6);
  q(static_cast<Index>(Dof::rz)) = 1.0;
  EXPECT_NEAR(d.expand(q)(global_dof(c, Dof::v)), 3.0, 1e-15);
}

TEST(DofMap, RejectsContradictoryConstraints) {
  Model m;
  const Index a = test::add_node(m, 0.0), b = test::add_node(m, 1.0), c = test::add_node(m, 2.0);
  m.links.push_back({a, {c}});
  m.links.push_back({b, {c}});
  EXPECT_THROW(DofMap{m}, ModelStructureError);  // c follows two leaders

  Model loop;
  const Index p = test::add_node(loop, 0.0), q = test::add_node(loop, 1.0);
  loop.links.push_back({p, {q}});
  loop.links.push_back({q, {p}});
  EXPECT_THROW(DofMap{loop}, ModelStructureError);

  Model fixed_follower;
  const Index l = test::add_node(fixed_follower, 0.0), f = test::add_node(fixed_follower, 1.0);
  fixed_follower.links.push_back({l, {f}});
  test::fix(fixed_follower, f, {Dof::v});
  EXPECT_THROW(DofMap{fixed_follower}, ModelStructureError);
}

}  // namespace
}  // namespace feran::test_dof_map
