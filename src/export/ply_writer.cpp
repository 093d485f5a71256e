#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <set>

#include "export/mesh_support.h"
#include "export/mesh_writers.h"
#include "io/output_file.h"

namespace sylva::io {
namespace {

static_assert(std::endian::native == std::endian::little, "PLY output is written as the host's little-endian bytes");

using geometry::MeshPart;

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::uint8_t channel(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 255));
}

}  // namespace

void write_ply(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types, const std::string& provenance) {
  const std::size_t vertex_count = mesh.positions.size();
  std::size_t face_count = 0, edge_count = 0;
  for (const MeshPart& part : mesh.parts) face_count += part.index_count / 3;
  for (const MeshPart& part : mesh.line_parts) edge_count += part.index_count / 2;

  auto rgba_of = [&](int color) {
    const geometry::Material& m = palette.at(color);
    return std::array<std::uint8_t, 4>{channel(m.diffuse.r), channel(m.diffuse.g), channel(m.diffuse.b),
                                       channel(1 - m.transparency)};
  };
  // A vertex takes its part's colour; one in no part keeps colour index 1.
  std::vector<std::array<std::uint8_t, 4>> vertex_rgba(vertex_count, rgba_of(1));
  std::set<abi::ModuleId> modules;
  auto colour_vertices = [&](const std::vector<MeshPart>& parts, const std::vector<std::uint32_t>& indices) {
    for (const MeshPart& part : parts) {
      modules.insert(part.from.module_id);
      const auto rgba = rgba_of(part.color);
      for (std::uint32_t k = 0; k < part.index_count; ++k) vertex_rgba[indices[part.first_index + k]] = rgba;
    }
  };
  colour_vertices(mesh.parts, mesh.indices);
  colour_vertices(mesh.line_parts, mesh.line_indices);

  std::string out = "ply\nformat binary_little_endian 1.0\ncomment Sylva mesh\n";
  if (!provenance.empty()) out += "comment sylva:provenance " + provenance + "\n";  // api/provenance.h
  // The names behind module_id, for readers that have no registry.
  for (abi::ModuleId id : modules)
    out += "comment module " + std::to_string(id) + " " + mesh_support::module_name(types, id) + "\n";
  out += "element vertex " + std::to_string(vertex_count) +
         "\nproperty float x\nproperty float y\nproperty float z"
         "\nproperty float nx\nproperty float ny\nproperty float nz"
         "\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n";
  out += "element face " + std::to_string(face_count) +
         "\nproperty list uchar int vertex_indices\nproperty uint module_index\nproperty ushort module_id\n";
  if (edge_count > 0)
    out += "element edge " + std::to_string(edge_count) +
           "\nproperty int vertex1\nproperty int vertex2\nproperty uint module_index\nproperty ushort module_id\n";
  out += "end_header\n";
  out.reserve(out.size() + vertex_count * 28 + face_count * 19 + edge_count * 14);

  for (std::size_t v = 0; v < vertex_count; ++v) {
    const geometry::Vec3& p = mesh.positions[v];
    geometry::Vec3 n = v < mesh.normals.size() ? mesh.normals[v] : geometry::Vec3{};
    for (float f : {p.x, p.y, p.z, n.x, n.y, n.z}) put(out, f);
    out.append(reinterpret_cast<const char*>(vertex_rgba[v].data()), 4);
  }
  for (const MeshPart& part : mesh.parts) {
    for (std::uint32_t k = 0; k + 3 <= part.index_count; k += 3) {
      put(out, std::uint8_t{3});
      for (std::uint32_t j = 0; j < 3; ++j) put(out, static_cast<std::int32_t>(mesh.indices[part.first_index + k + j]));
      put(out, part.from.module_index);
      put(out, static_cast<std::uint16_t>(part.from.module_id));
    }
  }
  for (const MeshPart& part : mesh.line_parts) {
    for (std::uint32_t k = 0; k + 2 <= part.index_count; k += 2) {
      for (std::uint32_t j = 0; j < 2; ++j)
        put(out, static_cast<std::int32_t>(mesh.line_indices[part.first_index + k + j]));
      put(out, part.from.module_index);
      put(out, static_cast<std::uint16_t>(part.from.module_id));
    }
  }
  write_output_file(path, out);
}

void write_ply(const std::string& path, const geometry::TriangleMesh& mesh, const geometry::Palette& palette,
               const ModuleTypes& types) {
  write_ply(path, mesh, palette, types, std::string());
}

}  // namespace sylva::io
