// Polygons (SP PP EP, cpfg's { . }): open polygons nest; each keeps its
// vertices, with the turtle's up at each, until it ends and is triangulated
// into the Scene.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/scene.h"
#include "turtle/frame.h"
#include "turtle/triangle_group.h"

namespace sylva::turtle {

class PolygonBuilder {
 public:
  bool any_open() const { return !open_.empty(); }

  // Opens a polygon (inside the open ones); it is the module `from`'s.
  // Returns how many are open.
  int start(geometry::Provenance from);
  // A vertex of the innermost open polygon (there must be one) with the
  // turtle there; returns its number in the polygon, from 1.
  int add_vertex(Vec3 position, const Frame& frame);

  // How an ending polygon is drawn. `auto_normals`: its normal from its first
  // edges (the view file's "auto normals") rather than the turtle's ups.
  // `texture` (-1: none) is stretched over it along its first vertex's frame.
  struct Look {
    bool auto_normals = false;
    int texture = -1;
    int color = 1, back_color = -1;
  };
  struct Ended {
    int vertices = 0;
    int triangles = -1;  // -1: not drawn (no Scene, or fewer than 3 vertices)
  };
  // Ends the innermost open polygon (there must be one), drawing it into `scene` when given.
  Ended end(geometry::Scene* scene, const Look& look);

 private:
  void draw(geometry::Scene& scene, std::size_t first, const Frame& first_frame, const Look& look,
            geometry::Provenance from, Ended& ended);

  struct OpenPolygon {
    std::size_t first = 0;  // its first vertex in the pool
    geometry::Provenance from;
    Frame first_frame;  // the turtle's at the first vertex (cpfg's texture axes)
  };
  std::vector<OpenPolygon> open_;
  // The open polygons' vertices, in one pool.
  std::vector<Vec3> points_, ups_;
  std::vector<std::uint32_t> triangles_, triangulation_work_;
};

}  // namespace sylva::turtle
