// What a running model asks of the engine through its predefined functions
// (LPFG manual 6.1, 6.4, 6.6: OutputString, LoadString, OutputFrame,
// DisplayFrame, UseView), held until the model's code returns: the engine is
// never re-entered from inside a control statement or a rule. Simulation
// takes the requests and acts on them.
#pragma once

#include <string>
#include <vector>

namespace sylva {

struct ModelRequest {
  int kind = 0;  // abi::kRequest...
  int value = 0;
  std::string file;
};

class ModelRequestQueue {
 public:
  // The ControlState::request callback; `self` is a ModelRequestQueue.
  static void receive(void* self, int request, int value, const char* file) {
    static_cast<ModelRequestQueue*>(self)->requests_.push_back(ModelRequest{request, value, file ? file : ""});
  }
  // The requests so far, in the order made; the queue is left empty.
  std::vector<ModelRequest> take() {
    std::vector<ModelRequest> taken;
    taken.swap(requests_);
    return taken;
  }
  void clear() { requests_.clear(); }

 private:
  std::vector<ModelRequest> requests_;
};

}  // namespace sylva
