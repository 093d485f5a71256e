// Colours and materials, indexed as the turtle's colour index (1..255; 0 is
// the background). A colormap (.map) sets colours; a material file (.mat)
// sets full materials. Every output reads the same Palette.
#pragma once

#include <array>

namespace sylva::geometry {

struct Rgb {
  float r = 0, g = 0, b = 0;  // 0..1
  constexpr bool operator==(const Rgb&) const = default;
};

struct Material {
  Rgb ambient{0.2f, 0.2f, 0.2f};
  Rgb diffuse{0.8f, 0.8f, 0.8f};
  Rgb specular{0, 0, 0};
  Rgb emission{0, 0, 0};
  float shininess = 0;      // OpenGL's 0..128
  float transparency = 0;   // 0 opaque .. 1 invisible
};

struct Palette {
  std::array<Material, 256> entries{};
  // True when colours came from a material file (lit rendering uses all the
  // material's terms) rather than a colormap (a flat colour per index).
  bool from_materials = false;

  const Material& at(int index) const { return entries[static_cast<std::size_t>(index & 255)]; }
  // The colour to draw with when there is no lighting.
  Rgb color(int index) const { return at(index).diffuse; }
  Rgb background() const { return at(0).diffuse; }

  // lpfg's colours when no colormap or material file is given.
  static Palette default_palette();
};

}  // namespace sylva::geometry
