// Predefined parameter types of lpfg modules: EA20Array (environment
// communication), MouseStatus (mouse interaction) and SurfaceObj (dynamic
// Bézier surfaces). All are trivially copyable so modules can carry them.
#pragma once

#include <sylva/runtime/vectors.h>

// Twenty floats exchanged with an environment (Enviro manual, EA20).
struct EA20Array {
  float v[20];
  float& operator[](int i) { return v[i]; }
  const float& operator[](int i) const { return v[i]; }
};

// LPFG manual 7.4.
struct MouseStatus {
  int viewNum;
  int viewX, viewY;
  V3d atFront, atRear, atMiddle;
  bool lbDown;
  bool lbPushed;
  bool lbReleased;
};

// The 16 control points of a bicubic Bézier patch (LPFG manual 7.1).
struct SurfaceObj {
  V3f points[16];
  void Set(int id, const V3f& v) { points[id] = v; }
  void Set(int id, const float* arr) { points[id] = V3f(arr[0], arr[1], arr[2]); }
  V3f Get(int id) const { return points[id]; }
  void Scale(const V3f& s) {
    for (V3f& p : points) p = V3f(p.x * s.x, p.y * s.y, p.z * s.z);
  }
  const SurfaceObj operator*(float r) const {
    SurfaceObj o = *this;
    for (V3f& p : o.points) p = V3f(p.x * r, p.y * r, p.z * r);
    return o;
  }
};
inline SurfaceObj operator*(float r, const SurfaceObj& obj) { return obj * r; }
inline SurfaceObj operator+(const SurfaceObj& l, const SurfaceObj& r) {
  SurfaceObj o;
  for (int i = 0; i < 16; ++i)
    o.points[i] = V3f(l.points[i].x + r.points[i].x, l.points[i].y + r.points[i].y,
                      l.points[i].z + r.points[i].z);
  return o;
}
