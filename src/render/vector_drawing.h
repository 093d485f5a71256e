// A Scene projected to the plane of a drawing: the 2D shapes every vector
// format draws, sorted back to front. Kept apart from the writers so SVG and
// the cairo formats draw exactly the same shapes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/camera.h"
#include "geometry/material.h"
#include "geometry/scene.h"
#include "geometry/tessellation.h"

namespace sylva::io {

enum class LineCap : std::uint8_t { Butt, Round, Square };

constexpr float kSeamStroke = 0.5f;  // pixels; see Shape::hide_seams

struct Shape {
  enum class Kind : std::uint8_t { Line, Polygon, Circle, Text };
  Kind kind = Kind::Line;
  // Line: the two ends. Polygon: the vertices of its loops, one after another.
  // Circle and Text: the centre or the text's anchor (baseline start).
  std::vector<geometry::Vec2> points;
  // Polygon with several loops (filled even-odd): where each loop ends in
  // `points`. Empty for a single loop.
  std::vector<std::uint32_t> loop_ends;
  float radius = 0;  // Circle
  // Line: its width. Polygon and Circle: 0 filled, else the outline's width.
  float stroke = 0;
  // Filled triangles of a mesh also get a thin outline of their own colour,
  // so that neighbours leave no antialiasing seam between them.
  bool hide_seams = false;  // with an outline kSeamStroke wide
  std::string text;
  geometry::Rgb color;
  float opacity = 1;
  geometry::Provenance from;
  float depth = 0;  // distance from the eye along the view direction
};

struct Drawing {
  int width = 0, height = 0;
  geometry::Rgb background;
  LineCap line_cap = LineCap::Round;
  float font_size = 12;  // lpfg's default label font: courier bold 12 pixels
  std::vector<Shape> shapes;  // back to front
  // The run record's JSON (api/provenance.h), when not empty: SVG's
  // <metadata>, PostScript's %%sylva:provenance comment, PDF's Subject.
  std::string provenance;
};

Drawing project_scene(const geometry::Scene& scene, const geometry::Palette& palette,
                      const geometry::ViewParameters& view, geometry::LineStyle line_style, int width, int height,
                      LineCap line_cap);

}  // namespace sylva::io
