// Multi-view mode (LPFG manual 7.3) without a window: every view the model
// turns on with UseView is written as a file of its own. The views are the
// window: commands of the view file, numbered from 1 in order: vgroup 0 is
// the rules outside any vgroup, which query modules and the environment use
// (manual 5.12), and no window. The first (lowest numbered) view gets the
// output path as given; each other view gets the path with "-NAME" before the
// extension, NAME being its window: name: -o plant.png -> plant.png,
// plant-Side.png. Each view is drawn at its window's share of
// --width/--height.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "api/outputs.h"

namespace sylva {

struct ViewOutput {
  int view = 0;
  std::string path;
  OutputOptions size;
};

// The view number of the window: command at `index` (from 0) in the view file.
constexpr int window_view(std::size_t index) { return static_cast<int>(index) + 1; }

// The files `path` becomes: one, for view 0, when the model uses no views.
std::vector<ViewOutput> view_outputs(const std::string& path, const Simulation& simulation,
                                     const OutputOptions& options);

// Throws ModelError (at `model_path`) unless `view` is a window: of the view
// file: UseView of any other number would draw a full-size image of no window.
void check_view(int view, const io::InputFiles& inputs, const std::string& model_path);

// "-D name=id" for every window: of the view file (ids from 1 in order), so
// models can write UseView(name) and vgroup name:.
std::vector<std::string> view_name_defines(const io::InputFiles& inputs);

}  // namespace sylva
