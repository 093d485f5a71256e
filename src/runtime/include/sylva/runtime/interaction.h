// lpfg's functions that ask its windows and their user (LPFG manual 6.4, 6.5,
// 9.1, 9.4, 9.5): view volumes, the camera, the mouse, the tablet, the user
// menu, the terrain, the parameter panel, other programs.
//
// A batch run has no window, no user and no terrain, so each gives what lpfg
// gives when it runs without them (lpfg -b): the view functions find no view
// (vvXmin and kin 0, vvScale 1, the camera all zeros), the menu has no
// choice (-1), the terrain is not loaded (false, the point unchanged), the
// parameter panel answers 0. The mouse is never pushed and over no view
// (viewNum -1): lpfg -b has no mouse to ask. Each function says once, on
// the first call, what it could not do.
#pragma once

#include <sylva/runtime/functions.h>
#include <sylva/runtime/types.h>
#include <sylva/runtime/vectors.h>

#include <cstdio>

namespace sylva::rt {
// Says `what` once per call site of the macro below (each function has one).
inline void tell_once(bool& told, const char* function, const char* what) {
  if (told) return;
  told = true;
  char text[256];
  std::snprintf(text, sizeof text, "%s: %s (a batch run)\n", function, what);
  message(text);
}
}  // namespace sylva::rt

#define SYLVA_TELL_ONCE(function, what)          \
  do {                                           \
    static bool sylva_told = false;              \
    ::sylva::rt::tell_once(sylva_told, function, what); \
  } while (false)

// ---- Views (6.4) ----------------------------------------------------------

inline float vvXmin(int) { SYLVA_TELL_ONCE("vvXmin", "no view window, 0 returned"); return 0.0f; }
inline float vvYmin(int) { SYLVA_TELL_ONCE("vvYmin", "no view window, 0 returned"); return 0.0f; }
inline float vvZmin(int) { SYLVA_TELL_ONCE("vvZmin", "no view window, 0 returned"); return 0.0f; }
inline float vvXmax(int) { SYLVA_TELL_ONCE("vvXmax", "no view window, 0 returned"); return 0.0f; }
inline float vvYmax(int) { SYLVA_TELL_ONCE("vvYmax", "no view window, 0 returned"); return 0.0f; }
inline float vvZmax(int) { SYLVA_TELL_ONCE("vvZmax", "no view window, 0 returned"); return 0.0f; }
inline float vvScale(int) { SYLVA_TELL_ONCE("vvScale", "no view window, 1 returned"); return 1.0f; }
inline CameraPosition GetCameraPosition(int) {
  SYLVA_TELL_ONCE("GetCameraPosition", "no view window, a camera of zeros returned");
  return CameraPosition();
}
inline void CloseView(int) { SYLVA_TELL_ONCE("CloseView", "no view window to close; ignored"); }

// ---- Mouse, tablet and user menu (6.5, 7.4, 7.5, 9.4) -------------------------

inline MouseStatus GetMouseStatus() {
  SYLVA_TELL_ONCE("GetMouseStatus", "no mouse; nothing pushed, over no view");
  return MouseStatus();
}
inline TabletStatus GetTabletStatus() {
  SYLVA_TELL_ONCE("GetTabletStatus", "no tablet connected");
  return TabletStatus();
}
inline void UserMenuItem(const char*, unsigned int) {
  SYLVA_TELL_ONCE("UserMenuItem", "no menu to add to; ignored, and UserMenuChoice() is -1");
}
inline void UserMenuClear() {}
inline int UserMenuChoice() { return -1; }

// ---- Terrain (9.1): never loaded here --------------------------------------

inline bool terrainHeightAt(V3f, V3f&) {
  SYLVA_TELL_ONCE("terrainHeightAt", "no terrain is loaded; false returned");
  return false;
}
inline bool terrainNormalAt(V3f, V3f&) {
  SYLVA_TELL_ONCE("terrainNormalAt", "no terrain is loaded; false returned");
  return false;
}
inline void terrainVisibilityAll(VisibilityMode) {
  SYLVA_TELL_ONCE("terrainVisibilityAll", "no terrain is loaded; ignored");
}
inline void terrainVisibilityPatch(VisibilityMode, int, V3f) {
  SYLVA_TELL_ONCE("terrainVisibilityPatch", "no terrain is loaded; ignored");
}
inline void scaleTerrainBy(float) { SYLVA_TELL_ONCE("scaleTerrainBy", "no terrain is loaded; ignored"); }

// ---- B-spline surfaces (7.1.2): none are read ------------------------------

inline BsurfaceObjS GetBsurfaceS(int) {
  SYLVA_TELL_ONCE("GetBsurfaceS", "B-spline surfaces are not read; an empty surface returned");
  return BsurfaceObjS();
}
inline BsurfaceObjM GetBsurfaceM(int) {
  SYLVA_TELL_ONCE("GetBsurfaceM", "B-spline surfaces are not read; an empty surface returned");
  return BsurfaceObjM();
}

// ---- The parameter panel (9.5): lpfg answers 0 and keeps nothing -----------

inline float SetOrGetParameterf(const char*, float) { return 0.0f; }
inline int SetOrGetParameteri(const char*, int) { return 0; }
inline bool ParametersNeedUpdating() { return false; }
inline float GetParameterf(const char*) { return 0.0f; }
inline int GetParameteri(const char*) { return 0; }
inline void SetParameterf(const char*, float) {}
inline void SetParameteri(const char*, int) {}
inline void DelayWrite() {}
inline void Write() {}

// ---- Other programs and timing ------------------------------------------------

// lpfg starts the command and does not wait for it; a batch run starts nothing.
inline void Run(const char*) { SYLVA_TELL_ONCE("Run", "other programs are not started; ignored"); }
inline void StartPerformance() {}
inline void StopPerformance() {}

#undef SYLVA_TELL_ONCE
