// A curve of cpfg's curve functions (curveX, curveY, curveZ, curveGAL; CPFG
// manual 5.6), evaluated as cpfg evaluates it: the curve's points at
// `samples` evenly spaced parameters make a table of arc lengths; a
// function's t (a fraction of the length) is found in that table, the
// parameter interpolated linearly there, and the curve itself evaluated at
// that parameter. The length is the table's polyline, not the exact arc.
#pragma once

#include <vector>

#include "geometry/contour.h"

namespace sylva::geometry {

class CpfgCurve {
 public:
  // cpfg's view file gives `samples` ("curve: file n"; 100 without n).
  CpfgCurve(const Contour& curve, int samples);

  // The point at t in [0,1] of the length (t is clamped, as cpfg clamps it).
  Vec3 at(double t) const;
  double length() const { return length_; }

 private:
  const Contour& curve_;
  std::vector<double> arc_;  // normalized arc length at each sample
  double length_ = 0;
};

}  // namespace sylva::geometry
