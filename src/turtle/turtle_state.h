// What the turtle carries from module to module and saves on its stack at SB:
// position, frame, drawing parameters, the coordinate system of MoveTo and
// LineTo, and the generalized-cylinder settings.
#pragma once

#include <cstdint>

#include "geometry/radius_profile.h"
#include "turtle/frame.h"

namespace sylva::turtle {

struct TurtleState {
  Vec3 position;
  Frame frame;
  float width = 1;
  int color = 1;
  // cpfg's turtle scale (@D, @Di, @Dd): multiplies a cpfg model's steps and
  // circle and sphere sizes.
  float scale = 1;
  // cpfg's @; @,: the back side's colour index (-1: as the front), given to
  // the triangles of surfaces, polygons and cylinders.
  int back_color = -1;
  // The heading and up of the last step (F f G g ...), which cpfg's @Tp
  // carries to the current heading without twist.
  Vec3 step_heading{0, 1, 0}, step_up{0, 0, 1};

  // SetCoordinateSystem: MoveTo, LineTo ... points are origin + x*px + y*py + z*pz.
  Vec3 origin{0, 0, 0};
  Vec3 axis_x{1, 0, 0}, axis_y{0, 1, 0}, axis_z{0, 0, 1};

  // Generalized cylinders: the contour (blended toward a second one), its
  // scale, the sides of the next cylinder (0: the contour's or the view
  // file's) and the cylinder this branch is adding control points to.
  int contour = 0, blend_contour = 0;
  float blend = 0;
  float contour_scale_left = 1, contour_scale_up = 1;
  int contour_sides = 0;
  // cpfg's @Gt(start,end): the Hermite tangent coefficients of the next
  // stretch of a cylinder (CPFG manual 6.7.3).
  float cylinder_tangent_start = 1.2f, cylinder_tangent_end = 1.2f;
  // cpfg's @Gr: how the radius goes along the next stretches.
  geometry::RadiusTangents radius_tangents;
  int cylinder = -1;             // index of the open cylinder, -1: none
  std::uint32_t cylinder_serial = 0;  // tells a reused cylinder slot from the one this state knew

  // CurrentTexture (cpfg's @Tx) and TextureVCoeff: the texture (-1: none),
  // how much of it a unit of F covers along a cylinder, and the v reached so
  // far (lpfg's _textureV, kept with the branch's state).
  int texture = -1;
  float texture_v = 1;
  float texture_v_at = 0;
  int u_precision = 0, v_precision = 0;  // 0: the surface's own
};

}  // namespace sylva::turtle
