// What the turtle takes from the view file and the other input files.
#pragma once

#include <vector>

#include "geometry/contour.h"
#include "geometry/function.h"
#include "geometry/predefined_mesh.h"
#include "geometry/surface.h"
#include "geometry/vec3.h"

namespace sylva::turtle {

// A tropism (LPFG manual 8.1.4): the heading bends toward `direction` by
// elasticity * |H x T| at each F. A torque twists the turtle around H instead.
struct Tropism {
  geometry::Vec3 direction{0, -1, 0};  // T:
  float angle = 0;         // A: the angle to T that segments try to reach (degrees)
  float intensity = 1;     // I:
  float elasticity = 0;    // E:
  float step = 0;          // S: what IncElasticity / DecElasticity add or subtract
  bool torque = false;     // torque: twists around H instead of bending H
};

struct TurtleSettings {
  float initial_width = 1;
  int initial_color = 1;
  int contour_sides = 8;
  // lpfg's fixed Up/Down/RollL/RollR directions (view file "corrected rotation").
  bool corrected_rotation = true;
  // The view file's "auto normals": polygon normals from the first two edges
  // rather than the turtle's up vector.
  bool auto_normals = false;
  std::vector<Tropism> tropisms;     // SetElasticity(id, ...) counts from 1
  Tropism simple_tropism;            // the view file's "stropism", set by Elasticity(v)
  const std::vector<geometry::BezierSurface>* surfaces = nullptr;  // Surface(id, ...) counts from 0
  const std::vector<geometry::Contour>* contours = nullptr;        // CurrentContour(id) counts from 1
  const std::vector<geometry::PredefinedMesh>* meshes = nullptr;  // Mesh(id, ...) counts from 0
};

}  // namespace sylva::turtle
