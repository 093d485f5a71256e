// What the turtle takes from the view file and the other input files.
#pragma once

#include <vector>

#include "geometry/contour.h"
#include "geometry/function.h"
#include "geometry/surface.h"
#include "geometry/vec3.h"

namespace sylva::turtle {

// A tropism (LPFG manual 8.1.4): the heading bends toward `direction` by
// elasticity * |H x T| at each F. A torque twists the turtle around H instead.
struct Tropism {
  geometry::Vec3 direction{0, -1, 0};
  float elasticity = 0;
  float step = 0;          // what IncElasticity / DecElasticity add or subtract
  bool torque = false;
};

struct TurtleSettings {
  float initial_width = 1;
  int initial_color = 1;
  int contour_sides = 8;
  // lpfg's fixed Up/Down/RollL/RollR directions (view file "corrected rotation").
  bool corrected_rotation = true;
  std::vector<Tropism> tropisms;     // SetElasticity(id, ...) counts from 1
  Tropism simple_tropism;            // the view file's "stropism", set by Elasticity(v)
  const std::vector<geometry::BezierSurface>* surfaces = nullptr;  // Surface(id, ...) counts from 0
  const std::vector<geometry::Contour>* contours = nullptr;        // CurrentContour(id) counts from 1
};

}  // namespace sylva::turtle
