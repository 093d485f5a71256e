// Tests of the ring, in-body context and group examples: closed-subdivision
// (checked against the subdivision computed here directly), in-body-signal
// and alternating-groups (checked against strings traced by hand).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

std::string model(const std::string& name) { return example_path(name + "/" + name + ".l"); }

// ---------------------------------------------------------------------------
// closed-subdivision: cubic B-spline subdivision of a closed pentagon.

struct Point {
  double x, y;
};

// One step of closed cubic B-spline subdivision, indices taken round the polygon.
std::vector<Point> subdivide(const std::vector<Point>& p) {
  const std::size_t n = p.size();
  std::vector<Point> out;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& l = p[(i + n - 1) % n];
    const Point& v = p[i];
    const Point& r = p[(i + 1) % n];
    out.push_back({(l.x + 6 * v.x + r.x) / 8, (l.y + 6 * v.y + r.y) / 8});
    out.push_back({(v.x + r.x) / 2, (v.y + r.y) / 2});
  }
  return out;
}

// "(x,y)" as printed for a V2f.
Point read_point(const std::string& text) {
  const std::vector<std::string> xy = split_top_level(text.substr(1, text.size() - 2));
  return {float_number(xy.at(0)), float_number(xy.at(1))};
}

TEST(ExampleClosedSubdivision, PointsAreTheClosedSubdivision) {
  std::vector<Point> expected = {{0, 0}, {8, 0}, {12, 8}, {4, 16}, {-4, 8}};
  for (int step = 1; step <= 4; ++step) {
    expected = subdivide(expected);
    const std::vector<Module> s = parse_modules(derive_string(model("closed-subdivision"), step));
    ASSERT_EQ(s.size(), expected.size()) << "after " << step << " steps";
    // Integer corners and weights 1/8, 3/4, 1/2: every point is a binary
    // fraction with at most 3 bits per step, exact in float and double alike.
    for (std::size_t i = 0; i < s.size(); ++i) {
      ASSERT_EQ(s[i].name, "P");
      const Point got = read_point(s[i].params.at(0));
      EXPECT_EQ(got.x, expected[i].x) << "point " << i << " after " << step << " steps";
      EXPECT_EQ(got.y, expected[i].y) << "point " << i << " after " << step << " steps";
    }
  }
}

// The first point's left neighbour is the last one (the ring): after one
// step the first point is (-4,8)/8 + 3/4 (0,0) + (8,0)/8 = (0.5, 1).
TEST(ExampleClosedSubdivision, FirstPointUsesTheLastAsNeighbour) {
  const std::vector<Module> s = parse_modules(derive_string(model("closed-subdivision"), 1));
  ASSERT_EQ(s.size(), 10u);
  EXPECT_EQ(s[0].params.at(0), "(0.5,1)");
  // The last edge point joins the last corner to the first: ((-4,8) + (0,0)) / 2.
  EXPECT_EQ(s[9].params.at(0), "(-2,4)");
}

// The interpretation rule draws each point from its left neighbour, across
// the ring for the first: a closed polyline of as many segments as points.
TEST(ExampleClosedSubdivision, DrawingIsClosed) {
  const ProcessResult r =
      run_sylva({"run", model("closed-subdivision"), "--steps", "0", "--interpreted", "-"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out,
            "MoveTo2f((-4,8)) LineTo2f((0,0)) MoveTo2f((0,0)) LineTo2f((8,0)) MoveTo2f((8,0)) LineTo2f((12,8)) "
            "MoveTo2f((12,8)) LineTo2f((4,16)) MoveTo2f((4,16)) LineTo2f((-4,8))\n");
}

// ---------------------------------------------------------------------------
// in-body-signal: the trace in the model's comment, worked by hand.

TEST(ExampleInBodySignal, SignalMovesUntilTheWall) {
  const std::vector<std::string> expected = {
      "S(1) A(0) A(0) A(0) W A(0)",  // axiom
      "A(1) S(2) A(0) A(0) W A(0)",  // S sees A(0) on its right and leaves; A(0) receives 1
      "A(1) A(2) S(4) A(0) W A(0)",  // the next cell receives 2
      "A(1) A(2) A(4) S(8) W A(0)",  // the last cell before the wall receives 4
      "A(1) A(2) A(4) S(8) W A(0)",  // W on its right: InRightContext(A(n)) is false, S stays
      "A(1) A(2) A(4) S(8) W A(0)",  // and A(0) beyond the wall never sees it
  };
  for (int step = 0; step < static_cast<int>(expected.size()); ++step)
    EXPECT_EQ(derive_string(model("in-body-signal"), step), expected[static_cast<std::size_t>(step)])
        << "after " << step << " steps";
}

// ---------------------------------------------------------------------------
// alternating-groups: growth (group 1) and elongation (group 2) in turn.

TEST(ExampleAlternatingGroups, PhasesAlternate) {
  const std::vector<std::string> expected = {
      "T(0) A(0)",                    // axiom
      "T(1) I(1) A(1)",               // group 1: A lays I(1); T by group 0
      "T(2) I(2) A(1)",               // group 2: I doubles; A falls back to group 0 (no rule: stays)
      "T(3) I(2) I(1) A(2)",          // group 1: I has no rule there or in group 0: stays
      "T(4) I(4) I(2) A(2)",          // group 2
      "T(5) I(4) I(2) I(1) A(3)",     // group 1
      "T(6) I(8) I(4) I(2) A(3)",     // group 2: after 2k steps the internodes are 2^k ... 2
  };
  for (int step = 0; step < static_cast<int>(expected.size()); ++step)
    EXPECT_EQ(derive_string(model("alternating-groups"), step), expected[static_cast<std::size_t>(step)])
        << "after " << step << " steps";
}

}  // namespace
}  // namespace sylva::test::examples
