// Tests of the open-curve variants (-D OPEN) of the general stencil form
// (examples/stencil-subdivision/stencil-subdivision.l) and of the L-systems
// inferred from a subdivision matrix (matrix-inference.l), after section 6 of
// "L-system description of subdivision curves" (Prusinkiewicz, Samavati,
// Smith, Karwowski; SIGGRAPH 2003 course notes "L-systems and Beyond").
//
// The expectations are computed a second way: the open subdivision matrices
// are built here for any number of points and multiplied with the polygon
// read from the model's string at step 0: Chaikin's (27) as printed, the cubic
// B-spline's and the four-point scheme's as their own examples define them,
// and the models' general end rule (end points kept, rows centred outside the
// polygon dropped, phantom points extrapolated past the ends) written again
// as a matrix whose rows are sorted by where they are centred.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "examples/example_strings.h"
#include "examples/plane_points.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

const std::string kStencil = example_path("stencil-subdivision/stencil-subdivision.l");
const std::string kInference = example_path("stencil-subdivision/matrix-inference.l");
const std::string kBspline = example_path("cubic-bspline-subdivision/cubic-bspline-subdivision.l");
const std::string kFourPoint = example_path("four-point/four-point.l");

// Rows given as (column, weight) pairs, columns 0-based.
struct Builder {
  int n;
  Matrix m;
  void row(std::vector<std::pair<int, double>> entries) {
    std::vector<double> r(static_cast<std::size_t>(n), 0.0);
    for (auto [c, w] : entries) r.at(static_cast<std::size_t>(c)) += w;
    m.push_back(r);
  }
};

// (27): 1; 1/2 1/2; then 3/4 1/4 and 1/4 3/4 on each inner pair; 1/2 1/2; 1.
Matrix chaikin_27(int n) {
  Builder b{n, {}};
  b.row({{0, 1}});
  b.row({{0, 0.5}, {1, 0.5}});
  for (int k = 1; k <= n - 3; ++k) {
    b.row({{k, 0.75}, {k + 1, 0.25}});
    b.row({{k, 0.25}, {k + 1, 0.75}});
  }
  b.row({{n - 2, 0.5}, {n - 1, 0.5}});
  b.row({{n - 1, 1}});
  return b.m;
}

// cubic-bspline-subdivision.l -D OPEN: 1; 1/2 1/2; 1/8 3/4 1/8; 1/2 1/2; ...; 1.
Matrix bspline_open(int n) {
  Builder b{n, {}};
  b.row({{0, 1}});
  b.row({{0, 0.5}, {1, 0.5}});
  for (int i = 1; i <= n - 2; ++i) {
    b.row({{i - 1, 0.125}, {i, 0.75}, {i + 1, 0.125}});
    b.row({{i, 0.5}, {i + 1, 0.5}});
  }
  b.row({{n - 1, 1}});
  return b.m;
}

// four-point.l -D OPEN: old points kept, 1/16 (-1, 9, 9, -1) inside, the
// middle of the cubic through the four end points in the end intervals.
Matrix four_point_open(int n) {
  Builder b{n, {}};
  for (int i = 0; i < n - 1; ++i) {
    b.row({{i, 1}});
    if (i == 0)
      b.row({{0, 5.0 / 16}, {1, 15.0 / 16}, {2, -5.0 / 16}, {3, 1.0 / 16}});
    else if (i == n - 2)
      b.row({{n - 4, 1.0 / 16}, {n - 3, -5.0 / 16}, {n - 2, 15.0 / 16}, {n - 1, 5.0 / 16}});
    else
      b.row({{i - 1, -1.0 / 16}, {i, 9.0 / 16}, {i + 1, 9.0 / 16}, {i + 2, -1.0 / 16}});
  }
  b.row({{n - 1, 1}});
  return b.m;
}

// The general end rule for masks a, b on (vl, v, vr, vrr): every old point i
// gives the rows a and b, centred at i + sum(weight x offset); the rows
// centred in (0, n-1) are kept, sorted by their centre, between the end points.
// A phantom point at index j < 0 or j >= n is the polynomial of degree 1 or 3
// through the end points (Lagrange), as a row on the real points.
std::vector<double> point_row(int j, int n, int degree) {
  std::vector<double> r(static_cast<std::size_t>(n), 0.0);
  if (j >= 0 && j < n) {
    r[static_cast<std::size_t>(j)] = 1;
    return r;
  }
  const bool left = j < 0;
  std::vector<int> nodes;  // the degree + 1 points nearest the end
  for (int k = 0; k <= degree; ++k) nodes.push_back(left ? k : n - 1 - k);
  for (int node : nodes) {
    double l = 1;
    for (int other : nodes)
      if (other != node) l *= double(j - other) / double(node - other);
    r[static_cast<std::size_t>(node)] += l;
  }
  return r;
}

Matrix general_open(const std::vector<double>& mask, int degree, int n) {
  std::vector<std::pair<double, std::vector<double>>> rows;  // (centre, row)
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) {
      const double* w = mask.data() + 4 * k;
      const double centre = i - w[0] + w[2] + 2 * w[3];
      if (centre <= 1e-12 || centre >= n - 1 - 1e-12) continue;
      std::vector<double> r(static_cast<std::size_t>(n), 0.0);
      for (int o = -1; o <= 2; ++o) {
        const std::vector<double> p = point_row(i + o, n, degree);
        for (std::size_t c = 0; c < r.size(); ++c) r[c] += w[o + 1] * p[c];
      }
      rows.push_back({centre, r});
    }
  std::stable_sort(rows.begin(), rows.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  Matrix m = {point_row(0, n, 1)};
  for (const auto& r : rows) m.push_back(r.second);
  m.push_back(point_row(n - 1, n, 1));
  return m;
}

const std::vector<double> kChaikinMask = {0.25, 0.75, 0, 0, 0, 0.75, 0.25, 0};
const std::vector<double> kBsplineMask = {0.125, 0.75, 0.125, 0, 0, 0.5, 0.5, 0};
const std::vector<double> kFourPointMask = {0, 1, 0, 0, -1.0 / 16, 9.0 / 16, 9.0 / 16, -1.0 / 16};
const std::vector<double> kQuarticMask = {5.0 / 16, 10.0 / 16, 1.0 / 16, 0, 1.0 / 16, 10.0 / 16, 5.0 / 16, 0};

void expect_points_near(const std::vector<Pt>& got, const std::vector<Pt>& want, double tolerance,
                        const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i].x, want[i].x, tolerance) << what << ", point " << i;
    EXPECT_NEAR(got[i].y, want[i].y, tolerance) << what << ", point " << i;
  }
}

struct OpenCase {
  std::vector<std::string> defines;
  Matrix (*matrix)(int);  // or null: the general rule with `mask`, `degree`
  std::vector<double> mask;
  int degree;
  int extra;  // points after a step: 2n - 2 + extra
};

Matrix matrix_of(const OpenCase& c, int n) { return c.matrix ? c.matrix(n) : general_open(c.mask, c.degree, n); }

// Steps 1..5 of `model` (run step by step) against the matrices, the ends kept
// exactly and the markers in place.
void check_open(const std::string& model, const OpenCase& c) {
  std::string what;
  for (const std::string& d : c.defines) what += d + " ";
  SCOPED_TRACE(model + " " + what);
  Stepper run(model, c.defines);
  std::vector<Pt> p = points(run.modules());
  ASSERT_EQ(p.size(), 6u);
  const std::vector<Pt> p0 = p;
  for (int steps = 1; steps <= 5; ++steps) {
    const std::size_t before = p.size();
    p = multiply(matrix_of(c, static_cast<int>(p.size())), p);
    run.step();
    const std::vector<Module> s = run.modules();
    const std::vector<Pt> got = points(s);
    EXPECT_EQ(got.size(), 2 * before - 2 + static_cast<std::size_t>(c.extra)) << "step " << steps;
    expect_points_near(got, p, 1e-12, "after " + std::to_string(steps) + " steps");
    ASSERT_FALSE(got.empty());
    EXPECT_EQ(got.front().x, p0.front().x);  // exactly
    EXPECT_EQ(got.front().y, p0.front().y);
    EXPECT_EQ(got.back().x, p0.back().x);
    EXPECT_EQ(got.back().y, p0.back().y);
    EXPECT_EQ(count_named(s, "E"), 2);
    EXPECT_EQ(s.at(1).name, "E");  // after Control
    EXPECT_EQ(s.back().name, "E");
  }
  EXPECT_EQ(run.messages.find("warning"), std::string::npos) << run.messages;
}

// The test's matrices agree with each other where they should: the general
// rule gives the cubic B-spline's section-6 matrix (linear phantoms) and the
// four-point example's (cubic phantoms).
TEST(StencilOpen, GeneralRuleGivesTheExamplesMatrices) {
  for (int n : {4, 6, 9, 17}) {
    const Matrix b = bspline_open(n), g = general_open(kBsplineMask, 1, n);
    const Matrix f = four_point_open(n), h = general_open(kFourPointMask, 3, n);
    ASSERT_EQ(b.size(), g.size());
    ASSERT_EQ(f.size(), h.size());
    for (std::size_t r = 0; r < b.size(); ++r)
      for (std::size_t c = 0; c < b[r].size(); ++c) {
        EXPECT_NEAR(b[r][c], g[r][c], 1e-15) << n << " " << r << " " << c;
        EXPECT_NEAR(f[r][c], h[r][c], 1e-15) << n << " " << r << " " << c;
      }
    EXPECT_EQ(chaikin_27(n).size(), 2u * n - 2);
    EXPECT_EQ(general_open(kQuarticMask, 1, n).size(), 2u * n);
  }
}

TEST(StencilOpen, TableSchemesAreTheOpenMatrixProducts) {
  const std::vector<OpenCase> cases = {
      {{"OPEN", "SCHEME=CHAIKIN"}, chaikin_27, {}, 0, 0},            // the notes' (28)-(36)
      {{"OPEN"}, bspline_open, {}, 0, 1},                             // default: cubic B-spline
      {{"OPEN", "SCHEME=FOUR_POINT"}, four_point_open, {}, 0, 1},    // cubic end intervals
      {{"OPEN", "SCHEME=QUARTIC_BSPLINE"}, nullptr, kQuarticMask, 1, 2},
  };
  for (const OpenCase& c : cases) check_open(kStencil, c);
}

TEST(StencilOpen, MasksAndPhantomsFromTheCommandLine) {
  const std::vector<OpenCase> cases = {
      {{"OPEN", "SCHEME=CHAIKIN", "EXTRAPOLATE=1"}, nullptr, kChaikinMask, 1, 2},
      {{"OPEN", "SCHEME=FOUR_POINT", "EXTRAPOLATE=1"}, nullptr, kFourPointMask, 1, 1},
      {{"OPEN", "SCHEME=QUARTIC_BSPLINE", "EXTRAPOLATE=3"}, nullptr, kQuarticMask, 3, 2},
      {{"OPEN", "MASK=0,1,0,0,-0.1,0.6,0.6,-0.1"}, nullptr, {0, 1, 0, 0, -0.1, 0.6, 0.6, -0.1}, 1, 1},
      {{"OPEN", "MASK=0,1,0,0,-0.0625,0.5625,0.5625,-0.0625", "EXTRAPOLATE=3"}, four_point_open, {}, 0, 1},
  };
  for (const OpenCase& c : cases) check_open(kStencil, c);
}

// The open variants give the points of the examples that have them.
TEST(StencilOpen, SameAsTheOpenExamples) {
  for (int steps : {1, 4}) {
    expect_points_near(points(parse_modules(derive_with(kStencil, steps, {"OPEN"}))),
                       points(parse_modules(derive_with(kBspline, steps, {"OPEN"}))), 1e-12, "cubic B-spline");
    expect_points_near(points(parse_modules(derive_with(kStencil, steps, {"OPEN", "SCHEME=FOUR_POINT"}))),
                       points(parse_modules(derive_with(kFourPoint, steps, {"OPEN"}))), 1e-12, "four-point");
  }
}

TEST(StencilOpen, StartSaysWhichEndRule) {
  {
    Stepper run(kStencil, {"OPEN", "SCHEME=CHAIKIN"});
    EXPECT_NE(run.messages.find("open curve: the notes' end rules (28)-(35)"), std::string::npos) << run.messages;
  }
  {
    Stepper run(kStencil, {"OPEN", "SCHEME=FOUR_POINT"});
    EXPECT_NE(run.messages.find("cubic phantom points"), std::string::npos) << run.messages;
  }
  Stepper run(kStencil, {"OPEN", "MASK=0,0,1,0,0,0,0,1"});  // rows centred at 1 and 2
  EXPECT_NE(run.messages.find("warning: P(vr) is centred 1 from its point"), std::string::npos) << run.messages;
}

// ---------------------------------------------------------------------------
// matrix-inference -D OPEN

std::string printed(std::vector<std::string> defines) {
  defines.push_back("OPEN");
  Stepper run(kInference, defines);
  return run.messages;
}

TEST(MatrixInferenceOpen, PrintsTheNotesProductionsForMatrix27) {
  EXPECT_EQ(printed({"SCHEME=CHAIKIN"}),
            "# < P(v) -> P(v)\n"                                                          // (28)
            "# P(vl) < P(v) > P(vr) -> P(0.5 vl + 0.5 v) P(0.75 v + 0.25 vr)\n"           // (29), (34)
            "P(vl) < P(v) > P(vr) # -> P(0.25 vl + 0.75 v) P(0.5 v + 0.5 vr)\n"           // (31), (35)
            "P(v) > # -> P(v)\n"                                                          // (32)
            "P(vl) < P(v) > P(vr) -> P(0.25 vl + 0.75 v) P(0.75 v + 0.25 vr)\n");         // (36)
}

TEST(MatrixInferenceOpen, PrintsTheOtherExamplesProductions) {
  // cubic-bspline-subdivision.l -D OPEN
  EXPECT_EQ(printed({"SCHEME=CUBIC_BSPLINE"}),
            "# < P(v) > P(vr) -> P(v) P(0.5 v + 0.5 vr)\n"
            "P(v) > # -> P(v)\n"
            "P(vl) < P(v) > P(vr) -> P(0.125 vl + 0.75 v + 0.125 vr) P(0.5 v + 0.5 vr)\n");
  // four-point.l -D OPEN
  EXPECT_EQ(printed({"SCHEME=FOUR_POINT"}),
            "# < P(v) > P(vr) P(vrr) P(vrrr) -> P(v) P(0.3125 v + 0.9375 vr - 0.3125 vrr + 0.0625 vrrr)\n"
            "P(vll) P(vl) < P(v) > P(vr) # -> P(v) P(0.0625 vll - 0.3125 vl + 0.9375 v + 0.3125 vr)\n"
            "P(v) > # -> P(v)\n"
            "P(vl) < P(v) > P(vr) P(vrr) -> P(v) P(-0.0625 vl + 0.5625 v + 0.5625 vr - 0.0625 vrr)\n");
  // Another mapping of (27): the last point's rows go to the point before it.
  EXPECT_EQ(printed({"SCHEME=CHAIKIN", "D=0"}),
            "# < P(v) > P(vr) -> P(v) P(0.5 v + 0.5 vr)\n"
            "P(v) > P(vr) # -> P(0.5 v + 0.5 vr) P(vr)\n"
            "P(v) > # -> (empty)\n"
            "P(v) > P(vr) -> P(0.75 v + 0.25 vr) P(0.25 v + 0.75 vr)\n");
}

// Whatever the mapping, the inferred L-system (read off the 8-column matrix)
// gives the open matrix products for 6, 10, 18, ... points.
TEST(MatrixInferenceOpen, DerivesTheOpenMatrixProducts) {
  struct Case {
    std::string scheme;
    Matrix (*matrix)(int);
    int extra;
  };
  for (const Case& c : {Case{"CHAIKIN", chaikin_27, 0}, Case{"CUBIC_BSPLINE", bspline_open, 1},
                        Case{"FOUR_POINT", four_point_open, 1}})
    for (int d : {-1, 0, 1})
      check_open(kInference, {{"OPEN", "SCHEME=" + c.scheme, "D=" + std::to_string(d)}, c.matrix, {}, 0, c.extra});
}

}  // namespace
}  // namespace sylva::test::examples
