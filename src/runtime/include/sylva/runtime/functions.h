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

// The first patch of surface `id` of the view file (6.2.4), to reshape (7.1).
inline SurfaceObj GetSurface(int id) {
  double out[48] = {};
  sylva::rt::ask_inputs(sylva::abi::kQuerySurfacePatch, id, nullptr, out, "GetSurface");
  SurfaceObj s;
  for (int k = 0; k < 16; ++k)
    s.points[k] = V3f(static_cast<float>(out[3 * k]), static_cast<float>(out[3 * k + 1]), static_cast<float>(out[3 * k + 2]));
  return s;
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
