// sylva/curves.h — small helpers for L+C models of curves in affine geometry.
//
// Models that treat module parameters as points (Prusinkiewicz, Shirmohammadi
// and Samavati, "L-systems in Geometric Modeling": Chaikin, Lane–Riesenfeld,
// de Casteljau, rational curves; examples/chaikin, lane-riesenfeld,
// de-casteljau, rational-circle) include it after lpfgall.h:
//
//     #include <lpfgall.h>
//     #include <sylva/curves.h>
//
// Header-only, and it needs nothing but the vector types of lpfgall.h (V2f
// V2d V3f V3d). Every function works on any of them; a homogeneous point in
// the plane is a V3f or V3d whose z is the weight.
#pragma once

#include <sylva/runtime/vectors.h>

#ifndef NOAUTOOVERLOAD

// The affine combination (1 - t) a + t b of two points (the paper's equation
// 6): the point dividing the segment from a to b in proportion t : 1 - t.
// Lerp(a, b, 0) is a, Lerp(a, b, 1) is b. Homogeneous points combine the same
// way (the de Casteljau algorithm of rational curves, the paper's section 5).
template <class V>
inline V Lerp(const V& a, const V& b, double t) {
  using S = decltype(a.x);
  return V(static_cast<S>(1 - t) * a + static_cast<S>(t) * b);
}

// The midpoint of a and b: Lerp(a, b, 0.5).
template <class V>
inline V Midpoint(const V& a, const V& b) {
  return Lerp(a, b, 0.5);
}

// The point of the plane z = 1 that the homogeneous point h = (w x, w y, w)
// stands for, seen from the origin: (x, y) = (h.x / h.z, h.y / h.z) (the
// paper's interpretation rule 20). The weight h.z must not be 0.
inline V2d Project(const V3d& h) { return V2d(h.x / h.z, h.y / h.z); }
inline V2f Project(const V3f& h) { return V2f(h.x / h.z, h.y / h.z); }

// The homogeneous point of (x, y) with weight w: (w x, w y, w). Project undoes it.
inline V3d Homogeneous(const V2d& p, double w) { return V3d(w * p.x, w * p.y, w); }
inline V3f Homogeneous(const V2f& p, float w) { return V3f(w * p.x, w * p.y, w); }

#endif  // NOAUTOOVERLOAD
