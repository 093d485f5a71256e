// Tests of examples/vv-sqrt3, Kobbelt's sqrt(3) subdivision after
// "Relational specification of surface subdivision algorithms" (SIGGRAPH
// 2003 course notes "L-systems and Beyond", part 3, Algorithm 5).
//
// The surface is read back from what the model draws: its interpreted
// string, SP (SetHead MoveTo3d(p) PP)... EP per face, with the points as
// printed doubles (as in vv_surfaces_test.cpp). The expectations are
// computed here a second way, from the face list alone (no rings): the
// closed-form counts, Euler's characteristic, each level's points from the
// previous level's faces by Kobbelt's rules written again (centroids, old
// vertices relaxed with beta_n = (4 - 2 cos(2 pi / n)) / (9 n)), and each
// level's faces as the flipped ones: for every old edge (a, b) with faces
// f and g on either side, the triangles (a, c_f, c_g) and (b, c_f, c_g).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "examples/vv_meshes.h"

namespace sylva::test::examples {
namespace {

// The drawn point nearest to p, and how far it is.
std::pair<int, double> nearest(const std::vector<P>& points, const P& p) {
  int best = -1;
  double distance = 1e300;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (const double d = norm(points[i] - p); d < distance) distance = d, best = static_cast<int>(i);
  return {best, distance};
}

// Kobbelt's weight on each neighbour of a vertex of valence n.
double beta(int n) { return (4 - 2 * std::cos(2 * M_PI / n)) / (9.0 * n); }

// One sqrt(3) step from the faces alone: the points (old ones relaxed, then
// one centroid per face, in face order) and the faces, as indices into them.
TriMesh sqrt3_step(const TriMesh& m) {
  TriMesh out;
  const auto nb = m.neighbours();
  for (std::size_t v = 0; v < m.points.size(); ++v) {
    const int n = static_cast<int>(nb[v].size());
    P p = (1 - n * beta(n)) * m.points[v];
    for (int u : nb[v]) p = p + beta(n) * m.points[static_cast<std::size_t>(u)];
    out.points.push_back(p);
  }
  const int old = static_cast<int>(m.points.size());
  for (const auto& f : m.faces)
    out.points.push_back((1.0 / 3.0) * (m.points[f[0]] + m.points[f[1]] + m.points[f[2]]));
  for (const auto& [e, s] : m.sides()) {
    EXPECT_EQ(s.size(), 2u);
    if (s.size() != 2) continue;
    out.faces.push_back({e.first, old + s[0], old + s[1]});
    out.faces.push_back({e.second, old + s[0], old + s[1]});
  }
  return out;
}

TEST(VvSqrt3Test, CountsEulerAndClosedSurface) {
  const Levels run = run_levels("vv-sqrt3", 4);
  const long V0 = 12, E0 = 30, F0 = 20;
  long p = 1;  // 3^n
  for (std::size_t n = 0; n < run.meshes.size(); ++n, p *= 3) {
    const TriMesh& m = run.meshes[n];
    const long F = F0 * p, E = E0 * p, V = V0 + F0 * (p - 1) / 2;
    EXPECT_EQ(m.non_triangles, 0);
    EXPECT_EQ(static_cast<long>(m.faces.size()), F) << "level " << n;
    EXPECT_EQ(static_cast<long>(m.edges().size()), E) << "level " << n;
    EXPECT_EQ(static_cast<long>(m.points.size()), V) << "level " << n;
    // Euler's characteristic of the sphere, from what was drawn.
    EXPECT_EQ(static_cast<long>(m.points.size() - m.edges().size() + m.faces.size()), 2) << "level " << n;
    // Every edge has two faces and no face is drawn twice: a closed surface.
    for (const auto& [edge, faces] : m.sides()) EXPECT_EQ(faces.size(), 2u) << "level " << n;
    std::set<std::array<int, 3>> distinct;
    for (auto f : m.faces) std::sort(f.begin(), f.end()), distinct.insert(f);
    EXPECT_EQ(distinct.size(), m.faces.size()) << "level " << n;
    // What the model printed agrees.
    const std::string line = "vv-sqrt3 level " + std::to_string(n) + ": V=" + std::to_string(V) +
                             " E=" + std::to_string(E) + " F=" + std::to_string(F) + "\n";
    EXPECT_NE(run.messages.find(line), std::string::npos) << line << run.messages;
  }
}

TEST(VvSqrt3Test, PointsAndFacesFollowKobbeltsRules) {
  // Squashed along z, so that the corners are not all alike.
  const Levels run = run_levels("vv-sqrt3", 4, {"STRETCH=0.6"});
  for (std::size_t n = 0; n + 1 < run.meshes.size(); ++n) {
    const std::string what = "level " + std::to_string(n + 1);
    const TriMesh want = sqrt3_step(run.meshes[n]);
    const TriMesh& got = run.meshes[n + 1];
    ASSERT_EQ(got.points.size(), want.points.size()) << what;
    ASSERT_EQ(got.faces.size(), want.faces.size()) << what;
    // Every expected point is drawn, within 1e-12; the map to the drawn
    // points is one to one.
    std::vector<int> to_drawn;
    double worst = 0;
    for (const P& w : want.points) {
      const auto [i, d] = nearest(got.points, w);
      to_drawn.push_back(i);
      worst = std::max(worst, d);
    }
    EXPECT_LE(worst, 1e-12) << what;
    EXPECT_EQ(std::set<int>(to_drawn.begin(), to_drawn.end()).size(), got.points.size()) << what;
    // The faces are the flipped ones, each once.
    std::set<std::array<int, 3>> drawn, expected;
    for (auto f : got.faces) std::sort(f.begin(), f.end()), drawn.insert(f);
    for (const auto& f : want.faces) {
      std::array<int, 3> g{to_drawn[f[0]], to_drawn[f[1]], to_drawn[f[2]]};
      std::sort(g.begin(), g.end());
      expected.insert(g);
    }
    EXPECT_EQ(drawn, expected) << what;
    // All wound outward (the squashed icosahedron's subdivisions are convex
    // about the origin).
    for (const auto& f : got.faces) {
      const P a = got.points[f[0]], b = got.points[f[1]], c = got.points[f[2]];
      EXPECT_GT(dot(cross(b - a, c - a), a + b + c), 0) << what;
    }
  }
  // Old vertices keep their valence (5 on the icosahedron's corners), every
  // centroid has valence 6.
  expect_icosahedral_valences(run);
}

}  // namespace
}  // namespace sylva::test::examples
