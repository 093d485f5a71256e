// cpfg's generalized cylinders (CPFG manual 6.7.3): the axis between two
// control points is the cubic Hermite curve
//   p(t) = h00 p0 + h10 m0 + h01 p1 + h11 m1,
//   h00 = 2t^3 - 3t^2 + 1, h10 = t^3 - 2t^2 + t, h01 = -2t^3 + 3t^2, h11 = t^3 - t^2,
// with tangents m = heading x distance x coefficient (@Gt(start,end), 1.2 by
// default); @Gc(strips) / .(strips) / @Ge(strips) put strips - 1 rings inside
// the stretch, at t = k / strips. Worked out by hand below; initial frame
// H = (0,1,0), L = (-1,0,0), U = (0,0,1); - turns H toward -L (+x).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>

#include "turtle/turtle_fixture.h"

namespace sylva::test::turtle_tests {
namespace {

// A cpfg model whose axiom is `axiom`, drawn with `view` as its view file.
Scene draw_cpfg_cylinder(const std::string& name, const std::string& axiom,
                         const std::string& view = "angle increment: 90") {
  const std::string dir = make_temp_dir("cpfg-cylinder-" + name);
  std::ofstream(dir + "/lsystem.l") << "Lsystem: 1\nderivation length: 0\nAxiom: " << axiom << "\nendlsystem\n";
  std::ofstream(dir + "/view.v") << view << "\n";
  build::BuildOptions build;
  build.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(dir + "/lsystem.l", SimulationOptions{build, {dir + "/view.v"}});
  simulation.run(0);
  return simulation.scene();
}

Vec3 ring_center(const Scene& s, int ring, int sides) {
  Vec3 c{0, 0, 0};
  for (int i = 0; i < sides; ++i) c += s.positions[static_cast<std::size_t>(ring * sides + i)];
  return c / static_cast<float>(sides);
}

// The largest distance of a ring's points from its center.
float ring_radius(const Scene& s, int ring, int sides) {
  const Vec3 c = ring_center(s, ring, sides);
  float r = 0;
  for (int i = 0; i < sides; ++i)
    r = std::max(r, length(s.positions[static_cast<std::size_t>(ring * sides + i)] - c));
  return r;
}

// Two control points 2 apart along H, 4 strips: 4 x (4 + 1) = 20 vertices,
// one group of 4 strips x 4 sides x 2 triangles. m0 = m1 = (0, 2 x 1.2, 0):
// y(1/4) = 0.140625 x 2.4 + 0.15625 x 2 - 0.046875 x 2.4 = 0.5375,
// y(1/2) = 0.125 x 2.4 + 0.5 x 2 - 0.125 x 2.4 = 1, y(3/4) = 2 - 0.5375.
TEST(CpfgCylinder, StraightAxisRingsAtTheHermitePositions) {
  Scene s = draw_cpfg_cylinder("straight", "@!(4)#(2)@Gs F(2) @Ge(4)");
  ASSERT_EQ(s.positions.size(), 4u * (4 + 1));
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].index_count, 4u * 4 * 2 * 3);
  const float y[] = {0, 0.5375f, 1, 1.4625f, 2};
  for (int k = 0; k < 5; ++k) {
    expect_near(ring_center(s, k, 4), {0, y[k], 0});
    EXPECT_NEAR(ring_radius(s, k, 4), 1, 1e-5) << k;  // width 2 all along
  }
  // Rings lie across the axis: every point at the ring's height.
  for (int k = 0; k < 5; ++k)
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(s.positions[static_cast<std::size_t>(4 * k + i)].y, y[k], 1e-5);

  // With coefficients 1 the tangents are p1 - p0 and the curve is the
  // segment at constant speed: rings at 0.5, 1, 1.5.
  Scene even = draw_cpfg_cylinder("straight-even", "@!(4)#(2)@Gt(1,1)@Gs F(2) @Ge(4)");
  ASSERT_EQ(even.positions.size(), 20u);
  for (int k = 0; k < 5; ++k) expect_near(ring_center(even, k, 4), {0, 0.5f * static_cast<float>(k), 0});
}

// Without a parameter @Gc and @Ge keep one strip (a ring per control point);
// .(strips) is @Gc(strips). Rings: 1 + 2 + 3 for both spellings.
TEST(CpfgCylinder, StripsPerStretch) {
  for (const char* axiom : {"@!(5)@Gs F @Gc(2) F @Ge(3)", "@!(5)@Gs F .(2) F @Ge(3)"}) {
    Scene s = draw_cpfg_cylinder(axiom[11] == '@' ? "strips-at" : "strips-dot", axiom);
    EXPECT_EQ(s.positions.size(), 5u * 6) << axiom;
    ASSERT_EQ(s.groups.size(), 2u) << axiom;
    EXPECT_EQ(s.groups[0].index_count, 2u * 5 * 6) << axiom;
    EXPECT_EQ(s.groups[1].index_count, 3u * 5 * 6) << axiom;
  }
  Scene plain = draw_cpfg_cylinder("strips-default", "@!(5)@Gs F @Gc F @Ge");
  EXPECT_EQ(plain.positions.size(), 5u * 3);
}

// The manual's Figure 3: @Gs-(45)f-(45)@Gt(start,end)@Ge(20). p0 = 0 with
// heading (0,1,0); p1 = (s, s, 0), s = sin 45, with heading (1,0,0); the
// distance is 1. At t = 1/2 (ring 10): p = p0/2 + m0/8 + p1/2 - m1/8
// = (s/2 - end/8, s/2 + start/8, 0). The chord runs along (1,1)/sqrt2 and
// the curve bulges to its (-1,1) side by (start + end) / (8 sqrt2): larger
// coefficients push the midpoint outward.
TEST(CpfgCylinder, TangentCoefficientsBulgeTheCurve) {
  const float s = std::sqrt(0.5f);
  struct Case {
    const char* name;
    float start, end;
  };
  float previous_bulge = -1;
  for (const Case& c : {Case{"gt-half", 0.5f, 0.5f}, Case{"gt-default", 1.2f, 1.2f}, Case{"gt-two", 2, 2}}) {
    const std::string gt = c.start == 1.2f ? "" : "@Gt(" + std::to_string(c.start) + "," + std::to_string(c.end) + ")";
    Scene scene = draw_cpfg_cylinder(c.name, "@!(8)#(0.1)@Gs-(45)f-(45)" + gt + "@Ge(20)");
    ASSERT_EQ(scene.positions.size(), 8u * 21) << c.name;
    const Vec3 mid = ring_center(scene, 10, 8);
    expect_near(mid, {s / 2 - c.end / 8, s / 2 + c.start / 8, 0});
    const float bulge = dot(mid, Vec3{-s, s, 0});
    EXPECT_NEAR(bulge, (c.start + c.end) / (8 * std::sqrt(2.0f)), 1e-5) << c.name;
    EXPECT_GT(bulge, previous_bulge) << c.name;
    previous_bulge = bulge;
    // The ring there lies across the curve: its tangent 1.5 (p1 - p0) - (m0 + m1) / 4.
    const Vec3 tangent = Vec3{s, s, 0} * 1.5f - Vec3{c.end, c.start, 0} * 0.25f;
    for (int i = 0; i < 8; ++i)
      EXPECT_NEAR(dot(scene.positions[static_cast<std::size_t>(80 + i)] - mid, normalized(tangent)), 0, 1e-4)
          << c.name << " " << i;
    // Both ends are the control points.
    expect_near(ring_center(scene, 0, 8), {0, 0, 0});
    expect_near(ring_center(scene, 20, 8), {s, s, 0});
  }
  // (d) 4, 1: the start tangent dominates, the midpoint is pulled up:
  // (s/2 - 1/8, s/2 + 1/2, 0).
  Scene d = draw_cpfg_cylinder("gt-four-one", "@!(8)#(0.1)@Gs-(45)f-(45)@Gt(4,1)@Ge(20)");
  expect_near(ring_center(d, 10, 8), {s / 2 - 0.125f, s / 2 + 0.5f, 0});
}

// Width 2 at the first control point, 6 at the second: the radius goes
// linearly, 1 to 3 (2 at the middle ring); the end rings keep their own.
TEST(CpfgCylinder, RadiusInterpolatedLinearly) {
  Scene s = draw_cpfg_cylinder("radius", "@!(6)#(2)@Gs F(2) #(6)@Ge(4)");
  ASSERT_EQ(s.positions.size(), 6u * 5);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(ring_radius(s, k, 6), 1 + 0.5f * static_cast<float>(k), 1e-5) << k;
}

// @Gr(angle1,length1,angle2,length2): the radius is the Hermite curve from
// (0, r0) to (X, r1) with tangents length (cos angle, sin angle), taken where
// its first coordinate is t X; X = 1 (adjusted, the default) or, after
// @Gr(0), the stretch's length. With r0 = r1 = 1/2:
// (a) angles 30 and -30, lengths 1: symmetric, so the middle is at u = 1/2:
//     1/2 + (1/8) sin 30 + (1/8) sin 30 = 0.625.
// (b) tangents (1, 1) and (1, -1) (45 degrees, length sqrt 2) on X = 1: the
//     first coordinate is u itself, so at t = 1/4 the radius is
//     1/2 + 0.140625 x 1 + 0.046875 x 1 = 0.6875, at t = 1/2 0.75.
// (c) @Gr(0) on a stretch of length 2 with tangents (2, 2) and (2, -2): the
//     first coordinate is 2u, so at t = 1/4: 1/2 + 0.140625 x 2 + 0.046875 x 2
//     = 0.875, at t = 1/2: 1/2 + 0.125 x 2 + 0.125 x 2 = 1.
TEST(CpfgCylinder, RadiusTangentsShapeTheRadius) {
  Scene a = draw_cpfg_cylinder("gr-thirty", "@!(8)#(1)@Gs @Gr(30,1,-30,1) F(2) @Ge(2)");
  ASSERT_EQ(a.positions.size(), 8u * 3);
  EXPECT_NEAR(ring_radius(a, 0, 8), 0.5, 1e-5);
  EXPECT_NEAR(ring_radius(a, 1, 8), 0.625, 1e-5);
  EXPECT_NEAR(ring_radius(a, 2, 8), 0.5, 1e-5);

  Scene b = draw_cpfg_cylinder("gr-unit", "@!(8)#(1)@Gs @Gr(45,1.41421356,-45,1.41421356) F(2) @Ge(4)");
  ASSERT_EQ(b.positions.size(), 8u * 5);
  const float expected_b[] = {0.5f, 0.6875f, 0.75f, 0.6875f, 0.5f};
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(ring_radius(b, k, 8), expected_b[k], 1e-5) << k;

  Scene c = draw_cpfg_cylinder("gr-real", "@!(8)#(1)@Gr(0)@Gs @Gr(45,2.82842712,-45,2.82842712) F(2) @Ge(4)");
  ASSERT_EQ(c.positions.size(), 8u * 5);
  const float expected_c[] = {0.5f, 0.875f, 1, 0.875f, 0.5f};
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(ring_radius(c, k, 8), expected_c[k], 1e-5) << k;
}

// A roll of 90 degrees about the straight axis between the control points:
// the inner rings turn by a quarter, half and three quarters of it, so the
// middle ring's first point is 45 degrees from both end rings' first points.
TEST(CpfgCylinder, RingFramesRollSmoothly) {
  Scene s = draw_cpfg_cylinder("roll", "@!(4)#(2)@Gs F(2) /(90) @Ge(4)");
  ASSERT_EQ(s.positions.size(), 20u);
  auto spoke = [&](int ring) {
    return normalized(s.positions[static_cast<std::size_t>(4 * ring)] - ring_center(s, ring, 4));
  };
  const float cos45 = std::sqrt(0.5f);
  EXPECT_NEAR(std::fabs(dot(spoke(0), spoke(4))), 0, 1e-5);  // the ends: a quarter turn apart
  EXPECT_NEAR(dot(spoke(2), spoke(0)), cos45, 1e-5);
  EXPECT_NEAR(dot(spoke(2), spoke(4)), cos45, 1e-5);
  EXPECT_NEAR(dot(spoke(1), spoke(0)), std::cos(3.14159265f / 8), 1e-5);
  // The inner rings stay across the axis (y constant on each).
  for (int k = 1; k < 4; ++k)
    for (int i = 1; i < 4; ++i)
      EXPECT_NEAR(s.positions[static_cast<std::size_t>(4 * k + i)].y, s.positions[static_cast<std::size_t>(4 * k)].y,
                  1e-5);
}

// {(type) (CPFG manual 6.7.3) defines no point at the start; each F makes
// one with 4 strips. {(1) F F F }(1): points at y = 1, 2, 3 (the start, y = 0,
// is none; } adds none, the turtle has not moved since the last F); two
// stretches of 4 strips: 1 + 4 + 4 = 9 rings of 4 sides, 2 groups of
// 4 strips x 4 sides x 2 triangles.
TEST(CpfgCylinder, BraceCylinderPointsAfterEachStep) {
  Scene s = draw_cpfg_cylinder("brace-steps", "@!(4){(1) F F F }(1)");
  ASSERT_EQ(s.positions.size(), 4u * 9);
  ASSERT_EQ(s.groups.size(), 2u);
  for (const auto& g : s.groups) EXPECT_EQ(g.index_count, 4u * 4 * 2 * 3);
  expect_near(ring_center(s, 0, 4), {0, 1, 0});
  expect_near(ring_center(s, 4, 4), {0, 2, 0});
  expect_near(ring_center(s, 8, 4), {0, 3, 0});
  // f makes points too; a G does not, so } adds the last: 1 + 4 rings.
  Scene moves = draw_cpfg_cylinder("brace-moves", "@!(4){(1) f G }(1)");
  EXPECT_EQ(moves.positions.size(), 4u * 5);
  // .(2) after a move adds a point with 2 strips: F (y=1), G (y=2), .(2):
  // 1 + 2 rings; } adds none.
  Scene dot = draw_cpfg_cylinder("brace-dot", "@!(4){(1) F G .(2) }(2)");
  EXPECT_EQ(dot.positions.size(), 4u * 3);
}

// {(2) F + F + F + F }(2) with 90 degrees: points (0,1,0), (-1,1,0),
// (-1,0,0), (0,0,0); the closed axis adds a fourth stretch back to the
// first: 4 stretches x 4 strips = 16 rings (the last stretch ends at the
// first ring, no ring of its own), 4 groups; the last band's second ring is
// ring 0's vertices.
TEST(CpfgCylinder, ClosedHermiteSquare) {
  Scene s = draw_cpfg_cylinder("closed-square", "@!(4){(2) F + F + F + F }(2)");
  ASSERT_EQ(s.positions.size(), 4u * 16);
  ASSERT_EQ(s.groups.size(), 4u);
  for (const auto& g : s.groups) EXPECT_EQ(g.index_count, 4u * 4 * 2 * 3);
  expect_near(ring_center(s, 0, 4), {0, 1, 0});
  expect_near(ring_center(s, 12, 4), {0, 0, 0});
  const auto& last = s.groups.back();
  std::uint32_t lowest = ~0u, highest = 0;
  for (std::uint32_t i = last.first_index; i < last.first_index + last.index_count; ++i) {
    lowest = std::min(lowest, s.indices[i]);
    highest = std::max(highest, s.indices[i]);
  }
  EXPECT_EQ(lowest, 0u);               // joins ring 0
  EXPECT_EQ(highest, 4u * 16 - 1);     // and the last ring
  // The open type 1 has no stretch back: 1 + 3 x 4 rings.
  Scene open = draw_cpfg_cylinder("open-square", "@!(4){(1) F + F + F + F }(1)");
  EXPECT_EQ(open.positions.size(), 4u * 13);
}

// {(3) F - F + F }(3): control points p0 = (0,1,0), p1 = (1,1,0),
// p2 = (1,2,0); the open B-spline gets phantom points 2 p0 - p1 = (-1,1,0)
// and 2 p2 - p1 = (1,3,0). Ring 0 is at p0: (-1 + 4 x 0 + 1, 1 + 4 + 1)/6.
// The middle ring (ring 4, the knot between the segments) is at
// (p0 + 4 p1 + p2) / 6 = (5/6, 7/6, 0), not at p1. Ring 2 (t = 1/2 of the
// first segment, weights 1/48, 23/48, 23/48, 1/48 of (-1,1), (0,1), (1,1),
// (1,2)) is at (23/48, 49/48, 0). Ring 8 is at p2.
TEST(CpfgCylinder, BSplineAxis) {
  Scene s = draw_cpfg_cylinder("bspline", "@!(4){(3) F - F + F }(3)");
  ASSERT_EQ(s.positions.size(), 4u * 9);
  ASSERT_EQ(s.groups.size(), 2u);
  expect_near(ring_center(s, 0, 4), {0, 1, 0});
  expect_near(ring_center(s, 2, 4), {23.0f / 48, 49.0f / 48, 0});
  expect_near(ring_center(s, 4, 4), {5.0f / 6, 7.0f / 6, 0});
  expect_near(ring_center(s, 8, 4), {1, 2, 0});
}

}  // namespace
}  // namespace sylva::test::turtle_tests
