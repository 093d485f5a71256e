#include "inputs/input_files.h"

#include <map>

#include "inputs/background_scene.h"
#include "inputs/contour_file.h"
#include "inputs/function_file.h"
#include "inputs/input_text.h"
#include "inputs/palette_files.h"
#include "inputs/parameter_file.h"
#include "inputs/view_file.h"
#include "inputs/view_file_inputs.h"
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

// cpfg's colour files, each of its number: all colormaps, or all material
// sets, whichever kind came last (cpfg: "later wins"); the other kind's files
// are read past.
geometry::Palette read_palette(InputKind mode, const std::map<int, std::optional<std::string>>& colormaps,
                               const std::map<int, std::optional<std::string>>& materials,
                               std::vector<std::string>& warnings) {
  const bool colormap = mode == InputKind::Colormap;
  geometry::Palette palette;
  palette.from_materials = !colormap;
  bool first = false;
  for (const auto& [slot, path] : colormap ? colormaps : materials) {
    if (!path) continue;
    geometry::Palette bank = colormap ? read_colormap_file(*path) : read_material_file(*path);
    if (slot == 1) {
      palette.entries = bank.entries;
      first = true;
    } else {
      palette.banks[slot] = bank.entries;
    }
  }
  // Without a first colormap, colours 0..255 get cpfg's default.
  if (!first) palette.entries.fill(palette.missing());
  for (const auto& [slot, path] : colormap ? materials : colormaps) {
    if (!path) continue;
    read_input_file(*path, "colour file");
    warnings.push_back(*path + ": warning: not used: a " + (colormap ? "colormap" : "material file") +
                       " given later decides that colours come from " +
                       (colormap ? "colormaps" : "material sets") + ", as in cpfg");
  }
  return palette;
}

// cpfg draws the view file's background scene only with colour files; its
// materials go to the palette's bank kBackgroundBank.
void read_background(InputFiles& inputs, const std::string& compiler, bool with_colour_files) {
  if (!with_colour_files) {
    inputs.warnings.push_back(inputs.view->path +
                              ": warning: background scene not drawn: cpfg draws it only with a colormap or "
                              "material file (-m or -M)");
    return;
  }
  BackgroundScene background = read_background_scene(inputs.view->background_scenes, compiler, inputs.palette.from_materials);
  geometry::MaterialBank& bank = inputs.palette.banks[kBackgroundBank];
  for (std::size_t k = 0; k < background.materials.size() && k < bank.size(); ++k) bank[k] = background.materials[k];
  if (background.materials.size() > bank.size())
    inputs.warnings.push_back(inputs.view->path + ": warning: only the background scene's first " +
                              std::to_string(bank.size()) + " materials are kept");
  inputs.warnings.insert(inputs.warnings.end(), background.warnings.begin(), background.warnings.end());
  inputs.background = std::move(background.scene);
}

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
  std::map<int, std::optional<std::string>> colormap_banks, material_banks;
  InputKind colour_mode = InputKind::Unknown;
  FunctionFiles function_files;
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
      case InputKind::Materials: {
        // cpfg keeps a colormap and a material set per number (-m2, -M3);
        // lpfg one colour file. The kind given last decides the mode.
        auto& banks = file.kind == InputKind::Colormap ? colormap_banks : material_banks;
        if (file.slot == 1) {
          // One first colour file: a colormap replaces a material set too.
          replace_earlier(colour_path, path, "colormap or material file", inputs.warnings);
          colormap_banks.erase(1);
          material_banks.erase(1);
        } else {
          replace_earlier(banks[file.slot], path, "colour file " + std::to_string(file.slot), inputs.warnings);
        }
        banks[file.slot] = path;
        colour_mode = file.kind;
        break;
      }
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
  const bool with_colour_files = colour_mode != InputKind::Unknown;
  if (with_colour_files) inputs.palette = read_palette(colour_mode, colormap_banks, material_banks, inputs.warnings);
  if (inputs.view && !inputs.view->background_scenes.empty()) read_background(inputs, compiler, with_colour_files);
  inputs.functions = function_files.read(inputs.warnings);
  if (inputs.view) {
    inputs.warnings.insert(inputs.warnings.end(), inputs.view->warnings.begin(), inputs.view->warnings.end());
    read_view_file_inputs(inputs);
  }
  if (inputs.animation)
    inputs.warnings.insert(inputs.warnings.end(), inputs.animation->warnings.begin(), inputs.animation->warnings.end());
  return inputs;
}

}  // namespace sylva::io
