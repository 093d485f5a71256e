// Colours and materials, indexed as the turtle's colour index (1..255; 0 is
// the background). A colormap (.map) sets colours; a material file (.mat)
// sets full materials. Every output reads the same Palette.
#pragma once

#include <array>
#include <map>

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

using MaterialBank = std::array<Material, 256>;

struct Palette {
  // Colour indices 0..255: lpfg's only palette, cpfg's colormap or material
  // set 1 (-m, -m1, -M, -M1).
  MaterialBank entries{};
  // cpfg's other colormaps or material sets (-m2 FILE ... -m11 FILE), by
  // number. cpfg keeps a colour as 256 * n + entry of colormap n, the turtle's
  // colour k (0..255) being 256 + k (cpfg/interpret.c, irisGL.c
  // my_getcolormapitem); the turtle here keeps k, so index i outside 0..255
  // is entry (i + 256) mod 256 of bank (i + 256) / 256.
  std::map<int, MaterialBank> banks;
  // True when colours came from a material file (lit rendering uses all the
  // material's terms) rather than a colormap (a flat colour per index).
  bool from_materials = false;

  static constexpr int kBankSize = 256;
  // The bank (1: `entries`) and the entry an index names.
  static int bank_of(int index);
  static int entry_of(int index);

  const Material& at(int index) const;
  // What an index of a bank no file gave gets: cpfg's default, grey
  // (200, 200, 200) in colormap mode, white diffuse with material sets.
  const Material& missing() const;
  // The colour to draw with when there is no lighting.
  Rgb color(int index) const { return at(index).diffuse; }
  Rgb background() const { return at(0).diffuse; }

  // lpfg's colours when no colormap or material file is given.
  static Palette default_palette();
};

}  // namespace sylva::geometry
