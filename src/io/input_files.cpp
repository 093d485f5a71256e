#include "io/input_files.h"

#include "io/contour_file.h"
#include "io/function_file.h"
#include "io/input_text.h"
#include "io/palette_files.h"
#include "io/parameter_file.h"
#include "io/surface_file.h"
#include "io/view_file.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

// lpfg keeps one file of each of these kinds: a later one replaces it.
void replace_earlier(std::optional<std::string>& seen, const std::string& path, const std::string& what,
                     std::vector<std::string>& warnings) {
  if (seen && *seen != path)
    warnings.push_back(path + ": warning: a second " + what + "; it replaces " + *seen + ", as in lpfg and cpfg");
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

InputKind input_kind_of(const std::string& path) {
  static const std::pair<const char*, InputKind> kinds[] = {
      {"v", InputKind::View},          {"dr", InputKind::View},          {"a", InputKind::Animation},
      {"map", InputKind::Colormap},    {"mat", InputKind::Materials},    {"con", InputKind::Contour},
      {"cset", InputKind::ContourSet}, {"func", InputKind::Function},    {"fset", InputKind::FunctionSet},
      {"tset", InputKind::TimedFunctionSet}, {"vset", InputKind::Parameters}, {"e", InputKind::Environment}};
  const std::string ext = extension_of(path);
  for (const auto& [name, kind] : kinds)
    if (ext == name) return kind;
  return InputKind::Unknown;
}

namespace {

// The functions of the input files in lpfg's order (see InputFiles::functions).
struct FunctionFiles {
  std::optional<std::string> set, timeline_set, parameters;
  std::vector<std::string> singles;

  std::vector<geometry::Function> read(std::vector<std::string>& warnings) const {
    std::vector<geometry::Function> functions;
    if (set) functions = read_function_set_file(*set);
    if (timeline_set)
      for (geometry::Function& f : read_timeline_set_file(*timeline_set)) functions.push_back(std::move(f));
    if (parameters)
      for (Parameter& p : read_parameter_file(*parameters)) {
        geometry::Function constant;
        constant.name = std::move(p.name);
        constant.constant = p.value;
        functions.push_back(std::move(constant));
      }
    for (const std::string& path : singles) functions.push_back(read_function_file(path));
    for (const geometry::Function& f : functions) {
      // (A file of the older format, without "samples:", says nothing.)
      if (f.constant || f.samples == 0 ||
          (f.samples >= geometry::LpfgFunction::kMinSamples && f.samples <= geometry::LpfgFunction::kMaxSamples))
        continue;
      const int kept = f.samples < geometry::LpfgFunction::kMinSamples ? geometry::LpfgFunction::kMinSamples
                                                                       : geometry::LpfgFunction::kMaxSamples;
      warnings.push_back("function " + f.name + ": warning: " + std::to_string(f.samples) +
                         " samples; lpfg keeps " + std::to_string(kept));
    }
    return functions;
  }
};

}  // namespace

InputFiles read_input_files(const std::vector<InputFile>& files, const std::string& compiler) {
  InputFiles inputs;
  std::optional<std::string> view_path, animation_path, colour_path;
  FunctionFiles function_files;
  for (const InputFile& file : files) {
    const std::string& path = file.path;
    switch (file.kind) {
      case InputKind::View:
        replace_earlier(view_path, path, "view file", inputs.warnings);
        inputs.view = read_view_file(path, compiler);
        break;
      case InputKind::Animation:
        replace_earlier(animation_path, path, "animation file", inputs.warnings);
        inputs.animation = read_animation_file(path);
        break;
      case InputKind::Colormap:
      case InputKind::Materials:
        if (file.slot != 1) {
          read_input_file(path, "colour file");
          inputs.warnings.push_back(path + ": warning: colour file " + std::to_string(file.slot) +
                                    " is not used; only the first colormap or material set is");
          break;
        }
        replace_earlier(colour_path, path, "colormap or material file", inputs.warnings);
        inputs.palette = file.kind == InputKind::Colormap ? read_colormap_file(path) : read_material_file(path);
        break;
      case InputKind::Contour:
        inputs.contours.push_back(read_contour_file(path));
        break;
      case InputKind::ContourSet:
        for (geometry::Contour& c : read_contour_set_file(path)) inputs.contours.push_back(std::move(c));
        break;
      case InputKind::Function:
        function_files.singles.push_back(path);
        break;
      case InputKind::FunctionSet:
        replace_earlier(function_files.set, path, "function set file", inputs.warnings);
        break;
      case InputKind::TimedFunctionSet:
        replace_earlier(function_files.timeline_set, path, "timeline function set file", inputs.warnings);
        break;
      case InputKind::Parameters:
        replace_earlier(function_files.parameters, path, "parameter file", inputs.warnings);
        break;
      case InputKind::Environment:
        break;  // the environment's own (EnvironmentOptions)
      case InputKind::Unknown:
        inputs.warnings.push_back(path + ": warning: not a kind of input file lpfg or cpfg reads (." +
                                  extension_of(path) + "); ignored");
        break;
    }
  }
  inputs.functions = function_files.read(inputs.warnings);
  if (inputs.view) {
    for (const SurfaceCommand& s : inputs.view->surfaces) inputs.surfaces.push_back(load_surface(*inputs.view, s));
    inputs.warnings.insert(inputs.warnings.end(), inputs.view->warnings.begin(), inputs.view->warnings.end());
  }
  if (inputs.animation)
    inputs.warnings.insert(inputs.warnings.end(), inputs.animation->warnings.begin(), inputs.animation->warnings.end());
  return inputs;
}

}  // namespace sylva::io
