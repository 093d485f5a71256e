// The view file (.v, LPFG manual 8.1, CPFG manual 8.1): camera, rendering,
// geometry presentation, tropisms and the external files (surfaces, meshes,
// textures; cpfg's contours, functions and curves). It goes through the C
// preprocessor first, as in lpfg and cpfg. lpfg and cpfg read different
// commands, and some alike commands differently, so the file is read in the
// dialect of the program the model is written for (docs/reference-dialects.md).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geometry/camera.h"
#include "geometry/material.h"
#include "geometry/render_settings.h"
#include "geometry/tessellation.h"
#include "geometry/vec3.h"
#include "turtle/turtle_settings.h"

namespace sylva::io {

// Which program's reading of the view file: lpfg's (L+C models) or cpfg's.
enum class ViewDialect { Lpfg, Cpfg };

enum class GenerateOnViewChange { Off, On, Triggered };

// window: (7.3): a view's place in the image, relative to its size.
struct ViewWindow {
  std::string name;  // its id is its position among the windows, from 1
  float left = 0, top = 0, width = 1, height = 1;
};

// tropism: and torque: (8.1.4), with every part the manual gives: the
// turtle's own Tropism.
using TropismCommand = turtle::Tropism;

// surface: (8.1.5); surfaces get ids from 0 in this order.
struct SurfaceCommand {
  std::string id;    // cpfg's form "surface: id file.s scale ..." (the ~id module); empty for lpfg's
  std::string file;  // as written
  std::string path;  // relative to the view file's folder
  float scale = 1;
  int s_divisions = 0, t_divisions = 0;  // 0: the surface's default
  int texture = -1;                      // -1: none
  std::string texture_path;              // cpfg's texfile, added to the textures at the end
  int line = 0, column = 0;              // of the file name, for messages
};

struct MeshCommand {
  std::string file, path;
  float scale = 1;
  geometry::Vec3 contact{0, 0, 0};
};

// cpfg's "contour: id file" (CPFG manual 8.1.5): the contour drawn as `id`.
struct ContourCommand {
  int id = 1;
  std::string file, path;  // as written; relative to the view file's folder
  int line = 0, column = 0;  // of the file name, for messages
};

// cpfg's "function: file [samples]" and "function set: file" (CPFG manual
// 8.1.6), and "curve: file [samples]" (the curves of curveX ... curveGAL).
struct FunctionCommand {
  std::string file, path;
  int samples = 0;  // 0: none given
  bool set = false;  // a function set (.fset): it replaces the functions before it
  int line = 0, column = 0;
};

// cpfg's deprecated tropism (CPFG manual 8.1.10): the direction every F
// bends toward by the turtle's elasticity, and the step of the _ module.
struct CpfgOldTropism {
  geometry::Vec3 direction{0, 1, 0};
  float initial_elasticity = 0;
  float elasticity_increment = 0;
};

struct WinFont {
  std::string name = "Arial";
  int size = 12;
  bool bold = false, italic = false;
};

struct ViewFile {
  std::string path;
  ViewDialect dialect = ViewDialect::Lpfg;

  // The camera of each view id (0 in single-view mode). A view without its
  // own view: or box: command gets default_view, which holds the global
  // projection:, scale:, front/back distance: commands.
  geometry::ViewParameters default_view;
  std::map<int, geometry::ViewParameters> views;
  const geometry::ViewParameters& view(int id = 0) const;

  float min_zoom = 0.05f, max_zoom = 50;
  GenerateOnViewChange generate_on_view_change = GenerateOnViewChange::Off;
  std::vector<ViewWindow> windows;
  int window_border_width = 1;
  geometry::Rgb window_border_color{0, 0, 0};

  geometry::RenderSettings render;
  std::vector<geometry::Light> lights;  // empty: the default light
  // The default light is directional: lpfg's along +z, cpfg's along its
  // "light direction:" (1,0,0 by default).
  geometry::Vec3 default_light_direction{0, 0, 1};
  std::vector<geometry::Light> lights_or_default() const;

  int contour_sides = 16;
  bool corrected_rotation = true;
  std::vector<TropismCommand> tropisms;  // ids from 1
  std::optional<TropismCommand> simple_tropism;  // stropism:

  std::vector<SurfaceCommand> surfaces;
  std::vector<MeshCommand> meshes;
  std::vector<std::string> textures;  // paths relative to the view file's folder; ids from 0
  std::vector<std::string> background_scenes;  // cpfg's background scene files (inputs/background_scene.h)
  // cpfg's contours, functions and curves, in the file's order; read by
  // read_input_files (inputs/view_file_inputs.h).
  std::vector<ContourCommand> contour_files;
  std::vector<FunctionCommand> function_files;
  std::vector<FunctionCommand> curve_files;

  std::string font = "-*-courier-bold-r-*-*-12-*-*-*-*-*-*-*";
  WinFont winfont;

  // cpfg's "initial color:" and "initial line width:" (lpfg reads neither).
  std::optional<int> initial_color;
  // Their second values, the back side's (cpfg's @; and @,).
  std::optional<int> initial_back_color, back_color_increment;
  std::optional<float> initial_line_width;
  // cpfg's other turtle commands (CPFG manual 8.1.1), with its defaults: what
  // a cpfg model's symbols without parameters use. "angle factor: y" sets
  // angle_increment to 360/y.
  float angle_increment = 45;
  float line_width_increment = 0;
  int color_increment = 1;
  float initial_scale = 1;
  float scale_multiplier = 1;
  CpfgOldTropism old_tropism;

  // "file:line:column: warning: ..." for commands the program does not
  // read, values it cannot read, and effects Sylva does not reproduce.
  std::vector<std::string> warnings;

  // What the turtle takes from the view file; the caller fills `surfaces`
  // and `contours`.
  turtle::TurtleSettings turtle_settings() const;
  geometry::TessellationOptions tessellation_options() const;
};

// Preprocesses `path` with `compiler -E` (empty: $SYLVA_CXX, $CXX, then g++)
// and reads its commands as `dialect`'s program does. A missing file or a
// preprocessor error is a ModelError at the file, line and column of the
// original text; as in lpfg and cpfg, a command the program does not know or
// whose values it cannot read is only a warning (the command is ignored).
ViewFile read_view_file(const std::string& path, const std::string& compiler = "",
                        ViewDialect dialect = ViewDialect::Lpfg);

}  // namespace sylva::io
