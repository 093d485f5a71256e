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
#include "io/animation_file.h"
#include "io/parameter_file.h"
#include "io/view_file.h"

namespace sylva::io {

struct InputFiles {
  std::optional<ViewFile> view;
  std::optional<AnimationFile> animation;
  geometry::Palette palette = geometry::Palette::default_palette();  // the default without .map or .mat
  // The view file's surfaces in its order (Surface(id) counts from 0), each
  // with its view-file scale folded into `size` and its subdivisions set.
  std::vector<geometry::BezierSurface> surfaces;
  // .con files and .cset sets in command-line order (CurrentContour(id)
  // counts from 1: contours[id - 1]).
  std::vector<geometry::Contour> contours;
  // .func files and .fset sets in command-line order; func(name, x) finds
  // a function by name.
  std::vector<geometry::Function> functions;
  // .vset parameters in command-line order; val(name) finds one by name.
  std::vector<Parameter> parameters;
  // The view and animation files' warnings, and input files read past.
  std::vector<std::string> warnings;

  // The view file's turtle settings (the view file's defaults without one),
  // pointing at this object's surfaces and contours.
  turtle::TurtleSettings turtle_settings() const;
};

// .v (.dr, older) view, .a animation, .map colormap, .mat materials, .con
// and .cset contours, .func and .fset functions, .vset parameters. The
// environment (.e) and timeline (.tset) files lpfg also takes are read past
// with a warning; any other extension, two view, animation or colour files,
// or a file that cannot be read is a ModelError naming the file.
InputFiles read_input_files(const std::vector<std::string>& paths, const std::string& compiler = "");

}  // namespace sylva::io
