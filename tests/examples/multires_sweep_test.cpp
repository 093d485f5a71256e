// Tests of examples/multires-sweep: multiresolution editing of the sweep of a
// branching structure, a leaf outline and a curve (Figures 8-10 of "L-system
// Implementation of Multiresolution Curves Based on Cubic B-Spline
// Subdivision", Poon, Bateman, Karwowski, Prusinkiewicz, Samavati; SIGGRAPH
// 2003 course notes "L-systems and Beyond").
//
// Every curve of the string (found by its E markers and its nesting depth) is
// checked against a second computation: the open-curve filters A, B, P, Q of
// Appendices A and B built here as matrices, the analysis of each curve's
// original points, and the sweep's modification (the bend) written again.
// Without an edit the curves come back (1e-9); with one, each level's
// restored detail (the fine point minus the subdivided coarse points) is the
// stored x-y vector unchanged (NORMALS=0), or has the stored signed distances
// along the normal and the tangent of the edited coarse polygon (NORMALS=1).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "examples/multires_filters.h"
#include "examples/plane_points.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

const std::string kModel = example_path("multires-sweep/multires-sweep.l");
constexpr int kLevels = 3;  // the model's default LEVELS

double dot(Pt a, Pt b) { return a.x * b.x + a.y * b.y; }

// The curves of a string: an E opens a curve at its bracket depth, the next E
// at that depth closes it; the C's at a curve's depth between them are its
// points (deeper ones are details' or a lateral's). In the order they open.
using Curve = std::vector<Pt>;
std::vector<Curve> curves(const std::vector<Module>& s) {
  std::vector<Curve> out;
  std::map<int, std::size_t> open;  // depth -> index in out
  int depth = 0;
  for (const Module& m : s) {
    if (m.name == "SB") ++depth;
    if (m.name == "EB") --depth;
    if (m.name == "E") {
      auto it = open.find(depth);
      if (it != open.end()) {
        open.erase(it);
      } else {
        open[depth] = out.size();
        out.emplace_back();
      }
    }
    if (m.name == "C") {
      auto it = open.find(depth);
      EXPECT_NE(it, open.end()) << "a point outside its curve";
      if (it != open.end()) out[it->second].push_back(read_pt(m.params.at(0)));
    }
  }
  EXPECT_TRUE(open.empty());
  return out;
}

int coarse_count(std::size_t fine) { return static_cast<int>(fine + 3) / 2; }

// One level of analysis of a curve: coarse points and x-y details.
struct Level {
  Curve coarse, details;
};
Level analyse(const Curve& fine) {
  const Filters f = open_filters(coarse_count(fine.size()));
  return {multiply(f.a, fine), multiply(f.b, fine)};
}

// The frame of detail j (0-based k = j - 1): c_j to c_{j+1}.
Pt unit_tangent(const Curve& c, std::size_t k) {
  const Pt t = c[k + 2] - c[k + 1];
  const double len = norm(t);
  return len == 0 ? Pt{1, 0} : (1 / len) * t;
}
Pt turned(Pt t) { return {-t.y, t.x}; }

// The sweep's modification, written again: the shape's axis bent into an arc
// of the same length turning by `degrees`, offsets from it times `widen`.
struct Axis {
  Pt o, u, w;
  double length;
};
Axis axis_of(const std::string& shape) {
  if (shape == "CURVE") return {{-8, 0}, {1, 0}, {0, 1}, 16};
  return {{0, 0}, {0, 1}, {-1, 0}, shape == "LEAF" ? 10.0 : 16.0};
}
Pt bend(const Axis& a, Pt p, double degrees, double widen) {
  const Pt q = p - a.o;
  const double s = dot(q, a.u), t = widen * dot(q, a.w), k = degrees * M_PI / 180 / a.length;
  const Pt arc = a.o + (std::sin(k * s) / k) * a.u + ((1 - std::cos(k * s)) / k) * a.w;
  const Pt normal = (-std::sin(k * s)) * a.u + std::cos(k * s) * a.w;
  return arc + t * normal;
}
Pt modified(const std::string& shape, int sweep, Pt p) {
  const double degrees = shape == "CURVE" ? 180 : -60;
  return sweep == 1 ? bend(axis_of(shape), p, degrees, 1) : bend(axis_of(shape), p, -degrees / 2, 1.6);
}

double max_distance(const Curve& a, const Curve& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, norm(a[i] - b[i]));
  return worst;
}

const std::vector<std::string> kShapes = {"CURVE", "BRANCHING", "LEAF"};
std::size_t expected_curves(const std::string& shape) { return shape == "BRANCHING" ? 6u : 1u; }

// Analysis level by level (point counts, coarse points equal to A f), then
// synthesis without an edit: every curve back, the string as it was.
TEST(MultiresSweep, RoundTripWithoutEditAndPointsPerLevel) {
  for (const std::string& shape : kShapes)
    for (int normals : {0, 1}) {
      SCOPED_TRACE(shape + " NORMALS=" + std::to_string(normals));
      Stepper run(kModel, {"SHAPE=" + shape, "NORMALS=" + std::to_string(normals)});
      const std::vector<Module> start = run.modules();
      const std::vector<Curve> original = curves(start);
      ASSERT_EQ(original.size(), expected_curves(shape));
      for (std::size_t k = 0; k < original.size(); ++k) EXPECT_EQ(original[k].size(), k == 0 ? 99u : 51u);
      std::vector<Curve> fine = original;
      for (int level = 1; level <= kLevels; ++level) {
        run.step(2);
        const std::vector<Curve> got = curves(run.modules());
        ASSERT_EQ(got.size(), original.size());
        for (std::size_t k = 0; k < got.size(); ++k) {
          EXPECT_EQ(got[k].size(), ((original[k].size() - 3) >> level) + 3) << "curve " << k << ", level " << level;
          EXPECT_LT(max_distance(got[k], analyse(fine[k]).coarse), 1e-12) << "curve " << k << ", level " << level;
        }
        fine = got;
      }
      for (int level = kLevels - 1; level >= 0; --level) {
        run.step(2);
        const std::vector<Curve> got = curves(run.modules());
        for (std::size_t k = 0; k < got.size(); ++k)
          EXPECT_EQ(got[k].size(), ((original[k].size() - 3) >> level) + 3) << "curve " << k << ", level " << level;
      }
      const std::vector<Module> end = run.modules();
      EXPECT_EQ(names(end), names(start));  // the laterals after their points again
      const std::vector<Curve> back = curves(end);
      ASSERT_EQ(back.size(), original.size());
      for (std::size_t k = 0; k < back.size(); ++k) EXPECT_LT(max_distance(back[k], original[k]), 1e-9) << "curve " << k;
    }
}

// With a modified sweep: the coarse points are the bent ones, and at every
// level of synthesis the detail restored at f_{2j} (the fine point minus the
// subdivided coarse points) keeps its x-y vector (NORMALS=0) or its signed
// distances along the new normal and tangent (NORMALS=1); the other fine
// points are P c + Q of those details.
TEST(MultiresSweep, ModifiedSweepKeepsTheDetails) {
  for (const std::string& shape : kShapes)
    for (int sweep : {1, 2})
      for (int normals : {0, 1}) {
        SCOPED_TRACE(shape + " SWEEP=" + std::to_string(sweep) + " NORMALS=" + std::to_string(normals));
        Stepper run(kModel, {"SHAPE=" + shape, "SWEEP=" + std::to_string(sweep), "NORMALS=" + std::to_string(normals)});
        const std::vector<Curve> original = curves(run.modules());
        // levels[k][l]: curve k's analysis from level l to l + 1
        std::vector<std::vector<Level>> levels(original.size());
        for (std::size_t k = 0; k < original.size(); ++k) {
          Curve fine = original[k];
          for (int l = 0; l < kLevels; ++l) levels[k].push_back(analyse(fine)), fine = levels[k].back().coarse;
        }
        run.step(2 * kLevels + 1);  // analysis, then the edit (and the outer brackets)
        std::vector<Curve> coarse = curves(run.modules());
        ASSERT_EQ(coarse.size(), original.size());
        for (std::size_t k = 0; k < coarse.size(); ++k) {
          Curve want;
          for (Pt p : levels[k][kLevels - 1].coarse) want.push_back(modified(shape, sweep, p));
          EXPECT_LT(max_distance(coarse[k], want), 1e-12) << "edited coarse points of curve " << k;
        }
        double turned_details = 0;  // how far NORMALS=1 turned them (not a vacuous check)
        for (int l = kLevels - 1; l >= 0; --l) {
          if (l < kLevels - 1) {
            run.step();  // SYNTHESIS_0
            coarse = curves(run.modules());
          }
          run.step();  // SYNTHESIS_1
          const std::vector<Curve> fine = curves(run.modules());
          ASSERT_EQ(fine.size(), coarse.size());
          for (std::size_t k = 0; k < fine.size(); ++k) {
            const Level& stored = levels[k][static_cast<std::size_t>(l)];
            const Filters f = open_filters(static_cast<int>(coarse[k].size()));
            ASSERT_EQ(fine[k].size(), f.p.size()) << "curve " << k << ", level " << l;
            const Curve subdivided = multiply(f.p, coarse[k]);
            Curve restored;
            for (std::size_t j = 0; j < stored.details.size(); ++j) {
              const std::size_t row = 2 * (j + 1);
              const Pt r = fine[k][row] - subdivided[row], d = stored.details[j];
              if (normals == 0) {
                EXPECT_LT(norm(r - d), 1e-9) << "curve " << k << ", level " << l << ", detail " << j;
              } else {
                const Pt t0 = unit_tangent(stored.coarse, j), t1 = unit_tangent(coarse[k], j);
                EXPECT_NEAR(dot(r, turned(t1)), dot(d, turned(t0)), 1e-9)
                    << "normal distance: curve " << k << ", level " << l << ", detail " << j;
                EXPECT_NEAR(dot(r, t1), dot(d, t0), 1e-9)
                    << "tangential distance: curve " << k << ", level " << l << ", detail " << j;
                turned_details = std::max(turned_details, norm(r - d));
              }
              restored.push_back(r);
            }
            const Curve qd = multiply(f.q, restored);
            Curve want;
            for (std::size_t i = 0; i < subdivided.size(); ++i) want.push_back(subdivided[i] + qd[i]);
            EXPECT_LT(max_distance(fine[k], want), 1e-9) << "curve " << k << ", level " << l;
          }
          coarse = fine;
        }
        if (normals == 1) {
          EXPECT_GT(turned_details, 0.05);
        }
        EXPECT_EQ(run.steps_done(), 4 * kLevels);
      }
}

// The two reconstructions differ, and the aligned one keeps the waves'
// amplitude across the bend: at the half circle's sides x-y details would lie
// along the curve.
TEST(MultiresSweep, AlignedAndNotAlignedDiffer) {
  auto final_curve = [](int normals) {
    return curves(parse_modules(derive_with(kModel, 4 * kLevels, {"SHAPE=CURVE", "SWEEP=1", "NORMALS=" + std::to_string(normals)})))
        .at(0);
  };
  EXPECT_GT(max_distance(final_curve(0), final_curve(1)), 0.1);
}

}  // namespace
}  // namespace sylva::test::examples
