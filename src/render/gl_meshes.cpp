#include "render/gl_meshes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace sylva::io::gl {

namespace {

// Big plants have hundreds of thousands of buds and internodes a few pixels
// across, which look the same with a handful of sides as with the view
// file's; the time and memory they take is proportional to their sides.
constexpr double kOutlineTolerance = 0.5;  // pixels

int sides_for(float radius_pixels, int fewest, int most) {
  fewest = std::min(fewest, most);
  if (!(radius_pixels > kOutlineTolerance)) return fewest;
  // A regular polygon of n sides strays r (1 - cos(pi / n)) inside its circle.
  const double n = std::numbers::pi / std::acos(1.0 - kOutlineTolerance / static_cast<double>(radius_pixels));
  if (!(n < most)) return most;
  int sides = std::max(fewest, static_cast<int>(std::ceil(n)));
  if (sides > 4) sides += sides & 1;  // fewer distinct counts, fewer meshes
  return std::min(sides, most);
}

// A regular polygon of n sides inscribed in the unit circle: its area, and
// its mean width (its perimeter over pi, the width averaged over directions).
double polygon_area(int n) { return n * 0.5 * std::sin(2 * std::numbers::pi / n); }
double polygon_width(int n) { return 2 * n * std::sin(std::numbers::pi / n) / std::numbers::pi; }

}  // namespace

geometry::Box drawn_bounds(const geometry::Scene& scene, geometry::LineStyle line_style) {
  if (line_style != geometry::LineStyle::Pixel || scene.segments.empty()) return scene.bounds();
  geometry::Scene others;
  others.circles = scene.circles;
  others.spheres = scene.spheres;
  others.labels = scene.labels;
  geometry::Box box = others.bounds();
  for (const geometry::TriangleGroup& g : scene.groups) {
    for (std::size_t k = g.first_index; k < std::size_t{g.first_index} + g.index_count && k < scene.indices.size(); ++k)
      if (scene.indices[k] < scene.positions.size()) box.add(scene.positions[scene.indices[k]]);
  }
  for (const geometry::Segment& s : scene.segments) {
    box.add(s.start);
    box.add(s.end);
  }
  return box;
}

std::vector<geometry::TriangleMesh> tessellate_for_view(const geometry::Scene& scene, const geometry::Camera& camera,
                                                        const geometry::TessellationOptions& options, float pixel_scale,
                                                        bool every_side) {
  using geometry::LineStyle;
  const int most = std::max(3, options.contour_sides);
  const bool facing = std::any_of(scene.circles.begin(), scene.circles.end(),
                                  [](const geometry::Circle& c) { return c.facing_viewer; });
  const bool pixel_lines = options.line_style == LineStyle::Pixel && !scene.segments.empty();
  const bool cylinders = options.line_style == LineStyle::Cylinder;
  auto pixels = [&](float radius, geometry::Vec3 at) { return radius * camera.pixels_per_unit_at(at) * pixel_scale; };

  std::vector<int> segment_sides(cylinders ? scene.segments.size() : 0, most);
  std::vector<int> circle_sides(scene.circles.size(), most), sphere_sides(scene.spheres.size(), most);
  // A sphere drawn after ContourSides has that many slices at most.
  auto sphere_most = [&](const geometry::Sphere& s) { return s.slices > 0 ? std::max(3, s.slices) : most; };
  for (std::size_t i = 0; i < sphere_sides.size(); ++i) sphere_sides[i] = sphere_most(scene.spheres[i]);
  if (!every_side) {
    for (std::size_t i = 0; i < segment_sides.size(); ++i) {
      const geometry::Segment& s = scene.segments[i];
      const float radius = std::max(s.start_width, s.end_width) * 0.5f;
      segment_sides[i] = sides_for(pixels(radius, (s.start + s.end) * 0.5f), 3, most);
    }
    for (std::size_t i = 0; i < circle_sides.size(); ++i) {
      const geometry::Circle& c = scene.circles[i];
      circle_sides[i] = sides_for(pixels(c.radius + std::max(0.0f, c.outline) * 0.5f, c.center), 4, most);
    }
    for (std::size_t i = 0; i < sphere_sides.size(); ++i)
      sphere_sides[i] =
          sides_for(pixels(scene.spheres[i].radius, scene.spheres[i].center), 4, sphere_most(scene.spheres[i]));
  }
  auto fewer = [&](const std::vector<int>& sides) {
    return std::any_of(sides.begin(), sides.end(), [&](int n) { return n < most; });
  };
  bool fewer_slices = false;
  for (std::size_t i = 0; i < sphere_sides.size(); ++i)
    fewer_slices = fewer_slices || sphere_sides[i] < sphere_most(scene.spheres[i]);
  if (!facing && !pixel_lines && !fewer(segment_sides) && !fewer(circle_sides) && !fewer_slices)
    return {geometry::tessellate(scene, {options.line_style, most})};

  // Primitives by the sides they get; the triangle pool goes with the rest.
  std::map<int, geometry::Scene, std::greater<>> by_sides;
  geometry::Scene& full = by_sides[most];
  full.positions = scene.positions;
  full.normals = scene.normals;
  full.indices = scene.indices;
  full.groups = scene.groups;
  full.texcoords = scene.texcoords;
  if (!pixel_lines) {
    for (std::size_t i = 0; i < scene.segments.size(); ++i) {
      geometry::Segment s = scene.segments[i];
      const int sides = cylinders ? segment_sides[i] : most;
      // As wide on screen, on average over the ways it can turn, as with every side.
      const auto scale = static_cast<float>(polygon_width(most) / polygon_width(sides));
      s.start_width *= scale;
      s.end_width *= scale;
      by_sides[sides].segments.push_back(s);
    }
  }
  // Fewer sides inscribed in the same circle would cover less: the radius
  // grows so that the primitive covers as much as it does with every side.
  auto area_scale = [&](int sides) { return static_cast<float>(std::sqrt(polygon_area(most) / polygon_area(sides))); };
  for (std::size_t i = 0; i < scene.circles.size(); ++i) {
    geometry::Circle c = scene.circles[i];
    if (c.facing_viewer) {
      c.facing_viewer = false;
      c.normal = -camera.direction();
    }
    c.radius *= area_scale(circle_sides[i]);
    by_sides[circle_sides[i]].circles.push_back(c);
  }
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    geometry::Sphere s = scene.spheres[i];
    const int own = sphere_most(s);
    s.radius *= static_cast<float>(std::sqrt(polygon_area(own) / polygon_area(sphere_sides[i])));
    s.slices = 0;  // the mesh's sides
    by_sides[sphere_sides[i]].spheres.push_back(s);
  }

  std::vector<geometry::TriangleMesh> meshes;
  for (auto& [sides, part] : by_sides) {
    if (part.empty()) continue;
    meshes.push_back(geometry::tessellate(part, {options.line_style, sides}));
    part = {};
  }
  return meshes;
}

}  // namespace sylva::io::gl
