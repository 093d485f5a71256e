#include "inputs/surface_file.h"

#include "inputs/input_text.h"

namespace sylva::io {

namespace {

geometry::Vec3 labelled_point(WordReader& in, const std::string& what) {
  geometry::Vec3 p;
  in.expect("X:");
  p.x = in.number("the x coordinate of the " + what);
  in.expect("Y:");
  p.y = in.number("the y coordinate of the " + what);
  in.expect("Z:");
  p.z = in.number("the z coordinate of the " + what);
  return p;
}

geometry::BezierPatch read_patch(WordReader& in) {
  geometry::BezierPatch patch;
  Word name = in.next("a patch name");
  if (parse_float(name.text)) in.fail(name, "expected a patch name, found the number '" + name.text + "'");
  patch.name = name.text;
  // The colour and neighbour lines ("TOP COLOR: 0 DIFFUSE: 0.0 ...",
  // "AL: ~ A: ~ AR: ~", ...) are words, "key:" value pairs, up to the first
  // control point.
  while (!in.at_end() && !in.next_is_number()) {
    Word w = in.next("a control point");
    if (w.text.ends_with(':')) in.next("a value after '" + w.text + "'");
  }
  for (int i = 0; i < 16; ++i) {
    std::string what = "control point " + std::to_string(i + 1) + " of 16 of patch '" + patch.name + "'";
    patch.points[static_cast<std::size_t>(i)] = in.vec3(what);
  }
  return patch;
}

}  // namespace

geometry::BezierSurface read_surface_file(const std::string& path) {
  WordReader in(path, read_input_file(path, "surface file"));
  geometry::BezierSurface surface;
  surface.name = stem_of(path);
  for (const char* bound : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"})
    in.number(std::string("the bounding box's ") + bound);
  // The older editors' "PRECISION S: s T: t" line: lpfg reads past it and
  // takes the precision from the view file, as Sylva does.
  if (to_lower(in.peek().text) == "precision") {
    in.next("PRECISION");
    in.expect("S:");
    in.integer("the precision along s");
    in.expect("T:");
    in.integer("the precision along t");
  }
  in.expect("CONTACT");
  in.expect("POINT");
  surface.contact = labelled_point(in, "contact point");
  in.expect("END");
  in.expect("POINT");
  labelled_point(in, "end point");
  in.expect("HEADING");
  surface.heading = labelled_point(in, "heading");
  in.expect("UP");
  surface.up = labelled_point(in, "up vector");
  in.expect("SIZE:");
  Word size_word = in.peek();
  surface.size = in.number("the size");
  if (surface.size <= 0) in.fail(size_word, "expected a positive size, found '" + size_word.text + "'");
  while (!in.at_end()) surface.patches.push_back(read_patch(in));
  if (surface.patches.empty()) in.expected("a patch");
  return surface;
}

}  // namespace sylva::io
