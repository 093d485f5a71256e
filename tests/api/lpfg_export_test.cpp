// An L+C model's mesh files hold what lpfg's OBJ export writes: lines as
// cylinders of the turtle's width (16 sides, seam at the turtle's left)
// whatever the view's line style, circles of 16 sides in the HL plane from
// the turtle's right, spheres with the view's contour sides and their poles
// on the y axis.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "api/outputs.h"
#include "api/simulation.h"
#include "test_support.h"

namespace sylva::test {
namespace {

using geometry::Vec3;

std::vector<Vec3> obj_vertices(const std::string& path) {
  std::ifstream in(path);
  std::vector<Vec3> out;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.starts_with("v ")) continue;
    std::istringstream words(line.substr(2));
    Vec3 v;
    words >> v.x >> v.y >> v.z;
    out.push_back(v);
  }
  return out;
}

// Positions told apart to 1e-4 (lpfg merges vertices closer than that).
std::set<std::tuple<long, long, long>> distinct(const std::vector<Vec3>& vertices) {
  std::set<std::tuple<long, long, long>> out;
  for (Vec3 v : vertices) out.insert({std::lround(v.x * 1e4f), std::lround(v.y * 1e4f), std::lround(v.z * 1e4f)});
  return out;
}

bool has_vertex(const std::vector<Vec3>& vertices, Vec3 p) {
  for (Vec3 v : vertices)
    if (std::fabs(v.x - p.x) < 1e-5f && std::fabs(v.y - p.y) < 1e-5f && std::fabs(v.z - p.z) < 1e-5f) return true;
  return false;
}

// The reference lpfg (-out ref.obj, run on this model and view file) wrote 95
// vertices: 32 for each line (16 sides at each end), 14 for the sphere (6
// slices: two poles and two rings of 6) and 17 for the circle (its centre and
// 16 round it); the vertices below are some of those it wrote, and its box.
TEST(LpfgExport, LinesCylindersCirclesAndSpheresAsLpfgWritesThem) {
  const std::string dir = make_temp_dir("lpfg-export");
  std::ofstream(dir + "/model.l") << "#include <lpfgall.h>\nderivation length: 1;\n"
                                     "Axiom: SetWidth(0.2) F(1) Left(90) SetWidth(0.5) F(2) Sphere(0.3) Circle(0.4);\n";
  std::ofstream(dir + "/view.v") << "line style: pixel\ncontour sides: 6\n";
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.input_files.push_back(dir + "/view.v");
  Simulation simulation(dir + "/model.l", options);
  simulation.run();
  const std::string path = dir + "/out.obj";
  write_output(path, simulation.scene(), simulation, {});

  const std::vector<Vec3> vertices = obj_vertices(path);
  EXPECT_EQ(distinct(vertices).size(), 95u);
  geometry::Box box;
  for (Vec3 v : vertices) box.add(v);
  EXPECT_NEAR(box.min.x, -2.4f, 1e-5f);
  EXPECT_NEAR(box.max.x, 0.1f, 1e-5f);
  EXPECT_NEAR(box.min.y, 0.0f, 1e-5f);
  EXPECT_NEAR(box.max.y, 1.4f, 1e-5f);
  EXPECT_NEAR(box.min.z, -0.259808f, 1e-5f);
  EXPECT_NEAR(box.max.z, 0.259808f, 1e-5f);
  for (Vec3 p : {Vec3{-0.1f, 0, 0}, Vec3{-0.092388f, 0, 0.0382683f}, Vec3{-0.1f, 1, 0}, Vec3{0, 0.75f, 0},
                 Vec3{0, 0.76903f, 0.0956709f}, Vec3{-2, 1.3f, 0}, Vec3{-2, 1.15f, -0.259808f},
                 Vec3{-2.225f, 1.15f, -0.129904f}, Vec3{-2.225f, 0.85f, 0.129904f}})
    EXPECT_TRUE(has_vertex(vertices, p)) << p.x << " " << p.y << " " << p.z;
}

}  // namespace
}  // namespace sylva::test
