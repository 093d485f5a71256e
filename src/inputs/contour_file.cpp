#include "inputs/contour_file.h"

#include "inputs/input_text.h"

namespace sylva::io {

namespace {

bool closed_type(WordReader& in, const Word& type) {
  std::string t = to_lower(type.text);
  // "oe" and "ce" (version 1.2) interpolate the end points; the B-spline
  // through them is still open or closed.
  if (t == "cr" || t == "ce" || t == "closed") return true;
  if (t == "or" || t == "oe" || t == "open") return false;
  in.fail(type, "expected a contour type (or, cr, oe, ce, open or closed), found '" + type.text + "'");
}

// Version 1.0: "n dim type", then n points of dim coordinates.
geometry::Contour read_first_version(WordReader& in, const std::string& name) {
  geometry::Contour contour;
  contour.name = name;
  contour.curve = geometry::Contour::Curve::BSpline;
  Word count_word = in.peek();
  int count = in.integer_at_most("the number of points", kMaxPoints);
  if (count < 2) in.fail(count_word, "expected at least 2 points, found " + count_word.text);
  Word dim_word = in.peek();
  int dim = in.integer("the dimension (2 or 3)");
  if (dim != 2 && dim != 3) in.fail(dim_word, "expected the dimension 2 or 3, found '" + dim_word.text + "'");
  contour.closed = closed_type(in, in.next("the contour type (open or closed)"));
  for (int i = 0; i < count; ++i) {
    std::string what = "point " + std::to_string(i + 1) + " of " + std::to_string(count);
    geometry::Vec3 p;
    p.x = in.number(what + " (x)");
    p.y = in.number(what + " (y)");
    if (dim == 3) p.z = in.number(what + " (z)");
    contour.points.push_back(p);
  }
  return contour;
}

// "cver 1 v" and what follows it.
geometry::Contour read_cuspy(WordReader& in, const std::string& default_name) {
  in.expect("cver");
  in.integer("the major version");
  in.integer("the minor version");
  geometry::Contour contour;
  contour.name = default_name;
  contour.curve = geometry::Contour::Curve::BSpline;
  int count = -1;
  bool have_type = false, have_points = false;
  // The keys come in a fixed order, but "name:", "background:",
  // "backgroundXY:" and "samples:" depend on the version: read what is there.
  // The editors write the point list after "points: n m" or, in version 1.3,
  // after the "type:" and "samples:" lines that follow it.
  while (!in.at_end()) {
    if (count >= 0 && !have_points && in.next_is_number()) {
      for (int i = 0; i < count; ++i) {
        std::string what = "control point " + std::to_string(i + 1) + " of " + std::to_string(count);
        geometry::Vec3 p = in.vec3(what);
        Word m_word = in.peek();
        int multiplicity = in.integer("the multiplicity of " + what);
        if (multiplicity < 1 || multiplicity > 3)
          in.fail(m_word, "expected a multiplicity of 1 to 3, found '" + m_word.text + "'");
        // A point of multiplicity m is m coincident B-spline control points.
        for (int k = 0; k < multiplicity; ++k) contour.points.push_back(p);
        contour.multiplicities.push_back(multiplicity);
      }
      have_points = true;
      continue;
    }
    std::string key = to_lower(in.peek().text);
    if (key == "cver" || key == "contourgalleryver") break;
    Word key_word = in.next("a key");
    if (key == "name:") {
      contour.name = in.rest_of_line("the contour's name");
    } else if (skip_editor_background(in, key)) {
    } else if (key == "points:") {
      if (count >= 0) in.fail(key_word, "the points are given twice");
      Word count_word = in.peek();
      count = in.integer_at_most("the number of control points", kMaxPoints);
      if (count < 1) in.fail(count_word, "expected at least 1 control point, found " + count_word.text);
      in.integer("the sum of the multiplicities");
    } else if (key == "type:") {
      contour.closed = closed_type(in, in.next("the contour type"));
      have_type = true;
    } else if (key == "samples:") {
      Word samples_word = in.peek();
      contour.samples = in.integer_at_most("the number of samples", kMaxSamples);
      if (contour.samples < 1)
        in.fail(samples_word, "expected a positive number of samples, found '" + samples_word.text + "'");
    } else {
      in.fail(key_word, "expected a contour key (name:, points:, type:, samples:), found '" + key_word.text + "'");
    }
  }
  if (count >= 0 && !have_points) in.expected("control point 1 of " + std::to_string(count) + " (x)");
  if (count < 0) in.expected("'points:'");
  if (!have_type) in.expected("'type:'");
  if (contour.points.size() < 2) in.fail(in.peek(), "expected at least 2 control points in contour '" + contour.name + "'");
  return contour;
}

}  // namespace

geometry::Contour read_contour_file(const std::string& path) {
  return parse_contour(read_input_file(path, "contour file"), path);
}

geometry::Contour parse_contour(const std::string& text, const std::string& path) {
  WordReader in(path, text);
  geometry::Contour contour =
      to_lower(in.peek().text) == "cver" ? read_cuspy(in, stem_of(path)) : read_first_version(in, stem_of(path));
  if (!in.at_end()) in.expected("the end of the contour");
  return contour;
}

std::vector<geometry::Contour> read_contour_set_file(const std::string& path) {
  return read_gallery<geometry::Contour>(path, "contour", "contour", read_cuspy);
}

}  // namespace sylva::io
