// Helpers for the tests of the vertex-vertex surface examples: the surface
// read back from what a model draws (its interpreted string, SP (SetHead
// MoveTo3d(p) PP)... EP per face, the points as printed doubles), as distinct
// points and faces, and the levels of a run. Vertices are the distinct
// points, edges the distinct pairs of consecutive corners.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "examples/example_strings.h"
#include "test_support.h"

namespace sylva::test::examples {

using P = std::array<double, 3>;
inline P operator+(P a, P b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline P operator-(P a, P b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline P operator*(double k, P a) { return {k * a[0], k * a[1], k * a[2]}; }
inline P cross(P a, P b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
inline double dot(P a, P b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(P a) { return std::sqrt(dot(a, a)); }

// A triangle mesh as drawn: distinct points and faces of point indices.
struct TriMesh {
  std::vector<P> points;
  std::vector<std::array<int, 3>> faces;
  int non_triangles = 0;

  std::set<std::pair<int, int>> edges() const {
    std::set<std::pair<int, int>> out;
    for (const auto& f : faces)
      for (int i = 0; i < 3; ++i) out.insert(std::minmax(f[i], f[(i + 1) % 3]));
    return out;
  }
  // The corners opposite each edge, one per face on it.
  std::map<std::pair<int, int>, std::vector<int>> opposite() const {
    std::map<std::pair<int, int>, std::vector<int>> out;
    for (const auto& f : faces)
      for (int i = 0; i < 3; ++i) out[std::minmax(f[i], f[(i + 1) % 3])].push_back(f[(i + 2) % 3]);
    return out;
  }
  // The faces on each edge (indices into faces), one per side.
  std::map<std::pair<int, int>, std::vector<int>> sides() const {
    std::map<std::pair<int, int>, std::vector<int>> out;
    for (std::size_t k = 0; k < faces.size(); ++k)
      for (int i = 0; i < 3; ++i)
        out[std::minmax(faces[k][i], faces[k][(i + 1) % 3])].push_back(static_cast<int>(k));
    return out;
  }
  std::vector<std::set<int>> neighbours() const {
    std::vector<std::set<int>> out(points.size());
    for (const auto& [a, b] : edges()) out[a].insert(b), out[b].insert(a);
    return out;
  }
};

// "(x,y,z)" as printed for a V3d.
inline P read_point(const std::string& text) {
  const std::vector<std::string> c = split_top_level(text.substr(1, text.size() - 2));
  EXPECT_EQ(c.size(), 3u) << text;
  return {number(c.at(0)), number(c.at(1)), number(c.at(2))};
}

inline TriMesh drawn_mesh(const std::vector<Module>& s) {
  TriMesh m;
  std::map<P, int> index;
  std::vector<int> face;
  P at{0, 0, 0};
  for (const Module& module : s) {
    if (module.name == "SP") face.clear();
    if (module.name == "MoveTo3d") at = read_point(module.params.at(0));
    if (module.name == "PP") {
      const auto [it, fresh] = index.emplace(at, static_cast<int>(m.points.size()));
      if (fresh) m.points.push_back(at);
      face.push_back(it->second);
    }
    if (module.name == "EP") {
      if (face.size() == 3) m.faces.push_back({face[0], face[1], face[2]});
      else ++m.non_triangles;
    }
  }
  return m;
}

// The drawn mesh at levels 0..levels (one derivation step per level), and
// what the model printed.
struct Levels {
  std::vector<TriMesh> meshes;
  std::string messages;
};
inline Levels run_levels(const std::string& name, int levels, std::vector<std::string> defines = {}) {
  Stepper run(example_path(name + "/" + name + ".l"), std::move(defines));
  Levels out;
  for (int k = 0; k <= levels; ++k) {
    if (k > 0) run.step();
    out.meshes.push_back(drawn_mesh(parse_modules(run.interpreted())));
  }
  out.messages = run.messages;
  return out;
}

// Subdivision of the icosahedron keeps its twelve corners at valence 5 and
// gives every new vertex valence 6.
inline void expect_icosahedral_valences(const Levels& run) {
  for (const TriMesh& m : run.meshes) {
    int fives = 0;
    for (const auto& n : m.neighbours()) {
      fives += n.size() == 5;
      EXPECT_TRUE(n.size() == 5 || n.size() == 6);
    }
    EXPECT_EQ(fives, 12);
  }
}

}  // namespace sylva::test::examples
