#include "render/gl_batches.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sylva::io::gl {

namespace {

using geometry::MeshPart;

// Past this many material changes in the mesh's own order, regrouping the
// triangles by material (one copy of the index array) beats switching
// materials between that many small draw calls.
constexpr std::size_t kMaxMaterialRuns = 4096;

// Regroups the triangles of `parts` by material when they change material
// too often, updating the parts' first indices.
void group_by_material(std::vector<MeshPart>& parts, std::vector<std::uint32_t>& indices) {
  std::size_t changes = 0;
  for (std::size_t i = 1; i < parts.size(); ++i)
    changes += parts[i].color != parts[i - 1].color || parts[i].back_color != parts[i - 1].back_color ||
               parts[i].texture != parts[i - 1].texture;
  if (changes <= kMaxMaterialRuns) return;
  std::stable_sort(parts.begin(), parts.end(),
                   [](const MeshPart& a, const MeshPart& b) {
                     return a.color != b.color           ? a.color < b.color
                            : a.back_color != b.back_color ? a.back_color < b.back_color
                                                           : a.texture < b.texture;
                   });
  std::vector<std::uint32_t> sorted;
  sorted.reserve(indices.size());
  for (MeshPart& p : parts) {
    const auto first = static_cast<std::uint32_t>(sorted.size());
    sorted.insert(sorted.end(), indices.begin() + p.first_index, indices.begin() + p.first_index + p.index_count);
    p.first_index = first;
  }
  indices.swap(sorted);
}

}  // namespace

Rgba8 to_rgba8(const geometry::Rgb& color, float transparency) {
  auto byte = [](float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255)); };
  return {byte(color.r), byte(color.g), byte(color.b), byte(1 - transparency)};
}

Batches::Batches(const geometry::Scene& scene, std::vector<geometry::TriangleMesh>& meshes,
                 const geometry::Palette& palette, const BatchOptions& options)
    : palette_(palette) {
  std::vector<std::vector<MeshPart>> parts(meshes.size());
  meshes_.resize(meshes.size());
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    MeshBatch& batch = meshes_[m];
    batch.mesh = &meshes[m];
    batch.indices = std::move(meshes[m].indices);
    parts[m] = meshes[m].parts;
    if (options.lit) group_by_material(parts[m], batch.indices);
    for (const MeshPart& p : parts[m]) transparent_ = transparent_ || palette.at(p.color).transparency > 0;
    if (!options.lit) {
      batch.colors.resize(meshes[m].positions.size());
      for (const MeshPart& p : parts[m]) {
        const Rgba8 c = to_rgba8(palette.color(p.color), palette.at(p.color).transparency);
        for (std::uint32_t k = p.first_index; k < p.first_index + p.index_count; ++k)
          batch.colors[batch.indices[k]] = c;
      }
    }
  }
  if (options.pixel_lines) build_lines(scene, options);
  if (options.string_order) set_depths(parts);

  for (std::size_t m = 0; m < meshes.size(); ++m)
    for (const MeshPart& p : parts[m])
      add({Draw::Kind::Triangles, static_cast<std::uint32_t>(m), p.first_index, p.index_count,
           options.lit ? p.color : -1, options.lit && p.back_color >= 0 ? p.back_color : -1, 1, p.texture});
  for (std::size_t l = 0; l < line_widths_.size(); ++l)
    add({Draw::Kind::Lines, 0, static_cast<std::uint32_t>(2 * l), 2, -1, -1, line_widths_[l]});
}

void Batches::build_lines(const geometry::Scene& scene, const BatchOptions& options) {
  const auto& segments = scene.segments;
  std::vector<std::uint32_t> order(segments.size());
  std::iota(order.begin(), order.end(), 0u);
  // lpfg's pixel lines are glLineWidth(width) wide: the turtle's width in pixels.
  auto width_of = [&](std::uint32_t i) { return std::max(1.0f, segments[i].start_width) * options.line_scale; };
  // One draw call per width: models use a handful of widths, often one.
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return width_of(a) < width_of(b); });
  line_positions_.reserve(2 * order.size());
  line_colors_.reserve(2 * order.size());
  line_widths_.reserve(order.size());
  line_modules_.reserve(order.size());
  for (std::uint32_t i : order) {
    const geometry::Segment& s = segments[i];
    const Rgba8 c = to_rgba8(palette_.color(s.color), palette_.at(s.color).transparency);
    transparent_ = transparent_ || c.a < 255;
    line_positions_.push_back(s.start);
    line_positions_.push_back(s.end);
    line_colors_.push_back(c);
    line_colors_.push_back(c);
    line_widths_.push_back(width_of(i));
    line_modules_.push_back(s.from.module_index);
  }
}

void Batches::set_depths(const std::vector<std::vector<MeshPart>>& parts) {
  // Module indices serve as ranks directly while a 24-bit depth buffer still
  // tells neighbours apart; beyond that only the indices in use are ranked.
  std::uint32_t max_index = 0;
  for (const auto& mesh_parts : parts)
    for (const MeshPart& p : mesh_parts) max_index = std::max(max_index, p.from.module_index);
  for (std::uint32_t m : line_modules_) max_index = std::max(max_index, m);
  std::vector<std::uint32_t> used;
  double ranks = static_cast<double>(max_index) + 1;
  if (max_index >= (1u << 22)) {
    for (const auto& mesh_parts : parts)
      for (const MeshPart& p : mesh_parts) used.push_back(p.from.module_index);
    used.insert(used.end(), line_modules_.begin(), line_modules_.end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    ranks = static_cast<double>(used.size());
  }
  auto depth = [&](std::uint32_t module) {
    const double rank =
        used.empty() ? module : static_cast<double>(std::lower_bound(used.begin(), used.end(), module) - used.begin());
    return static_cast<float>(1 - 2 * (rank + 1) / (ranks + 1));
  };
  for (std::size_t m = 0; m < meshes_.size(); ++m) {
    MeshBatch& batch = meshes_[m];
    batch.depths.assign(batch.mesh->positions.size(), 1.0f);
    for (const MeshPart& p : parts[m]) {
      const float d = depth(p.from.module_index);
      for (std::uint32_t k = p.first_index; k < p.first_index + p.index_count; ++k) batch.depths[batch.indices[k]] = d;
    }
  }
  line_depths_.reserve(2 * line_modules_.size());
  for (std::uint32_t m : line_modules_) line_depths_.insert(line_depths_.end(), 2, depth(m));
}

void Batches::add(const Draw& draw) {
  if (draw.count == 0) return;
  if (!draws_.empty()) {
    Draw& last = draws_.back();
    if (last.kind == draw.kind && last.mesh == draw.mesh && last.material == draw.material &&
        last.back_material == draw.back_material && last.width == draw.width && last.texture == draw.texture &&
        last.first + last.count == draw.first) {
      last.count += draw.count;
      return;
    }
  }
  draws_.push_back(draw);
}

}  // namespace sylva::io::gl
