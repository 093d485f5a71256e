// Bézier surfaces as the surface editor writes them (.s files, VLAB Tools
// manual): bicubic patches of 16 control points each.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geometry/vec3.h"

namespace sylva::geometry {

struct BezierPatch {
  std::string name;
  std::array<Vec3, 16> points;  // row-major: points[4 * row + column]
};

struct BezierSurface {
  std::string name;         // from the file
  std::vector<BezierPatch> patches;
  // The surface's own frame: the turtle places `contact` at its position and
  // aligns `heading`/`up` with its own H and U (VLAB Tools manual, .s format).
  Vec3 contact{0, 0, 0};
  Vec3 heading{0, 1, 0};
  Vec3 up{0, 0, 1};
  float size = 1;           // the surface is scaled by scale / size
  int u_divisions = 8;      // tessellation precision from the view file
  int v_divisions = 8;
  int texture = -1;         // the view file's texture for it (-1: none)
};

// Point on a bicubic patch at (u, v) in [0,1]^2, and its normal.
Vec3 evaluate_patch(const BezierPatch& patch, float u, float v);
Vec3 patch_normal(const BezierPatch& patch, float u, float v);

}  // namespace sylva::geometry
