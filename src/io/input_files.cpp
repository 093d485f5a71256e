#include "io/input_files.h"

#include "io/contour_file.h"
#include "io/function_file.h"
#include "io/input_text.h"
#include "io/palette_files.h"
#include "io/surface_file.h"
#include "io/view_file.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

void only_one(std::optional<std::string>& seen, const std::string& path, const std::string& what) {
  if (seen)
    throw ModelError(SourceLocation{path, 0, 0}, "a second " + what + " (" + *seen + " is one already); lpfg takes one");
  seen = path;
}

geometry::BezierSurface load_surface(const ViewFile& view, const SurfaceCommand& command) {
  geometry::BezierSurface surface;
  try {
    surface = read_surface_file(command.path);
  } catch (const ModelError& e) {
    // A surface file that is missing is the view file's mistake: say where it is named.
    if (e.where().line == 0)
      throw ModelError(SourceLocation{view.path, command.line, command.column}, e.message() + " " + command.path);
    throw;
  }
  // Surface(id, s) scales by s * (view-file scale) / size.
  surface.size /= command.scale;
  if (command.s_divisions > 0) {
    surface.u_divisions = command.s_divisions;
    surface.v_divisions = command.t_divisions;
  }
  return surface;
}

}  // namespace

turtle::TurtleSettings InputFiles::turtle_settings() const {
  // Without a view file, the manual's defaults (16 contour sides, ...).
  turtle::TurtleSettings settings = view ? view->turtle_settings() : ViewFile{}.turtle_settings();
  settings.surfaces = &surfaces;
  settings.contours = &contours;
  return settings;
}

InputFiles read_input_files(const std::vector<std::string>& paths, const std::string& compiler) {
  InputFiles inputs;
  std::optional<std::string> view_path, animation_path, colour_path;
  for (const std::string& path : paths) {
    std::string ext = extension_of(path);
    if (ext == "v" || ext == "dr") {
      only_one(view_path, path, "view file");
      inputs.view = read_view_file(path, compiler);
    } else if (ext == "a") {
      only_one(animation_path, path, "animation file");
      inputs.animation = read_animation_file(path);
    } else if (ext == "map") {
      only_one(colour_path, path, "colormap or material file");
      inputs.palette = read_colormap_file(path);
    } else if (ext == "mat") {
      only_one(colour_path, path, "colormap or material file");
      inputs.palette = read_material_file(path);
    } else if (ext == "con") {
      inputs.contours.push_back(read_contour_file(path));
    } else if (ext == "cset") {
      for (geometry::Contour& c : read_contour_set_file(path)) inputs.contours.push_back(std::move(c));
    } else if (ext == "func") {
      inputs.functions.push_back(read_function_file(path));
    } else if (ext == "fset") {
      for (geometry::Function& f : read_function_set_file(path)) inputs.functions.push_back(std::move(f));
    } else if (ext == "vset") {
      for (Parameter& p : read_parameter_file(path)) inputs.parameters.push_back(std::move(p));
    } else if (ext == "e" || ext == "tset") {
      read_input_file(path, "input file");
      inputs.warnings.push_back(path + ": warning: " + (ext == "e" ? "environment" : "timeline") +
                                " files are not supported; ignored");
    } else if (ext == "l") {
      throw ModelError(SourceLocation{path, 0, 0}, "an L-system, not an input file: give it as the model");
    } else {
      throw ModelError(SourceLocation{path, 0, 0},
                       "unknown kind of input file" + (ext.empty() ? std::string(" (no extension)") : " (." + ext + ")") +
                           ": expected .v, .a, .map, .mat, .con, .cset, .func, .fset or .vset");
    }
  }
  if (inputs.view) {
    for (const SurfaceCommand& s : inputs.view->surfaces) inputs.surfaces.push_back(load_surface(*inputs.view, s));
    inputs.warnings.insert(inputs.warnings.end(), inputs.view->warnings.begin(), inputs.view->warnings.end());
  }
  if (inputs.animation)
    inputs.warnings.insert(inputs.warnings.end(), inputs.animation->warnings.begin(), inputs.animation->warnings.end());
  return inputs;
}

}  // namespace sylva::io
