// The cairo plugin (cairo_plugin.h): a Drawing as PDF, PostScript or PNG.
#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo.h>

#include <cmath>
#include <memory>

#include "render/cairo_plugin.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void cairo_path_of(cairo_t* cr, const Shape& s) {
  std::size_t i = 0;
  std::vector<std::uint32_t> ends = s.loop_ends;
  if (ends.empty()) ends.push_back(static_cast<std::uint32_t>(s.points.size()));
  for (std::uint32_t end : ends) {
    for (std::size_t first = i; i < end; ++i) {
      if (i == first) cairo_move_to(cr, s.points[i].x, s.points[i].y);
      else cairo_line_to(cr, s.points[i].x, s.points[i].y);
    }
    cairo_close_path(cr);
  }
}

void cairo_shape(cairo_t* cr, const Shape& s, const Drawing& d) {
  using Kind = Shape::Kind;
  cairo_set_source_rgba(cr, s.color.r, s.color.g, s.color.b, s.opacity);
  auto fill_or_outline = [&] {
    if (s.stroke > 0) {
      cairo_set_line_width(cr, s.stroke);
      cairo_stroke(cr);
    } else if (s.hide_seams) {
      cairo_fill_preserve(cr);
      cairo_set_line_width(cr, kSeamStroke);
      cairo_stroke(cr);
    } else {
      cairo_fill(cr);
    }
  };
  switch (s.kind) {
    case Kind::Line:
      cairo_set_line_width(cr, s.stroke);
      cairo_set_line_cap(cr, d.line_cap == LineCap::Butt     ? CAIRO_LINE_CAP_BUTT
                             : d.line_cap == LineCap::Square ? CAIRO_LINE_CAP_SQUARE
                                                             : CAIRO_LINE_CAP_ROUND);
      cairo_move_to(cr, s.points[0].x, s.points[0].y);
      cairo_line_to(cr, s.points[1].x, s.points[1].y);
      cairo_stroke(cr);
      break;
    case Kind::Polygon:
      cairo_path_of(cr, s);
      fill_or_outline();
      break;
    case Kind::Circle:
      cairo_new_sub_path(cr);
      cairo_arc(cr, s.points[0].x, s.points[0].y, s.radius, 0, 2 * M_PI);
      fill_or_outline();
      break;
    case Kind::Text:
      cairo_move_to(cr, s.points[0].x, s.points[0].y);
      cairo_show_text(cr, s.text.c_str());
      cairo_new_path(cr);
      break;
  }
}

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

// Every format draws the same way, so a plot looks alike in all of them.
cairo_status_t draw(cairo_t* cr, const Drawing& d) {
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_select_font_face(cr, "Courier", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, d.font_size);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_set_source_rgb(cr, d.background.r, d.background.g, d.background.b);
  cairo_paint(cr);
  for (const Shape& s : d.shapes) cairo_shape(cr, s, d);
  return cairo_status(cr);
}

[[noreturn]] void cannot_draw(const std::string& path, cairo_status_t status) {
  throw ModelError(SourceLocation{path, 0, 0}, std::string("cannot draw the file: ") + cairo_status_to_string(status));
}

std::string cairo_document(const Drawing& d, DrawingFormat format, const std::string& path) {
  std::string out;
  Surface surface(format == DrawingFormat::Pdf
                      ? cairo_pdf_surface_create_for_stream(append_to_string, &out, d.width, d.height)
                      : cairo_ps_surface_create_for_stream(append_to_string, &out, d.width, d.height),
                  cairo_surface_destroy);
  if (format == DrawingFormat::Pdf) cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "Sylva");
  // Provenance (api/provenance.h): cairo 1.16 has no custom PDF metadata, so
  // the record goes in the Subject, after its key.
  if (format == DrawingFormat::Pdf && !d.provenance.empty())
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_SUBJECT,
                                   ("sylva:provenance " + d.provenance).c_str());
  if (format == DrawingFormat::Eps) cairo_ps_surface_set_eps(surface.get(), 1);
  {
    Context cr(cairo_create(surface.get()), cairo_destroy);
    draw(cr.get(), d);
    cairo_show_page(cr.get());
  }
  cairo_surface_finish(surface.get());
  cairo_status_t status = cairo_surface_status(surface.get());
  if (status != CAIRO_STATUS_SUCCESS) cannot_draw(path, status);
  return out;
}

std::string cairo_png(const Drawing& d, const std::string& path) {
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, d.width, d.height), cairo_surface_destroy);
  cairo_status_t status = cairo_surface_status(surface.get());
  if (status != CAIRO_STATUS_SUCCESS) cannot_draw(path, status);
  {
    Context cr(cairo_create(surface.get()), cairo_destroy);
    // Grey antialiasing: subpixel text (fontconfig's choice on some machines)
    // would fringe text with colours, and in a plot colours name the series.
    std::unique_ptr<cairo_font_options_t, decltype(&cairo_font_options_destroy)> options(cairo_font_options_create(),
                                                                                          cairo_font_options_destroy);
    cairo_font_options_set_antialias(options.get(), CAIRO_ANTIALIAS_GRAY);
    cairo_set_font_options(cr.get(), options.get());
    status = draw(cr.get(), d);
  }
  cairo_surface_flush(surface.get());
  std::string out;
  if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface.get());
  if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_write_to_png_stream(surface.get(), append_to_string, &out);
  if (status != CAIRO_STATUS_SUCCESS) cannot_draw(path, status);
  return out;
}

class CairoPrinter final : public VectorPrinter {
 public:
  std::string document(const Drawing& drawing, DrawingFormat format, const std::string& path) override {
    return format == DrawingFormat::Png ? cairo_png(drawing, path) : cairo_document(drawing, format, path);
  }
};

}  // namespace

}  // namespace sylva::io

extern "C" SYLVA_PLUGIN_EXPORT sylva::io::VectorPrinter* sylva_vector_printer() {
  static sylva::io::CairoPrinter printer;
  return &printer;
}
