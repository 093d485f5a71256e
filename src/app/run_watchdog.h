// The last resort of `sylva run --timeout`: the run checks its time limit
// between steps and wherever a string grows, but a model's own endless loop
// inside a production never comes back to a check. Past the limit and a
// grace period the watchdog says where the run was, removes what the run
// left half-written (temporary files, compiler process groups) and ends the
// process, rather than interrupting model code with a signal.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace sylva::app {

class RunWatchdog {
 public:
  // `where` says where the run is ("step 12"), from the watchdog's thread.
  RunWatchdog(double seconds, std::function<std::string()> where);
  ~RunWatchdog();  // the run ended in time: the watchdog stands down
  RunWatchdog(const RunWatchdog&) = delete;
  RunWatchdog& operator=(const RunWatchdog&) = delete;

  static constexpr double kGraceSeconds = 2;

 private:
  std::mutex mutex_;
  std::condition_variable stood_down_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace sylva::app
