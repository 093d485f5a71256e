// How a Scene is presented, beyond its camera and palette: the rendering
// settings, lights and label font that the renderers take and the view file
// gives (LPFG manual 8.1.2, 8.1.3, 8.1.7; CPFG manual 8.1).
#pragma once

#include <string>

#include "geometry/material.h"
#include "geometry/tessellation.h"
#include "geometry/vec3.h"

namespace sylva::geometry {

// cpfg's flat mode is drawn Shaded, its interpolated and fast modes Filled.
enum class RenderMode { Filled, Wireframe, Shaded, Shadows };

// light: (8.1.2). Without any light command, lpfg lights the scene with one
// directional light, Light{} below.
struct Light {
  enum class Kind { Directional, Point, Spot };
  Kind kind = Kind::Directional;
  Vec3 direction{0, 0, 1};  // V: for a directional light; P:'s direction for a spot
  Vec3 position{0, 0, 0};   // O: of a point light or spot
  float spot_exponent = 0;
  float spot_cutoff = 180;  // degrees
  Rgb ambient{1, 1, 1};
  Rgb diffuse{1, 1, 1};
  Rgb specular{1, 1, 1};
  float constant_attenuation = 1, linear_attenuation = 0, quadratic_attenuation = 0;  // T:
};

struct ShadowMap {
  int size = 1024;
  Rgb color{0.2f, 0.2f, 0.4f};
  float offset_factor = 5, offset_units = 10;
};

struct RenderSettings {
  bool z_buffer = false;
  RenderMode mode = RenderMode::Filled;
  ShadowMap shadow_map;
  bool stationary_lights = true;
  bool concave_polygons = false;
  bool auto_normals = false;
  int antialiasing = 0;  // samples per pixel, 0..10
  LineStyle line_style = LineStyle::Pixel;
  float wireframe_line_width = 1;
  bool capped_cylinders = false;
  bool backface_culling = false;
  // PostScript output (8.1.7).
  int ps_linecap = 0;  // 0 butt, 1 round, 2 projecting
  int gradient_direction = 0;  // 0 off, 1 vertical, 2 horizontal
  float gradient_magnitude = 0;
};

// The font labels are drawn in (Label in lpfg, @L in cpfg).
struct LabelFont {
  std::string family = "Times";
  float points = 12;  // Qt's point size, as both programs make their QFont
  bool bold = false, italic = false;
  // Pixels at the 96 dots per inch Qt assumes on a desktop.
  float pixels() const { return points * 96.0f / 72.0f; }
};

}  // namespace sylva::geometry
