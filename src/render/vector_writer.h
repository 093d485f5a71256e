// Vector drawings of a Scene (LPFG manual 8.1.7): SVG, PDF, PostScript or
// Encapsulated PostScript, chosen by the file's extension.
#pragma once

#include <string>

#include "geometry/camera.h"
#include "geometry/material.h"
#include "geometry/scene.h"
#include "geometry/tessellation.h"
#include "lstring/module_types.h"

namespace sylva::io {

// Writes `scene` as seen through the camera of `view` in a width x height
// drawing (one pixel is one point in PDF and PostScript), far primitives
// first. Segments are lines as wide as the turtle's width in pixels for
// LineStyle::Pixel (lpfg's glLineWidth), lines of their width in world units
// seen from the camera for LineStyle::Cylinder (a tapering one is the outline
// such a line would cover), and flat quads facing the turtle's up vector for
// LineStyle::Polygon. SVG elements are grouped by the module
// that made them (data-index, data-module-id and, given `types`, data-module).
// `ps_linecap` is the view file's "PS linecap:" (8.1.7; 0 butt, 1 round, 2
// projecting), for every format; lpfg's default is butt, but round (the
// default here) joins consecutive segments without notches.
// The file is written whole or not at all; "-" writes SVG to standard output.
// Throws ModelError naming the path on an unknown extension or a failed write.
// `provenance`, when not empty, is the run record's JSON (api/provenance.h):
// SVG <metadata id="sylva-provenance">, a PostScript and EPS header comment
// line `%%sylva:provenance {json}`, PDF's Subject `sylva:provenance {json}`.
void write_vector_drawing(const std::string& path, const geometry::Scene& scene, const geometry::Palette& palette,
                          const geometry::ViewParameters& view, geometry::LineStyle line_style, int width, int height,
                          const ModuleTypes* types = nullptr, int ps_linecap = 1, const std::string& provenance = {});

struct Drawing;

// `drawing` as the bytes of a PNG file, drawn by cairo in its plugin like PDF
// and PostScript (one drawing pixel is one image pixel). `path` names the file
// in errors; nothing is written.
std::string drawing_png(const Drawing& drawing, const std::string& path);

}  // namespace sylva::io
