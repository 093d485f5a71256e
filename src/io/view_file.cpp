#include "io/view_file.h"

#include <algorithm>
#include <functional>
#include <set>

#include "io/input_text.h"
#include "io/preprocessor.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

constexpr std::size_t kMaxLights = 8;

std::string warning_at(const std::string& file, const Word& at, const std::string& message) {
  return file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": warning: " + message;
}

// cpfg view-file commands that lpfg does not use; said as such rather than
// as unknown.
const std::set<std::string>& cpfg_commands() {
  static const std::set<std::string> names = {
      "ambient light", "background color", "light direction", "diffuse reflection",
      "cue range", "shade mode", "surface ambient", "surface diffuse", "tapered lines", "twist of cylinders",
      "viewpoint", "view reference point", "viewing angle", "twist", "interpretation step",
      "tropism direction", "initial elasticity", "elasticity increment", "function", "function set", "contour",
      "tsurface"};
  return names;
}

class Parser {
 public:
  explicit Parser(ViewFile& view) : view_(view) {}

  void command(const Command& c, const std::string& file);
  void finish();

 private:
  using Handler = void (Parser::*)(WordReader&);
  static const std::map<std::string, Handler>& handlers();

  float positive(WordReader& in, std::string_view what);
  bool flag(WordReader& in);
  int choice(WordReader& in, std::string_view what, std::initializer_list<const char*> names);
  geometry::Vec3 direction(WordReader& in, std::string_view what);
  geometry::Rgb color(WordReader& in, std::string_view what);
  int view_id(WordReader& in);
  geometry::ViewParameters& view_for(int id);
  void set_all_views(const std::function<void(geometry::ViewParameters&)>& set);

  void projection(WordReader& in);
  void scale(WordReader& in);
  void min_zoom(WordReader& in) { view_.min_zoom = positive(in, "the minimum zoom"); }
  void max_zoom(WordReader& in) { view_.max_zoom = positive(in, "the maximum zoom"); }
  void generate_on_view_change(WordReader& in);
  void view(WordReader& in);
  void box(WordReader& in);
  void window(WordReader& in);
  void window_border(WordReader& in);
  void front_distance(WordReader& in) { front_ = in.number("the front distance"); }
  void back_distance(WordReader& in) { back_ = in.number("the back distance"); }
  void z_buffer(WordReader& in) { view_.render.z_buffer = flag(in); }
  void render_mode(WordReader& in);
  void shadow_map(WordReader& in);
  void light(WordReader& in);
  void stationary_lights(WordReader& in) { view_.render.stationary_lights = flag(in); }
  void concave_polygons(WordReader& in) { view_.render.concave_polygons = flag(in); }
  void auto_normals(WordReader& in) { view_.render.auto_normals = flag(in); }
  void antialiasing(WordReader& in);
  void line_style(WordReader& in);
  void wireframe_line_width(WordReader& in) { view_.render.wireframe_line_width = positive(in, "the line width"); }
  void contour_sides(WordReader& in);
  void capped_cylinders(WordReader& in) { view_.render.capped_cylinders = flag(in); }
  void backface_culling(WordReader& in) { view_.render.backface_culling = flag(in); }
  void corrected_rotation(WordReader& in) { view_.corrected_rotation = flag(in); }
  void tropism(WordReader& in) { view_.tropisms.push_back(tropism_parts(in, false)); }
  void torque(WordReader& in) { view_.tropisms.push_back(tropism_parts(in, true)); }
  TropismCommand tropism_parts(WordReader& in, bool torque);
  void stropism(WordReader& in);
  void surface(WordReader& in);
  void mesh(WordReader& in);
  void texture(WordReader& in);
  void background_scene(WordReader& in);
  void font(WordReader& in) { view_.font = in.rest_of_line("an X font name"); }
  void winfont(WordReader& in);
  void ps_linecap(WordReader& in);
  void gradient(WordReader& in);
  void initial_color(WordReader& in);
  void initial_line_width(WordReader& in);
  void angle_increment(WordReader& in) { view_.angle_increment = in.number("the angle increment"); }
  void angle_factor(WordReader& in);
  void color_increment(WordReader& in);
  void line_width_increment(WordReader& in) { view_.line_width_increment = in.number("the line width increment"); }
  void initial_scale(WordReader& in) { view_.initial_scale = positive(in, "the initial scale"); }
  void scale_multiplier(WordReader& in) { view_.scale_multiplier = positive(in, "the scale multiplier"); }

  ViewFile& view_;
  std::string file_;  // of the command being read
  std::optional<float> front_, back_;
};

const std::map<std::string, Parser::Handler>& Parser::handlers() {
  static const std::map<std::string, Handler> table = {
      {"projection", &Parser::projection},
      {"scale", &Parser::scale},
      {"scale factor", &Parser::scale},
      {"min zoom", &Parser::min_zoom},
      {"max zoom", &Parser::max_zoom},
      {"generate on view change", &Parser::generate_on_view_change},
      {"view", &Parser::view},
      {"box", &Parser::box},
      {"window", &Parser::window},
      {"window border", &Parser::window_border},
      {"front distance", &Parser::front_distance},
      {"back distance", &Parser::back_distance},
      {"z buffer", &Parser::z_buffer},
      {"render mode", &Parser::render_mode},
      {"shadow map", &Parser::shadow_map},
      {"light", &Parser::light},
      {"stationary lights", &Parser::stationary_lights},
      {"concave polygons", &Parser::concave_polygons},
      {"auto normals", &Parser::auto_normals},
      {"antialiasing", &Parser::antialiasing},
      {"line style", &Parser::line_style},
      {"wireframe line width", &Parser::wireframe_line_width},
      {"contour sides", &Parser::contour_sides},
      {"capped cylinders", &Parser::capped_cylinders},
      {"backface culling", &Parser::backface_culling},
      {"corrected rotation", &Parser::corrected_rotation},
      {"tropism", &Parser::tropism},
      {"torque", &Parser::torque},
      {"stropism", &Parser::stropism},
      {"surface", &Parser::surface},
      {"mesh", &Parser::mesh},
      {"texture", &Parser::texture},
      {"background scene", &Parser::background_scene},
      {"font", &Parser::font},
      {"winfont", &Parser::winfont},
      {"ps linecap", &Parser::ps_linecap},
      {"gradient", &Parser::gradient},
      {"initial color", &Parser::initial_color},
      {"initial line width", &Parser::initial_line_width},
      {"angle increment", &Parser::angle_increment},
      {"angle factor", &Parser::angle_factor},
      {"color increment", &Parser::color_increment},
      {"line width increment", &Parser::line_width_increment},
      {"width increment", &Parser::line_width_increment},
      {"initial scale", &Parser::initial_scale},
      {"scale multiplier", &Parser::scale_multiplier},
  };
  return table;
}

void Parser::command(const Command& c, const std::string& file) {
  file_ = file;
  auto it = handlers().find(c.name);
  if (it == handlers().end()) {
    std::string what = cpfg_commands().count(c.name) ? "cpfg command '" + c.name_word.text + "' ignored: lpfg does not use it"
                                                     : "unknown command '" + c.name_word.text + "' ignored";
    view_.warnings.push_back(warning_at(file, c.name_word, what));
    return;
  }
  WordReader in(file, c.arguments, c.end);
  (this->*(it->second))(in);
  if (!in.at_end())
    view_.warnings.push_back(warning_at(file, in.peek(), "'" + in.peek().text + "' after '" + c.name_word.text + ":' ignored"));
}

float Parser::positive(WordReader& in, std::string_view what) {
  Word at = in.peek();
  float value = in.number(what);
  if (value <= 0) in.fail(at, "expected " + std::string(what) + " greater than 0, found '" + at.text + "'");
  return value;
}

bool Parser::flag(WordReader& in) {
  Word at = in.next("on or off");
  std::optional<bool> value = parse_flag(at.text);
  if (!value) in.fail(at, "expected on or off, found '" + at.text + "'");
  return *value;
}

int Parser::choice(WordReader& in, std::string_view what, std::initializer_list<const char*> names) {
  std::string list;
  int index = 0;
  for (const char* n : names) list += (list.empty() ? "" : ", ") + std::string(n);
  Word at = in.next(std::string(what) + " (" + list + ")");
  for (const char* n : names) {
    if (to_lower(at.text) == n) return index;
    ++index;
  }
  in.fail(at, "expected " + std::string(what) + " (" + list + "), found '" + at.text + "'");
}

geometry::Vec3 Parser::direction(WordReader& in, std::string_view what) {
  Word at = in.peek();
  geometry::Vec3 v = in.vec3(what);
  if (v == geometry::Vec3{0, 0, 0}) in.fail(at, "expected " + std::string(what) + " of non-zero length, found 0 0 0");
  return v;
}

geometry::Rgb Parser::color(WordReader& in, std::string_view what) {
  geometry::Vec3 v = in.vec3(what);
  return {v.x, v.y, v.z};
}

// A number, or the name of a window: command (windows count from 1, as
// the model's view names do: view 0 is no window, LPFG manual 5.12).
int Parser::view_id(WordReader& in) {
  Word at = in.next("a view id");
  if (std::optional<int> id = parse_int(at.text)) {
    if (*id < 0) in.fail(at, "expected a view id of 0 or more, found '" + at.text + "'");
    return *id;
  }
  for (std::size_t i = 0; i < view_.windows.size(); ++i)
    if (view_.windows[i].name == at.text) return static_cast<int>(i) + 1;
  in.fail(at, "expected a view id (a number, or a name given by an earlier window: command), found '" + at.text + "'");
}

geometry::ViewParameters& Parser::view_for(int id) {
  auto it = view_.views.find(id);
  if (it == view_.views.end()) it = view_.views.emplace(id, view_.default_view).first;
  return it->second;
}

// A global command holds for every view, those given so far included: the
// last command that sets a parameter wins.
void Parser::set_all_views(const std::function<void(geometry::ViewParameters&)>& set) {
  set(view_.default_view);
  for (auto& [id, params] : view_.views) set(params);
}

void Parser::projection(WordReader& in) {
  bool perspective = choice(in, "a projection", {"parallel", "perspective"}) == 1;
  set_all_views([&](geometry::ViewParameters& v) { v.perspective = perspective; });
}

void Parser::scale(WordReader& in) {
  float s = positive(in, "the scale");
  set_all_views([&](geometry::ViewParameters& v) { v.scale = s; });
}

void Parser::generate_on_view_change(WordReader& in) {
  static constexpr GenerateOnViewChange kinds[] = {GenerateOnViewChange::On, GenerateOnViewChange::Triggered,
                                                   GenerateOnViewChange::Off};
  view_.generate_on_view_change = kinds[choice(in, "when to generate", {"on", "triggered", "off"})];
}

void Parser::view(WordReader& in) {
  int id = view_id(in);
  geometry::ViewParameters& v = view_for(id);
  if (in.next_is_number()) {  // the deprecated "view: id px py pz scale ux uy uz"
    v.pan = in.vec3("the pan point");
    v.scale = positive(in, "the scale");
    v.up = direction(in, "the up direction");
    return;
  }
  while (!in.at_end()) {
    Word key = in.next("a view part");
    std::string k = to_lower(key.text);
    if (k == "dir:") {
      v.dir = direction(in, "the view direction");
    } else if (k == "up:") {
      v.up = direction(in, "the up direction");
    } else if (k == "pan:") {
      v.pan = in.vec3("the pan point");
    } else if (k == "fov:") {
      Word at = in.peek();
      v.fov = in.number("the field of view");
      if (v.fov <= 0 || v.fov >= 180) in.fail(at, "expected a field of view between 0 and 180 degrees, found '" + at.text + "'");
    } else if (k == "shift:") {
      v.shift = in.number("the shift");
    } else if (k == "scale:") {
      v.scale = positive(in, "the scale");
    } else {
      in.fail(key, "expected dir:, up:, pan:, fov:, shift: or scale:, found '" + key.text + "'");
    }
  }
}

void Parser::box(WordReader& in) {
  int id = view_id(in);
  float bounds[6];
  static const char* names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  Word first = in.peek();
  for (int i = 0; i < 6; ++i) bounds[i] = in.number(names[i]);
  if (bounds[0] > bounds[1] || bounds[2] > bounds[3] || bounds[4] > bounds[5])
    in.fail(first, "expected xmin xmax ymin ymax zmin zmax with each minimum at most its maximum");
  geometry::Box b;
  b.add({bounds[0], bounds[2], bounds[4]});
  b.add({bounds[1], bounds[3], bounds[5]});
  view_for(id).box = b;
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

void Parser::render_mode(WordReader& in) {
  static constexpr RenderMode modes[] = {RenderMode::Filled, RenderMode::Wireframe, RenderMode::Shaded,
                                         RenderMode::Shadows};
  view_.render.mode = modes[choice(in, "a render mode", {"filled", "wireframe", "shaded", "shadows"})];
}

void Parser::shadow_map(WordReader& in) {
  ShadowMap& s = view_.render.shadow_map;
  while (!in.at_end()) {
    Word key = in.next("a shadow map part");
    std::string k = to_lower(key.text);
    if (k == "size:") {
      Word at = in.peek();
      s.size = in.integer("the shadow map size");
      if (s.size <= 0 || s.size % 2 != 0) in.fail(at, "expected an even positive shadow map size, found '" + at.text + "'");
    } else if (k == "color:") {
      s.color = color(in, "the shadow colour");
    } else if (k == "offset:") {
      s.offset_factor = in.number("the offset factor");
      s.offset_units = in.number("the offset units");
    } else {
      in.fail(key, "expected size:, color: or offset:, found '" + key.text + "'");
    }
  }
}

void Parser::light(WordReader& in) {
  Light l;
  Word first = in.peek();
  bool directional = false, origin = false, spot = false;
  while (!in.at_end()) {
    Word key = in.next("a light part");
    std::string k = to_lower(key.text);
    if (k == "v:") {
      l.direction = direction(in, "the light direction");
      directional = true;
    } else if (k == "o:") {
      l.position = in.vec3("the light's origin");
      origin = true;
    } else if (k == "p:") {
      l.direction = direction(in, "the spotlight direction");
      l.spot_exponent = in.number("the spotlight exponent");
      Word at = in.peek();
      l.spot_cutoff = in.number("the spotlight cutoff angle");
      if (l.spot_cutoff < 0 || (l.spot_cutoff > 90 && l.spot_cutoff != 180))
        in.fail(at, "expected a cutoff angle from 0 to 90 degrees, or 180, found '" + at.text + "'");
      spot = true;
    } else if (k == "a:") {
      l.ambient = color(in, "the ambient colour");
    } else if (k == "d:") {
      l.diffuse = color(in, "the diffuse colour");
    } else if (k == "s:") {
      l.specular = color(in, "the specular colour");
    } else if (k == "t:") {
      l.constant_attenuation = in.number("the constant attenuation");
      l.linear_attenuation = in.number("the linear attenuation");
      l.quadratic_attenuation = in.number("the quadratic attenuation");
    } else {
      in.fail(key, "expected V:, O:, P:, A:, D:, S: or T:, found '" + key.text + "'");
    }
  }
  if (directional && (origin || spot))
    in.fail(first, "expected either a directional light (V:) or a point light or spotlight (O:, P:), not both");
  l.kind = spot ? Light::Kind::Spot : origin ? Light::Kind::Point : Light::Kind::Directional;
  if (view_.lights.size() >= kMaxLights) {
    view_.warnings.push_back(warning_at(file_, first, "more than 8 lights: this one is ignored"));
    return;
  }
  view_.lights.push_back(l);
}

void Parser::antialiasing(WordReader& in) {
  Word at = in.peek();
  view_.render.antialiasing = in.integer("the number of samples");
  if (view_.render.antialiasing < 0 || view_.render.antialiasing > 10)
    in.fail(at, "expected a number of samples from 0 to 10, found '" + at.text + "'");
}

void Parser::line_style(WordReader& in) {
  static constexpr geometry::LineStyle styles[] = {geometry::LineStyle::Pixel, geometry::LineStyle::Polygon,
                                                   geometry::LineStyle::Cylinder};
  view_.render.line_style = styles[choice(in, "a line style", {"pixel", "polygon", "cylinder"})];
}

void Parser::contour_sides(WordReader& in) {
  int n = in.integer("the number of sides");
  view_.contour_sides = std::max(n, 3);  // as lpfg clamps it
}

TropismCommand Parser::tropism_parts(WordReader& in, bool torque) {
  TropismCommand t;
  t.torque = torque;
  Word first = in.peek();
  bool have_vector = false;
  while (!in.at_end()) {
    Word key = in.next("a tropism part");
    std::string k = to_lower(key.text);
    if (k == "t:") {
      t.direction = direction(in, "the tropism vector");
      have_vector = true;
    } else if (k == "a:") {
      t.angle = in.number("the tropism angle");
    } else if (k == "i:") {
      t.intensity = in.number("the intensity");
    } else if (k == "e:") {
      t.elasticity = in.number("the elasticity");
    } else if (k == "s:") {
      t.step = in.number("the elasticity step");
    } else {
      in.fail(key, std::string("expected T:, ") + (torque ? "" : "A:, ") + "I:, E: or S:, found '" + key.text + "'");
    }
  }
  if (!have_vector) in.fail(first, "expected the tropism vector T: x y z");
  return t;
}

void Parser::stropism(WordReader& in) {
  TropismCommand t;
  t.direction = direction(in, "the tropism vector");
  t.elasticity = in.number("the elasticity");
  view_.simple_tropism = t;
}

void Parser::surface(WordReader& in) {
  SurfaceCommand s;
  Word at = in.next("a surface file name");
  // cpfg's form (CPFG manual 8.1.5) starts with the id the ~id module uses:
  // "surface: id file.s scale [i j] [texfile]"; lpfg's with the file.
  const bool cpfg = !in.at_end() && !in.next_is_number();
  if (cpfg) {
    s.id = at.text;
    for (const SurfaceCommand& other : view_.surfaces)
      if (other.id == s.id) in.fail(at, "a second surface with id '" + s.id + "'");
    at = in.next("a surface file name");
  }
  s.line = at.line;
  s.column = at.column;
  s.file = at.text;
  s.path = resolve_beside(view_.path, at.text);
  if (!in.at_end()) s.scale = positive(in, "the surface scale");
  if (!in.at_end() && (!cpfg || in.next_is_number())) {
    Word sw = in.peek();
    s.s_divisions = in.integer("the subdivisions along s");
    s.t_divisions = in.integer("the subdivisions along t (sdiv and tdiv go together)");
    if (s.s_divisions < 1 || s.t_divisions < 1) in.fail(sw, "expected positive numbers of subdivisions");
  }
  if (cpfg && !in.at_end()) {
    // Its texture goes after the texture: commands' (which @Tx numbers).
    s.texture_path = resolve_beside(view_.path, in.next("a texture file").text);
  } else if (!in.at_end()) {
    Word tw = in.peek();
    s.texture = in.integer("the texture id");
    if (s.texture < 0) in.fail(tw, "expected a texture id of 0 or more, found '" + tw.text + "'");
  }
  view_.surfaces.push_back(s);
}

void Parser::mesh(WordReader& in) {
  MeshCommand m;
  m.file = in.next("a mesh file name").text;
  m.path = resolve_beside(view_.path, m.file);
  while (!in.at_end()) {
    Word key = in.next("a mesh part");
    std::string k = to_lower(key.text);
    if (k == "s:") {
      m.scale = positive(in, "the mesh scale");
    } else if (k == "c:") {
      m.contact = in.vec3("the contact point");
    } else {
      in.fail(key, "expected S: or C:, found '" + key.text + "'");
    }
  }
  view_.meshes.push_back(m);
}

// lpfg: "texture: file" (ids from 0, LPFG manual 8.1.5); cpfg: subcommands
// "texture: F: file E: mode S: R: ratio H: filter L: filter" (ids from 1 in
// @Tx, CPFG manual 8.1.7). Only the file is used; the other subcommands are
// read and said to be ignored.
void Parser::texture(WordReader& in) {
  const Word first = in.next("an image file name or F:");
  if (first.text.size() < 2 || first.text.back() != ':') {
    view_.textures.push_back(resolve_beside(view_.path, first.text));
    return;
  }
  std::string file;
  for (Word key = first;; key = in.next("a texture subcommand")) {
    const std::string k = to_lower(key.text);
    if (k == "f:") {
      file = in.next("a texture file name").text;
    } else if (k == "s:") {
      view_.warnings.push_back(warning_at(file_, key, "texture subcommand S: (one texture per surface) ignored"));
    } else if (k == "e:" || k == "r:" || k == "h:" || k == "l:") {
      const Word value = in.next("the value of " + key.text);
      if (k == "e:" || k == "r:")
        view_.warnings.push_back(warning_at(file_, key, "texture subcommand " + key.text + " " + value.text + " ignored"));
    } else {
      in.fail(key, "expected a texture subcommand (F:, E:, S:, R:, H: or L:), found '" + key.text + "'");
    }
    if (in.at_end()) break;
  }
  if (file.empty()) in.fail(first, "a cpfg texture needs its file (F: file)");
  view_.textures.push_back(resolve_beside(view_.path, file));
}

// cpfg's "background scene: file" (CPFG manual 8.1.4, 8.3); cpfg splits the
// rest of the line into several files at blanks, commas and semicolons.
void Parser::background_scene(WordReader& in) {
  const std::string names = in.rest_of_line("a background scene file");
  std::string name;
  for (char c : names + " ") {
    if (c == ' ' || c == '\t' || c == ',' || c == ';') {
      if (!name.empty()) view_.background_scenes.push_back(resolve_beside(view_.path, name));
      name.clear();
    } else {
      name += c;
    }
  }
}

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
  view_.render.ps_linecap = in.integer("the line cap type");
  if (view_.render.ps_linecap < 0 || view_.render.ps_linecap > 2)
    in.fail(at, "expected a line cap type of 0, 1 or 2, found '" + at.text + "'");
}

void Parser::gradient(WordReader& in) {
  Word at = in.peek();
  view_.render.gradient_direction = in.integer("the gradient direction");
  if (view_.render.gradient_direction < 0 || view_.render.gradient_direction > 2)
    in.fail(at, "expected a gradient direction of 0, 1 or 2, found '" + at.text + "'");
  view_.render.gradient_magnitude = in.number("the gradient magnitude");
}

void Parser::initial_color(WordReader& in) {
  Word at = in.peek();
  int color = in.integer("the initial colour index");
  if (color < 0 || color > 255) in.fail(at, "expected a colour index from 0 to 255, found '" + at.text + "'");
  view_.initial_color = color;
  if (!in.at_end()) view_.initial_back_color = in.integer("the back side's colour index");
}

void Parser::initial_line_width(WordReader& in) {
  view_.initial_line_width = in.number("the initial line width");
  if (in.at_end()) return;
  // cpfg's optional style: p(ixels) are lines, s(haded) are cylinders.
  Word style = in.next("a line style");
  std::string s = to_lower(style.text);
  if (s == "p" || s == "pixels") view_.render.line_style = geometry::LineStyle::Pixel;
  else if (s == "s" || s == "shaded") view_.render.line_style = geometry::LineStyle::Cylinder;
  else in.fail(style, "expected the line style p (pixels) or s (shaded), found '" + style.text + "'");
}

void Parser::angle_factor(WordReader& in) {
  // The same setting as angle increment, as a fraction of a full turn.
  view_.angle_increment = 360 / positive(in, "the angle factor");
}

void Parser::color_increment(WordReader& in) {
  view_.color_increment = in.integer("the colour increment");
  if (!in.at_end()) view_.back_color_increment = in.integer("the back side's colour increment");
}

void Parser::finish() {
  for (SurfaceCommand& s : view_.surfaces) {
    if (s.texture_path.empty()) continue;
    s.texture = static_cast<int>(view_.textures.size());
    view_.textures.push_back(s.texture_path);
  }
  // The manual: both distances must be given to have an effect.
  if (front_ && back_)
    set_all_views([&](geometry::ViewParameters& v) {
      v.front_distance = front_;
      v.back_distance = back_;
    });
}

}  // namespace

const geometry::ViewParameters& ViewFile::view(int id) const {
  auto it = views.find(id);
  return it == views.end() ? default_view : it->second;
}

std::vector<Light> ViewFile::lights_or_default() const { return lights.empty() ? std::vector<Light>{Light{}} : lights; }

turtle::TurtleSettings ViewFile::turtle_settings() const {
  turtle::TurtleSettings settings;
  if (initial_line_width) settings.initial_width = *initial_line_width;
  if (initial_color) settings.initial_color = settings.cpfg_initial_color = *initial_color;
  settings.angle_increment = angle_increment;
  settings.width_increment = line_width_increment;
  settings.color_increment = color_increment;
  if (initial_back_color) settings.cpfg_initial_back_color = *initial_back_color;
  settings.back_color_increment = back_color_increment.value_or(color_increment);
  settings.initial_scale = initial_scale;
  settings.scale_multiplier = scale_multiplier;
  settings.contour_sides = contour_sides;
  settings.corrected_rotation = corrected_rotation;
  settings.auto_normals = render.auto_normals;

  settings.tropisms = tropisms;
  if (simple_tropism) settings.simple_tropism = *simple_tropism;
  for (const SurfaceCommand& s : surfaces) settings.surface_ids.push_back(s.id);
  return settings;
}

geometry::TessellationOptions ViewFile::tessellation_options() const {
  return geometry::TessellationOptions{render.line_style, contour_sides};
}

ViewFile read_view_file(const std::string& path, const std::string& compiler) {
  read_input_file(path, "view file");  // a missing file named as such, not as the preprocessor says it
  ViewFile view;
  view.path = path;
  Parser parser(view);
  OriginalColumns columns;
  for (const PreprocessedLine& line : preprocess_file(path, compiler.empty() ? default_preprocessor() : compiler)) {
    std::optional<Command> c = split_command(line.text, line.line);
    if (!c) continue;
    columns.restore(c->name_word, line.file, line.line);
    for (Word& w : c->arguments) columns.restore(w, line.file, line.line);
    parser.command(*c, line.file);
  }
  parser.finish();
  return view;
}

}  // namespace sylva::io
