// The geometric examples (snowflake, ternary-tree, query-height, leaf, stem)
// checked by the numbers in the Scene the turtle makes of them, through the
// public API. Every expected value is worked out by hand from the model and
// its input files, or computed here a second way (string rewriting and a
// walk in the plane for the snowflake, Bernstein polynomials for the leaf's
// surface and the stem's width function); none is copied from the program.
// Outputs of the command line (images, meshes, drawings, frames, the turtle's
// trace) are in geometry_examples_outputs_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "examples/example_strings.h"
#include "examples/geometry_examples.h"
#include "io/string_text.h"

namespace sylva::test::geometry_examples {
namespace {

using geometry::Scene;
using geometry::TriangleGroup;

int power(int base, int exponent) {
  int n = 1;
  while (exponent-- > 0) n *= base;
  return n;
}

// ---------------------------------------------------------------------------
// Snowflake: F -> F Left(60) F Right(120) F Left(60) F on a triangle of unit
// sides. After n steps, 3 * 4^n segments of length 3^-n, 3 * (4/3)^n long in all.

TEST(GeometryExampleSnowflake, SegmentCountsAndLengthsAfterEachStep) {
  for (int n = 0; n <= 4; ++n) {
    SCOPED_TRACE("after " + std::to_string(n) + " steps");
    auto sim = load("snowflake", inputs_of("snowflake"), n);
    const Scene scene = sim->scene();
    ASSERT_EQ(scene.segments.size(), static_cast<std::size_t>(3 * power(4, n)));
    const double side = std::pow(3.0, -n);
    double total = 0;
    for (const auto& s : scene.segments) {
      const double l = geometry::length(s.end - s.start);
      EXPECT_NEAR(l, side, 1e-5);
      EXPECT_EQ(s.start.z, 0.0f);  // a drawing in the plane
      EXPECT_EQ(s.end.z, 0.0f);
      total += l;
    }
    EXPECT_NEAR(total, 3 * std::pow(4.0 / 3.0, n), 1e-4);
    EXPECT_TRUE(scene.spheres.empty() && scene.groups.empty() && scene.circles.empty());
  }
}

TEST(GeometryExampleSnowflake, ClosedCurveWhoseVerticesMatchAWalkInThePlane) {
  for (int n = 0; n <= 3; ++n) {
    SCOPED_TRACE("after " + std::to_string(n) + " steps");
    auto sim = load("snowflake", inputs_of("snowflake"), n);
    const Scene scene = sim->scene();
    const std::vector<Segment2> walk = koch_snowflake(n);
    ASSERT_EQ(scene.segments.size(), walk.size());
    for (std::size_t k = 0; k < walk.size(); ++k) {
      const auto& s = scene.segments[k];
      EXPECT_TRUE(Near(s.start, Vec3(float(walk[k].x0), float(walk[k].y0), 0), 2e-5f)) << "segment " << k;
      EXPECT_TRUE(Near(s.end, Vec3(float(walk[k].x1), float(walk[k].y1), 0), 2e-5f)) << "segment " << k;
      // Each segment starts where the previous one ended; the last ends at the start.
      const auto& next = scene.segments[(k + 1) % walk.size()];
      EXPECT_TRUE(Near(next.start, s.end, 1e-5f)) << "after segment " << k;
    }
  }
}

// Step 0 is the triangle (0,0), (0,1), (sqrt3/2, 1/2). Step 1 puts a bump of
// height sqrt3/6 outward on each side: the left side's bump reaches x =
// -sqrt3/6; the two right sides' bumps peak at (sqrt3/3, 1) and (sqrt3/3, 0),
// not past the triangle's own extremes. So x in [-sqrt3/6, sqrt3/2], y in [0, 1].
TEST(GeometryExampleSnowflake, BoundingBoxAfterOneStepComputedByHand) {
  const double r3 = std::sqrt(3.0);
  auto sim = load("snowflake", inputs_of("snowflake"), 0);
  Scene scene = sim->scene();
  ASSERT_EQ(scene.segments.size(), 3u);
  EXPECT_TRUE(Near(scene.segments[0].end, Vec3(0, 1, 0), 1e-6f));
  EXPECT_TRUE(Near(scene.segments[1].end, Vec3(float(r3 / 2), 0.5f, 0), 1e-6f));
  EXPECT_TRUE(Near(scene.segments[2].end, Vec3(0, 0, 0), 1e-6f));

  sim = load("snowflake", inputs_of("snowflake"), 1);
  scene = sim->scene();
  geometry::Box box;
  for (const auto& s : scene.segments) box.add(s.start), box.add(s.end);
  EXPECT_NEAR(box.min.x, -r3 / 6, 1e-6);
  EXPECT_NEAR(box.max.x, r3 / 2, 1e-6);
  EXPECT_NEAR(box.min.y, 0, 1e-6);
  EXPECT_NEAR(box.max.y, 1, 1e-6);
  // The three bump peaks are vertices of the curve.
  std::vector<Vec3> peaks = {{float(-r3 / 6), 0.5f, 0}, {float(r3 / 3), 1, 0}, {float(r3 / 3), 0, 0}};
  for (Vec3 peak : peaks) {
    bool found = false;
    for (const auto& s : scene.segments) found = found || Near(s.end, peak, 1e-6f);
    EXPECT_TRUE(found) << "no vertex at (" << peak.x << ", " << peak.y << ")";
  }
}

// ---------------------------------------------------------------------------
// Ternary tree: A -> !(vr) F(50) [&F(50)A] /(d1) [&F(50)A] /(d2) [&F(50)A].
// Apices triple each step: 3^n after n steps, each drawn as a Sphere(4) in
// colour 3. Each A makes 4 F's: 1 + 4 (1 + 3 + ... + 3^(n-1)) = 2 * 3^n - 1.

TEST(GeometryExampleTernaryTree, SegmentsAndSpheresFollowTheRecurrence) {
  for (int n = 0; n <= 6; ++n) {
    SCOPED_TRACE("after " + std::to_string(n) + " steps");
    auto sim = load("ternary-tree", inputs_of("ternary-tree"), n);
    const Scene scene = sim->scene();
    EXPECT_EQ(scene.segments.size(), static_cast<std::size_t>(2 * power(3, n) - 1));
    ASSERT_EQ(scene.spheres.size(), static_cast<std::size_t>(power(3, n)));
    for (const auto& s : scene.spheres) {
      EXPECT_EQ(s.radius, 4.0f);
      EXPECT_EQ(s.color, 3);
    }
    EXPECT_TRUE(scene.groups.empty());
  }
}

// The trunk F(200) grows by lr = 1.109 per step and its width by vr = 1.732;
// it points straight up (along the tropism, which cannot bend it). At step 0
// it is 200 long, width 1, with the only apex on top.
TEST(GeometryExampleTernaryTree, TrunkIsVerticalAndGrowsByTheElongationRate) {
  for (int n = 0; n <= 6; ++n) {
    SCOPED_TRACE("after " + std::to_string(n) + " steps");
    auto sim = load("ternary-tree", inputs_of("ternary-tree"), n);
    const Scene scene = sim->scene();
    std::vector<const geometry::Segment*> from_ground;
    for (const auto& s : scene.segments)
      if (geometry::length(s.start) < 1e-6f) from_ground.push_back(&s);
    ASSERT_EQ(from_ground.size(), 1u);
    const double length = 200 * std::pow(1.109, n);
    EXPECT_TRUE(Near(from_ground[0]->end, Vec3(0, float(length), 0), float(length * 1e-6)));
    EXPECT_NEAR(from_ground[0]->start_width, std::pow(1.732, n), std::pow(1.732, n) * 1e-6);
    if (n == 0) {
      EXPECT_EQ(from_ground[0]->end, Vec3(0, 200, 0));
      EXPECT_EQ(from_ground[0]->start_width, 1.0f);
      EXPECT_TRUE(Near(scene.spheres[0].center, Vec3(0, 200, 0), 1e-6f));
    }
  }
}

// After one step: the trunk is 200 * 1.109 = 221.8, then F(50) straight up to
// y = 271.8, then three branches of 50 pitched down a = 18.95 degrees from
// the vertical, rolled d1 = 94.74 and then d2 = 132.63 degrees about it, so
// their directions seen from above are 94.74, 132.63 and 360 - 94.74 -
// 132.63 = 132.63 degrees apart. (The tropism only bends what comes after.)
TEST(GeometryExampleTernaryTree, FirstBranchesAfterOneStep) {
  auto sim = load("ternary-tree", inputs_of("ternary-tree"), 1);
  const Scene scene = sim->scene();
  ASSERT_EQ(scene.segments.size(), 5u);
  const Vec3 fork(0, 271.8f, 0);
  std::vector<const geometry::Segment*> branches;
  int internodes = 0;
  for (const auto& s : scene.segments) {
    if (Near(s.start, Vec3(0, 221.8f, 0), 1e-3f)) {
      EXPECT_TRUE(Near(s.end, fork, 1e-3f));  // the internode F(50) on top of the trunk
      ++internodes;
    }
    if (Near(s.start, fork, 1e-3f)) branches.push_back(&s);
  }
  EXPECT_EQ(internodes, 1);
  ASSERT_EQ(branches.size(), 3u);
  const double a = radians(18.95);
  std::vector<Vec3> across;  // horizontal direction of each branch
  for (const auto* b : branches) {
    const Vec3 d = b->end - b->start;
    EXPECT_NEAR(geometry::length(d), 50, 1e-3);
    EXPECT_NEAR(d.y, 50 * std::cos(a), 1e-3);
    EXPECT_NEAR(std::hypot(d.x, d.z), 50 * std::sin(a), 1e-3);
    EXPECT_NEAR(b->start_width, 1.732, 1e-5);
    across.push_back(geometry::normalized(Vec3(d.x, 0, d.z)));
  }
  auto degrees_between = [](Vec3 p, Vec3 q) {
    return std::acos(std::clamp(double(geometry::dot(p, q)), -1.0, 1.0)) * 180 / kPi;
  };
  EXPECT_NEAR(degrees_between(across[0], across[1]), 94.74, 1e-2);
  EXPECT_NEAR(degrees_between(across[1], across[2]), 132.63, 1e-2);
  EXPECT_NEAR(degrees_between(across[2], across[0]), 360 - 94.74 - 132.63, 1e-2);
  // Apices sit at the branch ends.
  ASSERT_EQ(scene.spheres.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_TRUE(Near(scene.spheres[k].center, branches[k]->end, 1e-4f));
}

// ---------------------------------------------------------------------------
// Query height (see geometry_examples.h for the hand count).

TEST(GeometryExampleQueryHeight, InternodesAndTipHeightsFromTheString) {
  auto sim = load("query-height", {});
  using namespace test::examples;
  const std::vector<Module> s = parse_modules(io::format_string(sim->string(), sim->types()));
  EXPECT_EQ(count_named(s, "F"), kQueryInternodes);
  EXPECT_EQ(count_named(s, "A"), 1);
  EXPECT_EQ(count_named(s, "B"), 5);
  // The GetPos just before each apex holds its tip's position.
  std::multiset<double> tips;
  for (std::size_t k = 1; k < s.size(); ++k)
    if ((s[k].name == "A" || s[k].name == "B") && s[k - 1].name == "GetPos") tips.insert(number(s[k - 1].params[1]));
  ASSERT_EQ(tips.size(), 6u);
  const double r = std::sqrt(0.5);
  std::multiset<double> expected = {5, 1 + 5 * r, 2 + 4 * r, 3 + 3 * r, 4 + r, 5};
  auto e = expected.begin();
  for (double tip : tips) {
    EXPECT_GE(tip, 4.5);
    EXPECT_LE(tip, 5.5);
    EXPECT_NEAR(tip, *e++, 1e-5);
  }
}

TEST(GeometryExampleQueryHeight, EveryTipEndsBetweenTheLimitAndOneMore) {
  auto sim = load("query-height", {});
  const Scene scene = sim->scene();
  ASSERT_EQ(scene.segments.size(), static_cast<std::size_t>(kQueryInternodes));
  const float r = std::sqrt(0.5f);
  int main_axis = 0;
  for (const auto& s : scene.segments) {
    EXPECT_NEAR(geometry::length(s.end - s.start), 1, 1e-5);
    if (std::fabs(s.start.x) < 1e-6f && std::fabs(s.end.x) < 1e-6f) {
      ++main_axis;  // straight up
      EXPECT_NEAR(s.end.y - s.start.y, 1, 1e-5);
    } else {
      EXPECT_TRUE(Near(s.end - s.start, Vec3(-r, r, 0), 1e-5f));  // Left(45): up and to the left
    }
  }
  EXPECT_EQ(main_axis, kQueryMainInternodes);
  // Tips: segment ends where no segment starts.
  std::vector<double> tips;
  for (const auto& s : scene.segments) {
    bool continued = false;
    for (const auto& t : scene.segments) continued = continued || Near(t.start, s.end, 1e-5f);
    if (!continued) tips.push_back(s.end.y);
  }
  std::sort(tips.begin(), tips.end());
  // The b = 5 branch has no internode: its tip is the main tip at 5.
  const double rr = std::sqrt(0.5);
  const std::vector<double> expected = {1 + 5 * rr, 4 + rr, 2 + 4 * rr, 5, 3 + 3 * rr};
  ASSERT_EQ(tips.size(), expected.size());
  for (std::size_t k = 0; k < tips.size(); ++k) {
    EXPECT_GE(tips[k], 4.5);
    EXPECT_LE(tips[k], 5.5);
    EXPECT_NEAR(tips[k], expected[k], 1e-5);
  }
}

// ---------------------------------------------------------------------------
// Leaf: 3 pairs of leaflets and a terminal one, each the surface of leaf.s.

struct Leaflet {
  Vec3 base, heading;
  double length;
};

// Where the turtle draws each leaflet: the petiole ends at y = 1.2, each
// internode adds 1.1; Left(60) turns the heading from (0,1,0) toward -x.
std::vector<Leaflet> expected_leaflets() {
  std::vector<Leaflet> out;
  const double s = std::sin(radians(kLeafletAngle)), c = std::cos(radians(kLeafletAngle));
  for (int k = 0; k < kPairs; ++k) {
    const Vec3 node(0, float(kPetiole + k * kInternode), 0);
    out.push_back({node, Vec3(float(-s), float(c), 0), kLeaflet});
    out.push_back({node, Vec3(float(s), float(c), 0), kLeaflet});
  }
  out.push_back({Vec3(0, float(kPetiole + kPairs * kInternode), 0), Vec3(0, 1, 0), kTerminal});
  return out;
}

// A point of leaf.s (local x across, y along, z up) as placed on a leaflet:
// y along the heading, x to the turtle's right (-L; here H turned a quarter
// clockwise about U = +z), z along U, all scaled by the leaflet's length.
Vec3 on_leaflet(const Leaflet& l, double x, double y, double z) {
  const Vec3 right(l.heading.y, -l.heading.x, 0);
  return l.base + (right * float(x) + l.heading * float(y) + Vec3(0, 0, 1) * float(z)) * float(l.length);
}

// The margin column of leaf.s's right patch (u = 1): control points (0,0,0),
// (0.42,0.15,0.05), (0.36,0.75,0.05), (0,1,0). At v = 1/2 the Bernstein
// weights are 1/8, 3/8, 3/8, 1/8: (0.2925, 0.4625, 0.0375). The midrib
// column (u = 0) is (0, 0|0.33|0.67|1, 0): (0, 0.5, 0). The left patch mirrors x.
double bezier_half(double p0, double p1, double p2, double p3) { return (p0 + 3 * p1 + 3 * p2 + p3) / 8; }

TEST(GeometryExampleLeaf, SevenSurfacesAndTheRachis) {
  auto sim = load("leaf", inputs_of("leaf"));
  const Scene scene = sim->scene();
  int surfaces = 0;
  for (const auto& g : scene.groups) {
    EXPECT_EQ(g.kind, TriangleGroup::Kind::Surface);
    EXPECT_EQ(g.index_count, static_cast<std::uint32_t>(3 * kSurfaceTriangles));
    EXPECT_EQ(g.color, 3);
    ++surfaces;
  }
  EXPECT_EQ(surfaces, 2 * kPairs + 1);
  // 2 patches of (8 + 1) x (8 + 1) vertices per surface.
  EXPECT_EQ(scene.positions.size(), static_cast<std::size_t>((2 * kPairs + 1) * 2 * 81));
  // Petiole and internodes, straight up, width 0.06.
  ASSERT_EQ(scene.segments.size(), static_cast<std::size_t>(1 + kPairs));
  for (int k = 0; k <= kPairs; ++k) {
    const auto& s = scene.segments[static_cast<std::size_t>(k)];
    const float y0 = k == 0 ? 0.0f : float(kPetiole + (k - 1) * kInternode);
    EXPECT_TRUE(Near(s.start, Vec3(0, y0, 0), 1e-5f));
    EXPECT_TRUE(Near(s.end, Vec3(0, float(kPetiole + k * kInternode), 0), 1e-5f));
    EXPECT_NEAR(s.start_width, 0.06, 1e-7);
  }
}

TEST(GeometryExampleLeaf, SurfaceCornersAndMarginsLandWhereTheTurtlePlacesThem) {
  auto sim = load("leaf", inputs_of("leaf"));
  const Scene scene = sim->scene();
  const std::vector<Leaflet> leaflets = expected_leaflets();
  std::vector<int> matched(leaflets.size(), 0);
  for (const auto& g : scene.groups) {
    std::vector<Vec3> points;
    float lowest_normal_z = 1;
    for (std::uint32_t k = 0; k < g.index_count; ++k) {
      const std::uint32_t i = scene.indices[g.first_index + k];
      points.push_back(scene.positions[i]);
      lowest_normal_z = std::min(lowest_normal_z, scene.normals[i].z);
    }
    auto has = [&](Vec3 p) {
      return std::any_of(points.begin(), points.end(), [&](Vec3 q) { return Near(q, p, 1e-4f); });
    };
    // Corners: the rows v = 0 and v = 1 of both patches collapse to the
    // base (the contact point, at the turtle) and the tip (local (0,1,0)).
    int which = -1;
    for (std::size_t k = 0; k < leaflets.size(); ++k)
      if (has(leaflets[k].base) && has(on_leaflet(leaflets[k], 0, 1, 0))) which = static_cast<int>(k);
    ASSERT_GE(which, 0) << "a surface that is no expected leaflet, from module " << g.from.module_index;
    const Leaflet& l = leaflets[static_cast<std::size_t>(which)];
    ++matched[static_cast<std::size_t>(which)];
    const double mx = bezier_half(0, 0.42, 0.36, 0), my = bezier_half(0, 0.15, 0.75, 1), mz = bezier_half(0, 0.05, 0.05, 0);
    EXPECT_TRUE(has(on_leaflet(l, mx, my, mz))) << "right margin of leaflet " << which;
    EXPECT_TRUE(has(on_leaflet(l, -mx, my, mz))) << "left margin of leaflet " << which;
    EXPECT_TRUE(has(on_leaflet(l, 0, bezier_half(0, 0.33, 0.67, 1), 0))) << "midrib of leaflet " << which;
    // The blade is no wider than its margin's control points allow.
    for (Vec3 p : points) {
      const Vec3 d = p - l.base;
      const Vec3 right(l.heading.y, -l.heading.x, 0);
      EXPECT_LE(std::fabs(geometry::dot(d, right)), 0.42 * l.length + 1e-4);
      EXPECT_GE(geometry::dot(d, l.heading), -1e-4);
      EXPECT_LE(geometry::dot(d, l.heading), l.length + 1e-4);
    }
    // The blade faces U = +z, toward the viewer.
    EXPECT_GT(lowest_normal_z, 0.5f);
  }
  for (std::size_t k = 0; k < leaflets.size(); ++k) EXPECT_EQ(matched[k], 1) << "leaflet " << k;
}

// ---------------------------------------------------------------------------
// Stem: one generalized cylinder of 13 rings of 32 points.

// taper.func is a clamped cubic B-spline of 4 control points: one Bezier
// segment. y at x by bisection on the Bernstein form of x(t). (lpfg finds x
// to within 0.01 / samples; the file's 1000 samples keep that within the
// tolerances below.)
double taper(double x) {
  const double px[4] = {0, 0.15, 0.6, 1}, py[4] = {1, 0.7, 0.55, 0.35};
  auto bezier = [](const double* p, double t) {
    const double s = 1 - t;
    return s * s * s * p[0] + 3 * t * s * s * p[1] + 3 * t * t * s * p[2] + t * t * t * p[3];
  };
  double lo = 0, hi = 1;
  for (int k = 0; k < 100; ++k) (bezier(px, (lo + hi) / 2) < x ? lo : hi) = (lo + hi) / 2;
  return bezier(py, (lo + hi) / 2);
}

TEST(GeometryExampleStem, VertexCountIsContourSidesTimesRings) {
  auto sim = load("stem", inputs_of("stem"));
  const Scene scene = sim->scene();
  EXPECT_TRUE(scene.segments.empty());  // F inside a cylinder draws nothing else
  EXPECT_EQ(scene.positions.size(), static_cast<std::size_t>(kStemSides * kStemRings));
  ASSERT_EQ(scene.groups.size(), static_cast<std::size_t>(kStemSegments));
  for (const auto& g : scene.groups) {
    EXPECT_EQ(g.kind, TriangleGroup::Kind::GeneralizedCylinder);
    EXPECT_EQ(g.index_count, static_cast<std::uint32_t>(kStemSides * 2 * 3));  // a band of quads
  }
  EXPECT_EQ(scene.indices.size(), static_cast<std::size_t>(kStemSegments * kStemSides * 2 * 3));
}

// The turtle's frame: RollR(30) about the vertical heading, so L is
// (-cos 30, 0, +-sin 30) (the sign is the roll's sense, taken from the
// drawing). Ring 0 (StartGC) is at the origin, heading up; ring k >= 1 is
// one unit further along the heading turned (k-1) * 2.5 degrees toward L,
// since Left(2.5) comes after each PointGC. A ring's point 0 is the start of
// the closed B-spline, (P[n-1] + 4 P[0] + P[1]) / 6 = ((1 + 3.4 + 1)/6, 0) =
// (0.9, 0): 0.9 * width / 2 along L. The width is 1.5 * taper(k / 12).
TEST(GeometryExampleStem, RingsFollowTheBentAxisAndTheWidthFunction) {
  auto sim = load("stem", inputs_of("stem"));
  const Scene scene = sim->scene();
  ASSERT_EQ(scene.positions.size(), static_cast<std::size_t>(kStemSides * kStemRings));
  const double c30 = std::cos(radians(30)), s30 = std::sin(radians(30));
  const double top_z = scene.positions[static_cast<std::size_t>(kStemSides * kStemSegments)].z;
  const double sense = top_z >= 0 ? 1 : -1;
  const Vec3 h0(0, 1, 0), l0(float(-c30), 0, float(sense * s30));
  auto rotated = [&](double degrees, bool heading) {  // rotation about U = h0 x l0
    const double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    return heading ? h0 * float(c) + l0 * float(s) : l0 * float(c) - h0 * float(s);
  };
  Vec3 position(0, 0, 0);
  for (int k = 0; k < kStemRings; ++k) {
    SCOPED_TRACE("ring " + std::to_string(k));
    const double turned = k == 0 ? 0 : (k - 1) * kStemBend;
    if (k > 0) position = position + rotated(turned, true) * float(kStemSegmentLength);
    const Vec3 heading = rotated(turned, true), left = rotated(turned, false);
    const Vec3* ring = &scene.positions[static_cast<std::size_t>(kStemSides * k)];
    Vec3 centroid;
    for (int i = 0; i < kStemSides; ++i) centroid += ring[i] / float(kStemSides);
    EXPECT_TRUE(Near(centroid, position, 2e-4f));
    const double width = kStemWidth * taper(float(k) / float(kStemSegments));
    EXPECT_TRUE(Near(ring[0], position + left * float(0.9 * width / 2), 2e-4f));
    for (int i = 0; i < kStemSides; ++i) {
      EXPECT_NEAR(geometry::dot(ring[i] - position, heading), 0, 2e-4) << "point " << i << " off the ring's plane";
      // The contour lies within its control polygon: |x|, |y| <= 1.
      EXPECT_LE(geometry::length(ring[i] - position), std::sqrt(2.0) * width / 2 + 1e-4);
    }
  }
}

// The function file's end points, which a clamped spline passes through:
// the base ring is 1.5 wide, the top one 1.5 * 0.35; widths fall in between.
TEST(GeometryExampleStem, WidthFallsFromBaseToTopAsTheFunctionFile) {
  auto sim = load("stem", inputs_of("stem"));
  const Scene scene = sim->scene();
  ASSERT_EQ(scene.positions.size(), static_cast<std::size_t>(kStemSides * kStemRings));
  std::vector<double> extent;  // the largest distance of a ring point from the ring's centre
  for (int k = 0; k < kStemRings; ++k) {
    const Vec3* ring = &scene.positions[static_cast<std::size_t>(kStemSides * k)];
    Vec3 centroid;
    for (int i = 0; i < kStemSides; ++i) centroid += ring[i] / float(kStemSides);
    double far = 0;
    for (int i = 0; i < kStemSides; ++i) far = std::max(far, double(geometry::length(ring[i] - centroid)));
    extent.push_back(far);
  }
  for (std::size_t k = 1; k < extent.size(); ++k) EXPECT_LT(extent[k], extent[k - 1]) << "ring " << k;
  EXPECT_NEAR(extent.back() / extent.front(), 0.35, 1e-4);
  EXPECT_NEAR(taper(0), 1, 1e-12);
  EXPECT_NEAR(taper(1), 0.35, 1e-12);
}

}  // namespace
}  // namespace sylva::test::geometry_examples
