// Inside the GL plugin (raster_plugin.h): the work of its RasterRenderer.
#pragma once

#include <string>

#include "render/png_renderer.h"

namespace sylva::io::gl {

// render_image's work, through OSMesa.
Image draw_image(const geometry::Scene& scene, const geometry::Palette& palette, const geometry::ViewParameters& view,
                 const ImageSettings& settings, int width, int height);

// `image` as an 8-bit RGB PNG, with libpng, with a tEXt chunk
// "sylva:provenance" holding `provenance` when it is not empty. `path` names
// the file in errors.
std::string encode_png(const std::string& path, const Image& image, const std::string& provenance);

}  // namespace sylva::io::gl
