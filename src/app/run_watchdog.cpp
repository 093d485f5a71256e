#include "app/run_watchdog.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>

#include "support/interruption.h"

namespace sylva::app {

RunWatchdog::RunWatchdog(double seconds, std::function<std::string()> where) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(seconds + kGraceSeconds));
  thread_ = std::thread([this, deadline, seconds, where = std::move(where)] {
    std::unique_lock lock(mutex_);
    if (stood_down_.wait_until(lock, deadline, [this] { return done_; })) return;
    char text[512];
    const int n = std::snprintf(text, sizeof text,
                                "sylva: error: %s: the run went past its time limit of %g s and did not come back to "
                                "a check (a model's own loop?); stopped (--timeout SECONDS sets another)\n",
                                where().c_str(), seconds);
    // Straight to the descriptor: the run's thread may hold stderr's lock.
    if (n > 0) (void)!write(STDERR_FILENO, text, static_cast<std::size_t>(n) < sizeof text ? n : sizeof text - 1);
    interruption::clean_up_now();
    _exit(1);
  });
}

RunWatchdog::~RunWatchdog() {
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  stood_down_.notify_one();
  thread_.join();
}

}  // namespace sylva::app
