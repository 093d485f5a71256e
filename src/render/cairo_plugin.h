// The door to the cairo plugin, libsylva_cairo.so: PDF and PostScript
// drawings, and PNG images of a Drawing (plots of recorded series), kept out
// of the program (cairo, pixman, fontconfig, freetype, X11's client
// libraries) until one is asked for (support/plugin_library.h).
#pragma once

#include <cstdint>
#include <string>

#include "render/vector_drawing.h"
#include "support/plugin_library.h"

namespace sylva::io {

enum class DrawingFormat : std::uint8_t { Svg, Pdf, Ps, Eps, Png };

class VectorPrinter {
 public:
  // `drawing` as a whole PDF, PostScript, EPS or PNG file (not SVG). `path`
  // names the file in errors.
  virtual std::string document(const Drawing& drawing, DrawingFormat format, const std::string& path) = 0;

 protected:
  ~VectorPrinter() = default;
};

}  // namespace sylva::io

// The plugin's one printer.
extern "C" SYLVA_PLUGIN_EXPORT sylva::io::VectorPrinter* sylva_vector_printer();
