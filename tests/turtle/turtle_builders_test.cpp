// The polygon and cylinder builders on their own: what they keep between
// commands and what they draw when a shape ends.
#include <gtest/gtest.h>

#include "turtle/cylinder_builder.h"
#include "turtle/polygon_builder.h"

namespace sylva::test {
namespace {

using geometry::Provenance;
using geometry::Vec3;
using turtle::Frame;

TEST(PolygonBuilder, NestedPolygonsKeepTheirOwnVertices) {
  turtle::PolygonBuilder polygons;
  EXPECT_FALSE(polygons.any_open());
  EXPECT_EQ(polygons.start(Provenance{3, 0}), 1);
  EXPECT_EQ(polygons.add_vertex({0, 0, 0}, Frame{}), 1);
  EXPECT_EQ(polygons.add_vertex({1, 0, 0}, Frame{}), 2);
  EXPECT_EQ(polygons.start(Provenance{6, 0}), 2);
  EXPECT_EQ(polygons.add_vertex({5, 5, 5}, Frame{}), 1);
  geometry::Scene scene;
  // The inner polygon: one vertex, nothing drawn.
  const turtle::PolygonBuilder::Ended inner = polygons.end(&scene, {});
  EXPECT_EQ(inner.vertices, 1);
  EXPECT_EQ(inner.triangles, -1);
  EXPECT_EQ(polygons.add_vertex({1, 1, 0}, Frame{}), 3);
  turtle::PolygonBuilder::Look look;
  look.color = 7;
  const turtle::PolygonBuilder::Ended outer = polygons.end(&scene, look);
  EXPECT_EQ(outer.vertices, 3);
  EXPECT_EQ(outer.triangles, 1);
  EXPECT_FALSE(polygons.any_open());
  ASSERT_EQ(scene.groups.size(), 1u);
  EXPECT_EQ(scene.groups[0].color, 7);
  EXPECT_EQ(scene.groups[0].from.module_index, 3u);  // the module that started it
  EXPECT_EQ(scene.positions.size(), 3u);
}

TEST(PolygonBuilder, WithoutASceneCountsOnly) {
  turtle::PolygonBuilder polygons;
  polygons.start(Provenance{});
  for (int k = 0; k < 4; ++k) polygons.add_vertex({static_cast<float>(k % 2), static_cast<float>(k / 2), 0}, Frame{});
  const turtle::PolygonBuilder::Ended ended = polygons.end(nullptr, {});
  EXPECT_EQ(ended.vertices, 4);
  EXPECT_EQ(ended.triangles, -1);
}

TEST(CylinderBuilder, ABranchEndsTheCylinderItStarted) {
  turtle::TurtleSettings settings;
  geometry::Scene scene;
  turtle::CylinderBuilder cylinders(settings, &scene);
  turtle::TurtleState trunk;
  trunk.contour_sides = 5;
  EXPECT_FALSE(cylinders.open(trunk));
  // The trunk's cylinder: a first point where it starts.
  EXPECT_EQ(cylinders.start(trunk, nullptr, 0, Provenance{0, 0}).rings, -1);
  EXPECT_TRUE(cylinders.open(trunk));
  trunk.position = {0, 1, 0};
  EXPECT_EQ(cylinders.add_point(trunk, Provenance{1, 0}, 1), 2);

  // A branch shares it until it starts its own, which ends with the branch.
  turtle::TurtleState branch = trunk;
  EXPECT_EQ(cylinders.start(branch, &trunk, 0, Provenance{2, 0}).rings, -1);  // the trunk's stays open
  branch.position = {1, 1, 0};
  EXPECT_EQ(cylinders.add_point(branch, Provenance{3, 0}, 1), 2);
  const turtle::CylinderBuilder::Closed branch_end = cylinders.end_branch(branch, trunk);
  EXPECT_EQ(branch_end.rings, 2);
  EXPECT_EQ(branch_end.sides, 5);
  EXPECT_FALSE(cylinders.open(branch));
  EXPECT_TRUE(cylinders.open(trunk));

  trunk.position = {0, 3, 0};
  const turtle::CylinderBuilder::Ended trunk_end = cylinders.end(trunk, Provenance{4, 0}, 2, 0);
  EXPECT_EQ(trunk_end.opened_type, 0);
  EXPECT_EQ(trunk_end.closed.rings, 4);  // 3 control points, the last stretch of 2 strips
  EXPECT_FALSE(cylinders.open(trunk));
  // A stretch a group: 1 in the branch, 2 in the trunk.
  EXPECT_EQ(scene.groups.size(), 3u);
}

TEST(CylinderBuilder, CpfgTypedCylindersAddAPointAfterEachStep) {
  turtle::TurtleSettings settings;
  turtle::CylinderBuilder cylinders(settings, nullptr);
  turtle::TurtleState s;
  cylinders.start(s, nullptr, 1, Provenance{});
  // {(1) defines no point; a step adds one where the turtle has moved.
  EXPECT_EQ(cylinders.step_point(s, Provenance{}), 1);
  EXPECT_EQ(cylinders.step_point(s, Provenance{}), 0);
  const turtle::CylinderBuilder::Dot strips = cylinders.dot(s, Provenance{}, 3);
  EXPECT_EQ(strips.point, 1);
  EXPECT_TRUE(strips.strips_only);
  s.position = {0, 1, 0};
  EXPECT_EQ(cylinders.step_point(s, Provenance{}), 2);
  // }(1) where the turtle has not moved adds no point: two points, the
  // first's ring and the second's 4 strips.
  const turtle::CylinderBuilder::Ended ended = cylinders.end(s, Provenance{}, 4, 1);
  EXPECT_EQ(ended.opened_type, 1);
  EXPECT_EQ(ended.closed.rings, 5);
  EXPECT_FALSE(cylinders.open(s));
}

}  // namespace
}  // namespace sylva::test
