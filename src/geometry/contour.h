// Contours (cross-sections) of generalized cylinders, as the contour editor
// writes them (.con, .cset files, VLAB Tools manual).
#pragma once

#include <string>
#include <vector>

#include "geometry/vec3.h"

namespace sylva::geometry {

struct Contour {
  std::string name;
  std::vector<Vec3> points;  // in the contour's plane (x: left, y: up), as given
  bool closed = true;
  // `sides` points spaced evenly along the contour (a B-spline through the
  // control points when the file says so; the polygon otherwise).
  std::vector<Vec3> resample(int sides) const;
  // The default contour: a unit circle.
  static Contour circle();
};

}  // namespace sylva::geometry
