#include "api/model_requests.h"

#include <algorithm>

#include "api/views.h"
#include "io/output_file.h"
#include "io/string_reader.h"
#include "io/string_text.h"
#include "support/diagnostic.h"

namespace sylva {

void ModelRequests::handle(void* self, int request, int value, const char* file) {
  static_cast<ModelRequests*>(self)->request(request, value, file);
}

std::string ModelRequests::file_name(const char* file, const char* function) const {
  if (!file || !*file)
    throw ModelError(SourceLocation{simulation_.model_path(), 0, 0},
                     std::string(function) + " needs a file name, and was given none");
  return file;
}

void ModelRequests::request(int request, int value, const char* file) {
  derive::Derivation& d = simulation_.derivation();
  switch (request) {
    case abi::kRequestOutputString:
      io::write_output_file(file_name(file, "OutputString"), io::format_string(d.string(), d.types()));
      break;
    case abi::kRequestLoadString:
      d.replace_string(io::read_string_file(file_name(file, "LoadString"), d.types()));
      break;
    case abi::kRequestOutputFrame: {
      std::string path = file_name(file, "OutputFrame");
      check_output_path(path);
      pending_frames_.push_back(std::move(path));
      break;
    }
    case abi::kRequestDisplayFrame:
      display_requested_ = true;
      break;
    case abi::kRequestUseView:
      check_view(value);
      if (std::find(views_.begin(), views_.end(), value) == views_.end()) {
        views_.push_back(value);
        std::sort(views_.begin(), views_.end());
      }
      break;
    default:
      break;
  }
}

// A view is a window: command of the view file (manual 6.4); any other
// number would be drawn as a full-size image of no window.
void ModelRequests::check_view(int view) const {
  const auto& view_file = simulation_.inputs().view;
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
  throw ModelError(SourceLocation{simulation_.model_path(), 0, 0},
                   "UseView(" + std::to_string(view) + "): no such view; " + defined);
}

void ModelRequests::on_phase(derive::Derivation::Phase phase, bool stopped) {
  if (phase == derive::Derivation::Phase::Starting) {
    views_.clear();
    pending_frames_.clear();
    display_requested_ = false;
    return;
  }
  std::vector<std::string> frames;
  frames.swap(pending_frames_);
  if (stopped) return;  // Stop() in the same step: lpfg outputs no frame
  for (const std::string& path : frames)
    for (const ViewOutput& out : view_outputs(path, simulation_, options))
      write_output(out.path, simulation_.scene(out.view), simulation_, out.size, out.view);
}

bool ModelRequests::take_display_request() {
  const bool requested = display_requested_;
  display_requested_ = false;
  return requested;
}

}  // namespace sylva
