// The door to the GL plugin, libsylva_gl.so: the raster renderer (OpenGL
// through OSMesa, which brings LLVM), its PNG encoder (libpng) and its labels
// (cairo), kept out of the program until an image is asked for
// (support/plugin_library.h).
#pragma once

#include <string>

#include "render/png_renderer.h"
#include "support/plugin_library.h"

namespace sylva::io {

class RasterRenderer {
 public:
  // See render_image.
  virtual Image render(const geometry::Scene& scene, const geometry::Palette& palette,
                       const geometry::ViewParameters& view, const ImageSettings& settings, int width, int height) = 0;
  // `image` as PNG bytes, with the run record `provenance` in a tEXt chunk
  // when it is not empty; `path` names the file in errors.
  virtual std::string encode_png(const std::string& path, const Image& image, const std::string& provenance) = 0;

 protected:
  ~RasterRenderer() = default;
};

}  // namespace sylva::io

// The plugin's one renderer.
extern "C" SYLVA_PLUGIN_EXPORT sylva::io::RasterRenderer* sylva_raster_renderer();
