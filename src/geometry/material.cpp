#include "geometry/material.h"

#include <cmath>

namespace sylva::geometry {

namespace {

Rgb from_hsv(float hue_degrees, float saturation, float value) {
  float h = std::fmod(hue_degrees, 360.0f) / 60.0f;
  int sector = static_cast<int>(h) % 6;
  float f = h - std::floor(h);
  float p = value * (1 - saturation), q = value * (1 - saturation * f), t = value * (1 - saturation * (1 - f));
  switch (sector) {
    case 0: return {value, t, p};
    case 1: return {q, value, p};
    case 2: return {p, value, t};
    case 3: return {p, q, value};
    case 4: return {t, p, value};
    default: return {value, p, q};
  }
}

}  // namespace

int Palette::bank_of(int index) {
  const int absolute = index + kBankSize;
  return absolute >= 0 ? absolute / kBankSize : -((-absolute + kBankSize - 1) / kBankSize);
}

int Palette::entry_of(int index) { return ((index % kBankSize) + kBankSize) % kBankSize; }

const Material& Palette::at(int index) const {
  if (index >= 0 && index < kBankSize) return entries[static_cast<std::size_t>(index)];
  auto bank = banks.find(bank_of(index));
  if (bank != banks.end()) return bank->second[static_cast<std::size_t>(entry_of(index))];
  return missing();
}

const Material& Palette::missing() const {
  constexpr float kGrey = 200 / 255.0f;
  static const Material missing_color{{kGrey, kGrey, kGrey}, {kGrey, kGrey, kGrey}, {}, {}, 0, 0};
  static const Material missing_material{{0, 0, 0}, {1, 1, 1}, {}, {}, 0, 0};
  return from_materials ? missing_material : missing_color;
}

// Neither the LPFG manual nor the VLAB tools manual lists lpfg's built-in
// colormap. Index 0 is the background and black, as in lpfg's window; 1, the
// turtle's initial colour, is white so a model drawn with no colormap shows.
// Every other index gets its own hue, a golden angle apart, so neighbouring
// indices (IncColor) are told apart at a glance.
Palette Palette::default_palette() {
  Palette palette;
  auto set = [&](int index, Rgb color) {
    Material& m = palette.entries[static_cast<std::size_t>(index)];
    m.ambient = color;
    m.diffuse = color;
  };
  set(0, {0, 0, 0});
  set(1, {1, 1, 1});
  for (int i = 2; i < 256; ++i) set(i, from_hsv(137.507764f * static_cast<float>(i - 2), 0.6f, 0.95f));
  return palette;
}

}  // namespace sylva::geometry
