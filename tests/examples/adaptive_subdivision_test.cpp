// examples/adaptive-subdivision: L-system 5 of "Generating subdivision curves
// with L-systems on a GPU" (adaptive Chaikin subdivision of an open curve),
// its -D KEEP_FLAT variant and L-system 3 (-D LSYSTEM3), against the same
// subdivision written here in plain C++ over an array of points: every point
// and type equal to 1e-12 after each of 5 steps.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "lstring/module_string.h"
#include "test_support.h"

namespace sylva::test {
namespace {

const std::string kModel = "adaptive-subdivision/adaptive-subdivision.l";

struct Point {
  bool end = false;  // E rather than P
  double x = 0, y = 0;
  int type = 1;      // P's t
};

Point lerp(const Point& a, double wa, const Point& b, double wb, int type) {
  return Point{false, wa * a.x + wb * b.x, wa * a.y + wb * b.y, type};
}

// One step of the paper's productions, tried in order for each point; the
// end points are copied. `keep_flat`: a point of type 0 between two of type
// 0 stays (the example's -D KEEP_FLAT). `chaikin`: L-system 3.
std::vector<Point> subdivide(const std::vector<Point>& in, double threshold, bool keep_flat, bool chaikin) {
  std::vector<Point> out;
  const std::size_t n = in.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& v = in[i];
    if (v.end) {
      out.push_back(v);
      continue;
    }
    const Point* l = i > 0 ? &in[i - 1] : nullptr;
    const Point* r = i + 1 < n ? &in[i + 1] : nullptr;
    const bool pl = l && !l->end, pr = r && !r->end;  // P neighbours
    const bool el = l && l->end, er = r && r->end;    // E neighbours
    if (chaikin) {
      if (el && pr) {
        out.push_back(lerp(*l, 0.5, v, 0.5, 1));
        out.push_back(lerp(v, 0.75, *r, 0.25, 1));
      } else if (pl && er) {
        out.push_back(lerp(*l, 0.25, v, 0.75, 1));
        out.push_back(lerp(v, 0.5, *r, 0.5, 1));
      } else if (pl && pr) {
        out.push_back(lerp(*l, 0.25, v, 0.75, 1));
        out.push_back(lerp(v, 0.75, *r, 0.25, 1));
      } else {
        out.push_back(v);
      }
      continue;
    }
    if (pl && v.type == 0 && l->type == 1) {  // p1
      out.push_back(lerp(*l, 0.25, v, 0.75, 0));
      continue;
    }
    if (pr && r->type == 1 && v.type == 0) {  // p2
      out.push_back(lerp(v, 0.75, *r, 0.25, 0));
      continue;
    }
    if (keep_flat && pl && pr && v.type == 0 && l->type == 0 && r->type == 0) {
      out.push_back(v);
      continue;
    }
    if (pl && pr) {  // p3
      const double dx = v.x - (l->x + r->x) / 2, dy = v.y - (l->y + r->y) / 2;
      if (std::sqrt(dx * dx + dy * dy) < threshold) {
        out.push_back(lerp(*l, 0.25, v, 0.75, 0));
        out.push_back(lerp(v, 0.75, *r, 0.25, 0));
        continue;
      }
    }
    if (el && pr) {  // p4
      out.push_back(lerp(*l, 0.5, v, 0.5, v.type));
      out.push_back(lerp(v, 0.75, *r, 0.25, v.type));
    } else if (pl && er) {  // p5
      out.push_back(lerp(*l, 0.25, v, 0.75, v.type));
      out.push_back(lerp(v, 0.5, *r, 0.5, v.type));
    } else if (pl && pr) {  // p6
      out.push_back(lerp(*l, 0.25, v, 0.75, 1));
      out.push_back(lerp(v, 0.75, *r, 0.25, 1));
    } else {
      out.push_back(v);
    }
  }
  return out;
}

// The example's control polygon.
std::vector<Point> control_polygon() {
  const double xy[][2] = {{1, 0}, {2, 0}, {3, 0.07}, {4, 0.3}, {5, 1.2}, {5.2, 2.6}, {4, 3}, {4.6, 1.6}};
  std::vector<Point> points = {Point{true, 0, 0, 1}};
  for (const auto& p : xy) points.push_back(Point{false, p[0], p[1], 1});
  points.push_back(Point{true, 6, 2, 1});
  return points;
}

std::vector<Point> engine_points(const Simulation& simulation, bool chaikin) {
  std::vector<Point> out;
  const ModuleString& s = simulation.string();
  const ModuleTypes& types = simulation.types();
  for (std::size_t at = 0; at < s.size_bytes(); at += types.encoded_size(module_id_at(s.data(), at))) {
    const ModuleId id = module_id_at(s.data(), at);
    const auto numbers = types.numbers(id, module_params(s.data(), at));
    Point p{types.name(id) == "E", numbers.at(0), numbers.at(1), 1};
    if (!p.end && !chaikin) p.type = static_cast<int>(numbers.at(2));
    out.push_back(p);
  }
  return out;
}

struct Variant {
  std::vector<std::string> defines;
  double threshold;
  bool keep_flat, chaikin;
  std::size_t points_after_5;  // modules, E included
};

class AdaptiveSubdivision : public ::testing::TestWithParam<Variant> {};

TEST_P(AdaptiveSubdivision, EqualsTheSubdivisionInCpp) {
  const Variant& v = GetParam();
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.defines = v.defines;
  Simulation simulation(example_path(kModel), options);
  std::vector<Point> want = control_polygon();
  for (int step = 1; step <= 5; ++step) {
    SCOPED_TRACE(testing::Message() << step << " steps");
    want = subdivide(want, v.threshold, v.keep_flat, v.chaikin);
    simulation.rewind();
    simulation.run(step);
    const auto got = engine_points(simulation, v.chaikin);
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].end, want[i].end) << "module " << i;
      EXPECT_NEAR(got[i].x, want[i].x, 1e-12) << "module " << i;
      EXPECT_NEAR(got[i].y, want[i].y, 1e-12) << "module " << i;
      EXPECT_EQ(got[i].type, want[i].type) << "module " << i;
    }
  }
  EXPECT_EQ(want.size(), v.points_after_5);
  // The ends stay where they are.
  EXPECT_EQ(want.front().x, 0);
  EXPECT_EQ(want.back().x, 6);
}

INSTANTIATE_TEST_SUITE_P(
    Variants, AdaptiveSubdivision,
    // L-system 5: fewer points than Chaikin's 258, far fewer where flat runs are kept.
    ::testing::Values(Variant{{}, 0.05, false, false, 220}, Variant{{"THRESHOLD=0.025"}, 0.025, false, false, 240},
                      Variant{{"KEEP_FLAT"}, 0.05, true, false, 86},
                      // L-system 3: 8 points, twice as many each step, and the two ends.
                      Variant{{"LSYSTEM3"}, 0.05, false, true, 8 * 32 + 2}));

}  // namespace
}  // namespace sylva::test
