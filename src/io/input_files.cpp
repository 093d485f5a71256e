#include "io/input_files.h"

#include "io/contour_file.h"
#include "io/function_file.h"
#include "io/input_text.h"
#include "io/palette_files.h"
#include "io/view_file.h"
#include "io/view_file_inputs.h"
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

InputFiles read_input_files(const std::vector<InputFile>& files, const std::string& compiler, ViewDialect dialect) {
  InputFiles inputs;
  std::optional<std::string> view_path, animation_path, colour_path;
  for (const InputFile& file : files) {
    const std::string& path = file.path;
    switch (file.kind) {
      case InputKind::View:
        replace_earlier(view_path, path, "view file", inputs.warnings);
        inputs.view = read_view_file(path, compiler, dialect);
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
        inputs.functions.push_back(read_function_file(path));
        break;
      case InputKind::FunctionSet:
        for (geometry::Function& f : read_function_set_file(path)) inputs.functions.push_back(std::move(f));
        break;
      case InputKind::Parameters:
        for (Parameter& p : read_parameter_file(path)) inputs.parameters.push_back(std::move(p));
        break;
      case InputKind::TimedFunctionSet:
        read_input_file(path, "timeline function set file");
        inputs.warnings.push_back(path + ": warning: timeline function sets are not supported; ignored");
        break;
      case InputKind::Environment:
        break;  // the environment's own (EnvironmentOptions)
      case InputKind::Unknown:
        inputs.warnings.push_back(path + ": warning: not a kind of input file lpfg or cpfg reads (." +
                                  extension_of(path) + "); ignored");
        break;
    }
  }
  if (inputs.view) {
    inputs.warnings.insert(inputs.warnings.end(), inputs.view->warnings.begin(), inputs.view->warnings.end());
    read_view_file_inputs(inputs);
  }
  if (inputs.animation)
    inputs.warnings.insert(inputs.warnings.end(), inputs.animation->warnings.begin(), inputs.animation->warnings.end());
  return inputs;
}

}  // namespace sylva::io
