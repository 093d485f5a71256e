// Generalized cylinders (LPFG manual 5.8): one ring of contour points per
// control point (StartGC, PointGC, EndGC), `sides` points per ring, the
// width the ring's diameter. Initial frame H = (0,1,0), L = (-1,0,0),
// U = (0,0,1); a contour point (x, y) goes to L * x * r + U * y * r.
#include "turtle/turtle_fixture.h"

#include <cmath>

#include "support/diagnostic.h"

namespace sylva::test::turtle_tests {
namespace {

using geometry::TriangleGroup;

// A square contour through (1,1), (-1,1), (-1,-1), (1,-1), as a polygon.
geometry::Contour square(float half) {
  geometry::Contour c;
  c.name = "square";
  c.curve = geometry::Contour::Curve::Polygon;
  c.points = {{half, half, 0}, {-half, half, 0}, {-half, -half, 0}, {half, -half, 0}};
  return c;
}

// Six sides, three control points: 18 vertices, 2 stretches of 6 bands of
// 2 triangles. Radius 1 (width 2): x = -cos(60k) in [-1, 1], z = sin(60k)
// in [-0.866, 0.866], y from 0 to 2. F draws nothing inside the cylinder.
TEST(TurtleCylinder, CircleContourCounts) {
  Scene s = draw("gc-circle", "ContourSides(6) SetWidth(2) StartGC F(1) PointGC F(1) EndGC");
  EXPECT_TRUE(s.segments.empty());
  EXPECT_EQ(s.positions.size(), 18u);
  ASSERT_EQ(s.groups.size(), 2u);
  EXPECT_EQ(s.groups[0].kind, TriangleGroup::Kind::GeneralizedCylinder);
  EXPECT_EQ(s.groups[0].index_count + s.groups[1].index_count, 2u * 6 * 2 * 3);
  // Each stretch is the module that ended it: PointGC (4) and EndGC (6).
  EXPECT_EQ(s.groups[0].from.module_index, 4u);
  EXPECT_EQ(s.groups[1].from.module_index, 6u);
  geometry::Box b = s.bounds();
  expect_near(b.min, {-1, 0, -0.8660254f});
  expect_near(b.max, {1, 2, 0.8660254f});
  expect_near(s.positions[0], {-1, 0, 0});  // contour point (1,0) along L
  // Normals point away from the axis (0, y, 0).
  for (std::size_t k = 0; k < s.positions.size(); ++k) {
    const Vec3 radial = normalized(Vec3{s.positions[k].x, 0, s.positions[k].z});
    EXPECT_GT(dot(s.normals[k], radial), 0.99f) << k;
  }
  // Triangles face outward too.
  const TriangleGroup& g = s.groups[0];
  for (std::uint32_t t = 0; t < g.index_count / 3; ++t) {
    const Vec3 a = s.positions[s.indices[g.first_index + 3 * t]];
    EXPECT_GT(dot(triangle_normal(s, g, t), Vec3{a.x, 0, a.z}), 0) << t;
  }
}

// A contour from the settings: the square, with the file's 4 samples as
// sides. Width 2 scales it by 1: the box is [-1,1] across, like the square;
// its first point (1,1) sits at L + U = (-1,0,1).
TEST(TurtleCylinder, ContourFromFileWithItsSamples) {
  std::vector<geometry::Contour> contours = {square(1)};
  contours[0].samples = 4;
  turtle::TurtleSettings settings;
  settings.contours = &contours;
  Scene s = draw("gc-square", "CurrentContour(1) SetWidth(2) StartGC F(1) PointGC F(2) PointGC F(1) EndGC", settings);
  EXPECT_EQ(s.positions.size(), 4u * 4);
  EXPECT_EQ(s.groups.size(), 3u);
  expect_near(s.positions[0], {-1, 0, 1});
  geometry::Box b = s.bounds();
  expect_near(b.min, {-1, 0, -1});
  expect_near(b.max, {1, 4, 1});
}

// Without ContourSides or samples, the view file's contour sides.
TEST(TurtleCylinder, ViewFileSides) {
  turtle::TurtleSettings settings;
  settings.contour_sides = 5;
  Scene s = draw("gc-view-sides", "StartGC F(1) EndGC", settings);
  EXPECT_EQ(s.positions.size(), 10u);
}

// ScaleContour(2, 0.5), four sides, width 2: contour points (1,0) (0,1)
// (-1,0) (0,-1) become x in [-2, 2], z in [-0.5, 0.5].
TEST(TurtleCylinder, ScaleContour) {
  Scene s = draw("gc-scale", "ContourSides(4) SetWidth(2) ScaleContour(2, 0.5) StartGC F(3) EndGC");
  geometry::Box b = s.bounds();
  expect_near(b.min, {-2, 0, -0.5f});
  expect_near(b.max, {2, 3, 0.5f});
}

// Halfway between the squares of half-size 1 and 3: half-size 2.
TEST(TurtleCylinder, BlendedContour) {
  std::vector<geometry::Contour> contours = {square(1), square(3)};
  turtle::TurtleSettings settings;
  settings.contours = &contours;
  Scene s = draw("gc-blend", "ContourSides(4) SetWidth(2) BlendedContour(1, 2, 0.5) StartGC F(1) EndGC", settings);
  geometry::Box b = s.bounds();
  expect_near(b.min, {-2, 0, -2});
  expect_near(b.max, {2, 1, 2});
}

// The ring at each control point lies across the turtle's heading there:
// after Left(90) at (0,1,0), L = (0,-1,0), so the second ring's first point
// (contour (1,0), radius 1) is (0,0,0).
TEST(TurtleCylinder, RingsFollowTheTurtle) {
  Scene s = draw("gc-turn", "ContourSides(6) SetWidth(2) StartGC F(1) Left(90) PointGC F(1) EndGC");
  ASSERT_EQ(s.positions.size(), 18u);
  expect_near(s.positions[6], {0, 0, 0});
  expect_near(s.positions[12], {-1, 0, 0});
}

// A cylinder in a branch is its own; the main one goes on around it.
// Main: (0,0,0) to (0,2,0); branch: (0,1,0) to (1,1,0). A branch that does
// not end its cylinder ends it at EB; the string's end ends the rest.
TEST(TurtleCylinder, BranchesAndUnclosedCylinders) {
  Scene s = draw("gc-branch", "ContourSides(3) StartGC F(1) SB Right(90) StartGC F(1) EndGC EB F(1) EndGC");
  EXPECT_EQ(s.positions.size(), 4u * 3);
  ASSERT_EQ(s.groups.size(), 2u);
  // The branch's cylinder is drawn first, along +x from (0,1,0).
  expect_near((s.positions[3] + s.positions[4] + s.positions[5]) / 3, {1, 1, 0});
  expect_near((s.positions[9] + s.positions[10] + s.positions[11]) / 3, {0, 2, 0});

  Scene open = draw("gc-open", "ContourSides(3) StartGC F(1) SB StartGC F(1) EB F(1) PointGC F(1)");
  // The branch's cylinder has only its StartGC when EB ends it: nothing to
  // draw. The main one has StartGC and PointGC when the string ends.
  EXPECT_EQ(open.groups.size(), 1u);
  EXPECT_EQ(open.positions.size(), 6u);
}

TEST(TurtleCylinder, UnknownContourIsAClearError) {
  std::vector<geometry::Contour> contours = {square(1)};
  turtle::TurtleSettings settings;
  settings.contours = &contours;
  try {
    draw("gc-missing", "CurrentContour(3) StartGC F(1) EndGC", settings);
    FAIL() << "expected a ModelError";
  } catch (const ModelError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("CurrentContour"), std::string::npos) << what;
    EXPECT_NE(what.find("no contour 3"), std::string::npos) << what;
  }
  EXPECT_THROW(draw("gc-missing-none", "BlendedContour(0, 1, 0.5)"), ModelError);
}

}  // namespace
}  // namespace sylva::test::turtle_tests
