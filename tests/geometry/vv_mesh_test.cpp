// Tests of sylva/vv.h, the vertex-vertex mesh of "Relational specification
// of surface subdivision algorithms" (SIGGRAPH 2003 course notes "L-systems
// and Beyond", part 3): the operations of the notes' Table 2 on small rings
// written out by hand, Edmonds' faces, building rings from faces, the
// notes' Algorithm 1 (insert), and one level of their Algorithm 2
// (polyhedral subdivision) on a tetrahedron, counted and checked against
// the old mesh.
#include "sylva/vv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <vector>

namespace {

using vv::Vertex;
struct Point {
  V3d pos;
  int label = 0;
};
using PointMesh = vv::Mesh<Point>;
using Ring = std::vector<Vertex>;

// A ring as the ids of its vertices, rotated to start at its smallest, so
// that two listings of the same circular list compare equal.
std::vector<unsigned> cyclic(const Ring& r) {
  std::vector<unsigned> ids;
  for (Vertex v : r) ids.push_back(v.id);
  if (!ids.empty()) std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end()), ids.end());
  return ids;
}

// A vertex v with the ring {a, b, c, d} (the notes' Figure 4a).
struct Star {
  PointMesh S;
  Vertex v, a, b, c, d, x;
  Star() {
    v = S.add(), a = S.add(), b = S.add(), c = S.add(), d = S.add(), x = S.add();
    S.make({a, b, c, d}, v);
  }
};

TEST(VvMeshTest, QueryAndSelectionFollowTheCircularList) {
  Star s;
  EXPECT_EQ(s.S.valence(s.v), 4u);
  EXPECT_TRUE(s.S.contains(s.c, s.v));
  EXPECT_FALSE(s.S.contains(s.x, s.v));
  EXPECT_EQ(s.S.nextto(s.a, s.v), s.b);
  EXPECT_EQ(s.S.nextto(s.d, s.v), s.a);  // the list is circular
  EXPECT_EQ(s.S.prevto(s.a, s.v), s.d);
  EXPECT_EQ(s.S.prevto(s.c, s.v), s.b);
  EXPECT_TRUE(s.S.nextto(s.x, s.v).null());  // note 2: x not in v*
  EXPECT_TRUE(s.S.prevto(s.x, s.v).null());
  EXPECT_EQ(s.S.any(s.v), s.a);
  EXPECT_TRUE(s.S.any(s.x).null());  // note 1: empty neighbourhood
  EXPECT_TRUE(s.a < s.b);            // the universe's order: creation order
}

TEST(VvMeshTest, EditingOperationsPutVerticesWhereTheTableSays) {
  {
    Star s;  // Figure 4f: splice x after b
    s.S.splice_after(s.x, s.b, s.v);
    EXPECT_EQ(s.S.ring(s.v), (Ring{s.a, s.b, s.x, s.c, s.d}));
  }
  {
    Star s;  // Figure 4g: splice x before b
    s.S.splice_before(s.x, s.b, s.v);
    EXPECT_EQ(s.S.ring(s.v), (Ring{s.a, s.x, s.b, s.c, s.d}));
  }
  {
    Star s;  // after the last element: between d and a, in circular terms
    s.S.splice_after(s.x, s.d, s.v);
    EXPECT_EQ(cyclic(s.S.ring(s.v)), cyclic({s.a, s.b, s.c, s.d, s.x}));
    EXPECT_EQ(s.S.nextto(s.d, s.v), s.x);
    EXPECT_EQ(s.S.prevto(s.a, s.v), s.x);
  }
  {
    Star s;  // Figure 4e: replace b with x keeps the place
    s.S.replace(s.b, s.x, s.v);
    EXPECT_EQ(s.S.ring(s.v), (Ring{s.a, s.x, s.c, s.d}));
  }
  {
    Star s;  // Figure 4d: erase c, and erasing what is not there does nothing
    s.S.erase(s.c, s.v);
    EXPECT_EQ(s.S.ring(s.v), (Ring{s.a, s.b, s.d}));
    s.S.erase(s.x, s.v);
    EXPECT_EQ(s.S.ring(s.v), (Ring{s.a, s.b, s.d}));
    EXPECT_EQ(s.S.nextto(s.b, s.v), s.d);
  }
  {
    Star s;  // note 5: no effect if a is not in v*
    s.S.splice_after(s.x, s.x, s.v);
    s.S.replace(s.x, s.a, s.v);
    EXPECT_EQ(s.S.ring(s.v), (Ring{s.a, s.b, s.c, s.d}));
  }
}

TEST(VvMeshTest, TheTablesErrorsAreReported) {
  Star s;
  EXPECT_THROW(s.S.splice_after(s.v, s.a, s.v), std::logic_error);  // x = v
  EXPECT_THROW(s.S.splice_after(s.c, s.a, s.v), std::logic_error);  // x in v* already
  EXPECT_THROW(s.S.replace(s.a, s.c, s.v), std::logic_error);
  EXPECT_THROW(s.S.make({s.a, s.v}, s.v), std::logic_error);  // note 3
  EXPECT_THROW(s.S.make({s.a, s.b, s.a}, s.v), std::logic_error);
  EXPECT_EQ(s.S.ring(s.v), (Ring{s.a, s.b, s.c, s.d}));  // nothing changed
}

TEST(VvMeshTest, RemovedVerticesLeaveTheSetButKeepTheirHandles) {
  Star s;
  s.S[s.c].label = 7;
  s.S.remove(s.x);
  EXPECT_EQ(s.S.size(), 5u);
  EXPECT_EQ(s.S.vertices(), (Ring{s.v, s.a, s.b, s.c, s.d}));
  EXPECT_FALSE(s.S.has(s.x));
  EXPECT_EQ(s.S[s.c].label, 7);
  EXPECT_FALSE(s.S.is_graph());  // a's neighbourhood lacks v
}

// The tetrahedron with corners 0..3 and the faces wound one way.
PointMesh tetrahedron(std::vector<Vertex>& c) {
  PointMesh S;
  c = {S.add(Point{V3d(1, 1, 1)}), S.add(Point{V3d(1, -1, -1)}), S.add(Point{V3d(-1, 1, -1)}),
       S.add(Point{V3d(-1, -1, 1)})};
  S.make_from_faces({{c[0], c[1], c[2]}, {c[0], c[2], c[3]}, {c[0], c[3], c[1]}, {c[1], c[3], c[2]}});
  return S;
}

TEST(VvMeshTest, RingsBuiltFromFacesGiveTheFacesBack) {
  std::vector<Vertex> c;
  const PointMesh S = tetrahedron(c);
  EXPECT_TRUE(S.is_graph());
  EXPECT_TRUE(S.connected());
  // In the face (0 1 2), 2 follows 0 in 1's ring: Edmonds' rule.
  EXPECT_EQ(S.nextto(c[0], c[1]), c[2]);
  EXPECT_EQ(cyclic(S.ring(c[0])), cyclic({c[1], c[3], c[2]}));
  EXPECT_EQ(S.edges().size(), 6u);
  std::set<std::vector<unsigned>> faces;
  for (const Ring& f : S.faces()) faces.insert(cyclic(f));
  EXPECT_EQ(faces, (std::set<std::vector<unsigned>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}));
  // The normal is on the side the faces are wound to (outside).
  for (Vertex v : c) EXPECT_GT(vv::normal(S, v) * S[v].pos, 0.99 * S[v].pos.Length());
}

TEST(VvMeshTest, InsertPutsANewVertexOnTheEdgeInBothRings) {
  std::vector<Vertex> c;
  PointMesh S = tetrahedron(c);
  const Ring before0 = S.ring(c[0]), before1 = S.ring(c[1]);
  const Vertex x = vv::insert(S, c[0], c[1]);
  EXPECT_EQ(S.ring(x), (Ring{c[0], c[1]}));
  EXPECT_FALSE(S.contains(c[1], c[0]));
  // x took c1's place in c0's ring and c0's place in c1's.
  for (std::size_t i = 0; i < before0.size(); ++i) EXPECT_EQ(S.ring(c[0])[i], before0[i] == c[1] ? x : before0[i]);
  for (std::size_t i = 0; i < before1.size(); ++i) EXPECT_EQ(S.ring(c[1])[i], before1[i] == c[0] ? x : before1[i]);
  EXPECT_TRUE(S.is_graph());
  EXPECT_EQ(S.size(), 5u);
  EXPECT_EQ(S.edges().size(), 7u);
  // The two triangles at the edge became quadrilaterals: V - E + F = 2 still.
  EXPECT_EQ(S.faces().size(), 4u);
}

// The notes' Algorithm 2 (polyhedral subdivision), one level.
void polyhedral(PointMesh& S) {
  const PointMesh old = S;
  std::vector<Vertex> NV;
  for (Vertex v : old.vertices())
    for (Vertex p : old.ring(v)) {
      if (p < v) continue;
      const Vertex x = vv::insert(S, v, p);
      S[x].pos = (S[p].pos + S[v].pos) / 2.0;
      NV.push_back(x);
    }
  for (Vertex v : NV) {
    const Vertex a = S.any(v);
    const Vertex b = S.nextto(a, v);
    S.make({S.nextto(v, b), b, S.prevto(v, b), S.nextto(v, a), a, S.prevto(v, a)}, v);
  }
}

TEST(VvMeshTest, PolyhedralSubdivisionSplitsEveryTriangleInFour) {
  std::vector<Vertex> c;
  PointMesh S = tetrahedron(c);
  for (int level = 1; level <= 3; ++level) {
    const PointMesh old = S;
    polyhedral(S);
    const std::size_t p = std::size_t{1} << (2 * level);  // 4^level
    EXPECT_EQ(S.size(), 2 * p + 2);
    EXPECT_EQ(S.edges().size(), 6 * p);
    const auto faces = S.faces();
    EXPECT_EQ(faces.size(), 4 * p);
    for (const Ring& f : faces) EXPECT_EQ(f.size(), 3u);
    EXPECT_TRUE(S.is_graph());
    EXPECT_TRUE(S.connected());
    // Old vertices keep their valence; their neighbours are all new, at the
    // midpoints of the old edges, in the old order.
    for (Vertex v : old.vertices()) {
      ASSERT_EQ(S.valence(v), old.valence(v));
      for (std::size_t i = 0; i < old.valence(v); ++i) {
        const Vertex x = S.ring(v)[i], q = old.ring(v)[i];
        EXPECT_FALSE(old.has(x));
        const V3d mid = (old[v].pos + old[q].pos) / 2.0, got = S[x].pos;
        EXPECT_EQ(got.x, mid.x);
        EXPECT_EQ(got.y, mid.y);
        EXPECT_EQ(got.z, mid.z);
      }
    }
    // New vertices have valence 6.
    for (Vertex v : S.vertices()) {
      if (!old.has(v)) {
        EXPECT_EQ(S.valence(v), 6u);
      }
    }
  }
}

TEST(VvMeshTest, TheSnapshotIsUnchangedByEditsOfTheMesh) {
  std::vector<Vertex> c;
  PointMesh S = tetrahedron(c);
  const PointMesh old = S;
  S[c[0]].pos = V3d(5, 5, 5);
  S.erase(c[1], c[0]);
  EXPECT_EQ(old[c[0]].pos.x, 1);
  EXPECT_EQ(old.valence(c[0]), 3u);
  EXPECT_EQ(S.valence(c[0]), 2u);
}

}  // namespace
