// What the turtle takes from the view file and the other input files.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/contour.h"
#include "geometry/function.h"
#include "geometry/predefined_mesh.h"
#include "geometry/surface.h"
#include "geometry/vec3.h"

namespace sylva::turtle {

class CpfgSymbols;

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
  // The cpfg id of each surface (`surface: l leaf.s 1`), drawn by ~l; empty
  // for surfaces given as lpfg gives them.
  std::vector<std::string> surface_ids;
  const std::vector<geometry::Contour>* contours = nullptr;        // CurrentContour(id) counts from 1
  const std::vector<geometry::PredefinedMesh>* meshes = nullptr;  // Mesh(id, ...) counts from 0

  // cpfg's view-file turtle commands (CPFG manual 8.1.1) with the manual's
  // defaults: what a cpfg model's symbols without parameters use (+ turns by
  // angle_increment, ! and # change the width by width_increment, ; and , the
  // colour by color_increment, @Di and @Dd the scale by scale_multiplier).
  float angle_increment = 45;
  float width_increment = 0;
  int color_increment = 1;
  // A cpfg model's first colour when the view file gives no initial color
  // (an L+C model's is initial_color).
  int cpfg_initial_color = 128;
  // The back side's (@; @,): the second values of initial color and color
  // increment; -1: the back side is coloured as the front until @; or @,.
  int cpfg_initial_back_color = -1;
  int back_color_increment = 1;
  float initial_scale = 1;
  float scale_multiplier = 1;
  // A cpfg model's symbol table, built once per model (Simulation does);
  // when null, the interpreter of a cpfg model builds its own.
  std::shared_ptr<const CpfgSymbols> cpfg_symbols;
};

}  // namespace sylva::turtle
