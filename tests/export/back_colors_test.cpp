// cpfg's back-side colours (@; @,, CPFG manual 6.3): the turtle gives the
// triangles of polygons, surfaces and cylinders the back side's colour; mesh
// files get the back as triangles of their own, wound the other way, in that
// colour (glTF materials one-sided); the PNG renderer lights the back side
// with the back colour's material.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "api/simulation.h"
#include "export/mesh_writers.h"
#include "export/tiny_gltf_setup.h"
#include "geometry/back_sides.h"
#include "geometry/tessellation.h"
#include "render/png_renderer.h"
#include "test_support.h"

namespace sylva {
namespace {

using geometry::MeshPart;
using geometry::Scene;
using geometry::Vec3;

// A triangle in the plane z = 0 covering the middle of the view, wound
// counter-clockwise seen from +z (normals +z) or, with `facing_away`, seen
// from -z (normals -z); front colour 2, back colour 3.
Scene triangle(bool facing_away = false) {
  Scene scene;
  const Vec3 n{0, 0, facing_away ? -1.0f : 1.0f};
  const std::vector<std::uint32_t> order = facing_away ? std::vector<std::uint32_t>{0, 2, 1} : std::vector<std::uint32_t>{0, 1, 2};
  scene.add_triangles(geometry::TriangleGroup::Kind::Surface, {{-1.5f, -1.5f, 0}, {1.5f, -1.5f, 0}, {0, 1.5f, 0}},
                      {n, n, n}, order, 2, {0, 0});
  scene.groups.back().back_color = 3;
  return scene;
}

// 2 red, 3 green.
geometry::Palette palette() {
  geometry::Palette p = geometry::Palette::default_palette();
  p.entries[2].diffuse = p.entries[2].ambient = {1, 0, 0};
  p.entries[3].diffuse = p.entries[3].ambient = {0, 1, 0};
  return p;
}

TEST(BackSides, SplitGivesTheBackItsOwnReversedPart) {
  geometry::TriangleMesh mesh = geometry::tessellate(triangle(), {});
  ASSERT_EQ(mesh.parts.size(), 1u);
  EXPECT_EQ(mesh.parts[0].back_color, 3);
  geometry::split_back_sides(mesh);
  ASSERT_EQ(mesh.parts.size(), 2u);
  const MeshPart& front = mesh.parts[0];
  const MeshPart& back = mesh.parts[1];
  EXPECT_EQ(front.side, MeshPart::Side::Front);
  EXPECT_EQ(front.color, 2);
  EXPECT_EQ(back.side, MeshPart::Side::Back);
  EXPECT_EQ(back.color, 3);
  ASSERT_EQ(back.index_count, 3u);
  ASSERT_EQ(mesh.positions.size(), 6u);
  // The same corners, the other way round, normals reversed.
  const std::uint32_t f[3] = {mesh.indices[front.first_index], mesh.indices[front.first_index + 1],
                              mesh.indices[front.first_index + 2]};
  const std::uint32_t b[3] = {mesh.indices[back.first_index], mesh.indices[back.first_index + 1],
                              mesh.indices[back.first_index + 2]};
  EXPECT_EQ(mesh.positions[b[0]], mesh.positions[f[0]]);
  EXPECT_EQ(mesh.positions[b[1]], mesh.positions[f[2]]);
  EXPECT_EQ(mesh.positions[b[2]], mesh.positions[f[1]]);
  for (std::uint32_t v : b) EXPECT_EQ(mesh.normals[v], (Vec3{0, 0, -1}));

  // A back in the front's colour, or none, leaves the part as it is.
  Scene same = triangle();
  same.groups.back().back_color = 2;
  geometry::TriangleMesh unchanged = geometry::tessellate(same, {});
  geometry::split_back_sides(unchanged);
  ASSERT_EQ(unchanged.parts.size(), 1u);
  EXPECT_EQ(unchanged.parts[0].side, MeshPart::Side::Both);
}

TEST(BackSides, ObjAndGlbHaveBothColours) {
  geometry::TriangleMesh mesh = geometry::tessellate(triangle(), {});
  geometry::split_back_sides(mesh);
  const ModuleTypes types{{{"A", 0, nullptr}}};
  const std::string dir = test::make_temp_dir("back-sides");

  io::write_obj(dir + "/m.obj", mesh, palette(), types);
  std::stringstream obj;
  obj << std::ifstream(dir + "/m.obj").rdbuf();
  EXPECT_NE(obj.str().find("usemtl color_2\nf 1//1 2//2 3//3\n"), std::string::npos) << obj.str();
  EXPECT_NE(obj.str().find("usemtl color_3\nf 4//4 6//6 5//5\n"), std::string::npos) << obj.str();
  std::stringstream mtl;
  mtl << std::ifstream(dir + "/m.mtl").rdbuf();
  EXPECT_NE(mtl.str().find("newmtl color_3\nKa 0 1 0\nKd 0 1 0\n"), std::string::npos) << mtl.str();

  io::write_glb(dir + "/m.glb", mesh, palette(), types);
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, dir + "/m.glb")) << error;
  std::map<std::string, bool> double_sided;
  for (const tinygltf::Material& m : model.materials) double_sided[m.name] = m.doubleSided;
  ASSERT_EQ(double_sided.size(), 2u);
  EXPECT_EQ(double_sided.count("color_2_one_sided"), 1u);
  EXPECT_EQ(double_sided.count("color_3_one_sided"), 1u);
  for (const auto& [name, both] : double_sided) EXPECT_FALSE(both) << name;
  ASSERT_EQ(model.meshes.size(), 1u);
  EXPECT_EQ(model.meshes[0].primitives.size(), 2u);
}

// Looking down -z: a triangle facing +z shows its front (red), one facing
// -z its back (green).
TEST(BackSides, PngLightsTheBackWithTheBackColour) {
  geometry::ViewParameters view;
  view.box = geometry::Box{{-2, -2, -2}, {2, 2, 2}};
  view.scale = 1;
  io::ImageSettings settings;
  settings.render.mode = geometry::RenderMode::Shaded;
  geometry::Light light;
  light.direction = {0, 0, 1};  // from the viewer
  settings.lights = {light};
  for (bool facing_away : {false, true}) {
    io::Image image = io::render_image(triangle(facing_away), palette(), view, settings, 40, 30);
    const auto p = image.pixel(20, 15);
    if (facing_away) {
      EXPECT_GT(p[1], 100) << "green back";
      EXPECT_LT(p[0], 20);
    } else {
      EXPECT_GT(p[0], 100) << "red front";
      EXPECT_LT(p[1], 20);
    }
  }
}

// @;(n) sets the back side's colour of what follows: a polygon and a
// cylinder carry it into the Scene.
TEST(BackSides, CpfgBackColourReachesTheScene) {
  const std::string dir = test::make_temp_dir("back-sides-cpfg");
  std::ofstream(dir + "/m.l") << "Lsystem: 1\nderivation length: 0\n"
                                 "Axiom: ;(2)@;(3){.f(1)+(90).f(1)+(90).}@;(4)@Gs F(1) @Ge\nendlsystem\n";
  build::BuildOptions build;
  build.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(dir + "/m.l", build);
  simulation.run(0);
  const Scene scene = simulation.scene();
  ASSERT_EQ(scene.groups.size(), 2u);
  EXPECT_EQ(scene.groups[0].kind, geometry::TriangleGroup::Kind::Polygon);
  EXPECT_EQ(scene.groups[0].color, 2);
  EXPECT_EQ(scene.groups[0].back_color, 3);
  EXPECT_EQ(scene.groups[1].kind, geometry::TriangleGroup::Kind::GeneralizedCylinder);
  EXPECT_EQ(scene.groups[1].color, 2);
  EXPECT_EQ(scene.groups[1].back_color, 4);
}

}  // namespace
}  // namespace sylva
