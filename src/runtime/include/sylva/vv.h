// sylva/vv.h — vertex-vertex systems for L+C models: polygon meshes as
// vertices with ordered neighbour rings, and the vertex-vertex algebra of
// Smith, Prusinkiewicz and Samavati, "Relational specification of surface
// subdivision algorithms" (SIGGRAPH 2003 course notes "L-systems and Beyond",
// part 3; Table 1 and Table 2).
//
// A model keeps a mesh in a global, changes it in its control statements and
// draws its faces as polygons in an interpretation rule (examples/vv-loop,
// vv-butterfly, vv-polyhedral):
//
//     #include <lpfgall.h>
//     #include <sylva/vv.h>
//     struct Point { V3d pos; };        // the notes' v$pos is mesh[v].pos
//     vv::Mesh<Point> mesh;
//
// The operations keep the notes' names and their word order, so that a line
// of the notes reads the same here:
//
//     nextto x in v              mesh.nextto(x, v)
//     prevto x in v              mesh.prevto(x, v)
//     any in v                   mesh.any(v)
//     valence v                  mesh.valence(v)
//     is x in v                  mesh.contains(x, v)
//     vertex v                   Vertex v = mesh.add()
//     make {a, b, c} nb_of v     mesh.make({a, b, c}, v)
//     erase x from v             mesh.erase(x, v)
//     replace a with x in v      mesh.replace(a, x, v)
//     splice x after a in v      mesh.splice_after(x, a, v)
//     splice x before a in v     mesh.splice_before(x, a, v)
//     forall v in S              for (Vertex v : S.vertices())
//     forall x in v              for (Vertex x : S.ring(v))
//     remove v from S            S.remove(v)
//     synchronize S; ... 'v      const Mesh old = S; ... old.ring(v), old[v].pos
//
// Where the notes keep new vertices in a second set NV and "merge S with NV"
// at the end, here every vertex made with add() is in the mesh at once, so
// merge has nothing to do; a loop over the old vertices iterates over the
// snapshot's vertices() (or a copy of the list taken before the loop).
//
// Header-only, C++20, needing nothing of the engine; the geometric helpers at
// the end (normal, perpendicular) use V3d of <sylva/runtime/vectors.h> and a
// `pos` member of the vertex data.
#pragma once

#include <sylva/runtime/vectors.h>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace vv {

// A vertex of the universe U: a handle, so that a snapshot of the mesh (the
// notes' 'v) and the mesh itself name the same vertex the same way. Handles
// count up as vertices are made and are never reused, which gives the notes'
// order x < v ("x was made before v"), used to visit each edge once.
struct Vertex {
  static constexpr std::uint32_t kNull = 0xffffffffu;
  std::uint32_t id = kNull;
  bool null() const { return id == kNull; }
  explicit operator bool() const { return !null(); }
  friend bool operator==(Vertex a, Vertex b) { return a.id == b.id; }
  friend bool operator!=(Vertex a, Vertex b) { return a.id != b.id; }
  friend bool operator<(Vertex a, Vertex b) { return a.id < b.id; }
};

// A vertex-vertex system: the vertex set S, each vertex's data and its
// neighbourhood v* as a circular list (first element follows the last).
// Data is the model's own per-vertex struct (position, labels, ...).
template <class Data>
class Mesh {
 public:
  using Ring = std::vector<Vertex>;

  // ---- set-theoretic operations (Table 1) ----

  // A new vertex with an empty neighbourhood, in the set ("vertex v" plus
  // "add v to S").
  Vertex add(Data data = Data{}) {
    nodes_.push_back(Node{std::move(data), {}, true});
    return Vertex{static_cast<std::uint32_t>(nodes_.size() - 1)};
  }
  // Takes v out of the set; its handle stays valid (old rings may still
  // name it) but it is no longer listed by vertices().
  void remove(Vertex v) { node(v).alive = false; }
  bool has(Vertex v) const { return !v.null() && v.id < nodes_.size() && nodes_[v.id].alive; }
  // The vertices of the set, in the universe's order. A copy, so that a loop
  // over it may add vertices ("forall v in S" sees S as it was).
  std::vector<Vertex> vertices() const {
    std::vector<Vertex> out;
    for (std::uint32_t i = 0; i < nodes_.size(); ++i)
      if (nodes_[i].alive) out.push_back(Vertex{i});
    return out;
  }
  std::size_t size() const {
    return static_cast<std::size_t>(std::count_if(nodes_.begin(), nodes_.end(), [](const Node& n) { return n.alive; }));
  }

  // The notes' v$f: the vertex's data.
  Data& operator[](Vertex v) { return node(v).data; }
  const Data& operator[](Vertex v) const { return node(v).data; }

  // ---- query and selection operations (Table 2) ----

  const Ring& ring(Vertex v) const { return node(v).ring; }
  std::size_t valence(Vertex v) const { return ring(v).size(); }
  bool contains(Vertex x, Vertex v) const { return find(x, v) >= 0; }
  // The notes' "any in v" returns a random neighbour; the first one is as
  // good for every algorithm there and keeps runs repeatable. Null if none.
  Vertex any(Vertex v) const { return ring(v).empty() ? Vertex{} : ring(v).front(); }
  // The neighbour after (before) x in v's ring; null if x is not in it.
  Vertex nextto(Vertex x, Vertex v) const { return step(x, v, +1); }
  Vertex prevto(Vertex x, Vertex v) const { return step(x, v, -1); }

  // ---- editing operations (Table 2) ----

  // v* = the circular list. A list naming v, or a vertex twice, is an error.
  void make(std::initializer_list<Vertex> list, Vertex v) { make(Ring(list), v); }
  void make(const Ring& list, Vertex v) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (list[i] == v) fail("make: a vertex cannot be its own neighbour");
      if (!has(list[i])) fail("make: no such vertex");
      for (std::size_t j = 0; j < i; ++j)
        if (list[j] == list[i]) fail("make: a vertex listed twice");
    }
    node(v).ring = list;
  }
  // Takes x out of v's ring; nothing if it is not there.
  void erase(Vertex x, Vertex v) {
    const long i = find(x, v);
    if (i >= 0) node(v).ring.erase(node(v).ring.begin() + i);
  }
  // Puts x where a is in v's ring: the only operation that changes a ring
  // without changing its size, so the insertion of a vertex on an edge
  // (Algorithm 1) keeps the rings' order.
  void replace(Vertex a, Vertex x, Vertex v) {
    const long i = find(a, v);
    if (i < 0) return;
    check_new(x, v);
    node(v).ring[static_cast<std::size_t>(i)] = x;
  }
  // Puts x just after (before) a in v's ring; nothing if a is not there.
  void splice_after(Vertex x, Vertex a, Vertex v) { splice(x, a, v, 1); }
  void splice_before(Vertex x, Vertex a, Vertex v) { splice(x, a, v, 0); }

  // ---- the structure as a whole ----

  // A graph: every neighbour is in the set and neighbourhoods are mutual
  // (u in v* iff v in u*), the condition for faces() to mean anything.
  bool is_graph() const {
    for (Vertex v : vertices())
      for (Vertex u : ring(v))
        if (!has(u) || !contains(v, u)) return false;
    return true;
  }
  // Whether every vertex can be reached from every other along the rings.
  bool connected() const {
    const std::vector<Vertex> all = vertices();
    if (all.empty()) return true;
    std::vector<char> seen(nodes_.size(), 0);
    std::vector<Vertex> stack{all.front()};
    seen[all.front().id] = 1;
    std::size_t reached = 1;
    while (!stack.empty()) {
      const Vertex v = stack.back();
      stack.pop_back();
      for (Vertex u : ring(v))
        if (has(u) && !seen[u.id]) seen[u.id] = 1, ++reached, stack.push_back(u);
    }
    return reached == all.size();
  }
  // Every edge once, as (u, v) with u < v.
  std::vector<std::pair<Vertex, Vertex>> edges() const {
    std::vector<std::pair<Vertex, Vertex>> out;
    for (Vertex v : vertices())
      for (Vertex u : ring(v))
        if (v < u) out.emplace_back(v, u);
    return out;
  }
  // The polygons of Edmonds' permutation technique (the notes' section 3.1):
  // from an oriented edge (u, v) the next corner is w = nextto u in v, then
  // nextto v in w, ... back to u. Every oriented edge is in exactly one
  // orbit, so a closed manifold mesh comes out with each face once and all
  // faces wound the same way. Throws if the structure is not a graph.
  std::vector<std::vector<Vertex>> faces() const {
    if (!is_graph()) fail("faces: the neighbourhoods are not mutual");
    std::unordered_set<std::uint64_t> done;
    auto key = [](Vertex a, Vertex b) { return (std::uint64_t{a.id} << 32) | b.id; };
    std::vector<std::vector<Vertex>> out;
    for (Vertex u0 : vertices())
      for (Vertex v0 : ring(u0)) {
        if (done.count(key(u0, v0))) continue;
        std::vector<Vertex> face;
        Vertex u = u0, v = v0;
        do {
          done.insert(key(u, v));
          face.push_back(u);
          const Vertex w = nextto(u, v);
          u = v;
          v = w;
        } while (!(u == u0 && v == v0));
        out.push_back(std::move(face));
      }
    return out;
  }

  // Builds the rings from polygons given as lists of vertices, all wound
  // the same way around a closed orientable surface (as in an OBJ file):
  // in a polygon ... u v w ..., w follows u in v's ring, so faces() gives
  // the polygons back with the same winding.
  void make_from_faces(const std::vector<std::vector<Vertex>>& polygons) {
    std::vector<std::vector<std::pair<Vertex, Vertex>>> corners(nodes_.size());  // (u, w) at v
    for (const std::vector<Vertex>& f : polygons)
      for (std::size_t i = 0; i < f.size(); ++i)
        corners[f[i].id].emplace_back(f[(i + f.size() - 1) % f.size()], f[(i + 1) % f.size()]);
    for (Vertex v : vertices()) {
      const auto& c = corners[v.id];
      Ring r;
      if (!c.empty()) r.push_back(c.front().first);
      while (r.size() < c.size()) {
        auto it = std::find_if(c.begin(), c.end(), [&](const auto& p) { return p.first == r.back(); });
        if (it == c.end()) fail("make_from_faces: the faces around a vertex do not close");
        r.push_back(it->second);
      }
      make(r, v);
    }
  }

 private:
  struct Node {
    Data data;
    Ring ring;
    bool alive = true;
  };
  std::vector<Node> nodes_;

  [[noreturn]] static void fail(const std::string& what) { throw std::logic_error("vv: " + what); }
  Node& node(Vertex v) {
    if (v.null() || v.id >= nodes_.size()) fail("no such vertex");
    return nodes_[v.id];
  }
  const Node& node(Vertex v) const {
    if (v.null() || v.id >= nodes_.size()) fail("no such vertex");
    return nodes_[v.id];
  }
  long find(Vertex x, Vertex v) const {
    const Ring& r = ring(v);
    const auto it = std::find(r.begin(), r.end(), x);
    return it == r.end() ? -1 : static_cast<long>(it - r.begin());
  }
  Vertex step(Vertex x, Vertex v, int by) const {
    const long i = find(x, v);
    if (i < 0) return Vertex{};
    const long n = static_cast<long>(ring(v).size());
    return ring(v)[static_cast<std::size_t>((i + by + n) % n)];
  }
  // Table 2, note 5: x may not be v or already be v's neighbour.
  void check_new(Vertex x, Vertex v) const {
    if (x == v) fail("a vertex cannot be its own neighbour");
    if (contains(x, v)) fail("the vertex is a neighbour already");
  }
  void splice(Vertex x, Vertex a, Vertex v, int after) {
    const long i = find(a, v);
    if (i < 0) return;
    check_new(x, v);
    Ring& r = node(v).ring;
    r.insert(r.begin() + i + after, x);
  }
};

// Algorithm 1 of the notes: a new vertex x on the edge (p, q), taking q's
// place in p's ring and p's place in q's, with {p, q} as its own ring.
template <class Data>
Vertex insert(Mesh<Data>& S, Vertex p, Vertex q) {
  const Vertex x = S.add();
  S.make({p, q}, x);
  S.replace(p, x, q);
  S.replace(q, x, p);
  return x;
}

#ifndef NOAUTOOVERLOAD
// The unit normal at v: the sum over its ring of the normals of the corner
// triangles (r_i, v, r_i+1), which faces() winds like the mesh's polygons,
// so the normal is on the side the polygons face (outside for a surface
// built by make_from_faces from counterclockwise polygons). The sum weights
// each corner by its area, which is what a smooth-shaded picture wants.
template <class Data>
V3d normal(const Mesh<Data>& S, Vertex v) {
  const typename Mesh<Data>::Ring& r = S.ring(v);
  const V3d p = S[v].pos;
  V3d n(0, 0, 0);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const V3d a = S[r[i]].pos, b = S[r[(i + 1) % r.size()]].pos;
    n += (p - a) % (b - p);
  }
  const double length = n.Length();
  return length > 0 ? V3d(n / length) : V3d(0, 0, 1);
}

// A unit vector across n: the turtle's heading when its up is set to a
// vertex normal (SetHead wants the two at right angles).
inline V3d perpendicular(const V3d& n) {
  const V3d axis = std::abs(n.x) < 0.9 ? V3d(1, 0, 0) : V3d(0, 1, 0);
  V3d h = axis % n;
  return V3d(h / h.Length());
}
#endif

}  // namespace vv
