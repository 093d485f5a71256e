// The predefined types of lpfg models (LPFG manual 5.13, 7.1, 7.4, 6.4, 9):
// EA20Array (environment communication), SurfaceObj and the B-spline
// surface objects (dynamic surfaces), MouseStatus and TabletStatus
// (interaction), CameraPosition, and the enumerations of the terrain and
// POV-Ray functions. All are trivially copyable, so modules can carry them;
// their fields and member functions are the ones lpfg's models use.
#pragma once

#include <sylva/runtime/vectors.h>

// Text given to a module (Label): lpfg's name for it.
typedef const char* __lc_Text;
// The type of a module's numeric id in lpfg.
typedef short int __lc_ModuleIdType;

// A fixed-length array that stays an array when passed by value (a module
// parameter), as a plain array would turn into a pointer.
template <class T, int length>
struct __lc_EncapsulatedArray {
  T data[length];
  const T& operator[](int i) const { return data[i]; }
  T& operator[](int i) { return data[i]; }
  int Length() const { return length; }
  const T* Array() const { return data; }
};

// Twenty floats exchanged with an environment (Enviro manual, EA20).
typedef __lc_EncapsulatedArray<float, 20> EA20Array;

// LPFG manual 7.4. Without interaction (a batch run) nothing is pushed or
// down, and no view holds the cursor (viewNum -1).
struct MouseStatus {
  int viewNum = -1;
  int viewX = 0, viewY = 0;
  V3td atFront, atRear, atMiddle;
  double selectDepth = 0;
  V3td selectPoint;
  int keypressed = 0;
  bool lbPushed = false, lbDown = false, lbReleased = false;
};

// A pen tablet's state (LPFG manual 9.4); never connected in a batch run.
struct TabletStatus {
  bool connected = false;
  int viewX = 0, viewY = 0;
  float azimuth = 0, altitude = 0;
  double pressure = 0;
  unsigned int cursorT = 0, buttonState = 0;
  V3d atFront, atRear;
};

// LPFG manual 6.4: where a view's camera is.
struct CameraPosition {
  V3tf position, lookat;
  V3tf head, left, up;
  float scale = 0;
};

// How terrain patches are drawn (LPFG manual 9.1).
enum VisibilityMode { Shaded, Hidden, Wireframe };
// How PovRayStart writes a model's meshes.
enum POVRayMeshMode { Instance, Single };

// The 16 control points of a bicubic Bézier patch (LPFG manual 7.1).
struct SurfaceObj {
  V3f points[16];
  void Set(int id, const V3f& v) { points[id] = v; }
  void Set(int id, const float* arr) { points[id] = V3f(arr[0], arr[1], arr[2]); }
  V3f Get(int id) const { return points[id]; }
  const float* Points() const { return &points[0].x; }
  void Scale(const V3f& s) {
    for (V3f& p : points) p = V3f(p.x * s.x, p.y * s.y, p.z * s.z);
  }
  friend SurfaceObj operator*(SurfaceObj o, float r) {
    o.Scale(V3f(r, r, r));
    return o;
  }
  friend SurfaceObj operator*(float r, const SurfaceObj& o) { return o * r; }
#ifndef NOAUTOOVERLOAD
  friend SurfaceObj operator+(const SurfaceObj& l, const SurfaceObj& r) {
    SurfaceObj o;
    for (int i = 0; i < 16; ++i)
      o.points[i] = V3f(l.points[i].x + r.points[i].x, l.points[i].y + r.points[i].y, l.points[i].z + r.points[i].z);
    return o;
  }
#endif
};

// The control net of a B-spline surface of at most N x M points (LPFG
// manual 7.1.2). Sylva reads no B-spline surfaces (GetBsurfaceS says so);
// the type is here so that models using it compile and run.
template <int N, int M>
struct BsurfaceObjNM {
  V3tf net[N][M];
  int n_u = 0, n_v = 0;

  V3f Get(int i, int j) const { return i >= 0 && i < N && j >= 0 && j < M ? V3f(net[i][j]) : V3f(0, 0, 0); }
  void Set(int i, int j, const V3f& v) {
    if (i >= 0 && i < N && j >= 0 && j < M) net[i][j] = v;
  }
  void Scale(V3f s) {
    for (auto& row : net)
      for (V3tf& p : row) p = V3f(p.x * s.x, p.y * s.y, p.z * s.z);
  }
  friend BsurfaceObjNM operator*(BsurfaceObjNM o, float r) {
    o.Scale(V3f(r, r, r));
    return o;
  }
  friend BsurfaceObjNM operator*(float r, const BsurfaceObjNM& o) { return o * r; }
  // Sums and blends point by point (over the first rows and columns).
  static BsurfaceObjNM blend(const BsurfaceObjNM& a, float wa, const BsurfaceObjNM& b, float wb, int rows, int columns) {
    BsurfaceObjNM o = a;
    for (int i = 0; i < N && i < rows; ++i)
      for (int j = 0; j < M && j < columns; ++j) {
        const V3tf p = a.net[i][j], q = b.net[i][j];
        o.net[i][j] = V3f(wa * p.x + wb * q.x, wa * p.y + wb * q.y, wa * p.z + wb * q.z);
      }
    return o;
  }
  friend BsurfaceObjNM operator+(const BsurfaceObjNM& l, const BsurfaceObjNM& r) { return blend(l, 1, r, 1, N, M); }
  friend BsurfaceObjNM Interpolate(const BsurfaceObjNM& a, const BsurfaceObjNM& b, float alpha, int rows, int columns) {
    return blend(a, 1 - alpha, b, alpha, rows, columns);
  }
  friend V3f Get(const BsurfaceObjNM& o, int i, int j) { return o.Get(i, j); }
  friend BsurfaceObjNM Set(const BsurfaceObjNM& o, int i, int j, V3f p) {
    BsurfaceObjNM copy = o;
    copy.Set(i, j, p);
    return copy;
  }
};
typedef BsurfaceObjNM<10, 10> BsurfaceObjS;
typedef BsurfaceObjNM<32, 32> BsurfaceObjM;
