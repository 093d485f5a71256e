// What the PNG renderer hands to OpenGL: the triangles of the tessellated
// Scene and its pixel-style lines, cut into as few glDrawElements /
// glDrawArrays calls as possible.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/material.h"
#include "geometry/scene.h"
#include "geometry/tessellation.h"

namespace sylva::io::gl {

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

Rgba8 to_rgba8(const geometry::Rgb& color, float transparency);

// One draw call.
struct Draw {
  enum class Kind : std::uint8_t { Triangles, Lines };
  Kind kind = Kind::Triangles;
  std::uint32_t mesh = 0;   // Triangles: which of meshes()
  std::uint32_t first = 0;  // Triangles: into the mesh's indices; Lines: into line_positions()
  std::uint32_t count = 0;  // indices or line vertices
  int material = -1;        // lit triangles: the colour index whose material to use
  int back_material = -1;   // lit triangles: the back side's (cpfg's @; @,); -1: as the front
  float width = 1;          // lines: in pixels
  int texture = -1;         // triangles: the texture mapped on them (-1: none)
};

struct BatchOptions {
  bool lit = false;  // triangles take materials (per draw) instead of vertex colours
  // The string's order decides what is seen (no z buffer): every vertex gets
  // its module's rank as a depth, which the renderer draws with.
  bool string_order = false;
  bool pixel_lines = false;  // segments are drawn as lines, straight from the Scene
  float line_scale = 1;      // pixels of the target per image pixel (supersampling)
};

// A tessellated mesh, ready to draw. Positions and normals are the mesh's own.
struct MeshBatch {
  const geometry::TriangleMesh* mesh = nullptr;
  std::vector<std::uint32_t> indices;  // the mesh's, perhaps regrouped by material
  std::vector<Rgba8> colors;           // per vertex, unlit only
  std::vector<float> depths;           // per vertex, string order only
};

class Batches {
 public:
  // Takes each mesh's index array; the meshes must outlive the Batches.
  Batches(const geometry::Scene& scene, std::vector<geometry::TriangleMesh>& meshes, const geometry::Palette& palette,
          const BatchOptions& options);

  const std::vector<MeshBatch>& meshes() const { return meshes_; }
  const std::vector<geometry::Vec3>& line_positions() const { return line_positions_; }
  const std::vector<Rgba8>& line_colors() const { return line_colors_; }
  // With string_order: depths in (-1, 1) in normalized device coordinates,
  // later modules nearer.
  const std::vector<float>& line_depths() const { return line_depths_; }
  const std::vector<Draw>& draws() const { return draws_; }
  // Some colour used is partly transparent: blending is needed.
  bool transparent() const { return transparent_; }

 private:
  void build_lines(const geometry::Scene& scene, const BatchOptions& options);
  void set_depths(const std::vector<std::vector<geometry::MeshPart>>& parts);
  void add(const Draw& draw);

  const geometry::Palette& palette_;
  std::vector<MeshBatch> meshes_;
  std::vector<geometry::Vec3> line_positions_;
  std::vector<Rgba8> line_colors_;
  std::vector<float> line_widths_;           // of each line (pair of vertices)
  std::vector<std::uint32_t> line_modules_;  // module index of each line
  std::vector<float> line_depths_;
  std::vector<Draw> draws_;
  bool transparent_ = false;
};

}  // namespace sylva::io::gl
