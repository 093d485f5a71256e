#include "inputs/curve_file.h"

#include <algorithm>

#include "inputs/contour_file.h"
#include "inputs/input_text.h"

namespace sylva::io {

namespace {

geometry::Contour read_cpfg_curve(WordReader& in, const std::string& name) {
  geometry::Contour curve;
  curve.name = name;
  curve.curve = geometry::Contour::Curve::BSpline;
  curve.closed = false;
  bool phantom = false;
  int count = -1, dimension = 2;
  // Keys until the first point's first number.
  while (!in.at_end() && !in.next_is_number()) {
    Word key = in.next("a curve key");
    const std::string k = to_lower(key.text);
    if (k == "version:") {
      in.next("the version");
    } else if (k == "contact:" || k == "end:" || k == "heading:" || k == "up:") {
      in.vec3(k.substr(0, k.size() - 1));  // the curve's placement: not used by the curve functions
    } else if (k == "size:") {
      in.number("the size");
    } else if (k == "range:") {
      in.number("the start of the range");
      in.number("the end of the range");
    } else if (k == "points:") {
      if (count >= 0) in.fail(key, "curves within a curve are not supported");
      Word count_word = in.peek();
      count = in.integer_at_most("the number of points", kMaxPoints);
      if (count < 1) in.fail(count_word, "expected a positive number of points, found '" + count_word.text + "'");
    } else if (k == "dim:" || k == "dimension:") {
      Word at = in.peek();
      dimension = in.integer("the dimension");
      if (dimension < 2 || dimension > 4) in.fail(at, "expected a dimension from 2 to 4, found '" + at.text + "'");
    } else if (k == "type:") {
      Word type = in.next("the curve type");
      const std::string t = to_lower(type.text);
      if (t == "bspline-closed") curve.closed = true;
      else if (t == "bspline-phantom") phantom = true;
      else if (t == "bspline-endpoint" || t == "bezier" || t == "bezier-surface")
        in.fail(type, "curves of type '" + type.text + "' are not supported");
    } else if (k.starts_with("//")) {
      in.rest_of_line("a comment");
    } else {
      in.fail(key, "expected a curve key (version:, contact:, end:, heading:, up:, size:, points:, range:, "
                   "dimension:, type:), found '" + key.text + "'");
    }
  }
  if (count < 0) in.expected("'points:'");
  for (int i = 0; i < count; ++i) {
    const std::string what = "point " + std::to_string(i + 1) + " of " + std::to_string(count);
    geometry::Vec3 p;
    p.x = in.number(what + " (x)");
    p.y = in.number(what + " (y)");
    int multiplicity = 1;
    if (dimension > 2) p.z = in.number(what + " (z)");
    if (dimension > 3) {
      const Word at = in.peek();
      const float m = in.number(what + " (multiplicity)");
      if (m >= kMaxMultiplicity)
        in.fail(at, "the multiplicity of " + what + " is past the limit of " + std::to_string(kMaxMultiplicity) +
                        ", far above any real curve's (is the file damaged?)");
      multiplicity = std::max(0, static_cast<int>(m));
    }
    curve.points.insert(curve.points.end(), static_cast<std::size_t>(multiplicity), p);
  }
  if (phantom && curve.points.size() >= 2) {
    const std::size_t n = curve.points.size();
    const geometry::Vec3 first = curve.points[0] * 2 - curve.points[1];
    const geometry::Vec3 last = curve.points[n - 1] * 2 - curve.points[n - 2];
    curve.points.insert(curve.points.begin(), first);
    curve.points.push_back(last);
  }
  if (!in.at_end()) in.expected("the end of the curve");
  return curve;
}

}  // namespace

geometry::Contour read_curve_file(const std::string& path) {
  const std::string text = read_input_file(path, "curve file");
  WordReader in(path, text);
  if (!in.at_end() && to_lower(in.peek().text) == "version:") return read_cpfg_curve(in, stem_of(path));
  return parse_contour(text, path);
}

}  // namespace sylva::io
