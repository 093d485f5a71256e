#include "inputs/palette_files.h"

#include <algorithm>

#include "inputs/input_text.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

constexpr std::size_t kColormapSize = 256 * 3;
constexpr std::size_t kMaterialRecordSize = 15;

float channel(unsigned char byte) { return static_cast<float>(byte) / 255.0f; }

geometry::Rgb rgb_at(const std::string& bytes, std::size_t offset) {
  auto b = [&](std::size_t i) { return static_cast<unsigned char>(bytes[offset + i]); };
  return {channel(b(0)), channel(b(1)), channel(b(2))};
}

}  // namespace

geometry::Palette read_colormap_file(const std::string& path) {
  std::string bytes = read_input_file(path, "colormap file");
  if (bytes.size() != kColormapSize)
    throw ModelError(SourceLocation{path, 0, 0}, "expected a colormap of 768 bytes (256 RGB triplets), found " +
                                                     std::to_string(bytes.size()) + " bytes");
  geometry::Palette palette;
  for (std::size_t i = 0; i < 256; ++i) {
    geometry::Rgb color = rgb_at(bytes, 3 * i);
    // lpfg colours lit geometry in colormap mode with the colour as both the
    // ambient and the diffuse term.
    palette.entries[i].ambient = color;
    palette.entries[i].diffuse = color;
  }
  return palette;
}

geometry::Palette read_material_file(const std::string& path) {
  std::string bytes = read_input_file(path, "material file");
  if (bytes.empty() || bytes.size() % kMaterialRecordSize != 0)
    throw ModelError(SourceLocation{path, 0, 0},
                     "expected 15-byte material records, found " + std::to_string(bytes.size()) +
                         " bytes (" + std::to_string(bytes.size() % kMaterialRecordSize) + " left over)");
  geometry::Palette palette;
  palette.from_materials = true;
  for (std::size_t offset = 0; offset < bytes.size(); offset += kMaterialRecordSize) {
    auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[offset + i]); };
    geometry::Material& m = palette.entries[byte(0)];
    m.transparency = channel(byte(1));
    m.ambient = rgb_at(bytes, offset + 2);
    m.diffuse = rgb_at(bytes, offset + 5);
    m.emission = rgb_at(bytes, offset + 8);
    m.specular = rgb_at(bytes, offset + 11);
    // OpenGL refuses a shininess above 128.
    m.shininess = std::min(128.0f, static_cast<float>(byte(14)));
  }
  return palette;
}

}  // namespace sylva::io
