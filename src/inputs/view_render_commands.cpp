// The view file's rendering commands and lights, as lpfg (LPFG manual 8.1.2
// to 8.1.7) and cpfg (CPFG manual 8.1.3, 8.1.4, 8.1.10) read them.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "inputs/view_parser.h"

namespace sylva::io {

namespace {

constexpr std::size_t kMaxLights = 8;

}  // namespace

// lpfg skips two characters after a part's letter ("D:", "D "), so only a
// word of one or two characters is a key there; cpfg splits the line at
// blanks and colons and looks at a word's first letter alone.
char part_key(const std::string& word, ViewDialect dialect) {
  if (word.empty() || !std::isupper(static_cast<unsigned char>(word[0]))) return 0;
  if (dialect == ViewDialect::Lpfg && word.size() > 2) return 0;
  return word[0];
}

void Parser::z_buffer(WordReader& in) { view_.render.z_buffer = cpfg() ? cpfg_flag(in) : flag(in); }

void Parser::concave_polygons(WordReader& in) {
  if (!cpfg()) {
    view_.render.concave_polygons = flag(in);
    return;
  }
  Word at = in.next("on or off");
  if (at.text.starts_with("on")) view_.render.concave_polygons = true;
  else if (at.text.starts_with("off")) view_.render.concave_polygons = false;
  else in.fail(at, "expected on or off, found '" + at.text + "'");
}

// lpfg's four modes; cpfg's seven, or their numbers from 1 (cpfg's order:
// wireframe, filled, flat, interpolated, shaded, fast, shadows). cpfg's flat
// shading is drawn shaded, its interpolated and fast modes filled.
void Parser::render_mode(WordReader& in) {
  using M = geometry::RenderMode;
  if (!cpfg()) {
    static constexpr M modes[] = {M::Filled, M::Wireframe, M::Shaded, M::Shadows};
    view_.render.mode = modes[choice(in, "a render mode", {"filled", "wireframe", "shaded", "shadows"})];
    return;
  }
  static constexpr M cpfg_modes[] = {M::Wireframe, M::Filled, M::Shaded, M::Filled, M::Shaded, M::Filled, M::Shadows};
  static const char* names[] = {"wireframe", "filled", "flat", "interpolated", "shaded", "fast", "shadows"};
  Word at = in.next("a render mode");
  int index = -1;
  for (int k = 0; k < 7; ++k)
    if (at.text == names[k]) index = k;
  if (index < 0 && !at.text.empty() && at.text[0] >= '1' && at.text[0] <= '7') index = at.text[0] - '1';
  if (index < 0)
    in.fail(at, "expected a render mode (wireframe, filled, flat, interpolated, shaded, fast, shadows, or 1 to 7), found '" +
                    at.text + "'");
  view_.render.mode = cpfg_modes[index];
}

// cpfg's deprecated shade mode (CPFG manual 8.1.10), turned into a render
// mode as cpfg turns it; a number after it (NURBS sampling) is read past.
void Parser::shade_mode(WordReader& in) {
  using M = geometry::RenderMode;
  const int mode = in.integer("the shade mode");
  static constexpr M modes[] = {M::Filled, M::Filled, M::Shaded, M::Wireframe, M::Wireframe, M::Shaded, M::Wireframe};
  view_.render.mode = mode >= 1 && mode <= 7 ? modes[mode - 1] : M::Filled;
  if (in.next_is_number()) in.number("the NURBS sampling");
}

void Parser::line_style(WordReader& in) {
  using geometry::LineStyle;
  static constexpr LineStyle styles[] = {LineStyle::Pixel, LineStyle::Polygon, LineStyle::Cylinder};
  // cpfg also takes the style's number from 1.
  if (cpfg() && !in.at_end()) {
    const std::string& word = in.peek().text;
    if (!word.empty() && word[0] >= '1' && word[0] <= '3') {
      view_.render.line_style = styles[in.next("").text[0] - '1'];
      return;
    }
  }
  view_.render.line_style = styles[choice(in, "a line style", {"pixel", "polygon", "cylinder"})];
}

void Parser::shadow_map(WordReader& in) {
  geometry::ShadowMap& s = view_.render.shadow_map;
  while (!in.at_end()) {
    Word key = in.next("a shadow map part");
    std::string k = to_lower(key.text);
    if (k.ends_with(":")) k.pop_back();  // cpfg reads its keys with or without the colon
    if (k == "size") {
      Word at = in.peek();
      s.size = in.integer_at_most("the shadow map size", kMaxShadowMapSize);
      if (s.size <= 0) in.fail(at, "expected a positive shadow map size, found '" + at.text + "'");
      if (s.size % 2 != 0) {
        warn(at, "the shadow map size should be even; " + std::to_string(s.size + 1) + " is used, as lpfg and cpfg do");
        s.size += 1;
      }
    } else if (k == "color") {
      s.color = color(in, "the shadow colour");
      s.color = {std::clamp(s.color.r, 0.0f, 1.0f), std::clamp(s.color.g, 0.0f, 1.0f), std::clamp(s.color.b, 0.0f, 1.0f)};
    } else if (k == "offset") {
      s.offset_factor = std::max(in.number("the offset factor"), 0.0f);
      s.offset_units = std::max(in.number("the offset units"), 0.0f);
    } else {
      in.fail(key, "expected size:, color: or offset:, found '" + key.text + "'");
    }
  }
}

// "light: V: x y z D: r g b ..." (LPFG manual 8.1.3, CPFG manual 8.1.3). A
// part's key is its letter (see part_key). The light's place is the last of
// V: (directional) and O: (a point); P: makes a point light a spotlight.
// Without V: or O:, lpfg's light shines along +z and cpfg's is a point at
// (0,0,1), as their defaults are.
void Parser::light(WordReader& in) {
  geometry::Light l;
  Word first = in.peek();
  bool point = cpfg(), spot = false;
  geometry::Vec3 place{0, 0, 1};
  geometry::Vec3 spot_direction{0, 0, -1};
  while (!in.at_end()) {
    Word key = in.next("a light part");
    switch (part_key(key.text, view_.dialect)) {
      case 'V':
        place = direction(in, "the light direction");
        point = false;
        break;
      case 'O':
        place = in.vec3("the light's origin");
        point = true;
        break;
      case 'P': {
        spot_direction = direction(in, "the spotlight direction");
        l.spot_exponent = in.number("the spotlight exponent");
        Word at = in.peek();
        l.spot_cutoff = in.number("the spotlight cutoff angle");
        if (l.spot_cutoff < 0 || (l.spot_cutoff > 90 && l.spot_cutoff != 180))
          in.fail(at, "expected a cutoff angle from 0 to 90 degrees, or 180, found '" + at.text + "'");
        spot = true;
        break;
      }
      case 'A':
        l.ambient = color(in, "the ambient colour");
        break;
      case 'D':
        l.diffuse = color(in, "the diffuse colour");
        break;
      case 'S':
        l.specular = color(in, "the specular colour");
        break;
      case 'T':
        l.constant_attenuation = in.number("the constant attenuation");
        l.linear_attenuation = in.number("the linear attenuation");
        l.quadratic_attenuation = in.number("the quadratic attenuation");
        break;
      default:
        in.fail(key, "expected V:, O:, P:, A:, D:, S: or T:, found '" + key.text + "'");
    }
  }
  if (point) {
    l.position = place;
    l.kind = spot ? geometry::Light::Kind::Spot : geometry::Light::Kind::Point;
    if (spot) l.direction = spot_direction;
  } else {
    // OpenGL makes no spotlight of a directional light.
    l.kind = geometry::Light::Kind::Directional;
    l.direction = place;
  }
  if (view_.lights.size() >= kMaxLights) {
    warn(first, "more than 8 lights: this one is ignored");
    return;
  }
  view_.lights.push_back(l);
}

// cpfg's "light direction: x,y,z": the directional light cpfg lights the
// model with when the file has no light: command.
void Parser::light_direction(WordReader& in) {
  view_.default_light_direction = geometry::normalized(direction(in, "the light direction"));
}

// lpfg's number of samples; cpfg's on or off (smooth lines), taken as 4
// samples.
void Parser::antialiasing(WordReader& in) {
  if (cpfg()) {
    view_.render.antialiasing = cpfg_flag(in) ? 4 : 0;
    return;
  }
  Word at = in.peek();
  view_.render.antialiasing = in.integer("the number of samples");
  if (view_.render.antialiasing < 0 || view_.render.antialiasing > 10)
    in.fail(at, "expected a number of samples from 0 to 10, found '" + at.text + "'");
}

// lpfg's X font name is the rest of the line; cpfg reads one word.
void Parser::font(WordReader& in) { view_.font = cpfg() ? in.next("an X font name").text : in.rest_of_line("an X font name"); }

void Parser::winfont(WordReader& in) {
  view_.winfont.name = in.next("a font name").text;
  Word at = in.peek();
  view_.winfont.size = in.integer("the font size");
  if (view_.winfont.size <= 0) in.fail(at, "expected a positive font size, found '" + at.text + "'");
  view_.winfont.bold = view_.winfont.italic = false;
  while (!in.at_end()) {
    Word f = in.next("b or i");
    for (char c : to_lower(f.text)) {
      if (c == 'b') view_.winfont.bold = true;
      else if (c == 'i') view_.winfont.italic = true;
      else in.fail(f, "expected the flags b (bold) and i (italic), found '" + f.text + "'");
    }
  }
}

void Parser::ps_linecap(WordReader& in) {
  Word at = in.peek();
  int cap = in.integer("the line cap type");
  if (cpfg() && cap > 2) {
    warn(at, "a line cap type above 2; 2 is used, as in cpfg");
    cap = 2;
  }
  if (cap < 0 || cap > 2) in.fail(at, "expected a line cap type of 0, 1 or 2, found '" + at.text + "'");
  view_.render.ps_linecap = cap;
}

void Parser::gradient(WordReader& in) {
  Word at = in.peek();
  view_.render.gradient_direction = in.integer("the gradient direction");
  if (view_.render.gradient_direction < 0 || view_.render.gradient_direction > 2)
    in.fail(at, "expected a gradient direction of 0, 1 or 2, found '" + at.text + "'");
  view_.render.gradient_magnitude = in.number("the gradient magnitude");
}

// Sylva draws lines tapered, cpfg's default; "off" cannot be reproduced.
void Parser::tapered_lines(WordReader& in) {
  Word at = in.peek();
  if (in.next("on or off").text != "on") warn(at, "lines that are not tapered are not reproduced; they are drawn tapered");
}

// cpfg's depth cueing (a range of colour indices), not reproduced.
void Parser::cue_range(WordReader& in) {
  Word at = in.peek();
  if (in.integer("the cue range") != 0) warn(at, "depth cueing is not reproduced; the cue range is ignored");
}

}  // namespace sylva::io
