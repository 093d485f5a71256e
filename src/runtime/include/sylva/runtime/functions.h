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

// The number of derivation steps completed so far: 0 in Start and during the
// first step's StartEach and productions, 1 from the first EndEach on.
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

// ---- Functions, curves and surfaces from input files (6.2) -----------------

namespace sylva::rt {
inline void ask_inputs(int query, int id, const double* in, double* out, const char* what) {
  if (!control.input_query || !control.input_query(control.inputs, query, id, in, out)) {
    char text[160];
    std::snprintf(text, sizeof text, "%s: there is no %d among the model's input files\n", what, id);
    message(text);
  }
}
}  // namespace sylva::rt

// Function `id` (a .func or .fset file, named by its #define) at x in [0,1].
inline float func(int id, float x) {
  double in[3] = {x, 0, 1}, out[1] = {0};
  sylva::rt::ask_inputs(sylva::abi::kQueryFunction, id, in, out, "func");
  return static_cast<float>(out[0]);
}
// The same function stretched over [min,max].
inline float pfunc(int id, float x, float min, float max) {
  double in[3] = {x, min, max}, out[1] = {0};
  sylva::rt::ask_inputs(sylva::abi::kQueryFunction, id, in, out, "pfunc");
  return static_cast<float>(out[0]);
}
inline V2f funcTangent(int id, float x) {
  double in[1] = {x}, out[2] = {0, 0};
  sylva::rt::ask_inputs(sylva::abi::kQueryFunctionTangent, id, in, out, "funcTangent");
  return V2f(static_cast<float>(out[0]), static_cast<float>(out[1]));
}

namespace sylva::rt {
inline V3d curve_point(int id, float s, int query, const char* what) {
  double in[1] = {s}, out[3] = {0, 0, 0};
  ask_inputs(query, id, in, out, what);
  return V3d(out[0], out[1], out[2]);
}
}  // namespace sylva::rt

// Curve `id` (contour files in command-line order, from 1) at normalized arc length s.
inline float curveX(int id, float s) { return static_cast<float>(sylva::rt::curve_point(id, s, sylva::abi::kQueryCurvePoint, "curveX").x); }
inline float curveY(int id, float s) { return static_cast<float>(sylva::rt::curve_point(id, s, sylva::abi::kQueryCurvePoint, "curveY").y); }
inline float curveZ(int id, float s) { return static_cast<float>(sylva::rt::curve_point(id, s, sylva::abi::kQueryCurvePoint, "curveZ").z); }
inline V2f curveXYf(int id, float s) {
  V3d p = sylva::rt::curve_point(id, s, sylva::abi::kQueryCurvePoint, "curveXY");
  return V2f(static_cast<float>(p.x), static_cast<float>(p.y));
}
inline V2d curveXYd(int id, float s) {
  V3d p = sylva::rt::curve_point(id, s, sylva::abi::kQueryCurvePoint, "curveXY");
  return V2d(p.x, p.y);
}
inline V2d curveXY(int id, float s) { return curveXYd(id, s); }
inline V3f curveXYZf(int id, float s) { return V3f(sylva::rt::curve_point(id, s, sylva::abi::kQueryCurvePoint, "curveXYZ")); }
inline V3d curveXYZd(int id, float s) { return sylva::rt::curve_point(id, s, sylva::abi::kQueryCurvePoint, "curveXYZ"); }
inline V3d curveXYZ(int id, float s) { return curveXYZd(id, s); }
inline float curveLength(int id) {
  double out[1] = {0};
  sylva::rt::ask_inputs(sylva::abi::kQueryCurveLength, id, nullptr, out, "curveLength");
  return static_cast<float>(out[0]);
}
inline V3f curveNormal(int id, float s) {
  return V3f(sylva::rt::curve_point(id, s, sylva::abi::kQueryCurveNormal, "curveNormal"));
}
// Changing curve `id` for the rest of the run: the curve functions and the
// generalized cylinders drawn with it see the change. A point set with
// curveSetPoint (control points counted from 0 as listed in the file) reaches
// the curve functions after curveRecalculate, as in lpfg.
inline void curveScale(int id, float x, float y, float z) {
  double in[3] = {x, y, z};
  sylva::rt::ask_inputs(sylva::abi::kQueryCurveScale, id, in, nullptr, "curveScale");
}
inline void curveSetPoint(int id, int p, float x, float y, float z) {
  double in[4] = {static_cast<double>(p), x, y, z};
  sylva::rt::ask_inputs(sylva::abi::kQueryCurveSetPoint, id, in, nullptr, "curveSetPoint");
}
inline void curveRecalculate(int id) {
  sylva::rt::ask_inputs(sylva::abi::kQueryCurveRecalculate, id, nullptr, nullptr, "curveRecalculate");
}
inline void curveReset(int id) {
  sylva::rt::ask_inputs(sylva::abi::kQueryCurveReset, id, nullptr, nullptr, "curveReset");
}

// Parameter `id` of the .vset file (6.2.1): its name is #defined to its id.
inline float val(int id) {
  double out[1] = {0};
  sylva::rt::ask_inputs(sylva::abi::kQueryParameter, id, nullptr, out, "val");
  return static_cast<float>(out[0]);
}

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

// ---- Gillespie groups (6.1.2, 7.2): their own generator, apart from ran().
// The engine draws from it (SplitMix64); a seed gives the same run each time.
inline void SeedGillespie(long seed) { sylva::rt::control.gillespie_random = static_cast<std::uint64_t>(seed); }
// τ, the time to the reaction fired by the last Gillespie step (infinite when
// no reaction could fire); 0 before the first.
inline float GillespieTime() { return static_cast<float>(sylva::rt::control.gillespie_time); }

// The first patch of surface `id` of the view file (6.2.4), to reshape (7.1).
inline SurfaceObj GetSurface(int id) {
  double out[48] = {};
  sylva::rt::ask_inputs(sylva::abi::kQuerySurfacePatch, id, nullptr, out, "GetSurface");
  SurfaceObj s;
  for (int k = 0; k < 16; ++k)
    s.points[k] = V3f(static_cast<float>(out[3 * k]), static_cast<float>(out[3 * k + 1]), static_cast<float>(out[3 * k + 2]));
  return s;
}

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
