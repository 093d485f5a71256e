// Bounds on a run: how many modules a string may hold, how many bytes the
// strings together may take, and how long the run may last. A runaway model
// (A -> A A for 60 steps) is stopped with a message naming the step and the
// limit, before the allocation that would cross it rather than after.
//
// The limits are checked where strings grow (every growth of a string's
// buffer, wherever it happens, model code included) and between the pieces
// of a step; so a check costs nothing while a string fits its buffer.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "support/diagnostic.h"

namespace sylva {

struct RunLimits {
  std::size_t max_modules = 0;  // in one string; 0: no limit
  std::size_t max_memory = 0;   // bytes of all strings together; 0: no limit
  double timeout_seconds = 0;   // the run: derivation, interpretation, outputs; 0: no limit
  // In a string about to be drawn (the turtle's geometry, images, meshes);
  // 0: no limit.
  std::size_t max_drawn_modules = 0;
};

// Defaults that keep a run from taking the machine down: half the physical
// memory for strings, and for a string that is drawn a module for every 64
// bytes of it, as the turtle's geometry needs many times a module's bytes.
// A string that is only derived and written is bounded by its memory alone
// (a cpfg symbol or an lpfg module without parameters is one byte). No time
// limit.
RunLimits default_run_limits();
// The drawing's module limit a memory limit implies (0 for none).
std::size_t max_modules_for_memory(std::size_t max_memory);

// A limit crossed: the message names the step, the amount and the limit.
class LimitExceeded : public ModelError {
 public:
  using ModelError::ModelError;
};

// The limits of one run, checked while it is active on this thread.
class RunBudget {
 public:
  RunBudget() = default;
  RunBudget(const RunBudget&) = delete;
  RunBudget& operator=(const RunBudget&) = delete;

  void set_limits(const RunLimits& limits) { limits_ = limits; }
  const RunLimits& limits() const { return limits_; }
  // The clock of the time limit starts now.
  void start_clock();
  // What the run is doing, for messages: the step under way (0: the axiom).
  void set_step(int step, bool drawing = false) {
    step_.store(step, std::memory_order_relaxed);
    drawing_.store(drawing, std::memory_order_relaxed);
  }
  // "step 12", "the axiom" or "drawing after step 12"; from any thread.
  std::string where() const;
  // The encoded size of each module type, for counting a string's modules.
  void set_module_sizes(const std::uint32_t* sizes) { sizes_ = sizes; }

  // Throws LimitExceeded past the time limit.
  void check_time() const;
  // Throws LimitExceeded when the encoded string `data` of `bytes` bytes
  // holds more modules than allowed. Counts only a string long enough to.
  void check_modules(const unsigned char* data, std::size_t bytes) const;
  // The same for a string about to be drawn, against max_drawn_modules.
  void check_drawn_modules(const unsigned char* data, std::size_t bytes) const;
  // Throws LimitExceeded when the strings would take more than allowed
  // with `more` bytes allocated on top of what they take now.
  void check_memory(std::size_t more) const;
  // As many of `wanted` bytes as may be set aside for a string ahead of need.
  std::size_t affordable(std::size_t wanted) const;

  // Makes `budget` the one that string growth on this thread checks, for
  // the life of the scope (scopes nest: the outer one is restored).
  class Scope {
   public:
    explicit Scope(RunBudget& budget);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    RunBudget* outer_;
  };
  // The budget active on this thread, or null.
  static RunBudget* active();

 private:
  [[noreturn]] void exceeded(const std::string& what, const std::string& option) const;
  bool more_modules_than(std::size_t max, const unsigned char* data, std::size_t bytes) const;
  RunLimits limits_;
  std::chrono::steady_clock::time_point deadline_ = std::chrono::steady_clock::time_point::max();
  const std::uint32_t* sizes_ = nullptr;
  std::atomic<int> step_{0};  // read by a watchdog thread
  std::atomic<bool> drawing_{false};
};

// A size such as 512M, 8G, 8GiB or 1000000 (bytes); suffixes K, M, G and T
// are powers of 1024. Nothing when the text is not one.
std::optional<std::size_t> parse_byte_size(const std::string& text);

// Bytes held by every string's buffer in the process.
std::size_t string_bytes_in_use();

}  // namespace sylva
