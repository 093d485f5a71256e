#include "render/png_renderer.h"

#include "io/output_file.h"
#include "render/raster_plugin.h"

namespace sylva::io {

namespace {

RasterRenderer& renderer() {
  static RasterRenderer& plugin =
      plugin_object<RasterRenderer>("libsylva_gl.so", "sylva_raster_renderer", "renders PNG images");
  return plugin;
}

}  // namespace

Image render_image(const geometry::Scene& scene, const geometry::Palette& palette, const geometry::ViewParameters& view,
                   const ImageSettings& settings, int width, int height) {
  return renderer().render(scene, palette, view, settings, width, height);
}

void write_png(const std::string& path, const Image& image, const std::string& provenance) {
  write_output_file(path, renderer().encode_png(path, image, provenance));
}

}  // namespace sylva::io
