#include "geometry/back_sides.h"

#include <algorithm>
#include <unordered_map>

namespace sylva::geometry {
namespace {

// Whether a part's back has a colour of its own (a colour index other than its front's).
bool has_own_back(const MeshPart& p) { return p.back_color >= 0 && p.back_color != p.color; }

}  // namespace

void split_back_sides(TriangleMesh& mesh) {
  if (std::none_of(mesh.parts.begin(), mesh.parts.end(), has_own_back)) return;
  std::vector<MeshPart> parts;
  parts.reserve(mesh.parts.size() * 2);
  std::unordered_map<std::uint32_t, std::uint32_t> copy_of;  // front vertex -> its reversed copy
  for (MeshPart front : mesh.parts) {
    if (!has_own_back(front)) {
      parts.push_back(front);
      continue;
    }
    front.side = MeshPart::Side::Front;
    parts.push_back(front);
    MeshPart back = front;
    back.side = MeshPart::Side::Back;
    back.color = front.back_color;
    back.first_index = static_cast<std::uint32_t>(mesh.indices.size());
    copy_of.clear();
    auto copy = [&](std::uint32_t v) {
      auto [it, added] = copy_of.emplace(v, static_cast<std::uint32_t>(mesh.positions.size()));
      if (added) {
        const Vec3 p = mesh.positions[v], n = mesh.normals[v];
        mesh.positions.push_back(p);
        mesh.normals.push_back(-n);
      }
      return it->second;
    };
    for (std::uint32_t k = 0; k + 2 < front.index_count; k += 3) {
      const std::uint32_t a = mesh.indices[front.first_index + k], b = mesh.indices[front.first_index + k + 1],
                          c = mesh.indices[front.first_index + k + 2];
      const std::uint32_t ca = copy(a), cb = copy(b), cc = copy(c);
      mesh.indices.insert(mesh.indices.end(), {ca, cc, cb});
    }
    back.index_count = static_cast<std::uint32_t>(mesh.indices.size()) - back.first_index;
    parts.push_back(back);
  }
  mesh.parts = std::move(parts);
}

}  // namespace sylva::geometry
