#include "geometry/tessellation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

// Invariants of the mesh made here, which the mesh writers rely on: every
// vertex belongs to exactly one part (so a vertex colour or a per-vertex
// provenance is never ambiguous), and a part's vertices are contiguous.
// Primitives that draw nothing (zero-length segments, zero widths and radii)
// get no part at all.

namespace sylva::geometry {
namespace {

constexpr float kTwoPi = 2 * std::numbers::pi_v<float>;

// A unit vector perpendicular to the unit vector `axis`, as close to `hint`
// as possible; any perpendicular when the hint is (nearly) parallel to the axis.
Vec3 perpendicular(Vec3 axis, Vec3 hint) {
  Vec3 p = hint - axis * dot(hint, axis);
  if (length(p) > 1e-6f * std::max(1.0f, length(hint))) return normalized(p);
  Vec3 other = std::fabs(axis.x) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return normalized(other - axis * dot(other, axis));
}

class Builder {
 public:
  Builder(TriangleMesh& mesh, const TessellationOptions& options)
      : mesh_(mesh),
        line_angles_(angles(options.line_sides > 0 ? options.line_sides : options.contour_sides)),
        circle_angles_(angles(options.circle_sides > 0 ? options.circle_sides : options.contour_sides)),
        sphere_angles_(angles(options.contour_sides)) {}

  void segment(const Segment& s, LineStyle style) {
    Vec3 axis = s.end - s.start;
    float len = length(axis);
    if (!(len > 0)) return;
    Vec3 h = axis / len;
    Vec3 u = perpendicular(h, s.up);
    if (style == LineStyle::Pixel) {
      auto base = vertex_count();
      add_vertex(s.start, u);
      add_vertex(s.end, u);
      MeshPart part = begin_part(MeshPart::Kind::Segment, s.color, s.from, mesh_.line_indices);
      mesh_.line_indices.insert(mesh_.line_indices.end(), {base, base + 1});
      end_part(part, mesh_.line_indices, mesh_.line_parts);
      return;
    }
    float r0 = std::max(0.0f, s.start_width) * 0.5f, r1 = std::max(0.0f, s.end_width) * 0.5f;
    if (r0 == 0 && r1 == 0) return;
    // cross(h, u) is the turtle's right (H x L = U): a strip spans heading and
    // right and faces up; a cylinder's sides go round from the seam at the
    // turtle's left toward up, as lpfg's OBJ export puts them.
    Vec3 v = cross(h, u);
    MeshPart part = begin_part(MeshPart::Kind::Segment, s.color, s.from, mesh_.indices);
    auto base = vertex_count();
    const bool textured = s.texture >= 0;
    part.texture = s.texture;
    if (style == LineStyle::Polygon) {
      add_vertex(s.start - v * r0, u);
      add_vertex(s.start + v * r0, u);
      add_vertex(s.end + v * r1, u);
      add_vertex(s.end - v * r1, u);
      if (textured) {
        set_texcoord(base, {0, s.texture_v0});
        set_texcoord(base + 1, {1, s.texture_v0});
        set_texcoord(base + 2, {1, s.texture_v1});
        set_texcoord(base + 3, {0, s.texture_v1});
      }
      add_quad(base, base + 1, base + 2, base + 3);
    } else if (textured) {
      // The texture wraps once round: the seam's vertices come twice, at
      // u = 0 and u = 1 (lpfg's contour repeats its first point too).
      auto n = static_cast<std::uint32_t>(line_angles_.size());
      Vec3 left = -v;
      for (int end = 0; end < 2; ++end) {
        for (std::uint32_t k = 0; k <= n; ++k) {
          const auto& [c, sn] = line_angles_[k % n];
          Vec3 dir = left * c + u * sn;
          add_vertex((end ? s.end : s.start) + dir * (end ? r1 : r0), normalized(dir * len + h * (r0 - r1)));
          set_texcoord(vertex_count() - 1,
                       {static_cast<float>(k) / static_cast<float>(n), end ? s.texture_v1 : s.texture_v0});
        }
      }
      for (std::uint32_t k = 0; k < n; ++k) add_quad(base + k, base + k + 1, base + n + 2 + k, base + n + 1 + k);
    } else {
      // Open ends: the segments of a branch meet there, and caps would be
      // hidden faces doubling the triangle count.
      // The normal of a tapered side leans toward the narrow end: it is
      // perpendicular to the slanted generator (h*len + dir*(r1-r0)).
      auto n = static_cast<std::uint32_t>(line_angles_.size());
      Vec3 left = -v;
      for (const auto& [c, sn] : line_angles_) {
        Vec3 dir = left * c + u * sn;
        add_vertex(s.start + dir * r0, normalized(dir * len + h * (r0 - r1)));
      }
      for (const auto& [c, sn] : line_angles_) {
        Vec3 dir = left * c + u * sn;
        add_vertex(s.end + dir * r1, normalized(dir * len + h * (r0 - r1)));
      }
      for (std::uint32_t k = 0; k < n; ++k) {
        std::uint32_t next = (k + 1) % n;
        add_quad(base + k, base + next, base + n + next, base + n + k);
      }
    }
    end_part(part, mesh_.indices, mesh_.parts);
  }

  void circle(const Circle& c) {
    // A screen-facing circle would need the camera to orient it; a mesh has
    // none, so it lies in the xy plane, facing +z (the default view's eye).
    Vec3 normal = c.facing_viewer ? Vec3{0, 0, 1} : normalized(c.normal);
    if (length(normal) == 0) normal = {0, 0, 1};
    // From the turtle's right toward its heading (lpfg's order); the mesh's
    // x and y axes for a screen-facing circle.
    Vec3 a = perpendicular(normal, c.facing_viewer ? Vec3{1, 0, 0} : cross(c.heading, normal));
    Vec3 b = cross(normal, a);
    auto n = static_cast<std::uint32_t>(circle_angles_.size());
    if (c.outline > 0) {
      float outer = std::max(0.0f, c.radius + c.outline * 0.5f);
      float inner = std::max(0.0f, c.radius - c.outline * 0.5f);
      if (outer == 0) return;
      MeshPart part = begin_part(MeshPart::Kind::Circle, c.color, c.from, mesh_.indices);
      auto base = vertex_count();
      for (const auto& [cs, sn] : circle_angles_) add_vertex(c.center + (a * cs + b * sn) * inner, normal);
      for (const auto& [cs, sn] : circle_angles_) add_vertex(c.center + (a * cs + b * sn) * outer, normal);
      for (std::uint32_t k = 0; k < n; ++k) {
        std::uint32_t next = (k + 1) % n;
        add_quad(base + k, base + n + k, base + n + next, base + next);
      }
      end_part(part, mesh_.indices, mesh_.parts);
      return;
    }
    if (!(c.radius > 0)) return;
    MeshPart part = begin_part(MeshPart::Kind::Circle, c.color, c.from, mesh_.indices);
    auto base = vertex_count();
    add_vertex(c.center, normal);
    for (const auto& [cs, sn] : circle_angles_) add_vertex(c.center + (a * cs + b * sn) * c.radius, normal);
    for (std::uint32_t k = 0; k < n; ++k) add_triangle(base, base + 1 + k, base + 1 + (k + 1) % n);
    end_part(part, mesh_.indices, mesh_.parts);
  }

  // `slices` slices around the y axis and (slices+1)/2 stacks from pole to
  // pole (LPFG manual 5.5): two pole vertices and stacks-1 rings between.
  // As lpfg's OBJ export places them: poles on the world's y axis, each
  // ring's first vertex toward -z, longitudes turning toward +x.
  void sphere(const Sphere& s) {
    if (!(s.radius > 0)) return;
    if (s.slices > 0 && static_cast<std::size_t>(s.slices) != own_sphere_angles_.size())
      own_sphere_angles_ = angles(s.slices);
    const auto& ring_angles = s.slices > 0 ? own_sphere_angles_ : sphere_angles_;
    auto n = static_cast<std::uint32_t>(ring_angles.size());
    auto stacks = (n + 1) / 2;
    MeshPart part = begin_part(MeshPart::Kind::Sphere, s.color, s.from, mesh_.indices);
    auto base = vertex_count();
    add_vertex(s.center + Vec3{0, s.radius, 0}, {0, 1, 0});
    for (std::uint32_t ring = 1; ring < stacks; ++ring) {
      float polar = std::numbers::pi_v<float> * static_cast<float>(ring) / static_cast<float>(stacks);
      float y = std::cos(polar), rho = std::sin(polar);
      for (const auto& [c, sn] : ring_angles) {
        Vec3 dir{-rho * sn, y, -rho * c};
        add_vertex(s.center + dir * s.radius, dir);
      }
    }
    std::uint32_t south = vertex_count();
    add_vertex(s.center - Vec3{0, s.radius, 0}, {0, -1, 0});
    auto ring_vertex = [&](std::uint32_t ring, std::uint32_t k) { return base + 1 + (ring - 1) * n + k % n; };
    for (std::uint32_t k = 0; k < n; ++k) add_triangle(base, ring_vertex(1, k), ring_vertex(1, k + 1));
    for (std::uint32_t ring = 1; ring + 1 < stacks; ++ring)
      for (std::uint32_t k = 0; k < n; ++k)
        add_quad(ring_vertex(ring, k), ring_vertex(ring + 1, k), ring_vertex(ring + 1, k + 1), ring_vertex(ring, k + 1));
    for (std::uint32_t k = 0; k < n; ++k) add_triangle(south, ring_vertex(stacks - 1, k + 1), ring_vertex(stacks - 1, k));
    end_part(part, mesh_.indices, mesh_.parts);
  }

  // Groups may share pool vertices; each gets its own copies (see the
  // invariants above). `stamp_`/`remap_` avoid clearing a table per group.
  void group(const Scene& scene, const TriangleGroup& g) {
    if (remap_.size() != scene.positions.size()) {
      remap_.assign(scene.positions.size(), 0);
      stamp_.assign(scene.positions.size(), 0);
    }
    ++group_number_;
    std::uint32_t count = g.index_count - g.index_count % 3;
    if (count == 0 || std::size_t{g.first_index} + count > scene.indices.size()) return;
    auto first = scene.indices.begin() + g.first_index;
    if (std::any_of(first, first + count, [&](std::uint32_t i) { return i >= scene.positions.size(); })) return;
    MeshPart part = begin_part(part_kind(g.kind), g.color, g.from, mesh_.indices);
    part.back_color = g.back_color;
    part.texture = g.texture;
    std::uint32_t base = vertex_count();
    for (auto it = first; it != first + count; ++it) {
      std::uint32_t i = *it;
      if (stamp_[i] != group_number_) {
        stamp_[i] = group_number_;
        remap_[i] = vertex_count();
        add_vertex(scene.positions[i], i < scene.normals.size() ? scene.normals[i] : Vec3{});
        if (g.texture >= 0) set_texcoord(remap_[i], scene.texcoord(i));
      }
      mesh_.indices.push_back(remap_[i]);
    }
    repair_normals(part.first_index, base);
    end_part(part, mesh_.indices, mesh_.parts);
  }

 private:
  static MeshPart::Kind part_kind(TriangleGroup::Kind kind) {
    switch (kind) {
      case TriangleGroup::Kind::Polygon: return MeshPart::Kind::Polygon;
      case TriangleGroup::Kind::Rhombus: return MeshPart::Kind::Rhombus;
      case TriangleGroup::Kind::Triangle: return MeshPart::Kind::Triangle;
      case TriangleGroup::Kind::Surface: return MeshPart::Kind::Surface;
      case TriangleGroup::Kind::GeneralizedCylinder: return MeshPart::Kind::GeneralizedCylinder;
      case TriangleGroup::Kind::Mesh: return MeshPart::Kind::Mesh;
    }
    return MeshPart::Kind::Mesh;
  }

  // Writers need unit normals everywhere; a vertex that came without one
  // gets the area-weighted normal of its triangles in the group.
  void repair_normals(std::uint32_t first_index, std::uint32_t first_vertex) {
    bool missing = false;
    for (std::uint32_t v = first_vertex; v < vertex_count(); ++v) {
      float l = length(mesh_.normals[v]);
      if (l > 0 && std::isfinite(l)) {
        mesh_.normals[v] = mesh_.normals[v] / l;
      } else {
        mesh_.normals[v] = {};
        missing = true;
      }
    }
    if (!missing) return;
    std::vector<Vec3> sum(vertex_count() - first_vertex);
    for (std::size_t k = first_index; k + 2 < mesh_.indices.size(); k += 3) {
      std::uint32_t a = mesh_.indices[k], b = mesh_.indices[k + 1], c = mesh_.indices[k + 2];
      Vec3 face = cross(mesh_.positions[b] - mesh_.positions[a], mesh_.positions[c] - mesh_.positions[a]);
      for (std::uint32_t v : {a, b, c}) sum[v - first_vertex] += face;
    }
    for (std::uint32_t v = first_vertex; v < vertex_count(); ++v) {
      if (mesh_.normals[v] == Vec3{}) {
        Vec3 n = normalized(sum[v - first_vertex]);
        mesh_.normals[v] = length(n) > 0 ? n : Vec3{0, 0, 1};
      }
    }
  }

  std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(mesh_.positions.size()); }
  void add_vertex(Vec3 p, Vec3 n) {
    mesh_.positions.push_back(p);
    mesh_.normals.push_back(n);
  }
  void set_texcoord(std::uint32_t vertex, TexCoord t) {
    if (mesh_.texcoords.size() <= vertex) mesh_.texcoords.resize(vertex + 1);
    mesh_.texcoords[vertex] = t;
  }
  void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
  }
  // Counter-clockwise a, b, c, d seen from the side the normal points to.
  void add_quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    add_triangle(a, b, c);
    add_triangle(a, c, d);
  }
  static MeshPart begin_part(MeshPart::Kind kind, int color, Provenance from, const std::vector<std::uint32_t>& into) {
    MeshPart part;
    part.kind = kind;
    part.color = color;
    part.from = from;
    part.first_index = static_cast<std::uint32_t>(into.size());
    return part;
  }
  static void end_part(MeshPart part, const std::vector<std::uint32_t>& into, std::vector<MeshPart>& parts) {
    part.index_count = static_cast<std::uint32_t>(into.size()) - part.first_index;
    if (part.index_count > 0) parts.push_back(part);
  }

  // cos, sin of each of `sides` angles round a circle (at least 3).
  static std::vector<std::pair<float, float>> angles(int sides) {
    sides = std::max(3, sides);
    std::vector<std::pair<float, float>> table;
    table.reserve(static_cast<std::size_t>(sides));
    for (int k = 0; k < sides; ++k) {
      float a = kTwoPi * static_cast<float>(k) / static_cast<float>(sides);
      table.push_back({std::cos(a), std::sin(a)});
    }
    return table;
  }

  TriangleMesh& mesh_;
  std::vector<std::pair<float, float>> line_angles_, circle_angles_, sphere_angles_;
  std::vector<std::pair<float, float>> own_sphere_angles_;  // of the last sphere with its own slices
  std::vector<std::uint32_t> remap_, stamp_;
  std::uint32_t group_number_ = 0;
};

}  // namespace

// Parts come in string order (the turtle fills each list in string order;
// the lists are merged here), which is the drawing order without a depth
// test and keeps a module's parts together in the files.
TriangleMesh tessellate(const Scene& scene, const TessellationOptions& options) {
  TriangleMesh mesh;
  Builder builder(mesh, options);
  std::size_t g = 0, s = 0, c = 0, p = 0;
  constexpr auto kDone = std::numeric_limits<std::uint64_t>::max();
  auto next = [](const auto& list, std::size_t k) -> std::uint64_t {
    return k < list.size() ? list[k].from.module_index : kDone;
  };
  for (;;) {
    std::uint64_t ng = next(scene.groups, g), ns = next(scene.segments, s), nc = next(scene.circles, c),
                  np = next(scene.spheres, p);
    std::uint64_t least = std::min({ng, ns, nc, np});
    if (least == kDone) break;
    if (ng == least)
      builder.group(scene, scene.groups[g++]);
    else if (ns == least)
      builder.segment(scene.segments[s++], options.line_style);
    else if (nc == least)
      builder.circle(scene.circles[c++]);
    else
      builder.sphere(scene.spheres[p++]);
  }
  if (!mesh.texcoords.empty()) mesh.texcoords.resize(mesh.positions.size());
  return mesh;
}

TessellationOptions lpfg_export_options(int contour_sides) {
  constexpr int kLpfgLineSides = 16;  // 2 x LPFGParams::DefaultContourDivisions
  return TessellationOptions{LineStyle::Cylinder, contour_sides, kLpfgLineSides, kLpfgLineSides};
}

const char* kind_name(MeshPart::Kind kind) {
  switch (kind) {
    case MeshPart::Kind::Segment: return "segment";
    case MeshPart::Kind::Circle: return "circle";
    case MeshPart::Kind::Sphere: return "sphere";
    case MeshPart::Kind::Polygon: return "polygon";
    case MeshPart::Kind::Rhombus: return "rhombus";
    case MeshPart::Kind::Triangle: return "triangle";
    case MeshPart::Kind::Surface: return "surface";
    case MeshPart::Kind::GeneralizedCylinder: return "generalized_cylinder";
    case MeshPart::Kind::Mesh: return "mesh";
  }
  return "unknown";
}

}  // namespace sylva::geometry
