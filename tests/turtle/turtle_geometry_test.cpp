// The geometry the turtle builds on: contour resampling, function curves,
// Bézier patches and polygon triangulation, checked against values worked
// out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/contour.h"
#include "geometry/function.h"
#include "geometry/polygon_triangulation.h"
#include "geometry/surface.h"

namespace sylva::geometry {
namespace {

void expect_near(Vec3 a, Vec3 b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(TurtleGeometryContour, CircleStartsAlongXAndRunsCounterClockwise) {
  std::vector<Vec3> p = Contour::circle().resample(4);
  ASSERT_EQ(p.size(), 4u);
  expect_near(p[0], {1, 0, 0});
  expect_near(p[1], {0, 1, 0});
  expect_near(p[2], {-1, 0, 0});
  expect_near(p[3], {0, -1, 0});
}

// A closed square polygon of perimeter 8 in 8 points: corners and midpoints.
TEST(TurtleGeometryContour, PolygonEvenlyByArcLength) {
  Contour c;
  c.curve = Contour::Curve::Polygon;
  c.points = {{1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}};
  std::vector<Vec3> p = c.resample(8);
  const Vec3 expected[] = {{1, 1, 0},   {0, 1, 0},   {-1, 1, 0}, {-1, 0, 0},
                           {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 0, 0}};
  ASSERT_EQ(p.size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) expect_near(p[k], expected[k]);

  // Open: the ends are the first and last points; length 2, 3 points.
  Contour open;
  open.curve = Contour::Curve::Polygon;
  open.closed = false;
  open.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  std::vector<Vec3> q = open.resample(3);
  ASSERT_EQ(q.size(), 3u);
  expect_near(q[0], {0, 0, 0});
  expect_near(q[1], {1, 0, 0});
  expect_near(q[2], {1, 1, 0});
}

// The closed uniform cubic B-spline of the square's corners starts each
// segment at (P[i-1] + 4 P[i] + P[i+1]) / 6: (2/3, 2/3) for the first
// corner. By symmetry the four segment starts are evenly spaced.
TEST(TurtleGeometryContour, ClosedBSpline) {
  Contour c;
  c.points = {{1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}};
  std::vector<Vec3> p = c.resample(4);
  const float t = 2.0f / 3;
  expect_near(p[0], {t, t, 0}, 1e-4f);
  expect_near(p[1], {-t, t, 0}, 1e-4f);
  expect_near(p[2], {-t, -t, 0}, 1e-4f);
  expect_near(p[3], {t, -t, 0}, 1e-4f);
}

// Four evenly spaced collinear control points make y = x. lpfg finds x to
// within 0.01 / samples, cpfg to within 0.001; both clamp x to [0,1].
TEST(TurtleGeometryFunction, LineAndClamping) {
  Function f;
  f.points = {{0, 0}, {1.0f / 3, 1.0f / 3}, {2.0f / 3, 2.0f / 3}, {1, 1}};
  f.samples = 1000;
  const LpfgFunction lpfg(f);
  EXPECT_NEAR(lpfg.value(0.3f), 0.3f, 2e-5f);
  EXPECT_NEAR(lpfg.value(0.9f), 0.9f, 2e-5f);
  EXPECT_NEAR(lpfg.value(-2), 0, 2e-5f);
  EXPECT_NEAR(lpfg.value(5), 1, 2e-5f);
  f.samples = 0;
  const CpfgFunction cpfg(f);
  EXPECT_NEAR(cpfg.value(0.3), 0.3, 1e-3);
  EXPECT_NEAR(cpfg.value(-2), 0, 1e-3);
  EXPECT_NEAR(cpfg.value(5), 1, 1e-3);
}

// Five points (0,0) (0.25,0) (0.5,1) (0.75,0) (1,0), knots 0 0 0 0 1 2 2 2 2:
// at the interior knot the curve is P1/4 + P2/2 + P3/4 = (0.5, 0.5), its peak.
TEST(TurtleGeometryFunction, CubicWithAnInteriorKnot) {
  Function f;
  f.points = {{0, 0}, {0.25f, 0}, {0.5f, 1}, {0.75f, 0}, {1, 0}};
  const CpfgFunction cpfg(f);
  EXPECT_NEAR(cpfg.value(0.5), 0.5, 1e-5);
  EXPECT_NEAR(cpfg.value(0), 0, 1e-5);  // x within 0.001 of 0, where y grows as x cubed
  f.samples = 101;  // a sample at x = 0.5
  const LpfgFunction lpfg(f);
  EXPECT_NEAR(lpfg.value(0.5f), 0.5f, 1e-5f);
}

BezierPatch flat_patch() {
  BezierPatch p;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) p.points[static_cast<std::size_t>(4 * r + c)] = {static_cast<float>(c), static_cast<float>(r), 0};
  return p;
}

// Corners are the corner control points; a flat patch in z = 0 with u along
// x and v along y has normal x cross y = (0,0,1), also where a row of points
// collapses into one (a leaf's tip).
TEST(TurtleGeometryPatch, CornersAndNormals) {
  BezierPatch p = flat_patch();
  expect_near(evaluate_patch(p, 0, 0), {0, 0, 0});
  expect_near(evaluate_patch(p, 1, 0), {3, 0, 0});
  expect_near(evaluate_patch(p, 0, 1), {0, 3, 0});
  expect_near(evaluate_patch(p, 1, 1), {3, 3, 0});
  expect_near(evaluate_patch(p, 0.5f, 0.5f), {1.5f, 1.5f, 0});
  expect_near(patch_normal(p, 0.3f, 0.7f), {0, 0, 1});
  for (int c = 0; c < 4; ++c) p.points[static_cast<std::size_t>(c)] = {1.5f, 0, 0};
  expect_near(patch_normal(p, 0.5f, 0), {0, 0, 1}, 1e-4f);
}

double area(const std::vector<Vec3>& p, const std::vector<std::uint32_t>& t) {
  double a = 0;
  for (std::size_t k = 0; k < t.size(); k += 3) a += 0.5 * length(cross(p[t[k + 1]] - p[t[k]], p[t[k + 2]] - p[t[k]]));
  return a;
}

// A comb (0,0) (3,0) (3,2) (2,2) (2,1) (1,1) (1,2) (0,2): 8 vertices, 6
// triangles, area 6 - 1 = 5; the same in a vertical plane and reversed.
TEST(TurtleGeometryPolygon, ConcaveCombInAnyPlane) {
  std::vector<Vec3> comb = {{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {2, 2, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  std::vector<std::uint32_t> triangles, work;
  EXPECT_EQ(triangulate_polygon(comb.data(), comb.size(), 0, triangles, work), 6u);
  EXPECT_NEAR(area(comb, triangles), 5.0, 1e-5);
  expect_near(normalized(newell_normal(comb.data(), comb.size())), {0, 0, 1});

  std::vector<Vec3> upright;
  for (auto it = comb.rbegin(); it != comb.rend(); ++it) upright.push_back({it->x, 0, it->y});
  triangles.clear();
  EXPECT_EQ(triangulate_polygon(upright.data(), upright.size(), 10, triangles, work), 6u);
  for (std::uint32_t& i : triangles) i -= 10;
  EXPECT_NEAR(area(upright, triangles), 5.0, 1e-5);
}

}  // namespace
}  // namespace sylva::geometry
