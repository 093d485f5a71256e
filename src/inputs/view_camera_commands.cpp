// The view file's camera commands: lpfg's (projection, scale, view, box,
// window ...; LPFG manual 8.1.1, lpfg's DrawParams) and cpfg's (viewpoint,
// view reference point, twist, viewing angle, box: x: y: z: ...; CPFG manual
// 8.1.2, cpfg's ReadViewData).
#include <cmath>
#include <numbers>

#include "inputs/view_parser.h"

namespace sylva::io {

namespace {

using geometry::Vec3;

// v turned by `degrees` about the unit axis, counterclockwise as seen from
// where the axis points.
Vec3 turned(Vec3 v, Vec3 axis, float degrees) {
  const float a = degrees * std::numbers::pi_v<float> / 180, c = std::cos(a), s = std::sin(a);
  return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}

}  // namespace

void Parser::projection(WordReader& in) {
  // Both programs compare the word's beginning only.
  Word at = in.next("a projection (parallel, perspective)");
  const std::string word = to_lower(at.text);
  bool perspective = false;
  if (word.starts_with("perspective")) {
    perspective = true;
  } else if (!word.starts_with("parallel")) {
    if (!cpfg()) in.fail(at, "expected a projection (parallel, perspective), found '" + at.text + "'");
    warn(at, "unknown projection '" + at.text + "'; parallel assumed, as in cpfg");
  }
  set_all_views([&](geometry::ViewParameters& v) { v.perspective = perspective; });
}

void Parser::scale(WordReader& in) {
  float s = positive(in, "the scale");
  set_all_views([&](geometry::ViewParameters& v) { v.scale = s; });
}

void Parser::cpfg_scale_factor(WordReader& in) {
  const float s = in.number("the scale factor");
  cpfg_view().scale = s == 0 ? 1 : s;  // as cpfg takes 0
}

void Parser::front_distance(WordReader& in) {
  const float d = in.number("the front distance");
  if (cpfg()) cpfg_view().front_distance = d;
  else front_ = d;
}

void Parser::back_distance(WordReader& in) {
  const float d = in.number("the back distance");
  if (cpfg()) cpfg_view().back_distance = d;
  else back_ = d;
}

void Parser::twist(WordReader& in) {
  // cpfg reads an integer: the digits before a fraction.
  cpfg_view().twist = static_cast<int>(std::trunc(in.number("the twist (tenths of a degree)")));
}

void Parser::generate_on_view_change(WordReader& in) {
  if (cpfg() && to_lower(in.peek().text) == "continuous") {  // cpfg's other word for on
    in.next("");
    view_.generate_on_view_change = GenerateOnViewChange::On;
    return;
  }
  static constexpr GenerateOnViewChange kinds[] = {GenerateOnViewChange::On, GenerateOnViewChange::Triggered,
                                                   GenerateOnViewChange::Off};
  view_.generate_on_view_change = kinds[choice(in, "when to generate", {"on", "triggered", "off"})];
}

// lpfg's view ids index its windows from 0; without windows only 0 is one.
// Sylva numbers window k as view k + 1 (view 0 is the view without windows,
// api/views.h), so lpfg's id 0 with windows is both the first window and
// view 0. A window's name, as an earlier window: command gives it, names it
// too.
std::vector<int> Parser::view_ids(WordReader& in) {
  Word at = in.next("a view id");
  const int windows = static_cast<int>(view_.windows.size());
  if (std::optional<int> id = parse_int(at.text)) {
    if (*id == 0) return windows > 0 ? std::vector<int>{1, 0} : std::vector<int>{0};
    if (*id > 0 && *id < windows) return {*id + 1};
    in.fail(at, "expected a view id (0" + (windows > 1 ? " to " + std::to_string(windows - 1) : std::string()) +
                    ", the windows counted from 0), found '" + at.text + "'");
  }
  for (int k = 0; k < windows; ++k)
    if (view_.windows[static_cast<std::size_t>(k)].name == at.text) return {k + 1};
  in.fail(at, "expected a view id (a number, or a name given by an earlier window: command), found '" + at.text + "'");
}

void Parser::view(WordReader& in) {
  const std::vector<int> ids = view_ids(in);
  if (in.next_is_number()) {
    old_style_view(in, ids);
    return;
  }
  geometry::ViewParameters parts = view_for(ids.front());
  while (!in.at_end()) {
    Word key = in.next("a view part");
    std::string k = to_lower(key.text);
    if (k == "dir:") {
      parts.dir = direction(in, "the view direction");
    } else if (k == "up:") {
      parts.up = direction(in, "the up direction");
    } else if (k == "pan:") {
      parts.pan = in.vec3("the pan point");
    } else if (k == "fov:") {
      Word at = in.peek();
      parts.fov = in.number("the field of view");
      if (parts.fov <= 0 || parts.fov >= 180) in.fail(at, "expected a field of view between 0 and 180 degrees, found '" + at.text + "'");
    } else if (k == "shift:") {
      parts.shift = in.number("the shift");
    } else if (k == "scale:") {
      parts.scale = positive(in, "the scale");
    } else {
      in.fail(key, "expected dir:, up:, pan:, fov:, shift: or scale:, found '" + key.text + "'");
    }
  }
  for (int id : ids) view_for(id) = parts;
}

// lpfg's deprecated form "view: id rx ry rz scale px py pz" as lpfg reads it
// (the manual's order differs): the view turned by rx, ry, rz degrees (q^-1 v q
// with q = qx qy qz: by -rx about x, then -ry about y, then -rz about z), a
// zoom of `scale` (the new form's scale: 1/scale), panned to px py pz.
void Parser::old_style_view(WordReader& in, const std::vector<int>& ids) {
  const float rx = in.number("the rotation about x"), ry = in.number("the rotation about y"),
              rz = in.number("the rotation about z");
  const float zoom = positive(in, "the scale");
  const Vec3 pan = in.vec3("the pan point");
  for (int id : ids) {
    geometry::ViewParameters& v = view_for(id);
    for (Vec3* w : {&v.dir, &v.up})
      *w = turned(turned(turned(*w, {1, 0, 0}, -rx), {0, 1, 0}, -ry), {0, 0, 1}, -rz);
    v.scale = 1 / zoom;
    v.pan = pan;
    v.shift = 1;
  }
}

void Parser::box(WordReader& in) {
  const std::vector<int> ids = view_ids(in);
  float bounds[6];
  static const char* names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  Word first = in.peek();
  for (int i = 0; i < 6; ++i) bounds[i] = in.number(names[i]);
  if (bounds[0] >= bounds[1] || bounds[2] >= bounds[3] || bounds[4] >= bounds[5])
    in.fail(first, "expected xmin xmax ymin ymax zmin zmax with each minimum below its maximum");
  geometry::Box b;
  b.add({bounds[0], bounds[2], bounds[4]});
  b.add({bounds[1], bounds[3], bounds[5]});
  for (int id : ids) view_for(id).box = b;
}

// cpfg's "box: x: xmin,xmax y: ymin,ymax z: zmin,zmax": the box framed
// instead of the model's bounds.
void Parser::cpfg_box(WordReader& in) {
  float bounds[6];
  for (int axis = 0; axis < 3; ++axis) {
    const std::string key = std::string(1, "xyz"[axis]) + ":";
    in.expect(key);
    bounds[2 * axis] = in.number("the least " + key.substr(0, 1));
    bounds[2 * axis + 1] = in.number("the greatest " + key.substr(0, 1));
  }
  geometry::Box b;
  b.add({bounds[0], bounds[2], bounds[4]});
  b.add({bounds[1], bounds[3], bounds[5]});
  cpfg_view().box = b;
}

void Parser::window(WordReader& in) {
  ViewWindow w;
  w.name = in.next("a view name").text;
  w.left = in.number("the left edge");
  w.top = in.number("the top edge");
  w.width = positive(in, "the width");
  w.height = positive(in, "the height");
  view_.windows.push_back(w);
}

void Parser::window_border(WordReader& in) {
  Word at = in.peek();
  view_.window_border_width = in.integer("the border size");
  if (view_.window_border_width < 0) in.fail(at, "expected a border size of 0 or more, found '" + at.text + "'");
  float rgb[3];
  for (float& c : rgb) {
    Word cw = in.peek();
    int v = in.integer("a colour component (0 to 255)");
    if (v < 0 || v > 255) in.fail(cw, "expected a colour component from 0 to 255, found '" + cw.text + "'");
    c = static_cast<float>(v) / 255.0f;
  }
  view_.window_border_color = {rgb[0], rgb[1], rgb[2]};
}

}  // namespace sylva::io
