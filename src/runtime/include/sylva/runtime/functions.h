// The predefined functions a model may call (LPFG manual, chapter 6).
//
// They act on the model's ControlState, which the engine reads between steps:
// the direction of the next step, the group to use, a stop request, and the
// state of the random-number generator.
#pragma once

#include <sylva/abi.h>
#include <sylva/runtime/vectors.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

namespace sylva::rt {
// One per compiled model: models are built with hidden visibility, so two
// loaded models never share it.
inline abi::ControlState control;

inline void message(const char* text) {
  if (control.message) control.message(control.host, text);
  else std::fputs(text, stderr);
}
}  // namespace sylva::rt

// ---- Controlling the simulation (6.1) --------------------------------------

// The number of derivation steps completed so far: 0 in Start and during the
// first step's StartEach and productions, 1 from the first EndEach on.
inline int StepNo() { return sylva::rt::control.step; }
inline void Stop() { sylva::rt::control.stop_requested = true; }
inline void RunSimulation() {}
inline void PauseSimulation() {}
inline void DisplayFrame() {}
inline void OutputFrame(const char*) {}

inline void UseGroup(int group) { sylva::rt::control.next_group = group; }
inline int CurrentGroup() { return sylva::rt::control.current_group; }

inline void Forward() { sylva::rt::control.forward = true; }
inline void Backward() { sylva::rt::control.forward = false; }
inline bool IsForward() { return sylva::rt::control.forward; }

inline void Environment() {}
inline void NoEnvironment() {}

// ---- Random numbers (6.3.2): drand48's generator, so seeded runs match lpfg.

namespace sylva::rt {
inline double next_rand48() {
  std::uint64_t& x = control.rand48;
  x = (0x5DEECE66DULL * x + 0xB) & ((1ULL << 48) - 1);
  return std::ldexp(static_cast<double>(x), -48);
}
}  // namespace sylva::rt

inline float ran(float range) { return static_cast<float>(sylva::rt::next_rand48() * range); }
inline void sran(long seed) {
  sylva::rt::control.rand48 = ((static_cast<std::uint64_t>(seed) & 0xFFFFFFFFULL) << 16) | 0x330EULL;
}

// ---- Output (6.6) -----------------------------------------------------------

inline void Printf(const char* format, ...) __attribute__((format(printf, 1, 2)));
inline void Printf(const char* format, ...) {
  char buffer[4096];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  sylva::rt::message(buffer);
}
