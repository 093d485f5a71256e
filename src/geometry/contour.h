// Contours (cross-sections) of generalized cylinders, as the contour editor
// writes them (.con, .cset files, VLAB Tools manual).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/vec3.h"

namespace sylva::geometry {

struct Contour {
  // How the points define the curve: control points of a uniform cubic
  // B-spline (the contour editor; a point of multiplicity m is repeated m
  // times), the vertices of a polygon, or an exact unit circle (points unused).
  enum class Curve : std::uint8_t { BSpline, Polygon, Circle };

  std::string name;
  std::vector<Vec3> points;  // in the contour's plane (x: left, y: up), as given
  // How many consecutive entries of `points` each control point of the file
  // is (its multiplicity); empty when every point is one entry.
  std::vector<int> multiplicities;
  bool closed = true;
  Curve curve = Curve::BSpline;
  int samples = 0;  // the file's "samples:": sides of a generalized cylinder; 0: not given
  // `sides` points spaced evenly (by arc length) along the curve, starting
  // where the curve starts; an open contour's ends are the first and last.
  std::vector<Vec3> resample(int sides) const;
  // The point at parameter t in [0,1] spread evenly over the curve's
  // segments (not by arc length), as cpfg's curves evaluate it.
  Vec3 at_parameter(double t) const;
  // The default contour: a unit circle.
  static Contour circle();
};

}  // namespace sylva::geometry
