// cpfg's background scene (CPFG manual 8.3, view-file "background scene:"):
// a file of OpenGL-like commands, preprocessed, drawn with the plant.
#pragma once

#include <string>
#include <vector>

#include "geometry/material.h"
#include "geometry/scene.h"
#include "inputs/preprocessor.h"

namespace sylva::io {

// The palette bank the background's materials go in (cpfg's own colormaps
// and material sets are 0..11): each `material` command is the next entry.
constexpr int kBackgroundBank = 12;

struct BackgroundScene {
  // Polygons, rectangles, meshes and boxes as triangles; spheres, cylinders
  // and cones as the turtle's spheres, segments and discs (drawn in the
  // view's line style, as cpfg draws them with the turtle's routines). All
  // of module index 0, so they come first, as cpfg draws the background
  // before the plant. Colours are palette indices: 0 (cpfg's colour 0 of
  // colormap 1) until a `material`, then entries of kBackgroundBank.
  geometry::Scene scene;
  std::vector<geometry::Material> materials;  // the bank's entries, in order
  std::vector<std::string> warnings;          // file:line: warning: ...
};

// The palette index of entry `entry` of the background's bank.
inline int background_color(int entry) { return geometry::Palette::kBankSize * (kBackgroundBank - 1) + entry; }

// Reads the files of a "background scene:" command (names separated by
// blanks, commas or semicolons, as cpfg splits them). As cpfg does, an
// unknown keyword or a command short of numbers is reported and skipped.
BackgroundScene read_background_scene(const std::vector<std::string>& paths, const std::string& compiler,
                                      bool from_materials);
// The same from the files' lines after the preprocessor, in order.
BackgroundScene parse_background_scene(const std::vector<PreprocessedLine>& lines, bool from_materials);

}  // namespace sylva::io
