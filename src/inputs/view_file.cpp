#include "inputs/view_file.h"

#include "inputs/input_text.h"
#include "inputs/preprocessor.h"
#include "inputs/view_parser.h"
#include "support/default_compiler.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

std::string warning_at(const std::string& file, const Word& at, const std::string& message) {
  return file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": warning: " + message;
}

}  // namespace

Parser::Parser(ViewFile& view) : view_(view) {
  if (!cpfg()) return;
  // cpfg's defaults where they differ from lpfg's (cpfg's InitializeParameters).
  view_.default_view.cpfg = geometry::CpfgView{};
  view_.render.z_buffer = true;
  view_.render.ps_linecap = 1;
  view_.contour_sides = 8;
  view_.default_light_direction = {1, 0, 0};
}

// Which commands each program reads (lpfg's DrawParams::Load, cpfg's
// ReadViewData). A program's command Sylva cannot reproduce says why.
const std::map<std::string, Parser::Entry>& Parser::commands() {
  using P = Parser;
  static const char* colormap_lighting = "cpfg's colormap-mode shading is not reproduced";
  static const std::map<std::string, Entry> table = {
      // The camera.
      {"projection", {{&P::projection}, {&P::projection}}},
      {"scale", {{&P::scale}, {}}},
      {"scale factor", {{&P::scale}, {&P::cpfg_scale_factor}}},
      {"min zoom", {{&P::min_zoom}, {&P::min_zoom}}},
      {"max zoom", {{&P::max_zoom}, {&P::max_zoom}}},
      {"generate on view change", {{&P::generate_on_view_change}, {&P::generate_on_view_change}}},
      {"view", {{&P::view}, {}}},
      {"box", {{&P::box}, {&P::cpfg_box}}},
      {"window", {{&P::window}, {}}},
      {"window border", {{&P::window_border}, {}}},
      {"front distance", {{&P::front_distance}, {&P::front_distance}}},
      {"back distance", {{&P::back_distance}, {&P::back_distance}}},
      {"viewpoint", {{}, {&P::viewpoint}}},
      {"view reference point", {{}, {&P::view_reference_point}}},
      {"twist", {{}, {&P::twist}}},
      {"viewing angle", {{}, {&P::viewing_angle}}},
      {"rotation", {{nullptr, "lpfg reads nothing from it"}, {}}},
      // Rendering and lights.
      {"z buffer", {{&P::z_buffer}, {&P::z_buffer}}},
      {"render mode", {{&P::render_mode}, {&P::render_mode}}},
      {"shade mode", {{}, {&P::shade_mode}}},
      {"shadow map", {{&P::shadow_map}, {&P::shadow_map}}},
      {"light", {{&P::light}, {&P::light}}},
      {"light direction", {{}, {&P::light_direction}}},
      {"diffuse reflection", {{}, {nullptr, colormap_lighting}}},
      {"surface ambient", {{}, {nullptr, colormap_lighting}}},
      {"surface diffuse", {{}, {nullptr, colormap_lighting}}},
      {"ambient light", {{}, {nullptr, "cpfg itself does not use it"}}},
      {"background color", {{}, {nullptr, "cpfg itself does not use it"}}},
      {"cue range", {{}, {&P::cue_range}}},
      {"stationary lights", {{&P::stationary_lights}, {}}},
      {"concave polygons", {{&P::concave_polygons}, {&P::concave_polygons}}},
      {"auto normals", {{&P::auto_normals}, {}}},
      {"antialiasing", {{&P::antialiasing}, {&P::antialiasing}}},
      {"line style", {{&P::line_style}, {&P::line_style}}},
      {"wireframe line width", {{&P::wireframe_line_width}, {}}},
      {"capped cylinders", {{&P::capped_cylinders}, {}}},
      {"backface culling", {{&P::backface_culling}, {}}},
      {"tapered lines", {{}, {&P::tapered_lines}}},
      {"tapered cylinders", {{nullptr, "tapered cylinders are not reproduced"}, {}}},
      {"font", {{&P::font}, {&P::font}}},
      {"winfont", {{&P::winfont}, {&P::winfont}}},
      {"ps linecap", {{&P::ps_linecap}, {&P::ps_linecap}}},
      {"gradient", {{&P::gradient}, {}}},
      {"interpretation step", {{}, {nullptr, "it only paces cpfg's drawing on screen"}}},
      {"interpretation past %", {{}, {nullptr, "interpretation always goes past %"}}},
      {"environment display", {{}, {nullptr, "it only orders cpfg's drawing on screen"}}},
      {"rayshade objects", {{}, {nullptr, "rayshade output is not supported"}}},
      {"rayshade scale", {{}, {nullptr, "rayshade output is not supported"}}},
      {"background scene", {{}, {&P::background_scene}}},
      // The turtle.
      {"contour sides", {{&P::contour_sides}, {&P::contour_sides}}},
      {"polygonization level", {{}, {&P::polygonization_level}}},
      {"corrected rotation", {{&P::corrected_rotation}, {}}},
      {"tropism", {{&P::tropism}, {&P::tropism}}},
      {"torque", {{&P::torque}, {&P::torque}}},
      {"stropism", {{&P::stropism}, {}}},
      {"tropism direction", {{}, {&P::tropism_direction}}},
      {"initial elasticity", {{}, {&P::initial_elasticity}}},
      {"elasticity increment", {{}, {&P::elasticity_increment}}},
      {"initial color", {{}, {&P::initial_color}}},
      {"initial line width", {{}, {&P::initial_line_width}}},
      {"angle increment", {{}, {&P::angle_increment}}},
      {"angle factor", {{}, {&P::angle_factor}}},
      {"color increment", {{}, {&P::color_increment}}},
      {"line width increment", {{}, {&P::line_width_increment}}},
      {"initial scale", {{}, {&P::initial_scale}}},
      {"scale multiplier", {{}, {&P::scale_multiplier}}},
      {"twist of cylinders", {{}, {&P::twist_of_cylinders}}},
      // External files.
      {"surface", {{&P::surface}, {&P::surface}}},
      {"mesh", {{&P::mesh}, {}}},
      {"texture", {{&P::texture}, {&P::texture}}},
      {"contour", {{}, {&P::contour}}},
      {"function", {{nullptr, "lpfg takes functions from the command line"}, {&P::function}}},
      {"function set", {{}, {&P::function_set}}},
      {"gallery", {{nullptr, "lpfg takes function sets from the command line"}, {}}},
      {"curve", {{}, {&P::curve}}},
      {"line", {{}, {nullptr, "lines drawn as surfaces are not supported"}}},
      {"tsurface", {{}, {nullptr, "rayshade triangle surfaces are not supported"}}},
      {"blob", {{}, {nullptr, "blobby environment fields are not supported"}}},
      {"terrain", {{nullptr, "terrains are not supported"}, {}}},
      {"bsurface", {{nullptr, "B-spline surfaces are not supported"}, {}}},
      {"animated mesh", {{nullptr, "lpfg itself does not read it"}, {}}},
  };
  return table;
}

void Parser::warn(const Word& at, const std::string& message) { view_.warnings.push_back(warning_at(file_, at, message)); }

void Parser::command(const Command& c, const std::string& file) {
  file_ = file;
  command_ = c.name_word.text;
  auto it = commands().find(c.name);
  if (it == commands().end()) {
    warn(c.name_word, "unknown command '" + command_ + "' ignored");
    return;
  }
  const Reading& reading = cpfg() ? it->second.cpfg : it->second.lpfg;
  if (!reading.handler) {
    if (reading.ignored) warn(c.name_word, "'" + command_ + ":' ignored: " + reading.ignored);
    else warn(c.name_word, std::string(cpfg() ? "lpfg" : "cpfg") + " command '" + command_ + "' ignored: " + program() +
                               " does not read it");
    return;
  }
  // lpfg and cpfg print a message about a value they cannot read and go on;
  // so does Sylva, leaving the command without effect.
  ViewFile before = view_;
  const std::optional<float> front = front_, back = back_;
  WordReader in(file, c.arguments, c.end);
  try {
    (this->*(reading.handler))(in);
  } catch (const ModelError& e) {
    std::vector<std::string> warnings = std::move(view_.warnings);
    view_ = std::move(before);
    view_.warnings = std::move(warnings);
    front_ = front, back_ = back;
    Word at{"", e.where().line, e.where().column};
    warn(at, e.message() + "; '" + command_ + ":' ignored");
    return;
  }
  if (!in.at_end()) warn(in.peek(), "'" + in.peek().text + "' after '" + command_ + ":' ignored");
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

bool Parser::cpfg_flag(WordReader& in) { return in.next("on or off").text.starts_with("on"); }

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

geometry::ViewParameters& Parser::view_for(int id) {
  auto it = view_.views.find(id);
  if (it == view_.views.end()) it = view_.views.emplace(id, view_.default_view).first;
  return it->second;
}

void Parser::set_all_views(const std::function<void(geometry::ViewParameters&)>& set) {
  set(view_.default_view);
  for (auto& [id, v] : view_.views) set(v);
}

void Parser::finish() {
  for (SurfaceCommand& s : view_.surfaces) {
    if (s.texture_path.empty()) continue;
    s.texture = static_cast<int>(view_.textures.size());
    view_.textures.push_back(s.texture_path);
  }
  if (!cpfg()) {
    // lpfg: both distances must be given to have an effect (LPFG manual 8.1.1).
    if (front_ && back_)
      set_all_views([&](geometry::ViewParameters& v) {
        v.front_distance = front_;
        v.back_distance = back_;
      });
    return;
  }
  // cpfg's checks once the file is read (the end of ReadViewData).
  geometry::CpfgView& v = cpfg_view();
  auto warn_file = [&](const std::string& message) { view_.warnings.push_back(view_.path + ": warning: " + message); };
  if (v.viewpoint == v.reference_point) {
    warn_file("the viewpoint and the view reference point are the same; cpfg's default view is used");
    v.viewpoint = {0, 0, -1};
    v.reference_point = {0, 0, 0};
  }
  if (view_.default_view.perspective) {
    if (v.front_distance < 0) {
      warn_file("the front distance cannot be negative in perspective; 0.1 is used, as in cpfg");
      v.front_distance = 0.1f;
    }
    if (v.front_distance > v.back_distance) {
      warn_file("the front distance is beyond the back distance; 1 and 100 are used, as in cpfg");
      v.front_distance = 1;
      v.back_distance = 100;
    }
  }
}

const geometry::ViewParameters& ViewFile::view(int id) const {
  auto it = views.find(id);
  return it == views.end() ? default_view : it->second;
}

std::vector<geometry::Light> ViewFile::lights_or_default() const {
  if (!lights.empty()) return lights;
  geometry::Light light;
  light.direction = default_light_direction;
  return {light};
}

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

ViewFile read_view_file(const std::string& path, const std::string& compiler, ViewDialect dialect) {
  read_input_file(path, "view file");  // a missing file named as such, not as the preprocessor says it
  ViewFile view;
  view.path = path;
  view.dialect = dialect;
  Parser parser(view);
  OriginalColumns columns;
  for (const PreprocessedLine& line : preprocess_file(path, compiler_or_default(compiler))) {
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
