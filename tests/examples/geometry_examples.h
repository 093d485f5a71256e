// Helpers for the tests of the geometric examples (snowflake, ternary-tree,
// query-height, leaf, stem, colors): loading a model with its input files
// through the public API, and the numbers worked out by hand that more than
// one test file needs.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "geometry/scene.h"
#include "test_support.h"

namespace sylva::test::geometry_examples {

using geometry::Vec3;

constexpr double kPi = 3.14159265358979323846;
inline double radians(double degrees) { return degrees * kPi / 180.0; }

// examples/<name>/<file>
inline std::string example_file(const std::string& name, const std::string& file) {
  return example_path(name + "/" + file);
}
inline std::string model_of(const std::string& name) { return example_file(name, name + ".l"); }

// The model with its input files (paths under examples/<name>/), built into
// the tests' cache and derived `steps` steps (its derivation length if < 0).
inline std::unique_ptr<Simulation> load(const std::string& name, const std::vector<std::string>& inputs,
                                        int steps = -1) {
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  for (const std::string& input : inputs) options.input_files.push_back(example_file(name, input));
  auto simulation = std::make_unique<Simulation>(model_of(name), options, [](const std::string&) {});
  simulation->run(steps);
  return simulation;
}

// The input files each example is run with (examples/README.md).
inline std::vector<std::string> inputs_of(const std::string& name) {
  if (name == "snowflake") return {"snowflake.v"};
  if (name == "ternary-tree") return {"ternary-tree.v"};
  if (name == "leaf") return {"leaf.v"};
  if (name == "stem") return {"stem.v", "stem.con", "taper.func"};
  if (name == "colors") return {"colors.v", "colors.map"};
  return {};
}

inline ::testing::AssertionResult Near(Vec3 actual, Vec3 expected, float tolerance) {
  const Vec3 d = actual - expected;
  if (std::fabs(d.x) <= tolerance && std::fabs(d.y) <= tolerance && std::fabs(d.z) <= tolerance)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") is not within "
                                       << tolerance << " of (" << expected.x << ", " << expected.y << ", "
                                       << expected.z << ")";
}

// ---- the snowflake, a second way -------------------------------------------------
// String rewriting of F -> F+F--F+F on the axiom F--F--F (+ a 60 degree turn
// to the left, - to the right), then a walk in the plane with angles in
// double precision from heading 90 degrees (up the screen) at the origin.
struct Segment2 {
  double x0, y0, x1, y1;
};

inline std::vector<Segment2> koch_snowflake(int steps) {
  std::string s = "F--F--F";
  for (int k = 0; k < steps; ++k) {
    std::string next;
    for (char c : s) next += c == 'F' ? std::string("F+F--F+F") : std::string(1, c);
    s = next;
  }
  const double side = std::pow(3.0, -steps);
  std::vector<Segment2> out;
  double x = 0, y = 0, angle = 90;
  for (char c : s) {
    if (c == '+') angle += 60;
    if (c == '-') angle -= 60;
    if (c == 'F') {
      const double nx = x + side * std::cos(radians(angle)), ny = y + side * std::sin(radians(angle));
      out.push_back({x, y, nx, ny});
      x = nx, y = ny;
    }
  }
  return out;
}

// ---- the query-height model, by hand ---------------------------------------------
// HEIGHT 4.5. The main apex grows a unit internode while the GetPos before it
// is below 4.5: at heights 0,1,2,3,4, so 5 internodes and its tip at 5. Each
// of those steps leaves a lateral apex at the new top, at heights b = 1..5; a
// branch climbs sin 45 per internode and grows while b + m sin 45 < 4.5:
//   b = 1: m < 4.95 -> 5 internodes, tip at 1 + 5 sin 45 = 4.5355
//   b = 2: m < 3.54 -> 4,               2 + 4 sin 45 = 4.8284
//   b = 3: m < 2.12 -> 3,               3 + 3 sin 45 = 5.1213
//   b = 4: m < 0.71 -> 1,               4 + 1 sin 45 = 4.7071
//   b = 5: 5 >= 4.5 -> 0,               5
// All growth ends at step 6, before the derivation length of 10.
inline constexpr int kQueryMainInternodes = 5;
inline const std::vector<int> kQueryBranchInternodes = {5, 4, 3, 1, 0};  // for b = 1..5
inline constexpr int kQueryInternodes = 5 + 5 + 4 + 3 + 1 + 0;           // 18

// ---- the leaf, by hand -------------------------------------------------------------
// leaf.l: petiole 1.2, internode 1.1, 3 pairs of leaflets 1.5 long at +-60
// degrees, terminal leaflet 1.9; leaf.s is a unit-long surface of size 1
// with its contact point at its base, in the view file at scale 1.
inline constexpr double kPetiole = 1.2, kInternode = 1.1, kLeaflet = 1.5, kTerminal = 1.9, kLeafletAngle = 60;
inline constexpr int kPairs = 3;
// Each surface: 2 patches tessellated 8 x 8 (leaf.v), 81 vertices and 128
// triangles each.
inline constexpr int kSurfaceTriangles = 2 * 8 * 8 * 2;

// ---- the stem, by hand ----------------------------------------------------------------
// stem.l: 12 segments of 1 (LENGTH 12), base width 1.5, 2.5 degrees of bend
// after each ring; stem.con asks for 32 samples. 13 rings.
inline constexpr int kStemSegments = 12, kStemSides = 32, kStemRings = kStemSegments + 1;
inline constexpr double kStemWidth = 1.5, kStemBend = 2.5, kStemSegmentLength = 1.0;

}  // namespace sylva::test::geometry_examples
