// SVG is written as plain text so that every element can say which module
// made it (cairo's SVG surface has no way to add attributes); PDF and
// PostScript go through cairo, in its plugin (cairo_plugin.h). Both draw the
// same projected Drawing.
#include "render/vector_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "io/output_file.h"
#include "render/cairo_plugin.h"
#include "render/vector_drawing.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

// Three decimals are a thousandth of a pixel: finer than any output shows.
std::string num(float v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f", static_cast<double>(v));
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string hex_color(geometry::Rgb c) {
  auto byte = [](float v) { return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255)); };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return buf;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += ch;
    }
  }
  return out;
}

const char* cap_name(LineCap cap) {
  switch (cap) {
    case LineCap::Butt: return "butt";
    case LineCap::Square: return "square";
    case LineCap::Round: break;
  }
  return "round";
}

// fill="..." or stroke="..." with its opacity when not opaque.
std::string paint(const char* attribute, const Shape& s) {
  std::string out = std::string(" ") + attribute + "=\"" + hex_color(s.color) + "\"";
  if (s.opacity < 1) out += std::string(" ") + attribute + "-opacity=\"" + num(s.opacity) + "\"";
  return out;
}

void svg_shape(std::string& out, const Shape& s, const Drawing& d) {
  using Kind = Shape::Kind;
  // Filled shapes, or outlines of a width (circles drawn with CircleB).
  auto fill_or_outline = [&] {
    if (s.stroke > 0) return std::string(" fill=\"none\"") + paint("stroke", s) + " stroke-width=\"" + num(s.stroke) + "\"";
    std::string a = paint("fill", s);
    if (s.hide_seams) a += paint("stroke", s) + " stroke-width=\"" + num(kSeamStroke) + "\" stroke-linejoin=\"round\"";
    return a;
  };
  switch (s.kind) {
    case Kind::Line:
      out += "<line x1=\"" + num(s.points[0].x) + "\" y1=\"" + num(s.points[0].y) + "\" x2=\"" + num(s.points[1].x) +
             "\" y2=\"" + num(s.points[1].y) + "\"" + paint("stroke", s) + " stroke-width=\"" + num(s.stroke) +
             "\" stroke-linecap=\"" + cap_name(d.line_cap) + "\"/>\n";
      break;
    case Kind::Polygon:
      if (s.loop_ends.empty()) {
        out += "<polygon points=\"";
        for (std::size_t i = 0; i < s.points.size(); ++i)
          out += (i ? " " : "") + num(s.points[i].x) + "," + num(s.points[i].y);
        out += "\"" + fill_or_outline() + "/>\n";
      } else {
        out += "<path d=\"";
        std::size_t i = 0;
        for (std::uint32_t end : s.loop_ends) {
          for (std::size_t first = i; i < end; ++i)
            out += (i == first ? "M" : " L") + num(s.points[i].x) + " " + num(s.points[i].y);
          out += " Z ";
        }
        out.pop_back();
        out += "\" fill-rule=\"evenodd\"" + fill_or_outline() + "/>\n";
      }
      break;
    case Kind::Circle:
      out += "<circle cx=\"" + num(s.points[0].x) + "\" cy=\"" + num(s.points[0].y) + "\" r=\"" + num(s.radius) + "\"" +
             fill_or_outline() + "/>\n";
      break;
    case Kind::Text:
      out += "<text x=\"" + num(s.points[0].x) + "\" y=\"" + num(s.points[0].y) +
             "\" font-family=\"Courier, monospace\" font-weight=\"bold\" font-size=\"" + num(d.font_size) + "\"" +
             paint("fill", s) + ">" + xml_escape(s.text) + "</text>\n";
      break;
  }
}

std::string svg_document(const Drawing& d, const ModuleTypes* types) {
  std::string out;
  out.reserve(128 + d.shapes.size() * 96);
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + std::to_string(d.width) +
         "\" height=\"" + std::to_string(d.height) + "\" viewBox=\"0 0 " + std::to_string(d.width) + " " +
         std::to_string(d.height) + "\">\n";
  if (!d.provenance.empty())  // api/provenance.h
    out += "<metadata id=\"sylva-provenance\">" + xml_escape(d.provenance) + "</metadata>\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + std::to_string(d.width) + "\" height=\"" + std::to_string(d.height) +
         "\" fill=\"" + hex_color(d.background) + "\"/>\n";
  // One group per run of shapes made by the same module; the painter's order
  // may split a module's shapes into several runs.
  const Shape* run = nullptr;
  for (const Shape& s : d.shapes) {
    if (!run || s.from.module_index != run->from.module_index || s.from.module_id != run->from.module_id) {
      if (run) out += "</g>\n";
      out += "<g data-index=\"" + std::to_string(s.from.module_index) + "\" data-module-id=\"" +
             std::to_string(s.from.module_id) + "\"";
      if (types && s.from.module_id < types->size())
        out += " data-module=\"" + xml_escape(types->name(s.from.module_id)) + "\"";
      out += ">\n";
      run = &s;
    }
    svg_shape(out, s, d);
  }
  if (run) out += "</g>\n";
  out += "</svg>\n";
  return out;
}

// `line` added to a PostScript file's header comments, before %%EndComments
// (cairo_ps_surface_dsc_comment takes no more than 255 characters).
std::string with_ps_comment(const std::string& document, const std::string& line) {
  std::size_t at = document.find("\n%%EndComments");
  if (at == std::string::npos) at = document.find('\n');
  if (at == std::string::npos) return document;
  return document.substr(0, at + 1) + line + "\n" + document.substr(at + 1);
}

VectorPrinter& printer() {
  static VectorPrinter& plugin = plugin_object<VectorPrinter>("libsylva_cairo.so", "sylva_vector_printer",
                                                              "writes PDF and PostScript drawings and PNG plots");
  return plugin;
}

DrawingFormat format_of(const std::string& path) {
  if (path == "-") return DrawingFormat::Svg;
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".svg") return DrawingFormat::Svg;
  if (ext == ".pdf") return DrawingFormat::Pdf;
  if (ext == ".ps") return DrawingFormat::Ps;
  if (ext == ".eps") return DrawingFormat::Eps;
  throw ModelError(SourceLocation{path, 0, 0},
                   "unknown vector drawing format '" + ext + "': expected .svg, .pdf, .ps or .eps");
}

}  // namespace

void write_vector_drawing(const std::string& path, const geometry::Scene& scene, const geometry::Palette& palette,
                          const geometry::ViewParameters& view, geometry::LineStyle line_style, int width, int height,
                          const ModuleTypes* types, int ps_linecap, const std::string& provenance) {
  const DrawingFormat format = format_of(path);
  const LineCap cap = ps_linecap == 0 ? LineCap::Butt : ps_linecap == 2 ? LineCap::Square : LineCap::Round;
  Drawing drawing = project_scene(scene, palette, view, line_style, width, height, cap);
  drawing.provenance = provenance;
  if (format == DrawingFormat::Svg) {
    write_output_file(path, svg_document(drawing, types));
    return;
  }
  std::string document = printer().document(drawing, format, path);
  if (!provenance.empty() && (format == DrawingFormat::Ps || format == DrawingFormat::Eps))
    document = with_ps_comment(document, std::string("%%sylva:provenance ") + provenance);
  write_output_file(path, document);
}

std::string drawing_png(const Drawing& drawing, const std::string& path) {
  return printer().document(drawing, DrawingFormat::Png, path);
}

}  // namespace sylva::io
