#include "studio/scene_instances.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <vector>

namespace sylva::studio {
namespace {

enum class Shape : std::uint32_t { Sphere = 0, Cylinder = 1 };

struct Group {
  std::vector<float> floats;
  std::vector<std::uint32_t> indices, ids;
};

class Writer {
 public:
  void u32(std::uint32_t v) { bytes(&v, 4); }
  void f32(float v) { bytes(&v, 4); }
  template <typename T>
  void array(const std::vector<T>& values) {
    bytes(values.data(), values.size() * sizeof(T));
  }
  std::string take() { return std::move(out_); }

 private:
  void bytes(const void* data, std::size_t size) { out_.append(static_cast<const char*>(data), size); }
  std::string out_;
};

}  // namespace

std::string take_instances(geometry::Scene& scene, const geometry::Palette& palette,
                           const geometry::TessellationOptions& tessellation, std::size_t threshold) {
  const bool cylinders = tessellation.line_style == geometry::LineStyle::Cylinder;
  const std::size_t count = scene.spheres.size() + (cylinders ? scene.segments.size() : 0);
  if (count <= threshold) return "";

  // One group per shape, slices and colour.
  using Key = std::tuple<Shape, int, int>;
  std::map<Key, Group> groups;
  const int contour_sides = std::max(3, tessellation.contour_sides);
  for (const geometry::Sphere& s : scene.spheres) {
    Group& g = groups[{Shape::Sphere, s.slices > 0 ? s.slices : contour_sides, s.color}];
    g.floats.insert(g.floats.end(), {s.center.x, s.center.y, s.center.z, s.radius});
    g.indices.push_back(s.from.module_index);
    g.ids.push_back(s.from.module_id);
  }
  scene.spheres.clear();
  if (cylinders) {
    // Textured lines keep their triangles: a texture needs its coordinates.
    std::vector<geometry::Segment> textured;
    const int sides = tessellation.line_sides > 0 ? tessellation.line_sides : contour_sides;
    for (const geometry::Segment& s : scene.segments) {
      if (s.texture >= 0) {
        textured.push_back(s);
        continue;
      }
      Group& g = groups[{Shape::Cylinder, sides, s.color}];
      g.floats.insert(g.floats.end(), {s.start.x, s.start.y, s.start.z, s.end.x, s.end.y, s.end.z,
                                       std::max(0.0f, s.start_width) * 0.5f, std::max(0.0f, s.end_width) * 0.5f});
      g.indices.push_back(s.from.module_index);
      g.ids.push_back(s.from.module_id);
    }
    scene.segments = std::move(textured);
  }

  Writer out;
  out.u32(0x494c5953);  // "SYLI"
  out.u32(1);
  out.u32(static_cast<std::uint32_t>(groups.size()));
  for (const auto& [key, g] : groups) {
    const auto [shape, slices, color] = key;
    const geometry::Material& m = palette.at(color);
    out.u32(static_cast<std::uint32_t>(shape));
    out.u32(static_cast<std::uint32_t>(g.indices.size()));
    out.u32(static_cast<std::uint32_t>(slices));
    out.f32(m.diffuse.r);
    out.f32(m.diffuse.g);
    out.f32(m.diffuse.b);
    out.f32(std::clamp(1 - m.transparency, 0.0f, 1.0f));
    out.array(g.floats);
    out.array(g.indices);
    out.array(g.ids);
  }
  return out.take();
}

}  // namespace sylva::studio
