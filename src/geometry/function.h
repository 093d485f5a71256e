// Graphically defined functions (.func, .fset files, VLAB Tools manual):
// a curve y(x) on [0,1] given by control points, evaluated by func(id, x).
#pragma once

#include <string>
#include <vector>

#include "geometry/vec3.h"

namespace sylva::geometry {

struct Function {
  std::string name;
  std::vector<Vec2> points;  // control points, x increasing
  int samples = 0;           // from the file; 0: default
  // y at x (x clamped to the domain), as the function editor defines it.
  float operator()(float x) const;
};

}  // namespace sylva::geometry
