#include "api/views.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "support/diagnostic.h"

namespace sylva {
namespace {

const io::ViewWindow* window_of(const Simulation& simulation, int view) {
  const auto& view_file = simulation.inputs().view;
  if (!view_file) return nullptr;
  for (std::size_t k = 0; k < view_file->windows.size(); ++k)
    if (window_view(k) == view) return &view_file->windows[k];
  return nullptr;
}

std::string path_for_view(const std::string& path, const std::string& name) {
  const std::filesystem::path p(path);
  std::filesystem::path named = p.parent_path() / (p.stem().string() + "-" + name + p.extension().string());
  return named.string();
}

int share(int pixels, float fraction) { return std::max(1, static_cast<int>(std::lround(pixels * fraction))); }

}  // namespace

std::vector<ViewOutput> view_outputs(const std::string& path, const Simulation& simulation,
                                     const OutputOptions& options) {
  const std::vector<int>& views = simulation.views();
  if (views.empty()) return {ViewOutput{0, path, options}};
  std::vector<ViewOutput> outputs;
  for (std::size_t k = 0; k < views.size(); ++k) {
    ViewOutput out{views[k], path, options};
    const io::ViewWindow* window = window_of(simulation, views[k]);
    if (k > 0) out.path = path_for_view(path, window ? window->name : "view" + std::to_string(views[k]));
    if (window) {
      out.size.width = share(options.width, window->width);
      out.size.height = share(options.height, window->height);
    }
    outputs.push_back(std::move(out));
  }
  return outputs;
}

std::vector<std::string> view_name_defines(const io::InputFiles& inputs) {
  std::vector<std::string> defines;
  if (!inputs.view) return defines;
  for (std::size_t k = 0; k < inputs.view->windows.size(); ++k)
    defines.push_back(inputs.view->windows[k].name + "=" + std::to_string(window_view(k)));
  return defines;
}

void check_view(int view, const io::InputFiles& inputs, const std::string& model_path) {
  const auto& view_file = inputs.view;
  const std::size_t windows = view_file ? view_file->windows.size() : 0;
  if (view >= window_view(0) && view < window_view(windows)) return;
  std::string defined;
  if (!view_file)
    defined = "there is no view file, so no window: commands";
  else if (windows == 0)
    defined = "the view file defines no windows";
  else
    defined = "the view file defines " + std::to_string(windows) + " window" + (windows == 1 ? "" : "s") +
              ", views " + std::to_string(window_view(0)) +
              (windows == 1 ? std::string() : " to " + std::to_string(window_view(windows - 1)));
  throw ModelError(SourceLocation{model_path, 0, 0}, "UseView(" + std::to_string(view) + "): no such view; " + defined);
}

}  // namespace sylva
