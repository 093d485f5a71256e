// What the mesh writers share: module names for provenance, the colour
// indices a mesh uses, and locale-independent shortest number text.
#pragma once

#include <array>
#include <charconv>
#include <string>
#include <vector>

#include "geometry/tessellation.h"
#include "lstring/module_types.h"

namespace sylva::io::mesh_support {

// "module<id>" for an id the registry does not know, so a mesh from a
// mismatched registry still writes.
inline std::string module_name(const ModuleTypes& types, abi::ModuleId id) {
  if (id < types.size() && !types.name(id).empty()) return types.name(id);
  return "module" + std::to_string(id);
}

inline int color_slot(int color) { return color & 255; }

// Ascending colour indices (0..255) used by triangle or line parts.
inline std::vector<int> colors_used(const geometry::TriangleMesh& mesh) {
  std::array<bool, 256> used{};
  for (const auto& part : mesh.parts) used[static_cast<std::size_t>(color_slot(part.color))] = true;
  for (const auto& part : mesh.line_parts) used[static_cast<std::size_t>(color_slot(part.color))] = true;
  std::vector<int> colors;
  for (int c = 0; c < 256; ++c)
    if (used[static_cast<std::size_t>(c)]) colors.push_back(c);
  return colors;
}

inline std::string material_name(int color) { return "color_" + std::to_string(color_slot(color)); }

// Shortest text that reads back to the same float, whatever the C locale.
inline void append_number(std::string& out, float value) {
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}
inline void append_number(std::string& out, std::uint64_t value) {
  char buffer[24];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace sylva::io::mesh_support
