#include "experiment/progress.h"

#include <cstdio>

namespace sylva::experiment {

Progress::Progress(std::size_t total, bool enabled) : total_(total), enabled_(enabled) {}

std::string Progress::line(std::size_t done, std::size_t total, std::size_t failed, double seconds) {
  constexpr int kWidth = 24;
  const int filled = total ? static_cast<int>(kWidth * done / total) : kWidth;
  std::string bar = "[" + std::string(filled, '#') + std::string(kWidth - filled, '-') + "]";
  char text[160];
  const double rate = seconds > 0 ? done / seconds : 0;
  if (done > 0 && done < total) {
    const long eta = static_cast<long>((total - done) / rate + 0.5);
    std::snprintf(text, sizeof text, " %zu/%zu runs  %.1f runs/s  ETA %ld:%02ld", done, total, rate, eta / 60, eta % 60);
  } else {
    std::snprintf(text, sizeof text, " %zu/%zu runs  %.1f runs/s", done, total, rate);
  }
  std::string out = bar + text;
  if (failed) out += "  " + std::to_string(failed) + " failed";
  return out;
}

void Progress::update(std::size_t done, std::size_t failed) {
  if (!enabled_) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  std::fprintf(stderr, "\r%s\033[K", line(done, total_, failed, seconds).c_str());
  std::fflush(stderr);
}

void Progress::finish() {
  if (enabled_) std::fputs("\n", stderr);
}

}  // namespace sylva::experiment
