// Functions, curves, surfaces and parameters from the input files (LPFG
// manual 6.2), answered by the engine through ControlState::input_query.
//
// Ids are lpfg's: functions (.fset, .tset, .vset, .func) and parameters
// share one list numbered from 1, curves are numbered from 1, surfaces from 0;
// the files' names are #defined to them. Values are lpfg's floats.
#pragma once

#include <sylva/abi.h>
#include <sylva/runtime/functions.h>
#include <sylva/runtime/types.h>
#include <sylva/runtime/vectors.h>

#include <cstdio>

namespace sylva::rt {
inline void ask_inputs(int query, int id, const double* in, double* out, const char* what) {
  if (!control.input_query || !control.input_query(control.inputs, query, id, in, out)) {
    char text[160];
    std::snprintf(text, sizeof text, "%s: there is no %d among the model's input files\n", what, id);
    message(text);
  }
}
inline float ask_value(int query, int id, double x, const char* what) {
  double in[1] = {x}, out[1] = {0};
  ask_inputs(query, id, in, out, what);
  return static_cast<float>(out[0]);
}
inline V3f ask_point(int query, int id, double x, const char* what) {
  double in[1] = {x}, out[3] = {0, 0, 0};
  ask_inputs(query, id, in, out, what);
  return V3f(static_cast<float>(out[0]), static_cast<float>(out[1]), static_cast<float>(out[2]));
}
}  // namespace sylva::rt

// ---- Graphically defined functions (6.2.2) ---------------------------------

// Function `id` at x, x clamped to [0,1].
inline float func(int id, float x) { return sylva::rt::ask_value(sylva::abi::kQueryFunction, id, x, "func"); }
// A .tset function at x in the interval its file gives (x is mapped onto
// [0,1] and clamped there).
inline float tfunc(int id, float x) {
  return sylva::rt::ask_value(sylva::abi::kQueryTimelineFunction, id, x, "tfunc");
}
// The function over [min,max]: lpfg makes that the function's interval for
// good (tfunc and funcTangent use it from then on).
inline float pfunc(int id, float x, float min, float max) {
  double limits[2] = {min, max};
  sylva::rt::ask_inputs(sylva::abi::kQueryFunctionLimits, id, limits, nullptr, "pfunc");
  return sylva::rt::ask_value(sylva::abi::kQueryTimelineFunction, id, x, "pfunc");
}
// The derivative of the function's curve (x, y) by its spline parameter.
inline V2f funcTangent(int id, float x) {
  const V3f t = sylva::rt::ask_point(sylva::abi::kQueryFunctionTangent, id, x, "funcTangent");
  return V2f(t.x, t.y);
}

namespace sylva::rt {
// cpfg's func(id, x) (CPFG manual 4.4): cpfg's own evaluation, in double.
inline double cpfg_func(int id, double x) {
  double in[1] = {x}, out[1] = {0};
  ask_inputs(abi::kQueryCpfgFunction, id, in, out, "func");
  return out[0];
}
}  // namespace sylva::rt

// Parameter `id` of the .vset file (6.2.1).
inline float val(int id) {
  double out[1] = {0};
  sylva::rt::ask_inputs(sylva::abi::kQueryParameter, id, nullptr, out, "val");
  return static_cast<float>(out[0]);
}

// ---- Curves (6.2.3): contour `id` at normalized arc length s in [0,1] ---------

inline float curveX(int id, float s) { return sylva::rt::ask_point(sylva::abi::kQueryCurvePoint, id, s, "curveX").x; }
inline float curveY(int id, float s) { return sylva::rt::ask_point(sylva::abi::kQueryCurvePoint, id, s, "curveY").y; }
inline float curveZ(int id, float s) { return sylva::rt::ask_point(sylva::abi::kQueryCurvePoint, id, s, "curveZ").z; }
inline V2f curveXY(int id, float s) {
  const V3f p = sylva::rt::ask_point(sylva::abi::kQueryCurvePoint, id, s, "curveXY");
  return V2f(p.x, p.y);
}
inline V3f curveXYZ(int id, float s) { return sylva::rt::ask_point(sylva::abi::kQueryCurvePoint, id, s, "curveXYZ"); }
inline V2f curveXYf(int id, float s) { return curveXY(id, s); }
inline V2d curveXYd(int id, float s) {
  const V2f p = curveXY(id, s);
  return V2d(p.x, p.y);
}
inline V3f curveXYZf(int id, float s) { return curveXYZ(id, s); }
inline V3d curveXYZd(int id, float s) {
  const V3f p = curveXYZ(id, s);
  return V3d(p.x, p.y, p.z);
}
inline V3f curveNormal(int id, float s) {
  return sylva::rt::ask_point(sylva::abi::kQueryCurveNormal, id, s, "curveNormal");
}
// The curve's arc length.
inline float curveGAL(int id) {
  double out[1] = {0};
  sylva::rt::ask_inputs(sylva::abi::kQueryCurveLength, id, nullptr, out, "curveGAL");
  return static_cast<float>(out[0]);
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

// ---- Surfaces of the view file (6.2.4, 7.1) -----------------------------------

// The first patch of surface `id`, to reshape.
inline SurfaceObj GetSurface(int id) {
  double out[48] = {};
  sylva::rt::ask_inputs(sylva::abi::kQuerySurfacePatch, id, nullptr, out, "GetSurface");
  SurfaceObj s;
  for (int k = 0; k < 16; ++k)
    s.points[k] = V3f(static_cast<float>(out[3 * k]), static_cast<float>(out[3 * k + 1]), static_cast<float>(out[3 * k + 2]));
  return s;
}
// Control point `point` of surface `id`: point k of patch p is 16 p + k.
inline V3f GetSurfacePoint(int id, int point) {
  return sylva::rt::ask_point(sylva::abi::kQuerySurfacePoint, id, point, "GetSurfacePoint");
}
