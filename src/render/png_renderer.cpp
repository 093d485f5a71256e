#include "render/png_renderer.h"

#include <array>
#include <cstdint>

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

void write_png(const std::string& path, const Image& image) {
  write_output_file(path, renderer().encode_png(path, image));
}

// ---- provenance (api/provenance.h): a tEXt chunk added to the encoded bytes

namespace {

std::uint32_t png_crc(std::string_view bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) c = table[(c ^ b) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void append_u32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((v >> shift) & 0xFF);
}

}  // namespace

std::string png_with_text(std::string_view png, const std::string& keyword, const std::string& text) {
  constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
  // The signature, then IHDR: 4 bytes of length (13), "IHDR", 13 bytes, CRC.
  constexpr std::size_t kAfterIhdr = 8 + 4 + 4 + 13 + 4;
  if (png.size() < kAfterIhdr || png.substr(0, 8) != kSignature || png.substr(12, 4) != "IHDR") return std::string(png);
  std::string chunk = "tEXt" + keyword;
  chunk += '\0';
  chunk += text;
  std::string out;
  out.reserve(png.size() + chunk.size() + 8);
  out.append(png.substr(0, kAfterIhdr));
  append_u32(out, static_cast<std::uint32_t>(chunk.size() - 4));
  out += chunk;
  append_u32(out, png_crc(chunk));
  out.append(png.substr(kAfterIhdr));
  return out;
}

void write_png(const std::string& path, const Image& image, const std::string& provenance) {
  std::string png = renderer().encode_png(path, image);
  if (!provenance.empty()) png = png_with_text(png, "sylva:provenance", provenance);
  write_output_file(path, png);
}

}  // namespace sylva::io
