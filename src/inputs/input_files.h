// The input files given beside the L-system (LPFG manual 1.1.2), recognized
// by their extension, in any order.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/contour.h"
#include "geometry/function.h"
#include "geometry/material.h"
#include "geometry/surface.h"
#include "inputs/animation_file.h"
#include "inputs/parameter_file.h"
#include "inputs/view_file.h"

namespace sylva::io {

// What an input file is to the run. lpfg recognises a file by its extension;
// cpfg also by a flag before it (-m colormap, -M materials, -e environment)
// or by its place (the second file is the view file, the third the
// animation file), so the kind travels with the path.
enum class InputKind {
  View,          // .v (.dr, older)
  Animation,     // .a
  Colormap,      // .map
  Materials,     // .mat
  Contour,       // .con
  ContourSet,    // .cset
  Function,      // .func
  FunctionSet,   // .fset
  TimedFunctionSet,  // .tset (timeline functions, tfunc)
  Parameters,    // .vset
  Environment,   // .e: read by the engine's environment, not here
  Unknown,
};

// The kind a file's extension names (Unknown for any other).
InputKind input_kind_of(const std::string& path);

struct InputFile {
  std::string path;
  InputKind kind = InputKind::Unknown;
  // cpfg's colormap and material numbers (-m2 file, -M3 file); 1 otherwise.
  int slot = 1;

  InputFile(std::string file_path) : path(std::move(file_path)), kind(input_kind_of(path)) {}  // NOLINT: a path is a file
  InputFile(const char* file_path) : InputFile(std::string(file_path)) {}                      // NOLINT
  InputFile(std::string file_path, InputKind file_kind, int number = 1)
      : path(std::move(file_path)), kind(file_kind), slot(number) {}
};

struct InputFiles {
  std::optional<ViewFile> view;
  std::optional<AnimationFile> animation;
  geometry::Palette palette = geometry::Palette::default_palette();  // the default without .map or .mat
  // The view file's surfaces in its order (Surface(id) counts from 0), each
  // with its view-file scale folded into `size` and its subdivisions set.
  std::vector<geometry::BezierSurface> surfaces;
  // .con files and .cset sets in command-line order (CurrentContour(id)
  // counts from 1: contours[id - 1]); then a cpfg view file's "contour: id
  // file" commands, each at its id (ids it leaves out are circles).
  std::vector<geometry::Contour> contours;
  // The curves of cpfg's curve functions (curveX ... curveGAL, ids from 1):
  // a cpfg view file's "curve:" files, each with its `samples` the size of
  // cpfg's arc-length table (geometry/curve_cpfg.h). Empty for lpfg, whose
  // curve functions read `contours`.
  std::vector<geometry::Contour> curves;
  // lpfg's one list of functions, whose ids (from 1) func, tfunc, pfunc and
  // val take: the functions of the .fset file, those of the .tset file, the
  // parameters of the .vset file (each a Function with only a name and a
  // constant), then those of the .func files in command-line order. Of
  // .fset, .tset and .vset files lpfg reads only the last one given. Then a
  // cpfg view file's "function:" and "function set:" files (cpfg names only a
  // function set's functions, as cpfg does).
  std::vector<geometry::Function> functions;
  // cpfg's background scene (view file "background scene:"), drawn with the
  // plant; its materials are the palette's bank kBackgroundBank.
  std::optional<geometry::Scene> background;
  // The view and animation files' warnings, and input files read past.
  std::vector<std::string> warnings;

  // The view file's turtle settings (the view file's defaults without one),
  // pointing at this object's surfaces and contours.
  turtle::TurtleSettings turtle_settings() const;
};

// Reads every file as its kind says, in the order given, the view file in
// `dialect`. As lpfg does, a second view, animation or colour file replaces
// the first (with a warning), .e files are left to the environment, and a
// file of no known kind is read past with a warning. A file that cannot be
// read, or is not what its kind says, is a ModelError naming the file; but a
// file the view file names that cannot be read is a warning, as in lpfg and
// cpfg (a surface is left out, a function is 0 everywhere, cpfg reads no
// contour from that one on).
InputFiles read_input_files(const std::vector<InputFile>& files, const std::string& compiler = "",
                            ViewDialect dialect = ViewDialect::Lpfg);

}  // namespace sylva::io
