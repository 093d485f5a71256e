// The experiment's progress on a terminal: one line redrawn in place,
//   [##########----------] 40/100 runs  3.2 runs/s  ETA 0:19  1 failed
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace sylva::experiment {

class Progress {
 public:
  // Draws only when `enabled` (standard error is a terminal).
  Progress(std::size_t total, bool enabled);
  void update(std::size_t done, std::size_t failed);
  void finish();
  // The line for `done` of the total after `seconds`, for tests.
  static std::string line(std::size_t done, std::size_t total, std::size_t failed, double seconds);

 private:
  std::size_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

}  // namespace sylva::experiment
