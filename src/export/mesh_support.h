// What the mesh writers share: module names for provenance, the colour
// indices a mesh uses, and locale-independent shortest number text.
#pragma once

#include <charconv>
#include <set>
#include <string>
#include <vector>

#include "geometry/material.h"
#include "geometry/tessellation.h"
#include "lstring/module_types.h"

namespace sylva::io::mesh_support {

// "module<id>" for an id the registry does not know, so a mesh from a
// mismatched registry still writes.
inline std::string module_name(const ModuleTypes& types, abi::ModuleId id) {
  if (id < types.size() && !types.name(id).empty()) return types.name(id);
  return "module" + std::to_string(id);
}

// Ascending colour indices used by triangle or line parts.
inline std::vector<int> colors_used(const geometry::TriangleMesh& mesh) {
  std::set<int> used;
  for (const auto& part : mesh.parts) used.insert(part.color);
  for (const auto& part : mesh.line_parts) used.insert(part.color);
  return {used.begin(), used.end()};
}

// color_N for the colours of the first colormap (0..255); color_B_N for
// entry N of cpfg's colormap or material set B (-m2 ...).
inline std::string material_name(int color) {
  if (color >= 0 && color < geometry::Palette::kBankSize) return "color_" + std::to_string(color);
  return "color_" + std::to_string(geometry::Palette::bank_of(color)) + "_" +
         std::to_string(geometry::Palette::entry_of(color));
}

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
