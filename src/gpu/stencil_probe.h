// Recognises a point-subdivision L-system in an ordinary L+C model and finds
// its stencil (gpu/stencil_deriver.h), by probing the compiled production
// through the engine: rings of unit and zero points are derived one step, the
// successors read back give the k × (left + 1 + right) coefficients, and
// random rings (and the model's own axiom) confirm that the production is
// that linear map to 1e-12. No new syntax: chaikin.l, cubic-bspline-
// subdivision.l and four-point.l are recognised as they are, closed and with
// -D OPEN.
//
// The class: (a) a ring L-system, or an open curve whose points next to the
// ends have rules of their own (found from the whole linear map of a step on
// 16 points: rows in the middle that repeat every k rows shifted by one point
// are the stencil, the rest the end rules, read at most 7 points from an end);
// (b) the string after the axiom is points,
// modules of one type whose parameters are float or double (numbers or one
// vector), with at most modules without parameters before and after them
// (Control, ignored by the context and never rewritten); (c) one step maps
// every point to k points, each a linear (affine: weights summing to 1 for
// translation invariance, not required) combination of the point and its
// neighbours, the same for every coordinate and at every place.
#pragma once

#include <string>
#include <vector>

#include "api/simulation.h"
#include "gpu/stencil_deriver.h"

namespace sylva::gpu {

// A string of the class: text around the points, and the points.
struct PointString {
  std::string prefix, suffix;  // modules before and after the points, as the string's text
  std::string name;            // the point module
  bool vector_form = false;    // P((x,y)) rather than P(x,y)
  int dim = 0;
  std::vector<double> points;  // n · dim
  std::size_t size() const { return dim ? points.size() / dim : 0; }
};

struct ProbeResult {
  bool in_class = false;
  std::string reason;  // why not, when not
  Stencil stencil;
  PointString axiom;   // the string after the axiom
};

// Leaves `simulation` rewound and set to start from a probe string: make a
// fresh Simulation for the run itself (the model is not compiled again).
ProbeResult probe_stencil(Simulation& simulation);

// Parses a string's text as a PointString; false with `reason` if it is not one.
bool parse_point_string(const std::string& text, const ModuleTypes& types, PointString& out, std::string& reason);

// The text of `layout` with `points` in place of its points, as the engine
// writes it (no newline). `as_float`: numbers written as the shortest text of
// the float nearest them (the GPU's precision) rather than of the double.
std::string format_point_string(const PointString& layout, const std::vector<double>& points, bool as_float);

}  // namespace sylva::gpu
