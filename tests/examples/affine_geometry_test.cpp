// Tests of the affine-geometry examples (Prusinkiewicz, Shirmohammadi and
// Samavati, "L-systems in Geometric Modeling"): chaikin, chaikin-edges,
// lane-riesenfeld, de-casteljau and rational-circle. Each model's points are
// compared, to 1e-12, with the same algorithm written here in plain C++
// with indices (Chaikin's corner cutting, Lane–Riesenfeld refinement and
// averaging, de Casteljau's triangle and Bernstein polynomials, homogeneous
// subdivision), started from the model's own initial polygon as its string
// shows it at step 0; the numbers of points and edges are compared with
// their closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

std::string model(const std::string& name) { return example_path(name + "/" + name + ".l"); }

constexpr double kTolerance = 1e-12;

// A point of the plane or of space (z = 0 in the plane), or a homogeneous
// point of the plane (z the weight).
struct Vec {
  double x = 0, y = 0, z = 0;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator*(double k, Vec a) { return {k * a.x, k * a.y, k * a.z}; }
double distance(Vec a, Vec b) {
  const Vec d = a - b;
  return std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
}
// (1 - t) a + t b.
Vec lerp(Vec a, Vec b, double t) { return (1 - t) * a + t * b; }

// "(x,y)" or "(x,y,z)" as a V2d or V3d parameter prints.
Vec read_vec(const std::string& text) {
  const std::vector<std::string> c = split_top_level(text.substr(1, text.size() - 2));
  Vec v{number(c.at(0)), number(c.at(1)), 0};
  if (c.size() == 3) v.z = number(c[2]);
  return v;
}

// The first parameter of every module named one of `names`, in string order.
std::vector<Vec> points(const std::vector<Module>& s, const std::vector<std::string>& names = {"P"}) {
  std::vector<Vec> out;
  for (const Module& m : s)
    if (std::find(names.begin(), names.end(), m.name) != names.end()) out.push_back(read_vec(m.params.at(0)));
  return out;
}

// The modules without Control (drawn, never rewritten) and their names.
std::vector<std::string> structure(const std::vector<Module>& s) {
  std::vector<std::string> out;
  for (const Module& m : s)
    if (m.name != "Control") out.push_back(m.name);
  return out;
}

void expect_same_points(const std::vector<Vec>& got, const std::vector<Vec>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_LE(distance(got[i], want[i]), kTolerance)
        << "point " << i << ": (" << got[i].x << "," << got[i].y << "," << got[i].z << "), expected (" << want[i].x
        << "," << want[i].y << "," << want[i].z << ")";
}

// The same closed polygon: the same points in the same cyclic order, from
// whichever point the ring's string happens to start at.
void expect_same_cycle(const std::vector<Vec>& got, const std::vector<Vec>& want) {
  ASSERT_EQ(got.size(), want.size());
  ASSERT_FALSE(got.empty());
  std::size_t shift = 0;
  for (std::size_t k = 1; k < want.size(); ++k)
    if (distance(got[0], want[k]) < distance(got[0], want[shift])) shift = k;
  std::vector<Vec> rotated;
  for (std::size_t i = 0; i < want.size(); ++i) rotated.push_back(want[(i + shift) % want.size()]);
  expect_same_points(got, rotated);
}

// ---------------------------------------------------------------------------
// Chaikin's corner cutting, by edges: each edge ab gives ¾a + ¼b and ¼a + ¾b.

std::vector<Vec> chaikin_closed(const std::vector<Vec>& p) {
  std::vector<Vec> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec a = p[i], b = p[(i + 1) % p.size()];
    out.push_back(0.75 * a + 0.25 * b);
    out.push_back(0.25 * a + 0.75 * b);
  }
  return out;
}

// Open: the end points stay.
std::vector<Vec> chaikin_open(const std::vector<Vec>& p) {
  std::vector<Vec> out{p.front()};
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    out.push_back(0.75 * p[i] + 0.25 * p[i + 1]);
    out.push_back(0.25 * p[i] + 0.75 * p[i + 1]);
  }
  out.push_back(p.back());
  return out;
}

TEST(AffineChaikin, ClosedPointsAreChaikinsCornersCut) {
  Stepper run(model("chaikin"));
  std::vector<Vec> want = points(run.modules());
  ASSERT_EQ(want.size(), 4u);
  for (int n = 1; n <= 5; ++n) {
    run.step();
    want = chaikin_closed(want);
    const std::vector<Module> s = run.modules();
    EXPECT_EQ(count_named(s, "P"), 4 << n) << "4·2^n points after n = " << n << " steps";
    expect_same_cycle(points(s), want);
  }
}

TEST(AffineChaikin, OpenKeepsTheEndPoints) {
  Stepper run(model("chaikin"), {"OPEN"});
  std::vector<Vec> want = points(run.modules());
  for (int n = 1; n <= 4; ++n) {
    run.step();
    want = chaikin_open(want);
    const std::vector<Vec> got = points(run.modules());
    EXPECT_EQ(got.size(), 4u << n);
    expect_same_points(got, want);
  }
}

// L-system 8: the same points, with an edge between every two of them.
TEST(AffineChaikinEdges, ClosedMatchesChaikinWithAnEdgeAfterEveryPoint) {
  Stepper run(model("chaikin-edges"));
  std::vector<Vec> want = points(run.modules());
  ASSERT_EQ(want.size(), 4u);
  for (int n = 1; n <= 5; ++n) {
    run.step();
    want = chaikin_closed(want);
    const std::vector<Module> s = run.modules();
    const std::vector<std::string> names = structure(s);
    ASSERT_EQ(names.size(), 8u << n) << "4·2^n points and 4·2^n edges";
    // E P E P ... after odd steps, P E P E ... after even ones.
    for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(names[i], (i + n) % 2 == 0 ? "P" : "E") << i;
    expect_same_cycle(points(s), want);
  }
}

TEST(AffineChaikinEdges, OpenMatchesChaikinOpen) {
  Stepper run(model("chaikin-edges"), {"OPEN"});
  std::vector<Vec> want = points(run.modules());
  for (int n = 1; n <= 4; ++n) {
    run.step();
    want = chaikin_open(want);
    const std::vector<Module> s = run.modules();
    const std::vector<std::string> names = structure(s);
    ASSERT_EQ(names.size(), (8u << n) - 1) << "4·2^n points, one edge fewer";
    for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(names[i], i % 2 == 0 ? "P" : "E") << i;
    expect_same_points(points(s), want);
  }
}

// Interpretation rule 9: each edge becomes Line2d(vl, vr) from its
// neighbours, across the ends of the ring too; Control draws the 4 sides of
// the control polygon first.
TEST(AffineChaikinEdges, EveryEdgeDrawnBetweenItsNeighbours) {
  Stepper run(model("chaikin-edges"));
  run.step(2);
  const std::vector<Vec> p = points(run.modules());
  std::vector<Vec> starts, ends;
  for (const Module& m : parse_modules(run.interpreted()))
    if (m.name == "Line2d") starts.push_back(read_vec(m.params.at(0))), ends.push_back(read_vec(m.params.at(1)));
  ASSERT_EQ(starts.size(), 4 + p.size());
  // The string after an even number of steps is P E P E ... P E: edge k
  // joins point k and point k + 1.
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_LE(distance(starts[4 + k], p[k]), 0.0) << k;
    EXPECT_LE(distance(ends[4 + k], p[(k + 1) % p.size()]), 0.0) << k;
  }
}

// L-system 10 with n = 1: two steps (p, then q) give one step of L-system 8.
TEST(AffineChaikinEdges, TablesTakeTwoStepsPerChaikinStep) {
  for (const std::vector<std::string>& open : {std::vector<std::string>{}, std::vector<std::string>{"OPEN"}}) {
    std::vector<std::string> tables = open;
    tables.push_back("TABLES");
    Stepper run(model("chaikin-edges"), tables), chaikin(model("chaikin-edges"), open);
    for (int n = 1; n <= 4; ++n) {
      run.step();  // p: every edge split at its midpoint
      EXPECT_EQ(count_named(run.modules(), "P"), (4 << (n - 1)) * 2 - (open.empty() ? 0 : 1));
      run.step();  // q: the midpoints of the edges
      chaikin.step();
      EXPECT_EQ(structure(run.modules()), structure(chaikin.modules())) << "after " << n << " cycles";
      expect_same_points(points(run.modules()), points(chaikin.modules()));
    }
  }
}

// ---------------------------------------------------------------------------
// Lane–Riesenfeld: refine (the points and the midpoints of the edges, in
// order), then degree - 1 rounds of averaging neighbours.

Vec mid(Vec a, Vec b) { return 0.5 * a + 0.5 * b; }

std::vector<Vec> refine(const std::vector<Vec>& p) {
  std::vector<Vec> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    out.push_back(p[i]);
    out.push_back(mid(p[i], p[(i + 1) % p.size()]));
  }
  return out;
}

std::vector<Vec> average(const std::vector<Vec>& p) {
  std::vector<Vec> out;
  for (std::size_t i = 0; i < p.size(); ++i) out.push_back(mid(p[i], p[(i + 1) % p.size()]));
  return out;
}

TEST(AffineLaneRiesenfeld, EveryDegreeMatchesRefineAndAverage) {
  for (int degree = 1; degree <= 5; ++degree) {
    SCOPED_TRACE("DEGREE=" + std::to_string(degree));
    Stepper run(model("lane-riesenfeld"), {"DEGREE=" + std::to_string(degree)});
    std::vector<Vec> want = points(run.modules());
    const std::size_t m = want.size();
    ASSERT_EQ(m, 6u);
    for (int cycle = 1; cycle <= 4; ++cycle) {
      run.step();
      want = refine(want);
      const std::vector<Module> after_p = run.modules();
      EXPECT_EQ(count_named(after_p, "P"), count_named(after_p, "E"));
      expect_same_cycle(points(after_p), want);
      for (int q = 1; q < degree; ++q) {
        run.step();
        want = average(want);
      }
      const std::vector<Module> s = run.modules();
      EXPECT_EQ(points(s).size(), m << cycle) << "m·2^c points after c cycles";
      EXPECT_EQ(count_named(s, "E"), static_cast<int>(m << cycle));
      expect_same_cycle(points(s), want);
    }
  }
}

// The cubic B-spline's limit points: after many cycles the polygon's points
// approach (a + 4b + c) / 6 of the control polygon at each control point b.
TEST(AffineLaneRiesenfeld, CubicConvergesToTheBSpline) {
  Stepper run(model("lane-riesenfeld"));  // DEGREE 3
  const std::vector<Vec> control = points(run.modules());
  run.step(3 * 10);
  const std::vector<Vec> p = points(run.modules());
  const std::size_t m = control.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec limit = (1.0 / 6) * (control[(i + m - 1) % m] + 4.0 * control[i] + control[(i + 1) % m]);
    double nearest = 1e9;
    for (const Vec& v : p) nearest = std::min(nearest, distance(v, limit));
    EXPECT_LT(nearest, 1e-5) << "control point " << i;
  }
}

// ---------------------------------------------------------------------------
// de Casteljau: the triangle of affine combinations, and the Bernstein form.

Vec de_casteljau(std::vector<Vec> b, double t) {
  for (std::size_t r = 1; r < b.size(); ++r)
    for (std::size_t i = 0; i + r < b.size(); ++i) b[i] = lerp(b[i], b[i + 1], t);
  return b.front();
}

Vec bernstein(const std::vector<Vec>& b, double t) {
  const int n = static_cast<int>(b.size()) - 1;
  Vec sum;
  double binomial = 1;  // C(n, i)
  for (int i = 0; i <= n; ++i) {
    sum = sum + (binomial * std::pow(t, i) * std::pow(1 - t, n - i)) * b[static_cast<std::size_t>(i)];
    binomial = binomial * (n - i) / (i + 1);
  }
  return sum;
}

// The two control polygons of the halves [0, t] and [t, 1]: the left and
// right sides of the triangle.
void split(const std::vector<Vec>& b, double t, std::vector<Vec>& left, std::vector<Vec>& right) {
  std::vector<Vec> row = b;
  left = {row.front()};
  right = {row.back()};
  while (row.size() > 1) {
    for (std::size_t i = 0; i + 1 < row.size(); ++i) row[i] = lerp(row[i], row[i + 1], t);
    row.pop_back();
    left.push_back(row.front());
    right.insert(right.begin(), row.back());
  }
}

// `levels` subdivisions of every segment at t; the segments' points in
// order, each shared end point once.
std::vector<Vec> subdivided(const std::vector<Vec>& control, double t, int levels) {
  std::vector<std::vector<Vec>> segments{control};
  for (int k = 0; k < levels; ++k) {
    std::vector<std::vector<Vec>> next;
    for (const std::vector<Vec>& s : segments) {
      std::vector<Vec> l, r;
      split(s, t, l, r);
      next.push_back(l);
      next.push_back(r);
    }
    segments = next;
  }
  std::vector<Vec> out{control.front()};
  for (const std::vector<Vec>& s : segments) out.insert(out.end(), s.begin() + 1, s.end());
  return out;
}

// The state parameter of every P.
std::vector<int> states(const std::vector<Module>& s) {
  std::vector<int> out;
  for (const Module& m : s)
    if (m.name == "P") out.push_back(static_cast<int>(number(m.params.at(1))));
  return out;
}

// L-systems 14 and 16: after c cycles of n + 1 steps, 2^c segments.
void check_subdivision(const std::vector<std::string>& defines, int degree, double t) {
  Stepper run(model("de-casteljau"), defines);
  const std::vector<Vec> control = points(run.modules());
  ASSERT_EQ(control.size(), static_cast<std::size_t>(degree + 1));
  for (int c = 1; c <= 3; ++c) {
    run.step(degree + 1);
    const std::vector<Module> s = run.modules();
    const int segments = 1 << c;
    EXPECT_EQ(count_named(s, "P"), degree * segments + 1) << "n·2^c + 1 points after c cycles";
    EXPECT_EQ(count_named(s, "E"), degree * segments);
    EXPECT_EQ(count_named(s, "I"), 0);
    const std::vector<int> state = states(s);
    for (std::size_t i = 0; i < state.size(); ++i)
      EXPECT_EQ(state[i], i % static_cast<std::size_t>(degree) == 0 ? 2 : 0) << "point " << i;
    expect_same_points(points(s), subdivided(control, t, c));
  }
}

TEST(AffineDeCasteljau, SubdivisionOfTheQuarticAtOneHalf) { check_subdivision({}, 4, 0.5); }

TEST(AffineDeCasteljau, SubdivisionOfOtherDegreesAndParameters) {
  for (int degree : {1, 2, 3, 6}) {
    SCOPED_TRACE("DEGREE=" + std::to_string(degree));
    check_subdivision({"DEGREE=" + std::to_string(degree)}, degree, 0.5);
  }
  SCOPED_TRACE("TPARAM=0.3");
  check_subdivision({"TPARAM=0.3"}, 4, 0.3);
}

// Within a cycle: the first step of a quartic (n = 4) gives the n points of
// the triangle's first row, states 1 0 0 1 between the ends (f of
// equation 15), the inner old points gone and the ends fenced off by I.
TEST(AffineDeCasteljau, FirstStepOfACycle) {
  Stepper run(model("de-casteljau"));
  const std::vector<Vec> b = points(run.modules());
  run.step();
  const std::vector<Module> s = run.modules();
  EXPECT_EQ(structure(s), (std::vector<std::string>{"P", "I", "P", "E", "P", "E", "P", "E", "P", "I", "P"}));
  EXPECT_EQ(states(s), (std::vector<int>{2, 1, 0, 0, 1, 2}));
  std::vector<Vec> want{b[0]};
  for (std::size_t i = 0; i + 1 < b.size(); ++i) want.push_back(lerp(b[i], b[i + 1], 0.5));
  want.push_back(b[4]);
  expect_same_points(points(s), want);
}

// L-system 13 on 101 control polygons at once, t = 0, 0.01, ... 1.
TEST(AffineDeCasteljau, EvaluationGivesTheCurvePoints) {
  Stepper run(model("de-casteljau"), {"EVALUATE"});
  std::vector<Module> s = run.modules();
  const std::vector<Vec> all = points(s);
  ASSERT_EQ(all.size(), 101u * 5);
  const std::vector<Vec> control(all.begin(), all.begin() + 5);
  for (int k = 1; k <= 4; ++k) {
    run.step();
    s = run.modules();
    EXPECT_EQ(count_named(s, "P"), 101 * (5 - k)) << "one point fewer per polygon per step";
    EXPECT_EQ(count_named(s, "E"), 101 * (4 - k));
  }
  const std::vector<Vec> curve = points(s);
  ASSERT_EQ(curve.size(), 101u);
  for (int k = 0; k <= 100; ++k) {
    const double t = k / 100.0;
    EXPECT_EQ(number(s[static_cast<std::size_t>(k) + 1].params.at(1)), t);
    EXPECT_LE(distance(curve[static_cast<std::size_t>(k)], de_casteljau(control, t)), kTolerance) << "t = " << t;
    EXPECT_LE(distance(curve[static_cast<std::size_t>(k)], bernstein(control, t)), kTolerance) << "t = " << t;
  }
  run.step();
  EXPECT_EQ(structure(run.modules()), std::vector<std::string>{}) << "p3 erases the last points";
}

TEST(AffineDeCasteljau, EvaluationAtOneParameter) {
  Stepper run(model("de-casteljau"), {"EVALUATE", "SAMPLES=1", "TPARAM=0.3", "DEGREE=3"});
  const std::vector<Vec> control = points(run.modules());
  ASSERT_EQ(control.size(), 4u);
  run.step(3);
  const std::vector<Vec> p = points(run.modules());
  ASSERT_EQ(p.size(), 1u);
  EXPECT_LE(distance(p[0], bernstein(control, 0.3)), kTolerance);
}

// L-systems 17, 18 and 19: one level of subdivision at ½ per step; P are
// the segments' end points, Q the inner control points.
void check_fixed_degree(const std::string& define, int degree) {
  SCOPED_TRACE(define);
  Stepper run(model("de-casteljau"), {define});
  const std::vector<Vec> control = points(run.modules(), {"P", "Q"});
  ASSERT_EQ(control.size(), static_cast<std::size_t>(degree + 1));
  for (int c = 1; c <= 4; ++c) {
    run.step();
    const std::vector<Module> s = run.modules();
    EXPECT_EQ(count_named(s, "P"), (1 << c) + 1);
    EXPECT_EQ(count_named(s, "Q"), (degree - 1) << c);
    EXPECT_EQ(count_named(s, "E"), degree << c);
    const std::vector<std::string> names = structure(s);
    for (std::size_t i = 0; i < names.size(); i += 2)
      EXPECT_EQ(names[i], i % static_cast<std::size_t>(2 * degree) == 0 ? "P" : "Q") << i;
    expect_same_points(points(s, {"P", "Q"}), subdivided(control, 0.5, c));
  }
}

TEST(AffineDeCasteljau, FixedDegreeQuadratic) { check_fixed_degree("QUADRATIC", 2); }
TEST(AffineDeCasteljau, FixedDegreeCubicPseudoLSystem) { check_fixed_degree("CUBIC", 3); }
TEST(AffineDeCasteljau, FixedDegreeCubicProper) { check_fixed_degree("CUBIC_PROPER", 3); }

// One level of L-system 17 is one cycle (3 steps) of L-systems 14 and 16.
TEST(AffineDeCasteljau, QuadraticIsOneCycleOfTheGeneralSubdivision) {
  Stepper fixed(model("de-casteljau"), {"QUADRATIC"}), general(model("de-casteljau"), {"DEGREE=2"});
  for (int c = 1; c <= 3; ++c) {
    fixed.step();
    general.step(3);
    expect_same_points(points(fixed.modules(), {"P", "Q"}), points(general.modules()));
  }
}

// In space: the helix's control polygon, subdivided and evaluated.
TEST(AffineDeCasteljau, ThreeDimensions) {
  check_subdivision({"THREE_D", "DEGREE=6"}, 6, 0.5);
  Stepper run(model("de-casteljau"), {"THREE_D", "EVALUATE", "SAMPLES=11", "DEGREE=6"});
  const std::vector<Vec> all = points(run.modules());
  const std::vector<Vec> control(all.begin(), all.begin() + 7);
  EXPECT_NE(control[1].z, 0.0);
  run.step(6);
  const std::vector<Vec> curve = points(run.modules());
  ASSERT_EQ(curve.size(), 11u);
  for (int k = 0; k <= 10; ++k)
    EXPECT_LE(distance(curve[static_cast<std::size_t>(k)], bernstein(control, k / 10.0)), kTolerance) << k;
}

// ---------------------------------------------------------------------------
// The rational circle: L-system 17 on homogeneous points in a ring.

Vec project(Vec h) { return {h.x / h.z, h.y / h.z, 0}; }
double norm(Vec v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// One level of subdivision of every arc P Q P at ½, in homogeneous
// coordinates, the string's order P Q P Q ... round the ring.
std::vector<Vec> subdivide_arcs(const std::vector<Vec>& pq) {
  std::vector<Vec> out;
  for (std::size_t i = 0; i < pq.size(); i += 2) {
    std::vector<Vec> l, r;
    split({pq[i], pq[i + 1], pq[(i + 2) % pq.size()]}, 0.5, l, r);
    out.insert(out.end(), {l[0], l[1], l[2], r[1]});
  }
  return out;
}

TEST(AffineRationalCircle, EveryPointOnTheUnitCircle) {
  Stepper run(model("rational-circle"));
  std::vector<Vec> want = points(run.modules(), {"P", "Q"});
  ASSERT_EQ(want.size(), 6u);
  for (int n = 0; n <= 6; ++n) {
    if (n > 0) {
      run.step();
      want = subdivide_arcs(want);
    }
    const std::vector<Module> s = run.modules();
    EXPECT_EQ(count_named(s, "P"), 3 << n);
    EXPECT_EQ(count_named(s, "Q"), 3 << n);
    EXPECT_EQ(count_named(s, "E"), 6 << n);
    const std::vector<Vec> pq = points(s, {"P", "Q"});
    expect_same_points(pq, want);
    // The string alternates P E Q E ...; every P projects onto the unit
    // circle, every Q onto the meeting point of the tangents at its
    // neighbours, (a + b) / (1 + a·b), with the weight of a circular arc.
    for (std::size_t i = 0; i < pq.size(); i += 2) {
      const Vec a = project(pq[i]), b = project(pq[(i + 2) % pq.size()]), q = project(pq[i + 1]);
      EXPECT_NEAR(norm(a), 1.0, kTolerance) << "step " << n << ", point " << i;
      const double c = dot(a, b);  // cos of the arc's angle
      EXPECT_LE(distance(q, (1 / (1 + c)) * (a + b)), kTolerance) << "step " << n << ", point " << i + 1;
      const double wq = pq[i + 1].z, wa = pq[i].z, wb = pq[(i + 2) % pq.size()].z;
      EXPECT_NEAR(wq * wq / (wa * wb), (1 + c) / 2, kTolerance) << "cos² of half the arc";
    }
  }
}

// Other weights give other conics: with weight 1 (parabolas) the arcs'
// midpoints lie off the circle.
TEST(AffineRationalCircle, WeightOneIsNotACircle) {
  Stepper run(model("rational-circle"), {"WEIGHT=1"});
  run.step();
  const std::vector<Vec> p = points(run.modules());
  ASSERT_EQ(p.size(), 6u);
  EXPECT_NEAR(norm(project(p[0])), 1.0, kTolerance);
  EXPECT_NEAR(norm(project(p[1])), 1.25, kTolerance) << "half way between the end points and the corner at 2";
}

}  // namespace
}  // namespace sylva::test::examples
