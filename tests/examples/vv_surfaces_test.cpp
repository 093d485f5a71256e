// Tests of the vertex-vertex surface examples (examples/vv-loop,
// vv-butterfly, vv-polyhedral) after "Relational specification of surface
// subdivision algorithms" (SIGGRAPH 2003 course notes "L-systems and
// Beyond", part 3, Algorithms 2, 3 and 4).
//
// The surface is read back from what each model draws: its interpreted
// string, SP (SetHead MoveTo3d(p) PP)... EP per face, with the points as
// printed doubles. Vertices are the distinct points, edges the distinct
// pairs of consecutive corners. The expectations are computed here a second
// way, from the face list alone (no rings): the closed-form counts, Euler's
// characteristic, and each level's points from the previous level's faces
// by the schemes' masks written again (Loop's edge and vertex masks, the
// butterfly's eight-point mask, midpoints), plus Loop's limit positions and
// the butterfly's interpolation of the original corners.
#include <gtest/gtest.h>

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

// V = v0 4^n + 2 ... for a subdivision that splits each triangle in four.
void expect_counts(const Levels& run, const std::string& name, long faces0) {
  for (std::size_t n = 0; n < run.meshes.size(); ++n) {
    const TriMesh& m = run.meshes[n];
    const long p = 1L << (2 * n), F = faces0 * p, E = 3 * F / 2, V = E - F + 2;
    EXPECT_EQ(m.non_triangles, 0);
    EXPECT_EQ(static_cast<long>(m.faces.size()), F) << name << " level " << n;
    EXPECT_EQ(static_cast<long>(m.edges().size()), E) << name << " level " << n;
    EXPECT_EQ(static_cast<long>(m.points.size()), V) << name << " level " << n;
    // Euler's characteristic of the sphere, from what was drawn.
    EXPECT_EQ(static_cast<long>(m.points.size() - m.edges().size() + m.faces.size()), 2);
    // Every edge has two faces and no face is drawn twice: a closed surface.
    for (const auto& [edge, corners] : m.opposite()) EXPECT_EQ(corners.size(), 2u);
    // What the model printed agrees.
    const std::string line = name + " level " + std::to_string(n) + ": V=" + std::to_string(V) +
                             " E=" + std::to_string(E) + " F=" + std::to_string(F) + "\n";
    EXPECT_NE(run.messages.find(line), std::string::npos) << line << run.messages;
  }
}

// Each expected point has a drawn point within `tolerance`, and as many.
void expect_same_points(const std::vector<P>& got, const std::vector<P>& want, double tolerance,
                        const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  double worst = 0;
  for (const P& w : want) {
    double best = 1e300;
    for (const P& g : got) best = std::min(best, norm(g - w));
    worst = std::max(worst, best);
  }
  EXPECT_LE(worst, tolerance) << what;
}

// Loop's weight on each neighbour of a vertex of valence n.
double loop_beta(int n) {
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2 * M_PI / n);
  return (5.0 / 8.0 - c * c) / n;
}

// One Loop step from the faces alone.
std::vector<P> loop_step(const TriMesh& m) {
  std::vector<P> out;
  const auto nb = m.neighbours();
  for (std::size_t v = 0; v < m.points.size(); ++v) {
    const int n = static_cast<int>(nb[v].size());
    const double beta = loop_beta(n);
    P p = (1 - n * beta) * m.points[v];
    for (int u : nb[v]) p = p + beta * m.points[static_cast<std::size_t>(u)];
    out.push_back(p);
  }
  for (const auto& [e, c] : m.opposite())
    out.push_back(0.375 * (m.points[e.first] + m.points[e.second]) + 0.125 * (m.points[c[0]] + m.points[c[1]]));
  return out;
}

// Loop's limit position of vertex v: (1 - n b') p + b' (sum of neighbours),
// b' = 1 / (3 / (8 beta) + n).
P loop_limit(const TriMesh& m, const std::vector<std::set<int>>& nb, std::size_t v) {
  const int n = static_cast<int>(nb[v].size());
  const double b = 1 / (3 / (8 * loop_beta(n)) + n);
  P p = (1 - n * b) * m.points[v];
  for (int u : nb[v]) p = p + b * m.points[static_cast<std::size_t>(u)];
  return p;
}

TEST(VvSurfacesTest, LoopOnTheIcosahedronCountsAndEuler) {
  const Levels run = run_levels("vv-loop", 4);
  expect_counts(run, "vv-loop", 20);
  // Only the twelve old corners have valence 5.
  expect_icosahedral_valences(run);
}

TEST(VvSurfacesTest, LoopPointsFollowTheMasksAndApproachTheLimit) {
  // Squashed along z, so that the corners are not all alike.
  const Levels run = run_levels("vv-loop", 4, {"STRETCH=0.6"});
  for (std::size_t n = 0; n + 1 < run.meshes.size(); ++n)
    expect_same_points(run.meshes[n + 1].points, loop_step(run.meshes[n]), 1e-13,
                       "Loop level " + std::to_string(n + 1));

  // The twelve old corners (valence 5) at each level, and their limits.
  std::vector<std::vector<P>> corners, limits;
  for (const TriMesh& m : run.meshes) {
    const auto nb = m.neighbours();
    corners.emplace_back(), limits.emplace_back();
    for (std::size_t v = 0; v < m.points.size(); ++v)
      if (nb[v].size() == 5) corners.back().push_back(m.points[v]), limits.back().push_back(loop_limit(m, nb, v));
  }
  ASSERT_EQ(limits[0].size(), 12u);
  double previous = 1e300;
  for (std::size_t n = 0; n < run.meshes.size(); ++n) {
    // The limit is the same from every level (it is a left eigenvector).
    expect_same_points(limits[n], limits[0], 1e-13, "Loop limits at level " + std::to_string(n));
    // The corners approach it: the distance shrinks at least by the
    // subdominant eigenvalue's rate (about 0.45 at valence 5; 0.6 allowed).
    double error = 0;
    for (std::size_t i = 0; i < corners[n].size(); ++i) error = std::max(error, norm(corners[n][i] - limits[n][i]));
    EXPECT_GT(error, 0) << n;
    EXPECT_LT(error, 0.6 * previous) << n;
    previous = error;
  }
  EXPECT_LT(previous, 0.01);
}

// One butterfly step from the faces alone: new points by the mask
// 1/2 (a + b) + 1/8 (c + d) - 1/16 (the four corners beyond the wings).
std::vector<P> butterfly_step(const TriMesh& m) {
  std::vector<P> out = m.points;
  const auto opp = m.opposite();
  auto beyond = [&](int a, int c, int not_this) {
    for (int x : opp.at(std::minmax(a, c)))
      if (x != not_this) return m.points[static_cast<std::size_t>(x)];
    ADD_FAILURE() << "no face beyond " << a << " " << c;
    return P{0, 0, 0};
  };
  for (const auto& [e, cd] : opp) {
    const int a = e.first, b = e.second, c = cd[0], d = cd[1];
    P x = 0.5 * (m.points[a] + m.points[b]) + 0.125 * (m.points[c] + m.points[d]);
    x = x - 0.0625 * (beyond(a, c, b) + beyond(b, c, a) + beyond(a, d, b) + beyond(b, d, a));
    out.push_back(x);
  }
  return out;
}

TEST(VvSurfacesTest, ButterflyInterpolatesAndFollowsItsMask) {
  const Levels run = run_levels("vv-butterfly", 3);
  expect_counts(run, "vv-butterfly", 8);
  const TriMesh& octahedron = run.meshes[0];
  ASSERT_EQ(octahedron.points.size(), 6u);
  for (const P& corner : octahedron.points) EXPECT_NEAR(norm(corner), 1.0, 0);
  for (std::size_t n = 1; n < run.meshes.size(); ++n) {
    // The original corners are still points of the mesh, to the last bit.
    const std::vector<P>& points = run.meshes[n].points;
    for (const P& corner : octahedron.points)
      EXPECT_NE(std::find(points.begin(), points.end(), corner), points.end()) << "level " << n;
    expect_same_points(points, butterfly_step(run.meshes[n - 1]), 1e-13, "butterfly level " + std::to_string(n));
  }
  // And every point of a level is a point of all later ones.
  for (const P& p : run.meshes[1].points) {
    const std::vector<P>& last = run.meshes.back().points;
    EXPECT_NE(std::find(last.begin(), last.end(), p), last.end());
  }
}

TEST(VvSurfacesTest, PolyhedralSubdivisionKeepsTheTetrahedron) {
  const Levels run = run_levels("vv-polyhedral", 3);
  expect_counts(run, "vv-polyhedral", 4);
  auto area = [](const TriMesh& m) {
    double a = 0;
    for (const auto& f : m.faces) a += norm(cross(m.points[f[1]] - m.points[f[0]], m.points[f[2]] - m.points[f[0]])) / 2;
    return a;
  };
  const TriMesh& tetrahedron = run.meshes[0];
  std::vector<P> planes;  // unit normals of the four faces, wound outward
  for (const auto& f : tetrahedron.faces) {
    const P n = cross(tetrahedron.points[f[1]] - tetrahedron.points[f[0]], tetrahedron.points[f[2]] - tetrahedron.points[f[0]]);
    planes.push_back((1 / norm(n)) * n);
  }
  for (std::size_t n = 1; n < run.meshes.size(); ++n) {
    const TriMesh& m = run.meshes[n];
    // The old points and the midpoints of the old edges, exactly.
    std::vector<P> want = run.meshes[n - 1].points;
    for (const auto& [a, b] : run.meshes[n - 1].edges())
      want.push_back(0.5 * (run.meshes[n - 1].points[a] + run.meshes[n - 1].points[b]));
    expect_same_points(m.points, want, 0, "polyhedral level " + std::to_string(n));
    // The same surface: the same area, every face in a face of the
    // tetrahedron and wound the same way.
    EXPECT_NEAR(area(m), area(tetrahedron), 1e-12);
    for (const auto& f : m.faces) {
      P normal = cross(m.points[f[1]] - m.points[f[0]], m.points[f[2]] - m.points[f[0]]);
      normal = (1 / norm(normal)) * normal;
      double best = 1e300;
      for (const P& plane : planes) best = std::min(best, norm(normal - plane));
      EXPECT_LT(best, 1e-12);
    }
  }
}

}  // namespace
}  // namespace sylva::test::examples
