// Raster images of a Scene (LPFG manual 8.1.2, 8.1.3): OpenGL through OSMesa,
// offscreen, so no display is needed, and PNG files written with libpng. Both
// are done in the GL plugin (raster_plugin.h), opened by the first image.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/camera.h"
#include "geometry/material.h"
#include "geometry/render_settings.h"
#include "geometry/scene.h"
#include "geometry/tessellation.h"
#include "geometry/vec3.h"
#include "io/texture_image.h"

namespace sylva::io {

// 8-bit RGB pixels, rows top to bottom.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes per pixel, width * height pixels

  std::array<std::uint8_t, 3> pixel(int x, int y) const {
    std::size_t at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    return {rgb[at], rgb[at + 1], rgb[at + 2]};
  }
};

// What a render takes from the view file (LPFG manual 8.1.2, 8.1.3): the
// rendering commands (z buffer, render mode, shadow map, stationary lights,
// antialiasing, line style, wireframe line width, backface culling), the
// lights and the contour sides.
//  - Without the z buffer later modules of the string cover earlier ones, as
//    lpfg draws them; with it (always on in the shaded and shadows modes)
//    nearer surfaces cover farther ones.
//  - At most 8 lights are used; none stands for lpfg's single directional
//    light from +z (Light{}). Stationary lights are fixed in the scene;
//    others are in eye coordinates, moving with the camera. Lit, a colormap
//    colour (Palette::from_materials false) reflects a quarter of it as
//    ambient light; a material file's materials are used whole.
//  - Pixel-style segments are unlit lines their width in pixels wide, and
//    the camera frames their end points; polygon and cylinder segments are
//    triangles (see tessellate).
//  - Shapes a few pixels across get fewer sides than `contour_sides` where
//    that cannot be seen (see gl::tessellate_for_view), except in wireframe.
//  - Antialiasing n > 1 draws the image ceil(sqrt(n)) times larger each way
//    (at most 4) and averages it down.
//  - Shadows are cast from the first directional or spot light only, and
//    multiply what lies in them by the shadow map's colour.
//  - Labels are drawn last, over everything, in `label_font` (see
//    raster_labels.h).
struct ImageSettings {
  geometry::RenderSettings render;
  std::vector<geometry::Light> lights;
  int contour_sides = 16;  // of cylinders, discs and spheres; < 3 counts as 3
  geometry::LabelFont label_font;
  // The view file's textures, by id: multiplied into the colour of the
  // triangles that name them (OpenGL's modulate, lpfg's and cpfg's default),
  // nearest texel, repeating past the edges. Ids with no image draw untextured.
  std::vector<TextureImage> textures;
};

// Draws `scene` through the camera of `view` into a width x height image on
// the palette's background (colour index 0). Throws
// ModelError when OpenGL cannot be set up or the image is too large for it,
// and when the GL plugin cannot be opened.
Image render_image(const geometry::Scene& scene, const geometry::Palette& palette, const geometry::ViewParameters& view,
                   const ImageSettings& settings, int width, int height);

// Writes `image` as an 8-bit RGB PNG, whole or not at all ("-": to standard
// output), with a tEXt chunk "sylva:provenance" holding `provenance` (the run
// record's JSON, api/provenance.h) when it is not empty. Throws ModelError
// naming the path when it cannot be written.
void write_png(const std::string& path, const Image& image, const std::string& provenance = "");

}  // namespace sylva::io
