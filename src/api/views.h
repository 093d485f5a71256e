// Multi-view mode (LPFG manual 7.3) without a window: every view the model
// turns on with UseView is written as a file of its own. The first (lowest
// numbered) view gets the output path as given; each other view gets the
// path with "-NAME" before the extension, NAME being its window: name in the
// view file ("view3" without one): -o plant.png -> plant.png, plant-Side.png.
// A view with a window: is drawn at that window's share of --width/--height.
#pragma once

#include <string>
#include <vector>

#include "api/outputs.h"

namespace sylva {

struct ViewOutput {
  int view = 0;
  std::string path;
  OutputOptions size;
};

// The files `path` becomes: one, for view 0, when the model uses no views.
std::vector<ViewOutput> view_outputs(const std::string& path, const Simulation& simulation,
                                     const OutputOptions& options);

// "-D name=id" for every window: of the view file (ids from 0 in order), so
// models can write UseView(name) and vgroup name:.
std::vector<std::string> view_name_defines(const io::InputFiles& inputs);

}  // namespace sylva
