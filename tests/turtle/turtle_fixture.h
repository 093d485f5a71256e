// Helpers for the turtle tests: small L+C models written to a temporary
// directory, built into the tests' cache, derived and interpreted.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "geometry/scene.h"
#include "sylva/predefined_ids.h"
#include "test_support.h"
#include "turtle/interpreter.h"

namespace sylva::test::turtle_tests {

using geometry::Scene;
using geometry::Vec3;
namespace mid = rt::mid;

// `body` (after #include <lpfgall.h>) as a model named `name`, ready to derive.
inline std::unique_ptr<Simulation> load_model(const std::string& name, const std::string& body) {
  const std::string path = make_temp_dir("turtle-" + name) + "/" + name + ".l";
  std::ofstream(path) << "#include <lpfgall.h>\n" << body << "\n";
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  return std::make_unique<Simulation>(path, options);
}

// The Scene of an axiom (no derivation step).
inline Scene draw(const std::string& name, const std::string& axiom, const turtle::TurtleSettings& settings = {},
                  std::string* trace = nullptr, const std::string& declarations = "") {
  auto simulation = load_model(name, declarations + "\nderivation length: 0;\naxiom: " + axiom + ";");
  simulation->run(0);
  Scene scene;
  turtle::walk_string(simulation->string(), simulation->types(), settings, &scene, trace);
  return scene;
}

// The parameters of the n-th module `id` in the simulation's string, as floats.
inline std::vector<float> module_floats(const Simulation& s, abi::ModuleId id, int nth, int count) {
  const StringView v = s.string().view(s.types());
  int seen = 0;
  for (std::size_t at = v.begin; at < v.end; at = v.next(at)) {
    if (v.id_at(at) != id || seen++ != nth) continue;
    std::vector<float> out(static_cast<std::size_t>(count));
    std::memcpy(out.data(), module_params(v.data, at), sizeof(float) * out.size());
    return out;
  }
  return {};
}

// What the turtle, with `settings`, tells the n-th query module `id` of the
// simulation's string (its first `count` parameters).
inline std::vector<float> queried_floats(const Simulation& s, const turtle::TurtleSettings& settings,
                                         abi::ModuleId id, int nth, int count) {
  derive::ParameterWrites answers;
  turtle::walk_string(s.string(), s.types(), settings, nullptr, nullptr, &answers);
  const StringView v = s.string().view(s.types());
  std::uint32_t index = 0;
  int seen = 0;
  for (std::size_t at = v.begin; at < v.end; at = v.next(at), ++index) {
    if (v.id_at(at) != id || seen++ != nth) continue;
    for (const derive::ParameterWrites::Write& w : answers.writes())
      if (w.module_index == index && w.first_float == 0 && w.count >= count)
        return std::vector<float>(answers.values().begin() + w.value_offset,
                                  answers.values().begin() + w.value_offset + count);
  }
  return {};
}

inline void expect_near(Vec3 actual, Vec3 expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance) << "x";
  EXPECT_NEAR(actual.y, expected.y, tolerance) << "y";
  EXPECT_NEAR(actual.z, expected.z, tolerance) << "z";
}

inline void expect_near(const std::vector<float>& actual, Vec3 expected, float tolerance = 1e-5f) {
  ASSERT_EQ(actual.size(), 3u);
  expect_near(Vec3{actual[0], actual[1], actual[2]}, expected, tolerance);
}

// Total area of a triangle group.
inline double group_area(const Scene& s, const geometry::TriangleGroup& g) {
  double area = 0;
  for (std::uint32_t k = 0; k < g.index_count; k += 3) {
    const Vec3 a = s.positions[s.indices[g.first_index + k]], b = s.positions[s.indices[g.first_index + k + 1]],
               c = s.positions[s.indices[g.first_index + k + 2]];
    area += 0.5 * length(cross(b - a, c - a));
  }
  return area;
}

// The (unnormalized) normal of triangle k of a group, by its winding.
inline Vec3 triangle_normal(const Scene& s, const geometry::TriangleGroup& g, std::uint32_t k) {
  const Vec3 a = s.positions[s.indices[g.first_index + 3 * k]], b = s.positions[s.indices[g.first_index + 3 * k + 1]],
             c = s.positions[s.indices[g.first_index + 3 * k + 2]];
  return cross(b - a, c - a);
}

}  // namespace sylva::test::turtle_tests
