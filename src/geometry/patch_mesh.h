// Tessellation of a bicubic Bézier patch into the Scene's triangle pool.
#pragma once

#include "geometry/placement.h"
#include "geometry/scene.h"
#include "geometry/surface.h"

namespace sylva::geometry {

// Appends the patch sampled on a (u_divisions + 1) x (v_divisions + 1) grid,
// mapped by `place`: vertices, normals and 2 * u_divisions * v_divisions
// triangles facing the patch normal. Groups are the caller's. `textured`:
// each vertex also gets lpfg's texture coordinate (v, 1 - u) (the texture
// mapped once per patch, lpfg/patch.cpp).
void append_patch(Scene& scene, const BezierPatch& patch, const Placement& place, int u_divisions, int v_divisions,
                  bool textured = false);

}  // namespace sylva::geometry
