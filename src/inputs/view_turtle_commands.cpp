// The view file's turtle commands: contour sides, tropisms and torques
// (LPFG manual 8.1.4, CPFG manual 8.1.8), lpfg's stropism, and cpfg's
// turtle defaults (CPFG manual 8.1.1) and deprecated tropism (8.1.10).
#include <algorithm>
#include <cmath>

#include "inputs/view_parser.h"

namespace sylva::io {

void Parser::contour_sides(WordReader& in) {
  Word at = in.peek();
  const int n = in.integer_at_most("the number of sides", kMaxSamples);
  const int least = 3, most = cpfg() ? n : 10000;  // lpfg's limits
  view_.contour_sides = std::clamp(n, least, std::max(least, most));
  if (view_.contour_sides != n)
    warn(at, std::to_string(n) + " contour sides cannot be drawn; " + std::to_string(view_.contour_sides) + " are used, as in " +
                 program());
}

// cpfg's older form: 2^(level + 1) sides, at least 3.
void Parser::polygonization_level(WordReader& in) {
  const int level = in.integer_at_most("the polygonization level", 16);  // 2^17 sides
  view_.contour_sides = std::max(3, static_cast<int>(std::lround(std::pow(2.0, level + 1))));
}

// "tropism: T: x y z A: angle I: intensity E: elasticity S: step", a part's
// key being its letter (part_key). lpfg's direction is (0,-1,0) unless given,
// times the intensity; cpfg's is T: made unit length times the intensity
// (given after T:), that product kept within -1 and 1, and nothing without
// T:.
TropismCommand Parser::tropism_parts(WordReader& in, bool torque) {
  TropismCommand t;
  t.torque = torque;
  double cpfg_length = 0;  // cpfg's scale of T: (0 until T: is read)
  while (!in.at_end()) {
    Word key = in.next("a tropism part");
    switch (part_key(key.text, view_.dialect)) {
      case 'T':
        t.direction = direction(in, "the tropism vector");
        cpfg_length = 1 / geometry::length(t.direction);
        break;
      case 'A': {
        Word at = in.peek();
        t.angle = in.number("the tropism angle");
        if (!cpfg() && torque) in.fail(key, "lpfg allows no angle A: in a torque");
        if (!cpfg() && std::fabs(t.angle) > 180) in.fail(at, "expected a tropism angle from -180 to 180 degrees, found '" + at.text + "'");
        break;
      }
      case 'I': {
        Word at = in.peek();
        const float intensity = in.number("the intensity");
        if (cpfg()) {
          cpfg_length = std::clamp(cpfg_length * intensity, -1.0, 1.0);
          if (cpfg_length == 0) in.fail(at, "a tropism of intensity 0 (given after T:, as cpfg needs it)");
        } else {
          if (intensity == 0) in.fail(at, "expected a non-zero intensity, found '" + at.text + "'");
          t.intensity = intensity;
        }
        break;
      }
      case 'E':
        t.elasticity = in.number("the elasticity");
        break;
      case 'S':
        t.step = in.number("the elasticity step");
        break;
      default:
        in.fail(key, std::string("expected T:, ") + (torque ? "" : "A:, ") + "I:, E: or S:, found '" + key.text + "'");
    }
  }
  if (cpfg()) {
    t.direction = t.direction * static_cast<float>(cpfg_length);
    t.intensity = 1;
  }
  return t;
}

void Parser::stropism(WordReader& in) {
  TropismCommand t;
  t.direction = in.vec3("the tropism vector");
  t.elasticity = in.number("the elasticity");
  view_.simple_tropism = t;
}

void Parser::tropism_direction(WordReader& in) {
  view_.old_tropism.direction = geometry::normalized(direction(in, "the tropism direction"));
}

// cpfg's first colour index, and the back side's (cpfg's double-sided
// surfaces) when a second is given.
void Parser::initial_color(WordReader& in) {
  view_.initial_color = in.integer("the initial colour index");
  if (!in.at_end()) view_.initial_back_color = in.integer("the back side's colour index");
}

// cpfg: the width, then an optional style word: p... (pixels) draws lines,
// s... (shaded) cylinders, and any other or none polygons.
void Parser::initial_line_width(WordReader& in) {
  view_.initial_line_width = in.number("the initial line width");
  view_.render.line_style = geometry::LineStyle::Polygon;
  if (in.at_end()) return;
  const std::string style = in.next("a line style").text;
  if (style.starts_with("p")) view_.render.line_style = geometry::LineStyle::Pixel;
  else if (style.starts_with("s")) view_.render.line_style = geometry::LineStyle::Cylinder;
}

void Parser::angle_factor(WordReader& in) {
  // The same setting as angle increment, as a fraction of a full turn.
  Word at = in.peek();
  const float factor = in.number("the angle factor");
  if (factor == 0) in.fail(at, "expected a non-zero angle factor, found '" + at.text + "'");
  view_.angle_increment = 360 / factor;
}

void Parser::color_increment(WordReader& in) {
  view_.color_increment = in.integer("the colour increment");
  if (!in.at_end()) view_.back_color_increment = in.integer("the back side's colour increment");
}

void Parser::initial_scale(WordReader& in) {
  Word at = in.peek();
  view_.initial_scale = in.number("the initial scale");
  if (view_.initial_scale == 0) {
    warn(at, "the initial scale cannot be 0; 1 is used, as in cpfg");
    view_.initial_scale = 1;
  }
}

void Parser::scale_multiplier(WordReader& in) {
  Word at = in.peek();
  view_.scale_multiplier = in.number("the scale multiplier");
  if (view_.scale_multiplier == 0) {
    warn(at, "the scale multiplier cannot be 0; 1 is used, as in cpfg");
    view_.scale_multiplier = 1;
  }
}

// Sylva's generalized cylinders always minimise their twist (cpfg's "off").
void Parser::twist_of_cylinders(WordReader& in) {
  Word at = in.peek();
  if (cpfg_flag(in)) warn(at, "generalized cylinders that keep their twist are not reproduced; their twist is minimised");
}

}  // namespace sylva::io
