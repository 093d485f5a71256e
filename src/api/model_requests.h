// What a running model asks of the engine through its predefined functions
// (LPFG manual 6.1, 6.4, 6.6): OutputString and LoadString at once,
// OutputFrame at the end of the step (none if Stop() came in the same step),
// DisplayFrame for animations shown on request, UseView for the views drawn.
#pragma once

#include <string>
#include <vector>

#include "api/outputs.h"
#include "derive/derivation.h"

namespace sylva {

class ModelRequests {
 public:
  explicit ModelRequests(Simulation& simulation) : simulation_(simulation) {}

  // The ControlState::request callback; `self` is a ModelRequests.
  static void handle(void* self, int request, int value, const char* file);
  // Derivation's phase hook.
  void on_phase(derive::Derivation::Phase phase, bool stopped);

  OutputOptions options;  // the size of OutputFrame images
  // Views turned on by UseView since the run began, in increasing order.
  const std::vector<int>& views() const { return views_; }
  // Whether DisplayFrame was called since the last time this was asked.
  bool take_display_request();

 private:
  void request(int request, int value, const char* file);
  std::string file_name(const char* file, const char* function) const;
  void check_view(int view) const;

  Simulation& simulation_;
  std::vector<int> views_;
  std::vector<std::string> pending_frames_;
  bool display_requested_ = false;
};

}  // namespace sylva
