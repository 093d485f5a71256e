// Tests of the multiresolution-curve examples after "L-system Implementation
// of Multiresolution Curves Based on Cubic B-Spline Subdivision" (Poon,
// Bateman, Karwowski, Prusinkiewicz, Samavati; SIGGRAPH 2003 course notes
// "L-systems and Beyond"): multires-curve (closed, Appendix A) and
// multires-open (open, Appendix B's end rules).
//
// The expectations are computed a second way: the notes' filters A, B
// (analysis) and P, Q (synthesis) are built here as matrices for any number of
// points (closed: equations 8-10; open: the end rows of Appendix B), checked
// to be inverse to each other, and applied to the fine polygon read from the
// model's string at step 0; the normal-aligned details (NORMALS=1) are the
// same details written in the frame of the coarse polygon. Properties in
// closed form: point counts per level, exact round trip, a translated
// coarse level translates the fine curve, a rotated one rotates it when the
// details follow the normals, scaling keeps the normal-aligned details.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "examples/multires_filters.h"
#include "examples/plane_points.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

const std::string kClosed = example_path("multires-curve/multires-curve.l");
const std::string kOpen = example_path("multires-open/multires-open.l");
constexpr int kLevels = 3;  // the models' default LEVELS

// The top-level points (C) and the details of the newest level (the D's one
// bracket deeper than the C's), in string order. The closed curve's string is
// a ring whose brackets balance only around it, so depths are relative.
struct Parsed {
  std::vector<Pt> points, details;
  int all_details = 0;
};
Parsed parse(const std::vector<Module>& s) {
  std::vector<int> depth;
  int d = 0;
  for (const Module& m : s) {
    if (m.name == "SB") ++d;
    if (m.name == "EB") --d;
    depth.push_back(d);
  }
  Parsed p;
  int point_depth = 1 << 30;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i].name == "C") point_depth = std::min(point_depth, depth[i]);
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i].name == "C") {
      EXPECT_EQ(depth[i], point_depth) << "a point inside a branch";
      p.points.push_back(read_pt(s[i].params.at(0)));
    }
    if (s[i].name == "D") {
      ++p.all_details;
      if (depth[i] == point_depth + 1) p.details.push_back(read_pt(s[i].params.at(0)));
    }
  }
  return p;
}

Filters filters(bool closed, int m) { return closed ? closed_filters(m) : open_filters(m); }
int coarse_count(bool closed, int fine) { return closed ? fine / 2 : (fine + 3) / 2; }

// The coarse points on either side of each detail: closed d_i between c_i and
// c_{i+1}; open d_j between c_j and c_{j+1}.
std::pair<Pt, Pt> sides(bool closed, const std::vector<Pt>& c, std::size_t k) {
  if (closed) return {c[k], c[(k + 1) % c.size()]};
  return {c[k + 1], c[k + 2]};
}
Pt unit_tangent(Pt l, Pt r) {
  const Pt t = r - l;
  const double len = norm(t);
  return len == 0 ? Pt{1, 0} : Pt{t.x / len, t.y / len};
}
// x-y detail -> (tangential, normal) components, and back.
Pt to_frame(Pt d, Pt l, Pt r) {
  const Pt t = unit_tangent(l, r);
  return {d.x * t.x + d.y * t.y, -d.x * t.y + d.y * t.x};
}
Pt from_frame(Pt s, Pt l, Pt r) {
  const Pt t = unit_tangent(l, r);
  return {s.x * t.x - s.y * t.y, s.x * t.y + s.y * t.x};
}

// One level of analysis and of synthesis in plain C++.
struct Level {
  std::vector<Pt> coarse, details;  // details as stored (x-y, or in the frame)
};
Level analyse(bool closed, bool normals, const std::vector<Pt>& fine) {
  const Filters f = filters(closed, coarse_count(closed, static_cast<int>(fine.size())));
  Level level{multiply(f.a, fine), multiply(f.b, fine)};
  if (normals)
    for (std::size_t k = 0; k < level.details.size(); ++k) {
      const auto [l, r] = sides(closed, level.coarse, k);
      level.details[k] = to_frame(level.details[k], l, r);
    }
  return level;
}
std::vector<Pt> synthesise(bool closed, bool normals, const std::vector<Pt>& coarse, std::vector<Pt> details) {
  const Filters f = filters(closed, static_cast<int>(coarse.size()));
  if (normals)
    for (std::size_t k = 0; k < details.size(); ++k) {
      const auto [l, r] = sides(closed, coarse, k);
      details[k] = from_frame(details[k], l, r);
    }
  const std::vector<Pt> pc = multiply(f.p, coarse), qd = multiply(f.q, details);
  std::vector<Pt> out;
  for (std::size_t i = 0; i < pc.size(); ++i) out.push_back(pc[i] + qd[i]);
  return out;
}

double max_distance(const std::vector<Pt>& a, const std::vector<Pt>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, norm(a[i] - b[i]));
  return worst;
}

std::vector<std::string> defines(bool normals, std::vector<std::string> more = {}) {
  more.push_back(normals ? "NORMALS=1" : "NORMALS=0");
  return more;
}

// The filters

TEST(MultiresFilters, AnalysisAndSynthesisAreInverse) {
  for (bool closed : {true, false})
    for (int m : {6, 7, 12, 15}) {
      const Filters f = filters(closed, m);
      const std::size_t n = f.p.size(), mc = f.a.size();
      ASSERT_EQ(n, static_cast<std::size_t>(closed ? 2 * m : 2 * m - 3));
      ASSERT_EQ(f.a.size() + f.b.size(), n);
      double worst = 0;
      for (std::size_t i = 0; i < n; ++i)      // [P | Q] [A ; B] = I
        for (std::size_t j = 0; j < n; ++j) {
          double s = 0;
          for (std::size_t k = 0; k < mc; ++k) s += f.p[i][k] * f.a[k][j];
          for (std::size_t k = 0; k < f.b.size(); ++k) s += f.q[i][k] * f.b[k][j];
          worst = std::max(worst, std::fabs(s - (i == j ? 1.0 : 0.0)));
        }
      EXPECT_LT(worst, 1e-15) << (closed ? "closed" : "open") << " m = " << m;
    }
}

TEST(MultiresFilters, ClosedMatricesAreThoseOfEquations8To10) {
  // The notes print A and B for 8 fine points (equations 8, 9); their coarse
  // points are the odd fine points C_2^n, C_4^n, ... (1-based), here the
  // even ones f_0, f_2, ... (0-based), i.e. the columns move by one. (The
  // printed P and Q of equation 10 are garbled by the conversion.)
  const Filters f = closed_filters(4);
  const double a[4][8] = {{-0.5, 2, -0.5, 0, 0, 0, 0, 0}, {0, 0, -0.5, 2, -0.5, 0, 0, 0},
                          {0, 0, 0, 0, -0.5, 2, -0.5, 0}, {-0.5, 0, 0, 0, 0, 0, -0.5, 2}};
  const double b[4][8] = {{1.5, -1, 0.25, 0, 0, 0, 0.25, -1}, {0.25, -1, 1.5, -1, 0.25, 0, 0, 0},
                          {0, 0, 0.25, -1, 1.5, -1, 0.25, 0}, {0.25, 0, 0, 0, 0.25, -1, 1.5, -1}};
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t j = 0; j < 8; ++j) {
      EXPECT_EQ(f.a[r][(j + 7) % 8], a[r][j]) << r << " " << j;
      EXPECT_EQ(f.b[(r + 3) % 4][(j + 7) % 8], b[r][j]) << r << " " << j;  // notes' D_1 is at f_{-1}
    }
}

// Analysis, then synthesis, compared with the matrices level by level.

void check_round_trip(const std::string& model, bool closed, bool normals) {
  SCOPED_TRACE(model + (normals ? " NORMALS=1" : " NORMALS=0"));
  Stepper run(model, defines(normals));
  const std::vector<Pt> original = parse(run.modules()).points;
  const std::size_t n = original.size();
  ASSERT_EQ(n, closed ? 96u : 99u);
  std::vector<std::vector<Pt>> levels = {original};
  std::vector<Pt> fine = original;
  for (int level = 1; level <= kLevels; ++level) {
    run.step(2);
    const Parsed got = parse(run.modules());
    const Level want = analyse(closed, normals, fine);
    const std::size_t m = closed ? n >> level : ((n - 3) >> level) + 3;  // closed form
    ASSERT_EQ(got.points.size(), m) << "level " << level;
    ASSERT_EQ(want.coarse.size(), m);
    EXPECT_EQ(static_cast<std::size_t>(got.all_details), n - m) << "level " << level;
    ASSERT_EQ(got.details.size(), want.details.size()) << "level " << level;
    EXPECT_LT(max_distance(got.points, want.coarse), 1e-12) << "coarse points, level " << level;
    EXPECT_LT(max_distance(got.details, want.details), 1e-12) << "details, level " << level;
    fine = got.points;
    levels.push_back(fine);
  }
  for (int level = kLevels - 1; level >= 0; --level) {
    run.step(2);
    const Parsed got = parse(run.modules());
    ASSERT_EQ(got.points.size(), levels[level].size()) << "synthesis to level " << level;
    EXPECT_LT(max_distance(got.points, levels[level]), 1e-9) << "synthesis to level " << level;
  }
  EXPECT_EQ(run.steps_done(), 4 * kLevels);
  const std::vector<Module> last = run.modules();
  EXPECT_EQ(count_named(last, "D") + count_named(last, "SB") + count_named(last, "H"), 0);
  EXPECT_EQ(count_named(last, "E"), closed ? 0 : 2);
}

TEST(MultiresCurves, ClosedRoundTrip) { check_round_trip(kClosed, true, false); }
TEST(MultiresCurves, ClosedRoundTripWithNormals) { check_round_trip(kClosed, true, true); }
TEST(MultiresCurves, OpenRoundTrip) { check_round_trip(kOpen, false, false); }
TEST(MultiresCurves, OpenRoundTripWithNormals) { check_round_trip(kOpen, false, true); }

TEST(MultiresCurves, OtherLevelCounts) {
  for (int levels : {1, 5}) {
    const std::vector<std::string> d = {"LEVELS=" + std::to_string(levels)};
    EXPECT_EQ(parse(parse_modules(derive_with(kClosed, 2 * levels, d))).points.size(), 96u >> levels);
    EXPECT_EQ(parse(parse_modules(derive_with(kOpen, 2 * levels, d))).points.size(), (96u >> levels) + 3);
    EXPECT_EQ(parse(parse_modules(derive_with(kOpen, 4 * levels, d))).points.size(), 99u);
  }
}

// The frames keep the details' lengths: with NORMALS=1 the coarse points are
// the same and every detail has the length of its x-y version.
TEST(MultiresCurves, NormalAlignedDetailsKeepTheirLengths) {
  for (const std::string& model : {kClosed, kOpen}) {
    const std::vector<Module> xy = parse_modules(derive_with(model, 2 * kLevels, defines(false)));
    const std::vector<Module> nf = parse_modules(derive_with(model, 2 * kLevels, defines(true)));
    ASSERT_EQ(xy.size(), nf.size());
    int compared = 0;
    for (std::size_t i = 0; i < xy.size(); ++i) {
      ASSERT_EQ(xy[i].name, nf[i].name);
      if (xy[i].name == "C") {
        EXPECT_EQ(xy[i].params, nf[i].params);
      }
      if (xy[i].name != "D") continue;
      EXPECT_NEAR(norm(read_pt(xy[i].params[0])), norm(read_pt(nf[i].params[0])), 1e-12);
      ++compared;
    }
    EXPECT_EQ(compared, model == kClosed ? 96 - 12 : 99 - 15);
  }
}

// Edits of the coarse level

std::vector<Pt> final_points(const std::string& model, std::vector<std::string> d) {
  return parse(parse_modules(derive_with(model, 4 * kLevels, std::move(d)))).points;
}

// The L-system's result of an edit equals the C++ synthesis of the edited
// coarse points with the stored details.
std::vector<Pt> cpp_edit_result(bool closed, bool normals, const std::vector<Pt>& original, Pt (*edit)(Pt, int)) {
  std::vector<Level> levels;
  std::vector<Pt> fine = original;
  for (int l = 0; l < kLevels; ++l) levels.push_back(analyse(closed, normals, fine)), fine = levels.back().coarse;
  for (std::size_t i = 0; i < fine.size(); ++i) fine[i] = edit(fine[i], static_cast<int>(i));
  for (int l = kLevels - 1; l >= 0; --l) fine = synthesise(closed, normals, fine, levels[static_cast<std::size_t>(l)].details);
  return fine;
}

TEST(MultiresCurves, TranslatingTheCoarseLevelTranslatesTheCurve) {
  for (const std::string& model : {kClosed, kOpen})
    for (bool normals : {false, true}) {
      const std::vector<Pt> original = final_points(model, defines(normals));
      const std::vector<Pt> moved = final_points(model, defines(normals, {"EDIT=1", "DX=2.5", "DY=-1.25"}));
      std::vector<Pt> want;
      for (Pt p : original) want.push_back(p + Pt{2.5, -1.25});
      EXPECT_LT(max_distance(moved, want), 1e-9) << model << " normals " << normals;
    }
}

TEST(MultiresCurves, RotatingTheCoarseLevelRotatesTheCurveOnlyWithNormals) {
  for (const std::string& model : {kClosed, kOpen}) {
    const std::vector<Pt> original = final_points(model, defines(false));
    std::vector<Pt> rotated;
    for (Pt p : original) rotated.push_back({-p.y, p.x});  // 90 degrees
    const std::vector<Pt> with = final_points(model, defines(true, {"EDIT=3", "ANGLE=90"}));
    const std::vector<Pt> without = final_points(model, defines(false, {"EDIT=3", "ANGLE=90"}));
    EXPECT_LT(max_distance(with, rotated), 1e-9) << model;
    EXPECT_GT(max_distance(without, rotated), 0.1) << model;  // x-y details keep their direction
  }
}

TEST(MultiresCurves, ScalingKeepsTheNormalAlignedDetails) {
  // One level: the fine points minus the subdivided coarse points are Q times
  // the details in x-y, the same before and after scaling the coarse level
  // (the frames of a scaled polygon are the same).
  for (const std::string& model : {kClosed, kOpen}) {
    const bool closed = model == kClosed;
    auto displacement = [&](bool normals, double scale) {
      Stepper run(model, defines(normals, {"LEVELS=1", "EDIT=2", "SCALE=" + std::to_string(scale)}));
      run.step(2);
      std::vector<Pt> coarse = parse(run.modules()).points;
      run.step(2);
      const std::vector<Pt> fine = parse(run.modules()).points;
      for (Pt& c : coarse) c = scale * c;
      const std::vector<Pt> subdivided = multiply(filters(closed, static_cast<int>(coarse.size())).p, coarse);
      std::vector<Pt> out;
      for (std::size_t i = 0; i < fine.size(); ++i) out.push_back(fine[i] - subdivided[i]);
      return out;
    };
    const std::vector<Pt> with = displacement(true, 1.0), without = displacement(false, 1.0);
    EXPECT_LT(max_distance(displacement(true, 1.75), with), 1e-9) << model;
    EXPECT_LT(max_distance(displacement(false, 1.75), without), 1e-9) << model;  // x-y: kept too
    // A negative factor turns the coarse polygon by 180 degrees: the
    // normal-aligned details turn with it, the x-y ones do not.
    std::vector<Pt> turned;
    for (Pt p : with) turned.push_back(-1 * p);
    EXPECT_LT(max_distance(displacement(true, -0.5), turned), 1e-9) << model;
    EXPECT_LT(max_distance(displacement(false, -0.5), without), 1e-9) << model;
    EXPECT_GT(max_distance(with, turned), 1e-3) << model;
  }
}

Pt move_point_3(Pt p, int i) { return i == 3 ? p + Pt{0.5, 2} : p; }
Pt stretch(Pt p, int) { return {1.5 * p.x, p.y}; }

TEST(MultiresCurves, EditedCoarseLevelGivesTheMatrixSynthesis) {
  for (const std::string& model : {kClosed, kOpen})
    for (bool normals : {false, true}) {
      const bool closed = model == kClosed;
      const std::vector<Pt> original = parse(parse_modules(derive_with(model, 0, {}))).points;
      const std::vector<Pt> moved = final_points(model, defines(normals, {"EDIT=4", "POINT=3", "DX=0.5", "DY=2"}));
      EXPECT_LT(max_distance(moved, cpp_edit_result(closed, normals, original, move_point_3)), 1e-9) << model;
      const std::vector<Pt> stretched = final_points(model, defines(normals, {"EDIT=5", "SCALE=1.5"}));
      EXPECT_LT(max_distance(stretched, cpp_edit_result(closed, normals, original, stretch)), 1e-9) << model;
      if (!normals) {
        // x-y details: moving one coarse point moves the fine points by
        // (P_1 P_2 P_3) e_3 (0.5, 2), only near it (the masks' support).
        int changed = 0;
        for (std::size_t i = 0; i < original.size(); ++i) changed += norm(moved[i] - original[i]) > 1e-9;
        EXPECT_GT(changed, 0);
        EXPECT_LT(changed, static_cast<int>(original.size()) / 2);
      }
    }
}

// Appendix C as printed (NORMALS=2) is not an inverse of the analysis.
TEST(MultiresCurves, NotesNormalRuleDoesNotRoundTrip) {
  const std::vector<Pt> original = parse(parse_modules(derive_with(kClosed, 0, {}))).points;
  const std::vector<Pt> notes = final_points(kClosed, {"NORMALS=2"});
  ASSERT_EQ(notes.size(), original.size());
  EXPECT_GT(max_distance(notes, original), 0.1);
}

}  // namespace
}  // namespace sylva::test::examples
