// Big scenes travel to the page as instances: a plant of a million modules
// has hundreds of thousands of spheres and cylinders, which tessellated are
// half a gigabyte of triangles, and as instances of one unit sphere and one
// unit cylinder are a few tens of megabytes the GPU draws in one call per
// colour. Small scenes stay triangles (scene_glb), exactly as drawn.
//
// The instances' binary form, all little-endian 32-bit values so the page
// reads them as typed arrays without copying:
//   "SYLI" u32 version (1) u32 group_count
//   per group:
//     u32 shape (0 sphere, 1 cylinder)  u32 count  u32 slices (sides round)
//     f32 diffuse r g b (sRGB)  f32 alpha
//     sphere:   count × f32 {x, y, z, radius}
//     cylinder: count × f32 {x0, y0, z0, x1, y1, z1, r0, r1} (a cone frustum)
//     count × u32 module index (in the interpreted string), count × u32 module id
#pragma once

#include <cstddef>
#include <string>

#include "geometry/material.h"
#include "geometry/scene.h"
#include "geometry/tessellation.h"

namespace sylva::studio {

// Moves the spheres, and the lines when drawn as cylinders, out of `scene`
// into instances, when there are more than `threshold` of them; returns
// their binary form ("" when the scene is left whole).
std::string take_instances(geometry::Scene& scene, const geometry::Palette& palette,
                           const geometry::TessellationOptions& tessellation, std::size_t threshold = 20000);

}  // namespace sylva::studio
