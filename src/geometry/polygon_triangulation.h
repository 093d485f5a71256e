// Triangulation of the turtle's polygons (SP ... EP), convex or concave, by
// ear clipping in the plane the polygon lies in.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/vec3.h"

namespace sylva::geometry {

// The polygon's normal by Newell's method (robust for concave and slightly
// non-planar polygons); its direction makes the vertex order counter-clockwise.
// Zero when the points are all on a line.
Vec3 newell_normal(const Vec3* points, std::size_t count);

// Appends to `triangles` (3 indices each, `base` added) the triangles of the
// simple polygon points[0..count). They wind like the polygon. Repeated
// consecutive points (a polygon closed on its first point) and collinear
// vertices make no triangle; a self-intersecting polygon is fanned. `work` is
// scratch space, kept by the caller so that no call allocates once it has grown.
// Returns the number of triangles.
std::size_t triangulate_polygon(const Vec3* points, std::size_t count, std::uint32_t base,
                                std::vector<std::uint32_t>& triangles, std::vector<std::uint32_t>& work);

}  // namespace sylva::geometry
