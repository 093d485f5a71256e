// The predefined functions a model may call (LPFG manual, chapter 6).
//
// They act on the model's ControlState, which the engine reads between steps:
// the direction of the next step, the group to use, a stop request, and the
// state of the random-number generator.
#pragma once

#include <sylva/abi.h>
#include <sylva/runtime/types.h>
#include <sylva/runtime/vectors.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <source_location>

namespace sylva::rt {
// One per compiled model: models are built with hidden visibility, so two
// loaded models never share it.
inline abi::ControlState control;

inline void message(const char* text) {
  if (control.message) control.message(control.host, text);
  else std::fputs(text, stderr);
}

// Passes a request to the engine; without one (a model loaded by hand) it is ignored.
inline void request(int what, int value, const char* file) {
  if (control.request) control.request(control.requests, what, value, file);
}
}  // namespace sylva::rt

// ---- Controlling the simulation (6.1) --------------------------------------

// The number of the derivation step under way, from 1, in its StartEach,
// productions, decompositions and EndEach (lpfg counts the step before
// StartEach); 0 in Start, and after the last step in End.
inline int StepNo() { return sylva::rt::control.step; }
inline void Stop() { sylva::rt::control.stop_requested = true; }
inline void RunSimulation() {}
inline void PauseSimulation() {}
// The engine draws the frame: with --frames and "display on request: on"
// in the animation file, as one more frame of the animation.
inline void DisplayFrame() { sylva::rt::request(sylva::abi::kRequestDisplayFrame, 0, nullptr); }
// An image (or mesh, drawing) of the string at the end of the current step,
// in the format the file's extension names; none if Stop() is called too.
inline void OutputFrame(const char* file) { sylva::rt::request(sylva::abi::kRequestOutputFrame, 0, file); }

// The call's place in the model (line markers make it the .l file's) goes
// with the group, so a group the model does not define is reported there.
inline void UseGroup(int group, std::source_location call = std::source_location::current()) {
  sylva::rt::control.next_group = group;
  sylva::rt::control.group_call_file = call.file_name();
  sylva::rt::control.group_call_line = static_cast<int>(call.line());
}
inline int CurrentGroup() { return sylva::rt::control.current_group; }

inline void Forward() { sylva::rt::control.forward = true; }
inline void Backward() { sylva::rt::control.forward = false; }
inline bool IsForward() { return sylva::rt::control.forward; }

// Whether the environmental pass (the interpretation for the environment,
// after EndEach) follows the current step; it stays so until changed. The
// same in StartEach or EndEach.
inline void Environment() { sylva::rt::control.environment = true; }
inline void NoEnvironment() { sylva::rt::control.environment = false; }

// The model's settings and the number of its groups and vgroups, as lpfg
// gives them to models (defined with the model: the derivation length, the
// decomposition and interpretation depths, whether it is a ring L-system).
int DerivationLength();
int DecompositionMaxDepth();
int InterpretationMaxDepth();
int RingLsystem();
int NumOfTables();
int NumOfViews();

// The environment pass can be switched off for the steps to come: lpfg's
// name for asking whether it is.
inline bool IgnoreEnvironment() { return !sylva::rt::control.environment; }

// ---- Random numbers (6.3.2): erand48's generator, as lpfg draws them ------

namespace sylva::rt {
// One step of the 48-bit generator of erand48 (and drand48) on `state`.
inline double next_rand48(std::uint64_t& state) { return abi::next_erand48(state); }
inline double next_rand48() { return next_rand48(control.rand48); }
// lpfg seeds its generators with the seed's low 32 bits as the state's
// low 32 bits (the state's words {seed, seed >> 16, 0}), not as srand48 does.
inline std::uint64_t lpfg_random_state(long seed) { return static_cast<std::uint64_t>(seed) & 0xFFFFFFFFULL; }
}  // namespace sylva::rt

// A number in [0, range): lpfg computes it in double, whatever it is stored in.
inline double ran(double range) {
  const sylva::abi::ControlState& c = sylva::rt::control;
  return (c.keyed_random ? c.keyed_random(c.host) : sylva::rt::next_rand48()) * range;
}
inline void sran(long seed) {
  if (!sylva::rt::control.seed_fixed) sylva::rt::control.rand48 = sylva::rt::lpfg_random_state(seed);
}

// ---- Gillespie groups (6.1.2, 7.2): their own generator, apart from ran().
inline void SeedGillespie(long seed) {
  if (!sylva::rt::control.seed_fixed) sylva::rt::control.gillespie_random = sylva::rt::lpfg_random_state(seed);
}
// The time of the Gillespie steps so far: the sum of the times to each
// reaction fired (lpfg's clock), 0 at Start and after ResetGillespie().
inline double GillespieTime() { return sylva::rt::control.gillespie_time; }
inline void ResetGillespie() { sylva::rt::control.gillespie_time = 0; }

// ---- Views (6.4) --------------------------------------------------------------

// Draws view `view` (a window: of the view file, by name) in outputs.
inline void UseView(int view) { sylva::rt::request(sylva::abi::kRequestUseView, view, nullptr); }

// ---- Output (6.6) -----------------------------------------------------------

// The current string written to, or read from, a file in Sylva's text
// format (which reads back exactly) rather than lpfg's binary one. Call them
// in a control statement (Start, StartEach, EndEach, End).
inline void OutputString(const char* file) { sylva::rt::request(sylva::abi::kRequestOutputString, 0, file); }
inline void LoadString(const char* file) { sylva::rt::request(sylva::abi::kRequestLoadString, 0, file); }

inline void Printf(const char* format, ...) __attribute__((format(printf, 1, 2)));
inline void Printf(const char* format, ...) {
  char buffer[4096];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  sylva::rt::message(buffer);
}
