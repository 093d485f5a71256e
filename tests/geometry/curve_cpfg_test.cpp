// cpfg's curve functions (geometry/curve_cpfg.h), worked by hand on an open
// polygon (0,0) (1,0) (1,3): parameter 0.5 is its corner (1,0).
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/curve_cpfg.h"

namespace sylva::geometry {
namespace {

Contour corner() {
  Contour c;
  c.curve = Contour::Curve::Polygon;
  c.closed = false;
  c.points = {{0, 0, 0}, {1, 0, 0}, {1, 3, 0}};
  return c;
}

TEST(CpfgCurve, ATableOfTwoSamplesIsTheChordAndItsParameter) {
  const Contour c = corner();
  const CpfgCurve curve(c, 2);
  // The table holds the ends only: its length is the chord, sqrt(10), and
  // half of it is parameter 0.5, the corner, not the point halfway along.
  EXPECT_NEAR(curve.length(), std::sqrt(10.0), 1e-6);
  const Vec3 half = curve.at(0.5);
  EXPECT_NEAR(half.x, 1, 1e-6);
  EXPECT_NEAR(half.y, 0, 1e-6);
}

TEST(CpfgCurve, ATableThroughTheCornerFollowsTheArc) {
  const Contour c = corner();
  const CpfgCurve curve(c, 3);
  // Samples at parameters 0, 0.5, 1: lengths 0, 1, 4. t = 0.5 (length 2)
  // lies a third of the way from the corner's sample to the end: parameter
  // 2/3, the point (1,1).
  EXPECT_NEAR(curve.length(), 4, 1e-6);
  const Vec3 p = curve.at(0.5);
  EXPECT_NEAR(p.x, 1, 1e-6);
  EXPECT_NEAR(p.y, 1, 1e-6);
  // t is clamped to [0,1].
  EXPECT_NEAR(curve.at(2).y, 3, 1e-6);
  EXPECT_NEAR(curve.at(-1).x, 0, 1e-6);
}

}  // namespace
}  // namespace sylva::geometry
