// Smooth vertex normals for triangles that come without them (generalized
// cylinders, meshes read without normals): each vertex gets the mean of the
// normals of the triangles around it, each weighted by the triangle's angle
// at the vertex, so that how a surface is cut into triangles does not tilt it.
#pragma once

#include <cstdint>

#include "geometry/scene.h"

namespace sylva::geometry {

// Sets scene.normals for the vertices [first_vertex, first_vertex + vertex_count)
// from the triangles in scene.indices [first_index, first_index + index_count).
void set_normals_from_faces(Scene& scene, std::uint32_t first_vertex, std::uint32_t vertex_count,
                            std::uint32_t first_index, std::uint32_t index_count);

}  // namespace sylva::geometry
