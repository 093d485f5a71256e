// Graphically defined functions (.func, .fset, .tset files, VLAB Tools
// manual): a curve y(x) on [0,1] given by the control points of a cubic
// B-spline, read by func(id, x).
//
// lpfg and cpfg evaluate the same files differently, and models depend on
// the last digits, so each program's way is reproduced:
//   - lpfg (LpfgFunction): in float. At `samples` evenly spaced x it finds
//     the spline parameter by bisection, stopping when x is within
//     0.01 / samples, keeps the y there (and the tangent), and interpolates
//     linearly between those values. So func(f, 0) is not quite the first
//     control point's y.
//   - cpfg (CpfgFunction): in double. The same bisection, stopping within
//     0.001 of x, and the y of the last point tried; with more than two
//     samples those values are tabulated and interpolated, otherwise every
//     call bisects.
// Both use the uniform cubic B-spline whose end knots are repeated four
// times, so the curve runs from the first control point to the last.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/vec3.h"

namespace sylva::geometry {

struct Function {
  std::string name;
  // Control points, x increasing; a point given with a multiplicity m
  // ("x y m") is here m times.
  std::vector<Vec2> points;
  // The number of tabulated values: the file's "samples:", or the view
  // file's for cpfg's files without one; 0: none.
  int samples = 0;
  // The interval tfunc maps onto [0,1] (a .tset function's start: and end:).
  float low = 0, up = 1;
  // A .vset parameter, which lpfg keeps in its list of functions: its value
  // (val(id)), and no curve.
  std::optional<float> constant;
};

// lpfg's evaluation of a function (see above).
class LpfgFunction {
 public:
  // lpfg keeps between 10 and 1000 samples; `samples` is clamped to them.
  static constexpr int kMinSamples = 10, kMaxSamples = 1000;
  explicit LpfgFunction(const Function& f);

  // y at v in [0,1] (v is clamped).
  float value(float v) const;
  // The curve's derivative (dx, dy) by its spline parameter at v in [0,1].
  Vec2 tangent(float v) const;

 private:
  std::vector<Vec2> points_;
  std::vector<float> values_;
  std::vector<Vec2> tangents_;
};

// cpfg's evaluation of a function (see above).
class CpfgFunction {
 public:
  explicit CpfgFunction(const Function& f);
  // y at v, v clamped to [0,1].
  double value(double v) const;

 private:
  double bisect(double v) const;

  std::vector<Vec2> points_;
  std::vector<double> values_;  // empty: every value is bisected
};

}  // namespace sylva::geometry
