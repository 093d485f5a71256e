#include <png.h>

#include <csetjmp>
#include <string>
#include <vector>

#include "render/gl_renderer.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

struct PngWriteStruct {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngWriteStruct() { png_destroy_write_struct(&png, &info); }
};

// libpng reports errors by longjmp; exceptions must not cross its C frames.
void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  try {
    out->append(reinterpret_cast<const char*>(data), length);
  } catch (...) {
    png_error(png, "out of memory");
  }
}

void no_flush(png_structp) {}

}  // namespace

std::string gl::encode_png(const std::string& path, const Image& image, const std::string& provenance) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
    throw ModelError(SourceLocation{path, 0, 0}, "cannot write an empty or malformed image");
  // Everything the encoder touches is set up before setjmp: locals changed
  // after it would be indeterminate once libpng jumps back.
  std::string out;
  out.reserve(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) / 2);
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (std::size_t y = 0; y < rows.size(); ++y)
    rows[y] = const_cast<png_bytep>(image.rgb.data() + y * static_cast<std::size_t>(image.width) * 3);
  // The run record (api/provenance.h) as a tEXt chunk before the image data.
  std::string key = "sylva:provenance", text = provenance;
  png_text chunk{};
  chunk.compression = PNG_TEXT_COMPRESSION_NONE;
  chunk.key = key.data();
  chunk.text = text.data();
  chunk.text_length = text.size();

  PngWriteStruct w;
  w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (w.png) w.info = png_create_info_struct(w.png);
  if (!w.png || !w.info) throw ModelError(SourceLocation{path, 0, 0}, "cannot encode the PNG image: out of memory");
  if (setjmp(png_jmpbuf(w.png))) throw ModelError(SourceLocation{path, 0, 0}, "cannot encode the PNG image");
  png_set_write_fn(w.png, &out, append_bytes, no_flush);
  // Rendered plants are mostly flat background: fast deflate with the
  // cheap "sub" filter compresses them nearly as well as the slow settings.
  png_set_compression_level(w.png, 3);
  png_set_filter(w.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_IHDR(w.png, w.info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!provenance.empty()) png_set_text(w.png, w.info, &chunk, 1);
  png_write_info(w.png, w.info);
  png_write_image(w.png, rows.data());
  png_write_end(w.png, nullptr);
  return out;
}

}  // namespace sylva::io
