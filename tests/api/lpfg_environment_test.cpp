// What an L+C model sees of the system through lpfgall.h: what lpfg's
// headers give models without their asking (standard headers, macros,
// types), lpfg's vector types, the values lpfg's interactive functions have
// in a batch run, and StepNo().
//
// Each model below was also run by the reference lpfg (lpfg -b lsystem.l,
// Virtual Laboratory 5.1); the expected Printf output is what it printed.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test {
namespace {

struct Run {
  std::string messages;
  std::unique_ptr<Simulation> simulation;
  std::string string() const {
    return io::format_string(simulation->string(), simulation->types());
  }
};

// Runs `model` (lsystem.l) to its end with `files` written beside it and
// given as input files; Printf's output collects in messages.
std::unique_ptr<Run> run(const std::string& name, const std::string& model,
                         const std::vector<std::pair<std::string, std::string>>& files = {}) {
  auto r = std::make_unique<Run>();
  const std::string dir = make_temp_dir("lpfg-environment-" + name);
  std::ofstream(dir + "/lsystem.l") << model;
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  for (const auto& [file, text] : files) {
    std::ofstream(dir + "/" + file) << text;
    options.input_files.push_back(dir + "/" + file);
  }
  Run* raw = r.get();
  r->simulation = std::make_unique<Simulation>(dir + "/lsystem.l", options,
                                               [raw](const std::string& text) { raw->messages += text; });
  r->simulation->run();
  return r;
}

// Lines of `text` that do not say what a batch run could not do.
std::string without_notes(const std::string& text) {
  std::string kept, line;
  for (char c : text) {
    line += c;
    if (c != '\n') continue;
    if (line.find("(a batch run)") == std::string::npos) kept += line;
    line.clear();
  }
  return kept + line;
}

// A model that uses, without including anything but lpfgall.h: std::string,
// snprintf, malloc and memcpy, sqrt, M_PI, abs, std::cout; lpfg's include
// guards, LINUX, DECLSPEC, StartBranchIdent/EndBranchIdent; lpfg's vector
// conversions (V3d from V3f, V3f from V2f, the V3tf of a module parameter),
// operators with int and double scalars, the cross product, v[2],
// Normalize; EA20Array's data, Length() and Array(); SurfaceObj's Points();
// MouseStatus, TabletStatus, CameraPosition, the terrain and POV-Ray
// enumerations; lparams.h's constants and __lc_ModuleIdType.
const char* const kImplicitEnvironment = R"(#include <lpfgall.h>
#if !defined(__LPFGALL_H__) || !defined(__LINTRFC_H__) || !defined(__LSYS_H__) || !defined(__STDMODS_H__) || !defined(__LPARAMS_H__)
#error guards
#endif
#ifndef LINUX
#error LINUX
#endif
DECLSPEC int Helper();
int Helper() { return 7; }
std::string label = std::string(StartBranchIdent) + EndBranchIdent;
derivation length: 1;
module A(V3tf, int);
Axiom: A(V3f(1, 2, 2), 0) MoveTo3f(V3f(3, 4, 0));
Start: {
  std::string v = "3";
  char buf[32]; snprintf(buf, sizeof buf, "%s", v.c_str());
  void* p = malloc(8); memset(p, 0, 8); memcpy(p, buf, 2); free(p);
  Printf("%s %s %.6f %.6f %d %d\n", buf, label.c_str(), sqrt(2.0), M_PI, abs(-3), Helper());
  V3f a(1, 2, 2); V3d d = a; V2f w(3, 4); V3f z = w; V2d w2 = w;
  V3f sum = a + a * 2 - 2.0 * a; V3f c = V3f(1, 0, 0) % V3f(0, 1, 0);
  V3f n = Normalize(a); a.Normalize();
  Printf("%g %g %g | %g %g %g | %g %g | %g %g %g | %g %g %g | %g %g\n", d.x, d.y, d[2], z.x, z.y, z.z, w2.x, w2.Length(),
         sum.x, sum.y, sum.z, c.x, c.y, c.z, n.x * 3, a * V3f(0, 0, 3));
  EA20Array e; for (int i = 0; i < e.Length(); ++i) e[i] = i; e.data[1] = 5;
  Printf("%d %g %g\n", e.Length(), e.Array()[1], e[19]);
  SurfaceObj s; s.Set(0, V3f(1, 2, 3)); s = s * 2.0f;
  Printf("%g %g\n", s.Get(0).y, s.Points()[2]);
  MouseStatus ms; TabletStatus ts; CameraPosition cp; cp.scale = 2; VisibilityMode vm = Wireframe; POVRayMeshMode pm = Single;
  Printf("%d %d %d %d %d %g %d %d\n", ms.lbPushed, ms.lbDown, ms.lbReleased, ts.connected, ts.cursorT, cp.scale, vm, pm);
  V3f gz(0, 0, 1);
  int idsize = sizeof(__lc_ModuleIdType);
  Printf("%g %d %d\n", gz.z, __lc_eMaxParams, idsize);
  std::cout << "";
}
A(p, k) : { V3f q = p; q = q + p; Printf("A %g %g %g\n", q.x, q.y, q.z); produce A(p, k + 1); }
MoveTo3f(p) : { V3d q = p; Printf("M %g %g %g %g\n", q.x, q.y, q.z, p.Length()); produce MoveTo3f(p); }
)";

TEST(LpfgEnvironment, AModelUsesWhatLpfgsHeadersGiveWithoutAsking) {
  auto r = run("implicit", kImplicitEnvironment);
  EXPECT_EQ(r->messages,
            "3 SBEB 1.414214 3.141593 3 7\n"
            "1 2 2 | 3 4 0 | 3 5 | 1 2 2 | 0 0 1 | 1 2\n"
            "20 5 19\n"
            "4 6\n"
            "0 0 0 0 0 2 2 1\n"
            "1 64 2\n"
            "A 2 4 4\n"
            "M 3 4 0 5\n");
}

// lpfgall.h declares no name that lpfg's does not (Sylva's own are in its
// namespace), so a model's own functions and types of any other name
// compile as in lpfg (lpfg -b printed the same).
TEST(LpfgEnvironment, AModelsOwnNamesDoNotCollide) {
  auto r = run("own-names", R"(#include <lpfgall.h>
float curveLength(int id) { return 2.0f * id; }
int control = 3;
int request = 4;
void message(const char* text) { Printf("%s", text); }
struct Vec3 { float x, y, z; };
struct Coords3 { int n; };
derivation length: 1;
module A();
Axiom: A;
Start: { Vec3 v = {1, 2, 3}; Coords3 c = {5}; message("ok "); Printf("%g %d %d %g %d\n", curveLength(2), control, request, v.z, c.n); }
)");
  EXPECT_EQ(r->messages, "ok 4 3 4 3 5\n");
}

// With NOAUTOOVERLOAD a model defines the vector operators itself. (lpfg's
// own headers do not compile in this mode; the values are worked by hand:
// q = p + 2p = (3,6,9), Normalize((3,0,4)) = (0.6,0,0.8).)
TEST(LpfgEnvironment, WithNoAutoOverloadTheModelBringsItsOperators) {
  auto r = run("no-auto-overload", R"(#define NOAUTOOVERLOAD
#include <lpfgall.h>
V3f operator+(const V3f& a, const V3f& b) { return V3f(a.x + b.x, a.y + b.y, a.z + b.z); }
V3f operator*(const V3f& a, float k) { return V3f(a.x * k, a.y * k, a.z * k); }
derivation length: 1;
module A(V3f);
Axiom: A(V3f(1, 2, 3));
A(p) : {
  V3f q = p + p * 2;
  V3tf r = q;
  V3f n = Normalize(V3f(3, 0, 4));
  Printf("%g %g %g %g %g\n", q.x, q.y, r.z, n.x, n.z);
  produce A(q);
}
)");
  EXPECT_EQ(r->messages, "3 6 9 0.6 0.8\n");
  EXPECT_EQ(r->string(), "A((3,6,9))\n");
}

// lpfg -b has no window, menu, terrain or parameter panel: the values it
// gives, which a batch run of Sylva gives too (each function also says once
// what it could not do). ran() and sran() draw as lpfg does: erand48 from
// the state {0x330E, 0, 0}, and sran(s) sets the state to s's low 32 bits.
TEST(LpfgEnvironment, InteractiveFunctionsGiveLpfgsBatchValues) {
  auto r = run("batch", R"(#include <lpfgall.h>
derivation length: 1;
module A();
Axiom: A;
Start: {
  UserMenuItem("first", 1); UserMenuClear(); UserMenuItem("second", 2);
  Printf("menu %d\n", UserMenuChoice());
  Printf("view %g %g %g %g %g %g %g\n", vvXmin(0), vvYmin(0), vvZmin(0), vvXmax(0), vvYmax(0), vvZmax(0), vvScale(0));
  CameraPosition cp = GetCameraPosition(0);
  Printf("camera %g %g %g %g %g\n", cp.position.x, cp.lookat.y, cp.head.z, cp.up.x, cp.scale);
  V3f at(1, 2, 3);
  bool hit = terrainHeightAt(V3f(0, 0, 0), at);
  Printf("terrain %d %g %g %g\n", hit, at.x, at.y, at.z);
  Printf("panel %g %d %g %d %d\n", SetOrGetParameterf("a", 2.5f), SetOrGetParameteri("b", 3), GetParameterf("a"), GetParameteri("b"), ParametersNeedUpdating());
  TabletStatus t = GetTabletStatus();
  Printf("tablet %d\n", t.connected);
  double r1 = ran(1); double r2 = ran(0.3);
  sran(5); double r3 = ran(2);
  Printf("ran %.17g %.17g %.17g\n", r1, r2, r3);
}
)");
  EXPECT_EQ(without_notes(r->messages),
            "menu -1\n"
            "view 0 0 0 0 0 0 1\n"
            "camera 0 0 0 0 0\n"
            "terrain 0 1 2 3\n"
            "panel 0 0 0 0 0\n"
            "tablet 0\n"
            "ran 0.17082803610628972 0.22497059414548914 0.00089581334063382201\n");
  // One note for each function that needs what a batch run lacks, once.
  EXPECT_NE(r->messages.find("UserMenuItem: "), std::string::npos) << r->messages;
  EXPECT_EQ(r->messages.find("UserMenuItem: "), r->messages.rfind("UserMenuItem: ")) << r->messages;
  EXPECT_NE(r->messages.find("terrainHeightAt: "), std::string::npos) << r->messages;
}

// lpfg -b cannot answer GetMouseStatus (it has no window and stops); the
// LPFG manual's mouse without interaction (7.4): nothing down, pushed or
// released, over no view.
TEST(LpfgEnvironment, TheMouseOfABatchRunIsOverNoViewAndNeverPushed) {
  auto r = run("mouse", R"(#include <lpfgall.h>
derivation length: 2;
module Cursor();
MouseStatus ms;
StartEach: { ms = GetMouseStatus(); }
Axiom: Cursor();
Cursor() : {
  Printf("%d %d %d %d\n", ms.viewNum, ms.lbDown, ms.lbPushed, ms.lbReleased);
  if (ms.lbPushed) produce MoveTo3d(ms.atMiddle) Cursor();
  if (ms.lbDown) produce LineTo3d(ms.atMiddle) Cursor();
}
)");
  EXPECT_EQ(without_notes(r->messages), "-1 0 0 0\n-1 0 0 0\n");
  EXPECT_EQ(r->string(), "Cursor\n");
}

// The user-menu example of the LPFG manual (7.5): the menu is defined in
// Start, the choice read in StartEach; without a choice the model keeps its
// shape (the reference string, lpfg -b: the same module after the steps).
TEST(LpfgEnvironment, AUserMenuModelRunsWithoutAChoice) {
  auto r = run("menu", R"(#include <lpfgall.h>
derivation length: 2;
module Shape(int);
int choice;
Start: { UserMenuItem("Square", 0); UserMenuItem("Circle", 1); }
StartEach: { choice = UserMenuChoice(); }
Axiom: Shape(5);
Shape(s) : { if (choice >= 0) produce Shape(choice); else produce Shape(s + 1); }
)");
  EXPECT_EQ(r->string(), "Shape(7)\n");
}

// Modules lpfg declares beyond the manual's drawing modules compile, run
// and print (lpfg -b's string: the same modules in this order).
TEST(LpfgEnvironment, LpfgsOtherPredefinedModulesCompileAndRun) {
  auto r = run("other-modules", R"(#include <lpfgall.h>
derivation length: 1;
module A();
Axiom: A;
A() : {
  CameraPosition cp; BsurfaceObjS s; BsurfaceObjM m;
  produce Orient() Rotate(V3f(0, 0, 1), 30) SetTropismDirection3f(V3f(0, 1, 0)) ContourNormal(V3f(1, 0, 0))
          Terrain(cp) PovRayStart("x", Instance) BSurface(0, 1) DBSurfaceS(s) DBSurfaceM(m) F(1);
}
)");
  const std::vector<std::string> names = {"Orient",      "Rotate",   "SetTropismDirection3f", "ContourNormal",
                                          "Terrain",     "PovRayStart", "BSurface", "DBSurfaceS", "DBSurfaceM", "F"};
  const std::string text = r->string();
  std::size_t at = 0;
  for (const std::string& name : names) {
    at = text.find(name, at);
    ASSERT_NE(at, std::string::npos) << name << " in " << text.substr(0, 200);
  }
  EXPECT_EQ(text.rfind("Orient Rotate((0,0,1),30) SetTropismDirection3f((0,1,0)) ContourNormal((1,0,0)) Terrain(", 0), 0u)
      << text.substr(0, 200);
}

// lpfg's functions of a model's settings and groups (lpfg -b printed this).
TEST(LpfgEnvironment, TheModelsSettingsAreFunctionsToo) {
  auto r = run("settings", R"(#include <lpfgall.h>
derivation length: 4;
ring L-system: 1;
module A();
Axiom: A;
Start: { Printf("%d %d %d %d %d %d\n", DerivationLength(), DecompositionMaxDepth(), InterpretationMaxDepth(), RingLsystem(), NumOfTables(), NumOfViews()); }
decomposition:
maximum depth: 3;
group 2:
A() : { produce A(); }
endgroup
interpretation:
maximum depth: 2;
vgroup 1:
A() : { produce F(1); }
endgroup
)");
  EXPECT_EQ(r->messages, "4 3 2 1 3 2\n");
}

// lpfg counts a step before its StartEach (lpfg -b printed this).
TEST(LpfgEnvironment, StepNoIsTheNumberOfTheStepUnderWay) {
  auto r = run("step-no", R"(#include <lpfgall.h>
module A(int);
derivation length: 2;
Start: { Printf("Start %d\n", StepNo()); }
StartEach: { Printf("StartEach %d\n", StepNo()); }
EndEach: { Printf("EndEach %d\n", StepNo()); }
End: { Printf("End %d\n", StepNo()); }
Axiom: A(0);
A(n) : { Printf("production %d\n", StepNo()); produce A(n+1); }
)");
  EXPECT_EQ(r->messages,
            "Start 0\n"
            "StartEach 1\nproduction 1\nEndEach 1\n"
            "StartEach 2\nproduction 2\nEndEach 2\n"
            "End 2\n");
}

}  // namespace
}  // namespace sylva::test
