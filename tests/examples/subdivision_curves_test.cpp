// Tests of the subdivision-curve examples after "L-system description of
// subdivision curves" (Prusinkiewicz, Samavati, Smith, Karwowski; SIGGRAPH 2003
// course notes "L-systems and Beyond"): cubic-bspline-subdivision, four-point,
// stencil-subdivision (stencil-subdivision.l, matrix-inference.l) and
// reverse-subdivision.
//
// The expectations are computed here a second way: the subdivision matrices of
// the notes' sections 5 and 6 are built for any number of points and
// multiplied with the same initial polygon (read from the model's string at
// step 0), the quartic scheme by Lane-Riesenfeld averaging, the reverse mask by
// solving the local least-squares problem; and properties in closed form: point
// counts, interpolation, cubic precision, limit positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "examples/plane_points.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

std::string model(const std::string& folder, const std::string& name) {
  return example_path(folder + "/" + name + ".l");
}
const std::string kBspline = "cubic-bspline-subdivision", kFourPoint = "four-point";

std::vector<Pt> points_after(const std::string& m, int steps, std::vector<std::string> defines = {}) {
  return points(parse_modules(derive_with(m, steps, std::move(defines))));
}

// x[(s + r) mod size]: the string of a mapping that starts r rows down.
std::vector<Pt> rotate(const std::vector<Pt>& x, long r) {
  const long n = static_cast<long>(x.size());
  std::vector<Pt> out;
  for (long s = 0; s < n; ++s) out.push_back(x[static_cast<std::size_t>(((s + r) % n + n) % n)]);
  return out;
}

void expect_points_near(const std::vector<Pt>& got, const std::vector<Pt>& want, double tolerance,
                        const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i].x, want[i].x, tolerance) << what << ", point " << i;
    EXPECT_NEAR(got[i].y, want[i].y, tolerance) << what << ", point " << i;
  }
}

// The closed-curve subdivision matrices of section 5 for n old points, in the
// notes' numbering: column i (old point P_i, 1-based) and rows 2i-1, 2i.
//   Chaikin (8):        row 2i-1 = 3/4 P_i + 1/4 P_{i-1},  row 2i = 3/4 P_i + 1/4 P_{i+1}
//   cubic B-spline (21): row 2i-1 = 1/2 (P_{i-1} + P_i),   row 2i = 1/8 (P_{i-1} + 6 P_i + P_{i+1})
//   four-point (24):    row 2i-1 = 1/16 (-P_{i-2} + 9 P_{i-1} + 9 P_i - P_{i+1}),  row 2i = P_i
enum Scheme { kChaikin, kCubicBspline, kFourPointScheme };

Matrix closed_matrix(Scheme scheme, int n) {
  Matrix m(2 * static_cast<std::size_t>(n), std::vector<double>(static_cast<std::size_t>(n), 0.0));
  auto at = [&](int row, int column) -> double& {  // 1-based, columns around the circle
    return m[static_cast<std::size_t>(row - 1)][static_cast<std::size_t>(((column - 1) % n + n) % n)];
  };
  for (int i = 1; i <= n; ++i) {
    switch (scheme) {
      case kChaikin:
        at(2 * i - 1, i) += 0.75, at(2 * i - 1, i - 1) += 0.25;
        at(2 * i, i) += 0.75, at(2 * i, i + 1) += 0.25;
        break;
      case kCubicBspline:
        at(2 * i - 1, i - 1) += 0.5, at(2 * i - 1, i) += 0.5;
        at(2 * i, i - 1) += 0.125, at(2 * i, i) += 0.75, at(2 * i, i + 1) += 0.125;
        break;
      case kFourPointScheme:
        at(2 * i - 1, i - 2) -= 1.0 / 16, at(2 * i - 1, i - 1) += 9.0 / 16;
        at(2 * i - 1, i) += 9.0 / 16, at(2 * i - 1, i + 1) -= 1.0 / 16;
        at(2 * i, i) += 1;
        break;
    }
  }
  return m;
}

// The string after `steps` steps of a closed-curve L-system whose production
// maps old point i to rows 2i + d - 1, 2i + d: the matrix products, the result
// of step k starting (2^k - 1) d rows down (each step shifts the old string by
// d, which the next matrix doubles).
std::vector<Pt> closed_expected(Scheme scheme, std::vector<Pt> p, int steps, int d) {
  long shift = 0;
  for (int k = 0; k < steps; ++k) {
    p = multiply(closed_matrix(scheme, static_cast<int>(p.size())), p);
    shift = 2 * shift + d;
  }
  return rotate(p, shift);
}

// Section 6's open-curve matrix for the cubic B-spline, n columns, 2n - 1 rows:
// the end points kept, 1/2 1/2 next to them, the closed rows in between.
Matrix open_bspline_matrix(int n) {
  Matrix m;
  auto row = [&](std::vector<std::pair<int, double>> entries) {
    std::vector<double> r(static_cast<std::size_t>(n), 0.0);
    for (auto [c, w] : entries) r[static_cast<std::size_t>(c)] += w;
    m.push_back(r);
  };
  row({{0, 1}});
  row({{0, 0.5}, {1, 0.5}});
  for (int i = 1; i <= n - 2; ++i) {
    row({{i - 1, 0.125}, {i, 0.75}, {i + 1, 0.125}});
    row({{i, 0.5}, {i + 1, 0.5}});
  }
  row({{n - 1, 1}});
  return m;
}

// The four-point scheme on an open polygon with the model's end rule: the
// middle of the cubic through the four end points, 1/16 (5, 15, -5, 1).
Matrix open_four_point_matrix(int n) {
  Matrix m;
  auto row = [&](std::vector<std::pair<int, double>> entries) {
    std::vector<double> r(static_cast<std::size_t>(n), 0.0);
    for (auto [c, w] : entries) r[static_cast<std::size_t>(c)] += w;
    m.push_back(r);
  };
  for (int i = 0; i < n - 1; ++i) {
    row({{i, 1}});
    if (i == 0)
      row({{0, 5.0 / 16}, {1, 15.0 / 16}, {2, -5.0 / 16}, {3, 1.0 / 16}});
    else if (i == n - 2)
      row({{n - 4, 1.0 / 16}, {n - 3, -5.0 / 16}, {n - 2, 15.0 / 16}, {n - 1, 5.0 / 16}});
    else
      row({{i - 1, -1.0 / 16}, {i, 9.0 / 16}, {i + 1, 9.0 / 16}, {i + 2, -1.0 / 16}});
  }
  row({{n - 1, 1}});
  return m;
}

// Largest distance from a point of `p` to the polygon's diameter scale.
double size_of(const std::vector<Pt>& p) {
  double s = 0;
  for (const Pt& a : p)
    for (const Pt& b : p) s = std::max(s, dist(a, b));
  return s;
}

// ---------------------------------------------------------------------------
// cubic-bspline-subdivision

TEST(SubdivisionCubicBspline, ClosedIsTheMatrixProduct) {
  const std::vector<Pt> p0 = points_after(model(kBspline, kBspline), 0);
  ASSERT_EQ(p0.size(), 7u);
  for (int steps = 1; steps <= 5; ++steps) {
    const std::vector<Pt> got = points_after(model(kBspline, kBspline), steps);
    EXPECT_EQ(got.size(), 7u << steps);  // n 2^k
    // Production (22): the vertex point first, d = 1.
    expect_points_near(got, closed_expected(kCubicBspline, p0, steps, 1), 1e-12,
                       "after " + std::to_string(steps) + " steps");
  }
}

// The point descended from P_i by vertex rules (index i 2^k) approaches the
// limit position (P_{i-1} + 4 P_i + P_{i+1}) / 6, which the mask 1/6 (1, 4, 1)
// keeps exactly at every step; the distance shrinks about fourfold per step.
TEST(SubdivisionCubicBspline, ClosedApproachesTheLimitPositions) {
  const std::vector<Pt> p = points_after(model(kBspline, kBspline), 0);
  const std::size_t n = p.size();
  std::vector<Pt> limit;
  for (std::size_t i = 0; i < n; ++i)
    limit.push_back((1.0 / 6) * (p[(i + n - 1) % n] + 4.0 * p[i] + p[(i + 1) % n]));
  std::vector<double> error;
  for (int k = 0; k <= 8; ++k) {
    const std::vector<Pt> q = points_after(model(kBspline, kBspline), k);
    ASSERT_EQ(q.size(), n << k);
    const std::size_t m = q.size();
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = i << k;
      const Pt mask = (1.0 / 6) * (q[(j + m - 1) % m] + 4.0 * q[j] + q[(j + 1) % m]);
      EXPECT_NEAR(mask.x, limit[i].x, 1e-12) << "point " << i << " after " << k << " steps";
      EXPECT_NEAR(mask.y, limit[i].y, 1e-12) << "point " << i << " after " << k << " steps";
      worst = std::max(worst, dist(q[j], limit[i]));
    }
    error.push_back(worst);
  }
  for (int k = 1; k <= 8; ++k) EXPECT_LT(error[k], 0.3 * error[k - 1]) << "step " << k;
  EXPECT_LT(error[8], 1e-4 * size_of(p));
}

TEST(SubdivisionCubicBspline, OpenIsTheSectionSixMatrixProduct) {
  std::vector<Pt> p = points_after(model(kBspline, kBspline), 0, {"OPEN"});
  ASSERT_EQ(p.size(), 6u);
  const std::vector<Pt> p0 = p;
  for (int steps = 1; steps <= 5; ++steps) {
    p = multiply(open_bspline_matrix(static_cast<int>(p.size())), p);
    const std::vector<Module> s = parse_modules(derive_with(model(kBspline, kBspline), steps, {"OPEN"}));
    const std::vector<Pt> got = points(s);
    EXPECT_EQ(got.size(), (6u - 1) * (1u << steps) + 1);  // (n - 1) 2^k + 1
    expect_points_near(got, p, 1e-12, "after " + std::to_string(steps) + " steps");
    // The markers stay at the ends; the end points never move.
    EXPECT_EQ(count_named(s, "E"), 2);
    EXPECT_EQ(s.at(1).name, "E");
    EXPECT_EQ(s.back().name, "E");
    EXPECT_EQ(got.front().x, p0.front().x);
    EXPECT_EQ(got.front().y, p0.front().y);
    EXPECT_EQ(got.back().x, p0.back().x);
    EXPECT_EQ(got.back().y, p0.back().y);
  }
  // The inner points approach their limit positions as in the closed case.
  const std::vector<Pt> q = points_after(model(kBspline, kBspline), 8, {"OPEN"});
  for (std::size_t i = 1; i + 1 < p0.size(); ++i) {
    const Pt limit = (1.0 / 6) * (p0[i - 1] + 4.0 * p0[i] + p0[i + 1]);
    EXPECT_LT(dist(q[i << 8], limit), 1e-4 * size_of(p0)) << "point " << i;
  }
}

// ---------------------------------------------------------------------------
// four-point

TEST(SubdivisionFourPoint, ClosedIsTheMatrixProductAndInterpolates) {
  std::vector<Module> before = parse_modules(derive_with(model(kFourPoint, kFourPoint), 0, {}));
  const std::vector<Pt> p0 = points(before);
  ASSERT_EQ(p0.size(), 7u);
  std::vector<Pt> old = p0;
  for (int steps = 1; steps <= 5; ++steps) {
    const std::vector<Pt> got = points_after(model(kFourPoint, kFourPoint), steps);
    EXPECT_EQ(got.size(), 7u << steps);
    // Production (25): the old point first, d = 1.
    expect_points_near(got, closed_expected(kFourPointScheme, p0, steps, 1), 1e-12,
                       "after " + std::to_string(steps) + " steps");
    ASSERT_EQ(got.size(), 2 * old.size());
    for (std::size_t i = 0; i < old.size(); ++i) {  // every old point kept, exactly
      EXPECT_EQ(got[2 * i].x, old[i].x) << "point " << i << ", step " << steps;
      EXPECT_EQ(got[2 * i].y, old[i].y) << "point " << i << ", step " << steps;
    }
    old = got;
  }
}

TEST(SubdivisionFourPoint, OpenIsTheMatrixProductAndInterpolates) {
  std::vector<Pt> p = points_after(model(kFourPoint, kFourPoint), 0, {"OPEN"});
  ASSERT_EQ(p.size(), 6u);
  for (int steps = 1; steps <= 5; ++steps) {
    const std::vector<Pt> old = p;
    p = multiply(open_four_point_matrix(static_cast<int>(p.size())), p);
    const std::vector<Pt> got = points_after(model(kFourPoint, kFourPoint), steps, {"OPEN"});
    EXPECT_EQ(got.size(), (6u - 1) * (1u << steps) + 1);
    expect_points_near(got, p, 1e-12, "after " + std::to_string(steps) + " steps");
    for (std::size_t i = 0; i < old.size(); ++i) {  // every old point kept, exactly
      EXPECT_EQ(got[2 * i].x, old[i].x) << "point " << i << ", step " << steps;
      EXPECT_EQ(got[2 * i].y, old[i].y) << "point " << i << ", step " << steps;
    }
  }
}

// With the end rule the open scheme has cubic precision: six points of the
// cubic (2t, (t^3 - 9t^2 + 20t)/4), t = 0..5, give after k steps the points of
// the same cubic at t = j / 2^k, the end intervals included.
TEST(SubdivisionFourPoint, OpenReproducesCubics) {
  auto cubic = [](double t) { return Pt{2 * t, (t * t * t - 9 * t * t + 20 * t) / 4}; };
  for (int steps = 0; steps <= 5; ++steps) {
    const std::vector<Pt> got = points_after(model(kFourPoint, kFourPoint), steps, {"OPEN", "CUBIC"});
    ASSERT_EQ(got.size(), 5u * (1u << steps) + 1);
    std::vector<Pt> want;
    for (std::size_t j = 0; j < got.size(); ++j) want.push_back(cubic(static_cast<double>(j) / (1 << steps)));
    expect_points_near(got, want, 1e-12, "after " + std::to_string(steps) + " steps");
  }
}

// ---------------------------------------------------------------------------
// stencil-subdivision: the production parameterised by the masks

const std::string kStencil = "stencil-subdivision";

// Lane-Riesenfeld: double every point, then average neighbours `degree` times.
std::vector<Pt> lane_riesenfeld(const std::vector<Pt>& p, int degree) {
  std::vector<Pt> q;
  for (const Pt& a : p) q.push_back(a), q.push_back(a);
  for (int pass = 0; pass < degree; ++pass) {
    std::vector<Pt> next;
    for (std::size_t j = 0; j < q.size(); ++j) next.push_back(0.5 * (q[j] + q[(j + 1) % q.size()]));
    q = next;
  }
  return q;
}

// The rotation r with got = rotate(want, r) within `tolerance`, or -1.
long rotation_between(const std::vector<Pt>& got, const std::vector<Pt>& want, double tolerance) {
  if (got.size() != want.size()) return -1;
  for (long r = 0; r < static_cast<long>(want.size()); ++r) {
    const std::vector<Pt> w = rotate(want, r);
    bool same = true;
    for (std::size_t i = 0; i < w.size() && same; ++i) same = dist(got[i], w[i]) <= tolerance;
    if (same) return r;
  }
  return -1;
}

TEST(SubdivisionStencil, SchemesOfTheNotesAreInstances) {
  const std::string m = model(kStencil, kStencil);
  const std::vector<Pt> p0 = points_after(m, 0);
  ASSERT_EQ(p0.size(), 7u);
  // Production (13) maps old point i to rows 2i-1, 2i (d = 0); (22) and (25)
  // to rows 2i, 2i+1 (d = 1).
  struct Case {
    std::string define;
    Scheme scheme;
    int d;
  };
  for (const Case& c : {Case{"SCHEME=CHAIKIN", kChaikin, 0}, Case{"SCHEME=CUBIC_BSPLINE", kCubicBspline, 1},
                        Case{"SCHEME=FOUR_POINT", kFourPointScheme, 1}}) {
    expect_points_near(points_after(m, 4, {c.define}), closed_expected(c.scheme, p0, 4, c.d), 1e-12, c.define);
  }
  // The default is the cubic B-spline, the same points as its own example.
  EXPECT_EQ(derive_with(m, 3, {}), derive_with(model(kBspline, kBspline), 3, {}));
  // ... and FOUR_POINT those of four-point.l.
  expect_points_near(points_after(m, 3, {"SCHEME=FOUR_POINT"}), points_after(model(kFourPoint, kFourPoint), 3),
                     1e-12, "four-point");
}

// Chaikin's scheme is Lane-Riesenfeld of degree 2, the cubic B-spline of
// degree 3, the quartic of degree 4 (up to where the string starts).
TEST(SubdivisionStencil, BsplineSchemesAreLaneRiesenfeld) {
  const std::string m = model(kStencil, kStencil);
  const std::vector<Pt> p0 = points_after(m, 0);
  struct Case {
    std::string define;
    int degree;
  };
  for (const Case& c : {Case{"SCHEME=0", 2}, Case{"SCHEME=1", 3}, Case{"SCHEME=QUARTIC_BSPLINE", 4}}) {
    std::vector<Pt> want = p0;
    for (int k = 0; k < 3; ++k) want = lane_riesenfeld(want, c.degree);
    EXPECT_GE(rotation_between(points_after(m, 3, {c.define}), want, 1e-12), 0) << c.define;
  }
}

// Masks given with -D MASK: the table's cubic B-spline gives the table's
// string; a four-point mask of tension w = 0.1 gives four-point.l -D W=0.1.
TEST(SubdivisionStencil, MasksFromTheCommandLine) {
  const std::string m = model(kStencil, kStencil);
  EXPECT_EQ(derive_with(m, 3, {"MASK=0.125,0.75,0.125,0,0,0.5,0.5,0"}), derive_with(m, 3, {}));
  expect_points_near(points_after(m, 3, {"MASK=0,1,0,0,-0.1,0.6,0.6,-0.1"}),
                     points_after(model(kFourPoint, kFourPoint), 3, {"W=0.1"}), 1e-12, "w = 0.1");
}

TEST(SubdivisionStencil, StartPrintsTheProductionAndWarnsOfNonAffineMasks) {
  const std::string m = model(kStencil, kStencil);
  {
    Stepper run(m, {"SCHEME=FOUR_POINT"});
    EXPECT_NE(run.messages.find("P(vl) < P(v) > P(vr) P(vrr) -> P(v) P(-0.0625 vl + 0.5625 v + 0.5625 vr - 0.0625 vrr)"),
              std::string::npos)
        << run.messages;
    EXPECT_EQ(run.messages.find("warning"), std::string::npos) << run.messages;
  }
  Stepper run(m, {"MASK=0.5,0.5,0,0,0,0.5,0.6,0"});
  EXPECT_NE(run.messages.find("warning: the weights of P(0.5 v + 0.6 vr) add up to 1.1"), std::string::npos)
      << run.messages;
}

// ---------------------------------------------------------------------------
// stencil-subdivision/matrix-inference: the production read off the matrix

const std::string kInference = "matrix-inference";

std::string inferred_production(const std::vector<std::string>& defines) {
  Stepper run(model(kStencil, kInference), defines);
  return run.messages;
}

// The productions the notes infer, printed as the notes write them.
TEST(SubdivisionMatrixInference, PrintsTheNotesProductions) {
  struct Case {
    std::vector<std::string> defines;
    std::string production;
  };
  const std::vector<Case> cases = {
      {{"SCHEME=CHAIKIN", "D=0"}, "P(vl) < P(v) > P(vr) -> P(0.25 vl + 0.75 v) P(0.75 v + 0.25 vr)"},  // (13)
      {{"SCHEME=CHAIKIN", "D=-1"}, "P(vl) < P(v) -> P(0.75 vl + 0.25 v) P(0.25 vl + 0.75 v)"},          // (17)
      {{"SCHEME=CHAIKIN", "D=1"}, "P(v) > P(vr) -> P(0.75 v + 0.25 vr) P(0.25 v + 0.75 vr)"},           // (18)
      // (20) as printed in the notes is d = 5 (see the model's comment); d = 3:
      {{"SCHEME=CHAIKIN", "D=3"}, "P(v) > P(vr) P(vrr) -> P(0.75 vr + 0.25 vrr) P(0.25 vr + 0.75 vrr)"},
      {{"SCHEME=CHAIKIN", "D=5"},
       "P(v) > P(vr) P(vrr) P(vrrr) -> P(0.75 vrr + 0.25 vrrr) P(0.25 vrr + 0.75 vrrr)"},  // (20)
      {{"SCHEME=CUBIC_BSPLINE", "D=1"},
       "P(vl) < P(v) > P(vr) -> P(0.125 vl + 0.75 v + 0.125 vr) P(0.5 v + 0.5 vr)"},  // (22)
      {{"SCHEME=CUBIC_BSPLINE", "D=0"},
       "P(vl) < P(v) > P(vr) -> P(0.5 vl + 0.5 v) P(0.125 vl + 0.75 v + 0.125 vr)"},  // (23)
      {{"SCHEME=FOUR_POINT", "D=1"},
       "P(vl) < P(v) > P(vr) P(vrr) -> P(v) P(-0.0625 vl + 0.5625 v + 0.5625 vr - 0.0625 vrr)"},  // (25)
      {{"SCHEME=FOUR_POINT", "D=0"},
       "P(vll) P(vl) < P(v) > P(vr) -> P(-0.0625 vll + 0.5625 vl + 0.5625 v - 0.0625 vr) P(v)"},  // (26)
  };
  for (const Case& c : cases) {
    const std::string printed = inferred_production(c.defines);
    EXPECT_EQ(printed, c.production + "\n") << c.defines[0] << " " << c.defines[1];
  }
}

// The inferred L-system, applied to a polygon of 7 points (the table is for
// 8), gives the matrix products for 7, 14, 28 points, shifted by the mapping.
TEST(SubdivisionMatrixInference, DerivesTheMatrixProductsForAnyMapping) {
  const std::vector<Pt> p0 = points_after(model(kStencil, kInference), 0);
  ASSERT_EQ(p0.size(), 7u);
  struct Case {
    std::string scheme;
    Scheme s;
    int d;
  };
  for (const Case& c : {Case{"CHAIKIN", kChaikin, 0}, Case{"CHAIKIN", kChaikin, -1}, Case{"CHAIKIN", kChaikin, 3},
                        Case{"CHAIKIN", kChaikin, 5}, Case{"CUBIC_BSPLINE", kCubicBspline, 0},
                        Case{"CUBIC_BSPLINE", kCubicBspline, 1}, Case{"FOUR_POINT", kFourPointScheme, 0},
                        Case{"FOUR_POINT", kFourPointScheme, 1}}) {
    const std::vector<std::string> defines = {"SCHEME=" + c.scheme, "D=" + std::to_string(c.d)};
    Stepper run(model(kStencil, kInference), defines);
    for (int steps = 1; steps <= 3; ++steps) {
      run.step();
      expect_points_near(points(run.modules()), closed_expected(c.s, p0, steps, c.d), 1e-12,
                         c.scheme + " d = " + std::to_string(c.d) + ", " + std::to_string(steps) + " steps");
    }
  }
}

// Past the context of three points (the four-point scheme with d = 5) nothing
// is inferred and the polygon stays.
TEST(SubdivisionMatrixInference, RefusesStencilsBeyondItsContext) {
  const std::vector<std::string> defines = {"SCHEME=FOUR_POINT", "D=5"};
  EXPECT_NE(inferred_production(defines).find("not inferred"), std::string::npos);
  const std::vector<Pt> p0 = points_after(model(kStencil, kInference), 0);
  expect_points_near(points_after(model(kStencil, kInference), 2, defines), p0, 0, "four-point, d = 5");
}

// ---------------------------------------------------------------------------
// reverse-subdivision

const std::string kReverse = "reverse-subdivision";

// The reverse mask: the middle coarse point of the least-squares fit of the 7
// fine points f_{2i-3..2i+3} by the subdivision of 5 coarse points c_{i-2..i+2}
// (the normal equations solved by Gaussian elimination).
std::vector<double> least_squares_mask() {
  double local[7][5] = {};  // fine row (offset -3..3) on coarse column (offset -2..2)
  for (int k = -3; k <= 3; ++k) {
    auto add = [&](int coarse, double w) {
      if (coarse >= -2 && coarse <= 2) local[k + 3][coarse + 2] += w;
    };
    if (k % 2 == 0) {
      add(k / 2 - 1, 0.125), add(k / 2, 0.75), add(k / 2 + 1, 0.125);
    } else {
      const int m = (k - 1) / 2;  // floor
      add(m, 0.5), add(m + 1, 0.5);
    }
  }
  // [N | P^T] with N = P^T P, reduced to [I | N^-1 P^T].
  double a[5][12] = {};
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 5; ++c)
      for (int f = 0; f < 7; ++f) a[r][c] += local[f][r] * local[f][c];
    for (int f = 0; f < 7; ++f) a[r][5 + f] = local[f][r];
  }
  for (int c = 0; c < 5; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 5; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[pivot][c])) pivot = r;
    std::swap(a[c], a[pivot]);
    const double d = a[c][c];
    for (double& x : a[c]) x /= d;
    for (int r = 0; r < 5; ++r)
      if (r != c) {
        const double f = a[r][c];
        for (int j = 0; j < 12; ++j) a[r][j] -= f * a[c][j];
      }
  }
  return std::vector<double>(a[2] + 5, a[2] + 12);
}

TEST(SubdivisionReverse, MaskIsTheLocalLeastSquaresFit) {
  const std::vector<double> mask = least_squares_mask();
  const std::vector<double> printed = {23.0 / 196, -23.0 / 49, 9.0 / 28, 52.0 / 49, 9.0 / 28, -23.0 / 49, 23.0 / 196};
  ASSERT_EQ(mask.size(), printed.size());
  for (std::size_t j = 0; j < mask.size(); ++j) EXPECT_NEAR(mask[j], printed[j], 1e-12) << j;
}

// One level of reverse subdivision in plain C++: c = A f with the mask
// centred on the even fine points (A, 2n columns, n rows), and the details
// f - P c with P the cubic B-spline matrix (vertex first, as the forward step
// places them).
struct Level {
  std::vector<Pt> coarse, even_details, odd_details;
};
Level reverse_level(const std::vector<Pt>& f) {
  const std::vector<double> mask = least_squares_mask();
  const std::size_t m = f.size(), n = m / 2;
  Matrix a(n, std::vector<double>(m, 0.0));
  for (std::size_t i = 0; i < n; ++i)
    for (int o = -3; o <= 3; ++o) {
      const long column = (static_cast<long>(2 * i) + o + static_cast<long>(m)) % static_cast<long>(m);
      a[i][static_cast<std::size_t>(column)] += mask[static_cast<std::size_t>(o + 3)];
    }
  Level level;
  level.coarse = multiply(a, f);
  const std::vector<Pt> subdivided = rotate(multiply(closed_matrix(kCubicBspline, static_cast<int>(n)), level.coarse), 1);
  for (std::size_t i = 0; i < n; ++i) {
    level.even_details.push_back(f[2 * i] - subdivided[2 * i]);
    level.odd_details.push_back(f[2 * i + 1] - subdivided[2 * i + 1]);
  }
  return level;
}

// The second parameter of the modules named `name` whose level (first
// parameter) is `level`, in string order.
std::vector<Pt> details(const std::vector<Module>& s, const std::string& name, int level) {
  std::vector<Pt> out;
  for (const Module& m : s)
    if (m.name == name && static_cast<int>(number(m.params.at(0))) == level) out.push_back(read_pt(m.params.at(1)));
  return out;
}

TEST(SubdivisionReverse, CoarsePolygonAndDetailsAreTheMatrixProducts) {
  const std::string m = model(kReverse, kReverse);
  std::vector<Pt> f = points_after(m, 0);
  ASSERT_EQ(f.size(), 96u);
  Stepper run(m);
  for (int level = 1; level <= 3; ++level) {
    const Level want = reverse_level(f);
    run.step(2);
    const std::vector<Module> s = run.modules();
    expect_points_near(points(s), want.coarse, 1e-12, "coarse points, level " + std::to_string(level));
    EXPECT_EQ(points(s).size(), 96u >> level);
    expect_points_near(details(s, "E", level), want.even_details, 1e-12, "even details, level " + std::to_string(level));
    expect_points_near(details(s, "H", level), want.odd_details, 1e-12, "odd details, level " + std::to_string(level));
    // The indices count the points of the level.
    int k = 0;
    for (const Module& p : s)
      if (p.name == "P") {
        EXPECT_EQ(number(p.params.at(1)), k++);
      }
    f = want.coarse;
  }
}

// Subdividing the coarse polygon and adding the details gives the original
// back: after 3 levels down and 3 up, the 96 points and their indices.
TEST(SubdivisionReverse, ForwardWithDetailsGivesTheOriginalBack) {
  const std::string m = model(kReverse, kReverse);
  for (const std::vector<std::string>& defines :
       {std::vector<std::string>{}, std::vector<std::string>{"SHIFT=1"}, std::vector<std::string>{"LEVELS=1"}}) {
    const int levels = defines == std::vector<std::string>{"LEVELS=1"} ? 1 : 3;
    const std::vector<Pt> original = points_after(m, 0, defines);
    ASSERT_EQ(original.size(), 96u);
    const std::vector<Module> s = parse_modules(derive_with(m, 3 * levels, defines));
    expect_points_near(points(s), original, 1e-9, "round trip " + (defines.empty() ? "" : defines[0]));
    EXPECT_EQ(count_named(s, "E") + count_named(s, "H") + count_named(s, "C") + count_named(s, "O"), 0);
    int k = 0;
    for (const Module& p : s)
      if (p.name == "P") {
        EXPECT_EQ(number(p.params.at(1)), k++);
      }
  }
  // Without the details the coarse polygon's subdivision would miss the
  // teeth (amplitude 0.25): details of level 2 are larger than that.
  const std::vector<Module> s = parse_modules(derive_with(m, 4, {}));
  double largest = 0;
  for (const Pt& d : details(s, "H", 2)) largest = std::max(largest, std::hypot(d.x, d.y));
  EXPECT_GT(largest, 0.25);
}

// The other partition (SHIFT = 1: pairs (1,2), (3,4), ...) coarsens the same
// contour into another polygon: the reverse of the shifted string.
TEST(SubdivisionReverse, OtherPartitionGivesAnotherApproximation) {
  const std::string m = model(kReverse, kReverse);
  const std::vector<Pt> shifted = points_after(m, 0, {"SHIFT=1"});
  const std::vector<Pt> original = points_after(m, 0);
  expect_points_near(shifted, rotate(original, 1), 0, "the shifted string");
  const std::vector<Pt> coarse = points_after(m, 2, {"SHIFT=1"});
  expect_points_near(coarse, reverse_level(shifted).coarse, 1e-12, "coarse points of the shifted string");
  EXPECT_LT(rotation_between(coarse, points_after(m, 2), 1e-3), 0);  // not the same polygon
}

}  // namespace
}  // namespace sylva::test::examples
