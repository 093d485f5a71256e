// The view file reader's parts (view_file.cpp dispatches; the commands are
// read in view_camera_commands.cpp, view_render_commands.cpp,
// view_turtle_commands.cpp and view_external_files.cpp): one Parser reads
// one file, a command at a time, in the dialect the file is read in.
#pragma once

#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "inputs/input_text.h"
#include "inputs/view_file.h"

namespace sylva::io {

class Parser {
 public:
  explicit Parser(ViewFile& view);

  // Reads one command. A value the program cannot read leaves the command
  // without effect and is a warning, as lpfg and cpfg only print a message.
  void command(const Command& c, const std::string& file);
  // What follows from the whole file: lpfg's pair of clipping distances,
  // cpfg's corrections of its view.
  void finish();

 private:
  using Handler = void (Parser::*)(WordReader&);
  // How one program reads a command: a handler, or (known to the program but
  // its effect not reproduced) why it is ignored.
  struct Reading {
    Handler handler = nullptr;
    const char* ignored = nullptr;
  };
  struct Entry {
    Reading lpfg, cpfg;
  };
  static const std::map<std::string, Entry>& commands();

  bool cpfg() const { return view_.dialect == ViewDialect::Cpfg; }
  const char* program() const { return cpfg() ? "cpfg" : "lpfg"; }
  void warn(const Word& at, const std::string& message);

  // Values, each failing (and so ignoring the command) with what was expected.
  float positive(WordReader& in, std::string_view what);
  bool flag(WordReader& in);
  // cpfg's flags: "on" (or any word starting so) is on, anything else off.
  bool cpfg_flag(WordReader& in);
  int choice(WordReader& in, std::string_view what, std::initializer_list<const char*> names);
  geometry::Vec3 direction(WordReader& in, std::string_view what);
  geometry::Rgb color(WordReader& in, std::string_view what);
  // The views a view id names (lpfg's id k: the k-th window, counted from 0).
  std::vector<int> view_ids(WordReader& in);
  geometry::ViewParameters& view_for(int id);
  geometry::CpfgView& cpfg_view() { return *view_.default_view.cpfg; }
  void set_all_views(const std::function<void(geometry::ViewParameters&)>& set);

  // Camera (view_camera_commands.cpp).
  void projection(WordReader& in);
  void scale(WordReader& in);
  void cpfg_scale_factor(WordReader& in);
  void min_zoom(WordReader& in) { view_.min_zoom = positive(in, "the minimum zoom"); }
  void max_zoom(WordReader& in) { view_.max_zoom = positive(in, "the maximum zoom"); }
  void generate_on_view_change(WordReader& in);
  void view(WordReader& in);
  void old_style_view(WordReader& in, const std::vector<int>& ids);
  void box(WordReader& in);
  void cpfg_box(WordReader& in);
  void window(WordReader& in);
  void window_border(WordReader& in);
  void front_distance(WordReader& in);
  void back_distance(WordReader& in);
  void viewpoint(WordReader& in) { cpfg_view().viewpoint = in.vec3("the viewpoint"); }
  void view_reference_point(WordReader& in) { cpfg_view().reference_point = in.vec3("the view reference point"); }
  void twist(WordReader& in);
  void viewing_angle(WordReader& in) { cpfg_view().viewing_angle = in.number("the viewing angle"); }

  // Rendering and lights (view_render_commands.cpp).
  void z_buffer(WordReader& in);
  void render_mode(WordReader& in);
  void shade_mode(WordReader& in);
  void shadow_map(WordReader& in);
  void light(WordReader& in);
  void light_direction(WordReader& in);
  void stationary_lights(WordReader& in) { view_.render.stationary_lights = flag(in); }
  void concave_polygons(WordReader& in);
  void auto_normals(WordReader& in) { view_.render.auto_normals = flag(in); }
  void antialiasing(WordReader& in);
  void line_style(WordReader& in);
  void wireframe_line_width(WordReader& in) { view_.render.wireframe_line_width = positive(in, "the line width"); }
  void capped_cylinders(WordReader& in) { view_.render.capped_cylinders = flag(in); }
  void backface_culling(WordReader& in) { view_.render.backface_culling = flag(in); }
  void font(WordReader& in);
  void winfont(WordReader& in);
  void ps_linecap(WordReader& in);
  void gradient(WordReader& in);
  void tapered_lines(WordReader& in);
  void cue_range(WordReader& in);

  // Turtle (view_turtle_commands.cpp).
  void contour_sides(WordReader& in);
  void polygonization_level(WordReader& in);
  void corrected_rotation(WordReader& in) { view_.corrected_rotation = flag(in); }
  void tropism(WordReader& in) { view_.tropisms.push_back(tropism_parts(in, false)); }
  void torque(WordReader& in) { view_.tropisms.push_back(tropism_parts(in, true)); }
  TropismCommand tropism_parts(WordReader& in, bool torque);
  void stropism(WordReader& in);
  void tropism_direction(WordReader& in);
  void initial_elasticity(WordReader& in) { view_.old_tropism.initial_elasticity = in.number("the elasticity"); }
  void elasticity_increment(WordReader& in) { view_.old_tropism.elasticity_increment = in.number("the increment"); }
  void initial_color(WordReader& in);
  void initial_line_width(WordReader& in);
  void angle_increment(WordReader& in) { view_.angle_increment = in.number("the angle increment"); }
  void angle_factor(WordReader& in);
  void color_increment(WordReader& in);
  void line_width_increment(WordReader& in) { view_.line_width_increment = in.number("the line width increment"); }
  void initial_scale(WordReader& in);
  void scale_multiplier(WordReader& in);
  void twist_of_cylinders(WordReader& in);

  // External files (view_external_files.cpp).
  void surface(WordReader& in);
  void mesh(WordReader& in);
  void texture(WordReader& in);
  void background_scene(WordReader& in);
  void contour(WordReader& in);
  void function(WordReader& in);
  void function_set(WordReader& in);
  void curve(WordReader& in);

  ViewFile& view_;
  std::string file_;     // of the command being read
  std::string command_;  // its name as written, for messages
  std::optional<float> front_, back_;  // lpfg's, which count only together
};

// The value of a light's or tropism's part key ("D:", "D", cpfg's "Diffuse"):
// its first letter, or 0 when `dialect` does not read the word as a key.
char part_key(const std::string& word, ViewDialect dialect);

}  // namespace sylva::io
