// The Scene: what the turtle makes of a string, and what every output reads.
//
// Lines, circles and spheres are kept as what they are (so vector drawings
// draw lines and circles, and a million spheres cost little until they are
// tessellated); everything else is triangles in one shared pool. Every
// primitive knows the module that made it: its index in the interpreted
// string and its module id.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec3.h"
#include "sylva/abi.h"

namespace sylva::geometry {

struct Provenance {
  std::uint32_t module_index = 0;  // position of the module in the string (0-based)
  abi::ModuleId module_id = 0;
};

// A line drawn by the turtle (F, G, LineTo, ...). How it looks depends on the
// view file's line style: pixel lines, flat polygons or cylinders.
struct Segment {
  Vec3 start, end;
  Vec3 up;  // the turtle's up vector at the start: orients polygons and cylinder seams
  float start_width = 1, end_width = 1;
  int color = 1;
  Provenance from;
  // The texture (an index into the view file's textures; -1: none) and the
  // texture's v at both ends, u going round a cylinder from its seam.
  int texture = -1;
  float texture_v0 = 0, texture_v1 = 1;
};

// A texture coordinate: u across the image, v up it (0 at its bottom row,
// as OpenGL takes it).
struct TexCoord {
  float u = 0, v = 0;
  constexpr bool operator==(const TexCoord&) const = default;
};

// A filled circle (disc) or a circle outline of width `outline` (CircleB).
struct Circle {
  Vec3 center;
  Vec3 normal;  // of the HL plane it lies in; ignored when facing_viewer
  float radius = 1;
  float outline = 0;  // 0: filled disc
  bool facing_viewer = false;  // CircleFront*: always in the screen plane
  int color = 1;
  Provenance from;
  // The turtle's heading: a tessellated circle starts at the turtle's right
  // (heading x normal) and turns toward the heading, as lpfg's OBJ export does.
  Vec3 heading{0, 1, 0};
};

struct Sphere {
  Vec3 center;
  float radius = 1;
  int color = 1;
  Provenance from;
  int slices = 0;  // the turtle's ContourSides (lpfg: also a sphere's slices); 0: the view's contour sides
};

struct Label {
  Vec3 position;
  std::string text;
  int color = 1;
  Provenance from;
};

// The view the Camera module asks for (LPFG manual 5.14): the camera at the
// turtle's position, looking along its heading, with the turtle's up.
struct CameraPose {
  Vec3 position;
  Vec3 heading{0, 1, 0};
  Vec3 up{0, 0, 1};
  Provenance from;
};

// A run of triangles in the Scene's pool: a polygon, a rhombus, a surface, a
// generalized cylinder ...
struct TriangleGroup {
  enum class Kind : std::uint8_t { Polygon, Rhombus, Triangle, Surface, GeneralizedCylinder, Mesh };
  Kind kind = Kind::Polygon;
  std::uint32_t first_index = 0;  // into Scene::indices
  std::uint32_t index_count = 0;  // a multiple of 3
  int color = 1;
  Provenance from;
  // cpfg's @; @, (CPFG manual 6.3): the colour of the side the triangles'
  // normals point away from; -1: that side is coloured as the front.
  int back_color = -1;
  // The texture mapped on the triangles (an index into the view file's
  // textures, with Scene::texcoords); -1: none.
  int texture = -1;
};

struct Scene {
  std::vector<Segment> segments;
  std::vector<Circle> circles;
  std::vector<Sphere> spheres;
  std::vector<Label> labels;

  // The triangle pool: per-vertex positions and normals, and triangle indices.
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<std::uint32_t> indices;
  std::vector<TriangleGroup> groups;
  // Texture coordinates of the pool's vertices, where a textured group gave
  // them: shorter than `positions` when the last vertices have none ((0, 0)).
  std::vector<TexCoord> texcoords;
  TexCoord texcoord(std::uint32_t vertex) const { return vertex < texcoords.size() ? texcoords[vertex] : TexCoord{}; }
  void set_texcoord(std::uint32_t vertex, TexCoord t) {
    if (texcoords.size() <= vertex) texcoords.resize(vertex + 1);
    texcoords[vertex] = t;
  }

  // Set by the last Camera module in the string.
  std::optional<CameraPose> camera;

  // Adds triangles (vertex indices relative to `vertices`) as one group.
  void add_triangles(TriangleGroup::Kind kind, const std::vector<Vec3>& vertices, const std::vector<Vec3>& vertex_normals,
                     const std::vector<std::uint32_t>& triangle_indices, int color, Provenance from);

  // Appends `other`'s primitives after this Scene's own (its triangle pool
  // indices moved past this one's).
  void append(const Scene& other);

  bool empty() const {
    return segments.empty() && circles.empty() && spheres.empty() && labels.empty() && groups.empty();
  }
  // Everything drawn, widths and radii included.
  Box bounds() const;
};

}  // namespace sylva::geometry
