#include "render/raster_labels.h"

#include <cairo.h>

#include <algorithm>
#include <cstdint>
#include <memory>

namespace sylva::io {

void draw_labels(Image& image, const std::vector<geometry::Label>& labels, const geometry::Palette& palette,
                 const geometry::Camera& camera, const geometry::LabelFont& font) {
  if (labels.empty() || image.width <= 0 || image.height <= 0) return;
  using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
  using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, image.width, image.height), cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) return;
  // RGB24 keeps each pixel in a native 32-bit word, 0x00RRGGBB.
  auto* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  auto word = [&](int x, int y) { return reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride) + x; };
  cairo_surface_flush(surface.get());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto p = image.pixel(x, y);
      *word(x, y) = (std::uint32_t{p[0]} << 16) | (std::uint32_t{p[1]} << 8) | p[2];
    }
  cairo_surface_mark_dirty(surface.get());
  {
    Context cr(cairo_create(surface.get()), cairo_destroy);
    cairo_select_font_face(cr.get(), font.family.c_str(), font.italic ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
                           font.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr.get(), font.pixels());
    for (const geometry::Label& label : labels) {
      if (label.text.empty()) continue;
      const geometry::Vec3 at = camera.to_pixels(label.position);
      if (!(at.z >= 0 && at.z <= 1)) continue;  // before the near or past the far plane
      const geometry::Material& m = palette.at(label.color);
      const geometry::Rgb c = palette.from_materials ? m.emission : m.diffuse;
      cairo_set_source_rgb(cr.get(), c.r, c.g, c.b);
      cairo_move_to(cr.get(), at.x, at.y);
      cairo_show_text(cr.get(), label.text.c_str());
    }
  }
  cairo_surface_flush(surface.get());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint32_t w = *word(x, y);
      const std::size_t at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 3;
      image.rgb[at] = static_cast<std::uint8_t>(w >> 16);
      image.rgb[at + 1] = static_cast<std::uint8_t>(w >> 8);
      image.rgb[at + 2] = static_cast<std::uint8_t>(w);
    }
}

}  // namespace sylva::io
