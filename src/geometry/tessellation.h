// The whole Scene as triangles (and, for the pixel line style, lines): what
// mesh files and the raster renderer draw. Segments become cylinders
// (line style cylinder) or flat strips facing the turtle's up vector
// (polygon); circles become discs, spheres UV spheres.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/scene.h"

namespace sylva::geometry {

enum class LineStyle { Pixel, Polygon, Cylinder };

struct TessellationOptions {
  LineStyle line_style = LineStyle::Cylinder;
  int contour_sides = 8;  // sphere slices (stacks: half as many), and the two below when 0
  int line_sides = 0;     // sides of a cylinder line
  int circle_sides = 0;   // sides of a circle
};

// What lpfg's OBJ export makes of the Scene (lpfg/objturtle.cpp): every line
// a cylinder as wide as the turtle's width whatever the view's line style,
// with 16 sides (twice lpfg's default contour divisions, not the view's
// contour sides), circles with 16 sides, spheres with `contour_sides` slices.
TessellationOptions lpfg_export_options(int contour_sides);

// A run of triangles (or of line vertex pairs) made by one primitive.
struct MeshPart {
  enum class Kind : std::uint8_t { Segment, Circle, Sphere, Polygon, Rhombus, Triangle, Surface, GeneralizedCylinder, Mesh };
  Kind kind = Kind::Segment;
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
  int color = 1;
  Provenance from;
  int back_color = -1;  // the TriangleGroup's; -1: both sides in `color`
  int texture = -1;     // the primitive's texture; -1: none
  // Which side of the triangles a part shows: both, or, once
  // split_back_sides has given the back its own part, one.
  enum class Side : std::uint8_t { Both, Front, Back };
  Side side = Side::Both;
};

struct TriangleMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  // Texture coordinates per vertex when some part is textured (else empty).
  std::vector<TexCoord> texcoords;
  std::vector<std::uint32_t> indices;  // triangles, 3 per
  std::vector<MeshPart> parts;          // runs of `indices`
  // Pixel-style segments: pairs of indices into positions.
  std::vector<std::uint32_t> line_indices;
  std::vector<MeshPart> line_parts;     // runs of `line_indices`
};

TriangleMesh tessellate(const Scene& scene, const TessellationOptions& options);

const char* kind_name(MeshPart::Kind kind);

}  // namespace sylva::geometry
