// Tests of the adaptive L-system examples (Abd El-Latif, "A New Conception
// in Constructive Branching Structures and Leaves using L-system", 2010):
// adaptive-branching and adaptive-leaf. Every drawn point is compared, to
// 1e-12, with the paper's curve (corrected as the examples' comments say)
// computed here in another form: the parabola through P1, P2, P3 with
// reference values 0, ½, 1 as a quadratic Bézier curve (control point
// 2 P2 - (P1 + P3)/2), and for other reference values by Neville's
// algorithm; the middle point P2 from the chord's angle (atan2). The chords
// themselves come from the paper's symbols rewritten as characters and
// walked by a turtle with a heading angle. Also checked: P2 perpendicular
// to the chord at the distance C, the curves through their three points,
// matching tangents where strokes G and H meet on an axis, the two margins
// of a leaf mirror images, and the numbers of modules in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

std::string model(const std::string& name) { return example_path(name + "/" + name + ".l"); }

constexpr double kTolerance = 1e-12;

struct Vec {
  double x = 0, y = 0;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
Vec operator*(double k, Vec a) { return {k * a.x, k * a.y}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y; }
double cross(Vec a, Vec b) { return a.x * b.y - a.y * b.x; }
double norm(Vec a) { return std::hypot(a.x, a.y); }
Vec unit(Vec a) { return (1 / norm(a)) * a; }
double distance(Vec a, Vec b) { return std::max(std::fabs(a.x - b.x), std::fabs(a.y - b.y)); }

// Within kTolerance of each other in both coordinates.
::testing::AssertionResult near_vec(Vec got, Vec want) {
  if (distance(got, want) <= kTolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << got.x << "," << got.y << "), expected (" << want.x << ","
                                       << want.y << ")";
}
#define EXPECT_NEAR_VEC(got, ...) EXPECT_TRUE(near_vec(got, __VA_ARGS__))

// "(x,y)" as a V2d parameter prints.
Vec read_vec(const std::string& text) {
  const std::vector<std::string> c = split_top_level(text.substr(1, text.size() - 2));
  return {number(c.at(0)), number(c.at(1))};
}

struct Segment {
  Vec a, b;
};

// The Line2d's of an interpreted string, in order.
std::vector<Segment> lines(const std::vector<Module>& interpreted) {
  std::vector<Segment> out;
  for (const Module& m : interpreted)
    if (m.name == "Line2d") out.push_back({read_vec(m.params.at(0)), read_vec(m.params.at(1))});
  return out;
}

// The middle point of a stroke on the chord p1 p3: at w1 p1 + w2 p3, moved
// by d·c·|p1p3| along the chord's direction turned by +90° (d = +1: left).
Vec middle_point(Vec p1, Vec p3, double w1, double c, int d) {
  const double angle = std::atan2(p3.y - p1.y, p3.x - p1.x) + M_PI / 2;
  const Vec p = w1 * p1 + (1 - w1) * p3;
  return p + (d * c * norm(p3 - p1)) * Vec{std::cos(angle), std::sin(angle)};
}

// The parabola through p1, p2, p3 at t = 0, ½, 1 as a quadratic Bézier curve.
Vec bezier(Vec p1, Vec p2, Vec p3, double t) {
  const Vec control = 2 * p2 - 0.5 * (p1 + p3);
  return ((1 - t) * (1 - t)) * p1 + (2 * t * (1 - t)) * control + (t * t) * p3;
}

// The parabola through (0, p1), (t2, p2), (1, p3) at t by Neville's algorithm.
Vec neville(Vec p1, Vec p2, Vec p3, double t2, double t) {
  const double ts[3] = {0, t2, 1};
  Vec p[3] = {p1, p2, p3};
  for (int level = 1; level < 3; ++level)
    for (int i = 0; i + level < 3; ++i)
      p[i] = (1 / (ts[i + level] - ts[i])) * ((ts[i + level] - t) * p[i] + (t - ts[i]) * p[i + 1]);
  return p[0];
}

// The derivative of the parabola through (0, p1), (½, p2), (1, p3).
Vec bezier_tangent(Vec p1, Vec p2, Vec p3, double t) {
  const Vec control = 2 * p2 - 0.5 * (p1 + p3);
  return (2 * (1 - t)) * (control - p1) + (2 * t) * (p3 - control);
}

// The drawn stroke of `n` lines from `first`: its n + 1 vertices, checked to
// be joined end to end.
std::vector<Vec> vertices(const std::vector<Segment>& drawn, std::size_t first, int n) {
  std::vector<Vec> out;
  EXPECT_LE(first + n, drawn.size());
  if (first + n > drawn.size()) return out;
  out.push_back(drawn[first].a);
  for (int k = 0; k < n; ++k) {
    if (k > 0) {
      EXPECT_NEAR_VEC(drawn[first + k].a, out.back());
    }
    out.push_back(drawn[first + k].b);
  }
  return out;
}

// ---------------------------------------------------------------------------
// adaptive-branching: ω G, G → G[+G]H[-H]G, H → H[-H]G[+G]H, δ = 25.7°.

std::string rewrite(std::string s, int steps) {
  for (int i = 0; i < steps; ++i) {
    std::string next;
    for (char c : s) next += c == 'G' ? "G[+G]H[-H]G" : c == 'H' ? "H[-H]G[+G]H" : std::string(1, c);
    s = next;
  }
  return s;
}

struct Stroke {
  char kind;  // 'G' or 'H'
  Vec a, b;
};

// A turtle with a heading angle, starting at the origin heading up, step
// 27/3^n: the chords of the strokes in string order.
std::vector<Stroke> walk(const std::string& s, int steps, double delta_degrees) {
  const double step = 27 / std::pow(3.0, steps), delta = delta_degrees * M_PI / 180;
  struct State {
    Vec p;
    double heading;
  };
  State t{{0, 0}, M_PI / 2};
  std::vector<State> stack;
  std::vector<Stroke> out;
  for (char c : s) {
    if (c == '+') t.heading += delta;
    if (c == '-') t.heading -= delta;
    if (c == '[') stack.push_back(t);
    if (c == ']') t = stack.back(), stack.pop_back();
    if (c == 'G' || c == 'H') {
      const Vec q = t.p + step * Vec{std::cos(t.heading), std::sin(t.heading)};
      out.push_back({c, t.p, q});
      t.p = q;
    }
  }
  return out;
}

std::vector<Stroke> strokes_of(const std::vector<Module>& s) {
  std::vector<Stroke> out;
  for (const Module& m : s)
    if (m.name == "GL" || m.name == "HR")
      out.push_back({m.name == "GL" ? 'G' : 'H', read_vec(m.params.at(0)), read_vec(m.params.at(1))});
  return out;
}

TEST(AdaptiveBranching, CountsAndChordsAreTheTurtlesDrawing) {
  Stepper run(model("adaptive-branching"));
  for (int n = 0; n <= 4; ++n) {
    if (n > 0) run.step();
    const std::vector<Module> s = run.modules();
    const long p = std::lround(std::pow(5.0, n));
    EXPECT_EQ(count_named(s, "GL"), (p + 1) / 2) << "(5^n + 1)/2 G after n = " << n;
    EXPECT_EQ(count_named(s, "HR"), (p - 1) / 2) << "(5^n - 1)/2 H after n = " << n;
    EXPECT_EQ(count_named(s, "SB"), (p - 1) / 2) << "2 (1 + 5 + ... + 5^(n-1)) branches after n = " << n;
    const std::vector<Stroke> got = strokes_of(s), want = walk(rewrite("G", n), n, 25.7);
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].kind, want[i].kind) << "stroke " << i;
      EXPECT_NEAR_VEC(got[i].a, want[i].a);
      EXPECT_NEAR_VEC(got[i].b, want[i].b);
    }
  }
}

// The drawn vertices of every stroke: the corrected curve at t = k/16.
void check_drawn_strokes(const std::vector<std::string>& defines, int steps, double w1, double c, double t2) {
  Stepper run(model("adaptive-branching"), defines);
  run.step(steps);
  const std::vector<Stroke> strokes = strokes_of(run.modules());
  const std::vector<Segment> drawn = lines(parse_modules(run.interpreted()));
  ASSERT_EQ(drawn.size(), 16 * strokes.size());
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    const Stroke& st = strokes[i];
    const int d = st.kind == 'G' ? 1 : -1;
    const Vec p2 = middle_point(st.a, st.b, w1, c, d);
    const std::vector<Vec> v = vertices(drawn, 16 * i, 16);
    for (int k = 0; k <= 16; ++k) {
      const double t = k / 16.0;
      const Vec want = t2 == 0.5 ? bezier(st.a, p2, st.b, t) : neville(st.a, p2, st.b, t2, t);
      EXPECT_NEAR_VEC(v[k], want) << " stroke " << i << " vertex " << k;
    }
    // Through its three points: P1, P3 and P2 (the vertex at t2), P2 at the
    // distance C from P = w1 P1 + w2 P3 perpendicular to the chord, on the
    // side D says.
    const Vec drawn_p2 = v[std::lround(16 * t2)], chord = st.b - st.a, p = w1 * st.a + (1 - w1) * st.b;
    EXPECT_NEAR_VEC(v.front(), st.a);
    EXPECT_NEAR_VEC(v.back(), st.b);
    EXPECT_NEAR(dot(drawn_p2 - p, chord), 0, kTolerance) << "P2 - P perpendicular to P1P3, stroke " << i;
    EXPECT_NEAR(norm(drawn_p2 - p), c * norm(chord), kTolerance);
    EXPECT_GT(d * cross(chord, drawn_p2 - p), 0) << "D = " << d << ": P2 on the " << (d > 0 ? "left" : "right");
  }
}

TEST(AdaptiveBranching, DrawnPointsAreTheCorrectedParabola) {
  check_drawn_strokes({}, 3, 0.5, 0.12, 0.5);
}

TEST(AdaptiveBranching, OtherWeightsAndReferenceValues) {
  check_drawn_strokes({"W1=0.7", "T2=0.25", "CURVATURE=0.3", "DELTA=40"}, 2, 0.7, 0.3, 0.25);
}

TEST(AdaptiveBranching, LinesDrawTheChords) {
  Stepper run(model("adaptive-branching"), {"LINES"});
  run.step(2);
  const std::vector<Stroke> strokes = strokes_of(run.modules());
  const std::vector<Segment> drawn = lines(parse_modules(run.interpreted()));
  ASSERT_EQ(drawn.size(), strokes.size());
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    EXPECT_NEAR_VEC(drawn[i].a, strokes[i].a);
    EXPECT_NEAR_VEC(drawn[i].b, strokes[i].b);
  }
}

// Strokes that follow each other on an axis (the next stroke at the same
// bracket depth, branches skipped) alternate G H and meet with the same
// tangent: for the formula's derivative and for the drawn lines at the join.
TEST(AdaptiveBranching, AxesAreSmoothWhereGMeetsH) {
  const int n = 3;
  Stepper run(model("adaptive-branching"));
  run.step(n);
  const std::vector<Module> s = run.modules();
  const std::vector<Segment> drawn = lines(parse_modules(run.interpreted()));
  // Index of each module's stroke, and the stroke following it on its axis.
  std::vector<int> stroke_at(s.size(), -1);
  int strokes = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i].name == "GL" || s[i].name == "HR") stroke_at[i] = strokes++;
  int joins = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (stroke_at[i] < 0) continue;
    std::size_t j = i + 1;
    while (j < s.size() && s[j].name == "SB") j = end_of_branch(s, j + 1) + 1;
    if (j >= s.size() || stroke_at[j] < 0) continue;
    ++joins;
    EXPECT_NE(s[i].name, s[j].name) << "G and H alternate on an axis";
    const Vec a1 = read_vec(s[i].params[0]), b1 = read_vec(s[i].params[1]);
    const Vec a2 = read_vec(s[j].params[0]), b2 = read_vec(s[j].params[1]);
    EXPECT_NEAR_VEC(b1, a2);
    const int d1 = s[i].name == "GL" ? 1 : -1, d2 = -d1;
    const Vec end = unit(bezier_tangent(a1, middle_point(a1, b1, 0.5, 0.12, d1), b1, 1));
    const Vec start = unit(bezier_tangent(a2, middle_point(a2, b2, 0.5, 0.12, d2), b2, 0));
    EXPECT_NEAR(cross(end, start), 0, kTolerance) << "tangents at the join of strokes " << stroke_at[i];
    EXPECT_GT(dot(end, start), 0);
    // Each end tangent makes the angle atan(4 CURVATURE) with its chord.
    EXPECT_NEAR(std::fabs(std::asin(cross(unit(b1 - a1), end))), std::atan(4 * 0.12), kTolerance);
    // The drawn lines on either side of the join are parallel too.
    const Segment last = drawn[16 * stroke_at[i] + 15], first = drawn[16 * stroke_at[j]];
    EXPECT_NEAR(cross(unit(last.b - last.a), unit(first.b - first.a)), 0, kTolerance);
  }
  // 5^n strokes on 1 + (5^n - 1)/2 axes: 5^n - 1 - (5^n - 1)/2 joins.
  EXPECT_EQ(joins, (125 - 1) / 2);
}

// ---------------------------------------------------------------------------
// adaptive-leaf.

struct Leaf {
  Vec a, b;
  double w1, c;
};

std::vector<Leaf> leaves_of(const std::vector<Module>& s) {
  std::vector<Leaf> out;
  for (const Module& m : s)
    if (m.name == "V")
      out.push_back({read_vec(m.params.at(0)), read_vec(m.params.at(1)), number(m.params.at(2)), number(m.params.at(3))});
  return out;
}

// Reflection of q across the line through a and b.
Vec reflect(Vec q, Vec a, Vec b) {
  const Vec u = unit(b - a), r = q - a;
  return a + (2 * dot(r, u)) * u - r;
}

// Each leaf's 81 lines: per margin (D = +1, then -1) 16 margin lines and
// 3 veins of 8 lines, then the midrib.
void check_leaves(const std::vector<Module>& s, const std::vector<Segment>& drawn, double t2) {
  std::size_t at = 0;
  for (const Module& m : s) {
    if (m.name == "I") {
      ASSERT_LT(at, drawn.size());
      EXPECT_NEAR_VEC(drawn[at].a, read_vec(m.params[0]));
      EXPECT_NEAR_VEC(drawn[at].b, read_vec(m.params[1]));
      ++at;
    }
    if (m.name != "V") continue;
    const Leaf leaf = leaves_of({m})[0];
    std::vector<Vec> margin[2];
    for (int side = 0; side < 2; ++side) {
      const int d = side == 0 ? 1 : -1;
      const Vec p2 = middle_point(leaf.a, leaf.b, leaf.w1, leaf.c, d);
      auto curve = [&](double t) { return t2 == 0.5 ? bezier(leaf.a, p2, leaf.b, t) : neville(leaf.a, p2, leaf.b, t2, t); };
      margin[side] = vertices(drawn, at, 16);
      ASSERT_EQ(margin[side].size(), 17u);
      for (int k = 0; k <= 16; ++k) EXPECT_NEAR_VEC(margin[side][k], curve(k / 16.0)) << " margin vertex " << k;
      const Vec p = leaf.w1 * leaf.a + (1 - leaf.w1) * leaf.b, drawn_p2 = margin[side][std::lround(16 * t2)];
      EXPECT_NEAR(dot(drawn_p2 - p, leaf.b - leaf.a), 0, kTolerance) << "P2 - P perpendicular to P1P3";
      EXPECT_NEAR(norm(drawn_p2 - p), leaf.c * norm(leaf.b - leaf.a), kTolerance) << "|PP2| = C";
      at += 16;
      for (int j = 1; j <= 3; ++j) {  // veins: midrib to margin, bowed towards the tip
        const std::vector<Vec> v = vertices(drawn, at, 8);
        ASSERT_EQ(v.size(), 9u);
        const double t = j / 4.0;
        EXPECT_NEAR_VEC(v.front(), (1 - t) * leaf.a + t * leaf.b);
        EXPECT_NEAR_VEC(v.back(), curve(t + 0.18));
        const Vec vm = middle_point(v.front(), v.back(), 0.5, leaf.c / 3, -d);
        for (int k = 0; k <= 8; ++k) {
          const Vec want = t2 == 0.5 ? bezier(v.front(), vm, v.back(), k / 8.0) : neville(v.front(), vm, v.back(), t2, k / 8.0);
          EXPECT_NEAR_VEC(v[k], want) << " vein vertex " << k;
        }
        EXPECT_GT(dot(v[4] - 0.5 * (v.front() + v.back()), leaf.b - leaf.a), 0) << "vein bowed towards the tip";
        at += 8;
      }
    }
    // The two margins are mirror images across the midrib.
    for (int k = 0; k <= 16; ++k) EXPECT_NEAR_VEC(reflect(margin[0][k], leaf.a, leaf.b), margin[1][k]);
    ASSERT_LT(at, drawn.size());
    EXPECT_NEAR_VEC(drawn[at].a, leaf.a);
    EXPECT_NEAR_VEC(drawn[at].b, leaf.b);
    ++at;
  }
  EXPECT_EQ(at, drawn.size());
}

TEST(AdaptiveLeaf, CompoundLeafCountsAndLeaflets) {
  const int pairs = 6;
  Stepper run(model("adaptive-leaf"));
  for (int n = 0; n <= pairs + 1; ++n) {
    if (n > 0) run.step();
    const std::vector<Module> s = run.modules();
    EXPECT_EQ(count_named(s, "I"), n);
    EXPECT_EQ(count_named(s, "V"), n <= pairs ? 2 * n : 2 * pairs + 1) << "after " << n << " steps";
    EXPECT_EQ(count_named(s, "A"), n <= pairs ? 1 : 0);
  }
  // A turtle up the rachis: node k at the sum of steps 0.85^i, leaflets
  // 1.5 steps long at ±55° from it, the last one straight on.
  const std::vector<Leaf> leaves = leaves_of(run.modules());
  Vec node{0, 0};
  double step = 1;
  for (int k = 0; k <= pairs; ++k) {
    node = node + Vec{0, step};
    for (int side = 0; side < (k < pairs ? 2 : 1); ++side) {
      const Leaf& leaf = leaves.at(k < pairs ? 2 * k + side : 2 * pairs);
      const double angle = M_PI / 2 + (k < pairs ? (side == 0 ? 1 : -1) * 55 * M_PI / 180 : 0);
      EXPECT_NEAR_VEC(leaf.a, node);
      EXPECT_NEAR_VEC(leaf.b, node + (1.5 * step) * Vec{std::cos(angle), std::sin(angle)});
      EXPECT_DOUBLE_EQ(leaf.w1, 0.6);
      EXPECT_DOUBLE_EQ(leaf.c, 0.22);
    }
    step *= 0.85;
  }
  check_leaves(run.modules(), lines(parse_modules(run.interpreted())), 0.5);
}

TEST(AdaptiveLeaf, TableOfWeightsAndCurvatures) {
  Stepper run(model("adaptive-leaf"), {"TABLE"});
  const std::vector<Module> s = run.modules();
  const std::vector<Leaf> leaves = leaves_of(s);
  ASSERT_EQ(leaves.size(), 20u);
  const double w1[4] = {0.3, 0.5, 0.6, 0.7};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 5; ++j) {
      EXPECT_DOUBLE_EQ(leaves[5 * i + j].w1, w1[i]);
      EXPECT_NEAR(leaves[5 * i + j].c, 0.1 * (j + 1), 1e-15);
    }
  check_leaves(s, lines(parse_modules(run.interpreted())), 0.5);
}

TEST(AdaptiveLeaf, OtherReferenceValue) {
  Stepper run(model("adaptive-leaf"), {"T2=0.375", "PAIRS=2"});
  run.step(3);
  check_leaves(run.modules(), lines(parse_modules(run.interpreted())), 0.375);
}

}  // namespace
}  // namespace sylva::test::examples
