// Tessellation checked against counts, areas and normals worked out by hand,
// and the mesh files read back by libraries other than the writers' own:
// assimp for OBJ, PLY and GLB, tinygltf's loader for GLB, and a small PLY
// reader here for the face properties assimp drops.

#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <sstream>

#include "export/mesh_writers.h"
#include "export/tiny_gltf_setup.h"
#include "geometry/tessellation.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;
using geometry::Circle;
using geometry::LineStyle;
using geometry::MeshPart;
using geometry::Provenance;
using geometry::Scene;
using geometry::Segment;
using geometry::Sphere;
using geometry::TriangleMesh;
using geometry::Vec3;

constexpr float kPi = std::numbers::pi_v<float>;

TriangleMesh tessellate(const Scene& scene, LineStyle style = LineStyle::Cylinder, int sides = 8) {
  return geometry::tessellate(scene, {style, sides});
}

std::size_t triangle_count(const TriangleMesh& mesh) { return mesh.indices.size() / 3; }

double part_area(const TriangleMesh& mesh, const MeshPart& part) {
  double area = 0;
  for (std::uint32_t k = 0; k < part.index_count; k += 3) {
    Vec3 a = mesh.positions[mesh.indices[part.first_index + k]];
    Vec3 b = mesh.positions[mesh.indices[part.first_index + k + 1]];
    Vec3 c = mesh.positions[mesh.indices[part.first_index + k + 2]];
    area += 0.5 * geometry::length(geometry::cross(b - a, c - a));
  }
  return area;
}

// The vertices a part's triangles use, each once.
std::vector<std::uint32_t> part_vertices(const TriangleMesh& mesh, const MeshPart& part) {
  std::set<std::uint32_t> used(mesh.indices.begin() + part.first_index,
                               mesh.indices.begin() + part.first_index + part.index_count);
  return {used.begin(), used.end()};
}

geometry::Box mesh_bounds(const TriangleMesh& mesh) {
  geometry::Box box;
  for (Vec3 p : mesh.positions) box.add(p);
  return box;
}

// Unit normals, and every triangle wound counter-clockwise seen from the side
// its vertex normals point to.
void expect_consistent_normals(const TriangleMesh& mesh) {
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (Vec3 n : mesh.normals) EXPECT_NEAR(geometry::length(n), 1.0f, 1e-5f);
  for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
    std::uint32_t a = mesh.indices[k], b = mesh.indices[k + 1], c = mesh.indices[k + 2];
    Vec3 face = geometry::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    if (geometry::length(face) < 1e-9f) continue;
    EXPECT_GT(geometry::dot(face, mesh.normals[a] + mesh.normals[b] + mesh.normals[c]), 0) << "triangle " << k / 3;
  }
}

void expect_vec_near(Vec3 a, Vec3 b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

Segment segment(Vec3 start, Vec3 end, Vec3 up, float width, int color = 1, Provenance from = {}) {
  Segment s;
  s.start = start;
  s.end = end;
  s.up = up;
  s.start_width = s.end_width = width;
  s.color = color;
  s.from = from;
  return s;
}

// ---------------------------------------------------------------- tessellation

TEST(Tessellation, CylinderHasTwoRingsOfSidesAndOpenEnds) {
  Scene scene;
  scene.segments.push_back(segment({0, 0, 0}, {0, 2, 0}, {0, 0, 1}, 1, 2, {12, 0}));
  TriangleMesh mesh = tessellate(scene);
  // n = 8 sides: a ring of 8 at each end, 2 triangles per side, no caps.
  EXPECT_EQ(mesh.positions.size(), 16u);
  EXPECT_EQ(triangle_count(mesh), 16u);
  ASSERT_EQ(mesh.parts.size(), 1u);
  EXPECT_EQ(mesh.parts[0].kind, MeshPart::Kind::Segment);
  EXPECT_EQ(mesh.parts[0].color, 2);
  EXPECT_EQ(mesh.parts[0].from.module_index, 12u);
  EXPECT_TRUE(mesh.line_indices.empty());
  // The seam is at the turtle's left, as in lpfg's OBJ export (then round
  // toward up): left = up x heading = (-1, 0, 0), the first vertex at
  // start + left * radius.
  expect_vec_near(mesh.positions[0], {-0.5f, 0, 0});
  expect_vec_near(mesh.positions[2], {0, 0, 0.5f});  // a quarter turn on, at up
  // Side area of the inscribed octagonal prism: n * (2 r sin(pi/n)) * length.
  EXPECT_NEAR(part_area(mesh, mesh.parts[0]), 8 * (2 * 0.5 * std::sin(kPi / 8)) * 2, 1e-5);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    Vec3 p = mesh.positions[v];
    Vec3 radial{p.x, 0, p.z};
    EXPECT_NEAR(geometry::length(radial), 0.5f, 1e-6f);
    expect_vec_near(mesh.normals[v], radial / 0.5f);
  }
  expect_consistent_normals(mesh);
  geometry::Box box = mesh_bounds(mesh);
  expect_vec_near(box.min, {-0.5f, 0, -0.5f});
  expect_vec_near(box.max, {0.5f, 2, 0.5f});
}

TEST(Tessellation, TaperedCylinderNormalsLeanTowardTheNarrowEnd) {
  Scene scene;
  Segment s = segment({1, 1, 1}, {1, 1, 4}, {1, 0, 0}, 0);
  s.start_width = 2;  // radius 1 ...
  s.end_width = 1;    // ... to 0.5 over length 3
  scene.segments.push_back(s);
  TriangleMesh mesh = tessellate(scene, LineStyle::Cylinder, 6);
  ASSERT_EQ(mesh.positions.size(), 12u);
  EXPECT_EQ(triangle_count(mesh), 12u);
  // left = up x heading = (1, 0, 0) x (0, 0, 1) = (0, -1, 0): the seam.
  expect_vec_near(mesh.positions[0], {1, 0, 1});
  expect_vec_near(mesh.positions[6], {1, 0.5f, 4});
  for (std::uint32_t k = 0; k < 6; ++k) {
    Vec3 n = mesh.normals[k];
    Vec3 generator = mesh.positions[k + 6] - mesh.positions[k];
    EXPECT_NEAR(geometry::dot(n, generator), 0, 1e-5f);
    EXPECT_GT(n.z, 0);  // toward the narrow end
    Vec3 radial = mesh.positions[k] - Vec3{1, 1, 1};
    EXPECT_GT(geometry::dot(n, radial), 0);
    // tan of the lean = (r0 - r1) / length
    EXPECT_NEAR(n.z / std::sqrt(n.x * n.x + n.y * n.y), 0.5f / 3, 1e-5f);
  }
  // Frustum of a hexagonal pyramid: the mean perimeter times the slant height.
  double apothem0 = std::cos(kPi / 6), apothem1 = 0.5 * std::cos(kPi / 6);
  double slant = std::hypot(3.0, apothem0 - apothem1);
  double side0 = 2 * std::sin(kPi / 6), side1 = 2 * 0.5 * std::sin(kPi / 6);
  EXPECT_NEAR(part_area(mesh, mesh.parts[0]), 6 * (side0 + side1) / 2 * slant, 1e-4);
  expect_consistent_normals(mesh);
}

TEST(Tessellation, PolygonStyleIsAFlatStripFacingUp) {
  Scene scene;
  // Up is not perpendicular to the heading: only its perpendicular part counts.
  scene.segments.push_back(segment({0, 0, 0}, {0, 2, 0}, {0, 1, 1}, 1, 7, {3, 0}));
  TriangleMesh mesh = tessellate(scene, LineStyle::Polygon);
  EXPECT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(triangle_count(mesh), 2u);
  ASSERT_EQ(mesh.parts.size(), 1u);
  EXPECT_NEAR(part_area(mesh, mesh.parts[0]), 2.0, 1e-6);
  for (std::size_t v = 0; v < 4; ++v) {
    EXPECT_FLOAT_EQ(mesh.positions[v].z, 0);
    EXPECT_FLOAT_EQ(std::fabs(mesh.positions[v].x), 0.5f);
    expect_vec_near(mesh.normals[v], {0, 0, 1});
  }
  expect_consistent_normals(mesh);
  geometry::Box box = mesh_bounds(mesh);
  expect_vec_near(box.min, {-0.5f, 0, 0});
  expect_vec_near(box.max, {0.5f, 2, 0});
}

TEST(Tessellation, PixelStyleMakesLines) {
  Scene scene;
  scene.segments.push_back(segment({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 3, 4, {1, 0}));
  scene.segments.push_back(segment({1, 0, 0}, {1, 1, 0}, {0, 0, 1}, 3, 5, {3, 0}));
  TriangleMesh mesh = tessellate(scene, LineStyle::Pixel);
  EXPECT_TRUE(mesh.indices.empty());
  EXPECT_TRUE(mesh.parts.empty());
  EXPECT_EQ(mesh.positions.size(), 4u);
  ASSERT_EQ(mesh.line_indices.size(), 4u);
  ASSERT_EQ(mesh.line_parts.size(), 2u);
  EXPECT_EQ(mesh.line_parts[1].first_index, 2u);
  EXPECT_EQ(mesh.line_parts[1].index_count, 2u);
  EXPECT_EQ(mesh.line_parts[1].color, 5);
  expect_vec_near(mesh.positions[mesh.line_indices[3]], {1, 1, 0});
}

TEST(Tessellation, SkipsWhatDrawsNothing) {
  Scene scene;
  scene.segments.push_back(segment({1, 2, 3}, {1, 2, 3}, {0, 0, 1}, 1));  // zero length
  scene.segments.push_back(segment({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0));  // zero width
  Circle circle;
  circle.radius = 0;
  scene.circles.push_back(circle);
  Sphere sphere;
  sphere.radius = 0;
  scene.spheres.push_back(sphere);
  for (LineStyle style : {LineStyle::Cylinder, LineStyle::Polygon}) {
    TriangleMesh mesh = tessellate(scene, style);
    EXPECT_TRUE(mesh.positions.empty());
    EXPECT_TRUE(mesh.parts.empty());
  }
  // A zero-width line still shows as a pixel line; a zero-length one does not.
  TriangleMesh lines = tessellate(scene, LineStyle::Pixel);
  EXPECT_EQ(lines.line_parts.size(), 1u);
}

TEST(Tessellation, DiscAreaAndNormal) {
  for (int n : {3, 8, 13}) {
    Scene scene;
    Circle c;
    c.center = {1, 2, 3};
    c.normal = {0, 2, 0};  // not unit
    c.radius = 1;
    scene.circles.push_back(c);
    TriangleMesh mesh = tessellate(scene, LineStyle::Cylinder, n);
    EXPECT_EQ(mesh.positions.size(), static_cast<std::size_t>(n + 1));
    EXPECT_EQ(triangle_count(mesh), static_cast<std::size_t>(n));
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.parts[0].kind, MeshPart::Kind::Circle);
    EXPECT_NEAR(part_area(mesh, mesh.parts[0]), n / 2.0 * std::sin(2 * std::numbers::pi / n), 1e-5);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      EXPECT_FLOAT_EQ(mesh.positions[v].y, 2);
      expect_vec_near(mesh.normals[v], {0, 1, 0});
      if (v > 0) {
        EXPECT_NEAR(geometry::length(mesh.positions[v] - c.center), 1.0f, 1e-6f);
      }
    }
    expect_consistent_normals(mesh);
  }
}

TEST(Tessellation, ScreenFacingCircleFacesPlusZ) {
  Scene scene;
  Circle c;
  c.normal = {1, 0, 0};
  c.facing_viewer = true;
  c.radius = 2;
  scene.circles.push_back(c);
  TriangleMesh mesh = tessellate(scene);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    EXPECT_FLOAT_EQ(mesh.positions[v].z, 0);
    expect_vec_near(mesh.normals[v], {0, 0, 1});
  }
  expect_consistent_normals(mesh);
  geometry::Box box = mesh_bounds(mesh);
  EXPECT_NEAR(box.max.x, 2, 1e-6);
  EXPECT_NEAR(box.min.x, -2, 1e-6);
}

TEST(Tessellation, CircleOutlineIsAnAnnulus) {
  Scene scene;
  Circle c;
  c.normal = {0, 0, 1};
  c.radius = 1;
  c.outline = 0.5f;  // from radius 0.75 to 1.25
  scene.circles.push_back(c);
  TriangleMesh mesh = tessellate(scene, LineStyle::Cylinder, 8);
  EXPECT_EQ(mesh.positions.size(), 16u);
  EXPECT_EQ(triangle_count(mesh), 16u);
  EXPECT_NEAR(part_area(mesh, mesh.parts[0]), 4 * std::sin(2 * std::numbers::pi / 8) * (1.25 * 1.25 - 0.75 * 0.75), 1e-5);
  expect_consistent_normals(mesh);
  geometry::Box box = mesh_bounds(mesh);
  EXPECT_NEAR(box.max.x, 1.25, 1e-6);
}

TEST(Tessellation, UvSphereCountsAndOutwardNormals) {
  // n longitudinal, (n+1)/2 transversal sections: (stacks-1) rings of n and
  // two poles; n triangles at each pole and 2n per band between rings.
  for (auto [n, vertices, triangles] : {std::tuple{3, 5u, 6u}, {5, 12u, 20u}, {8, 26u, 48u}, {9, 38u, 72u}}) {
    Scene scene;
    Sphere s;
    s.center = {1, -2, 0.5f};
    s.radius = 0.5f;
    s.color = 9;
    s.from = {7, 3};
    scene.spheres.push_back(s);
    TriangleMesh mesh = tessellate(scene, LineStyle::Polygon, n);
    EXPECT_EQ(mesh.positions.size(), vertices) << n;
    EXPECT_EQ(triangle_count(mesh), triangles) << n;
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.parts[0].kind, MeshPart::Kind::Sphere);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      Vec3 out = mesh.positions[v] - s.center;
      EXPECT_NEAR(geometry::length(out), 0.5f, 1e-6f);
      expect_vec_near(mesh.normals[v], out / 0.5f);
    }
    expect_consistent_normals(mesh);
    // The poles on the y axis, as lpfg's OBJ export puts them.
    geometry::Box box = mesh_bounds(mesh);
    EXPECT_NEAR(box.min.y, -2.5f, 1e-6);
    EXPECT_NEAR(box.max.y, -1.5f, 1e-6);
    EXPECT_LE(box.max.x, 1.5f + 1e-6f);
    EXPECT_GE(box.min.z, 0 - 1e-6f);
  }
}

// lpfg's OBJ export of Sphere(1) at the origin with 4 slices (2 stacks),
// by hand from lpfg/objturtle.cpp: the poles (0, +-1, 0) and one ring on the
// equator starting at longitude -pi, (sin lon, 0, cos lon) = (0, 0, -1),
// then (-1, 0, 0), (0, 0, 1), (1, 0, 0). A sphere's own slices (the
// turtle's ContourSides) win over the view's contour sides.
TEST(Tessellation, SphereVerticesAsLpfgExportsThem) {
  Scene scene;
  Sphere s;
  s.slices = 4;
  scene.spheres.push_back(s);
  TriangleMesh mesh = tessellate(scene, LineStyle::Cylinder, 16);
  ASSERT_EQ(mesh.positions.size(), 6u);
  expect_vec_near(mesh.positions[0], {0, 1, 0});
  expect_vec_near(mesh.positions[1], {0, 0, -1});
  expect_vec_near(mesh.positions[2], {-1, 0, 0});
  expect_vec_near(mesh.positions[3], {0, 0, 1});
  expect_vec_near(mesh.positions[4], {1, 0, 0});
  expect_vec_near(mesh.positions[5], {0, -1, 0});
  EXPECT_EQ(triangle_count(mesh), 8u);
  expect_consistent_normals(mesh);
}

TEST(Tessellation, TriangleGroupsAreCopiedWithOwnVertices) {
  Scene scene;
  // Two triangles sharing the pool's vertices 1 and 2; one normal missing.
  scene.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  scene.normals = {{0, 0, 1}, {0, 0, 2}, {0, 0, 0}, {0, 0, 1}};
  scene.indices = {0, 1, 2, 1, 3, 2};
  scene.groups.push_back({geometry::TriangleGroup::Kind::Surface, 0, 3, 4, {5, 1}});
  scene.groups.push_back({geometry::TriangleGroup::Kind::Rhombus, 3, 3, 6, {6, 2}});
  TriangleMesh mesh = tessellate(scene);
  EXPECT_EQ(mesh.positions.size(), 6u);
  EXPECT_EQ(triangle_count(mesh), 2u);
  ASSERT_EQ(mesh.parts.size(), 2u);
  EXPECT_EQ(mesh.parts[0].kind, MeshPart::Kind::Surface);
  EXPECT_EQ(mesh.parts[1].kind, MeshPart::Kind::Rhombus);
  EXPECT_EQ(mesh.parts[1].color, 6);
  EXPECT_EQ(mesh.parts[1].from.module_index, 6u);
  EXPECT_EQ(part_vertices(mesh, mesh.parts[0]), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(part_vertices(mesh, mesh.parts[1]), (std::vector<std::uint32_t>{3, 4, 5}));
  EXPECT_NEAR(part_area(mesh, mesh.parts[0]) + part_area(mesh, mesh.parts[1]), 1.0, 1e-6);
  for (Vec3 n : mesh.normals) expect_vec_near(n, {0, 0, 1});
  expect_consistent_normals(mesh);
}

TEST(Tessellation, PartsComeInStringOrder) {
  Scene scene;
  scene.segments.push_back(segment({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1, 1, {2, 0}));
  scene.segments.push_back(segment({0, 1, 0}, {0, 2, 0}, {0, 0, 1}, 1, 1, {9, 0}));
  Sphere s;
  s.from = {5, 2};
  scene.spheres.push_back(s);
  Circle c;
  c.normal = {0, 0, 1};
  c.from = {1, 1};
  scene.circles.push_back(c);
  TriangleMesh mesh = tessellate(scene);
  ASSERT_EQ(mesh.parts.size(), 4u);
  std::vector<std::uint32_t> order;
  for (const MeshPart& p : mesh.parts) order.push_back(p.from.module_index);
  EXPECT_EQ(order, (std::vector<std::uint32_t>{1, 2, 5, 9}));
}

TEST(Tessellation, KindNamesAndFewestSides) {
  EXPECT_STREQ(geometry::kind_name(MeshPart::Kind::Segment), "segment");
  EXPECT_STREQ(geometry::kind_name(MeshPart::Kind::GeneralizedCylinder), "generalized_cylinder");
  EXPECT_STREQ(geometry::kind_name(MeshPart::Kind::Sphere), "sphere");
  Scene scene;
  scene.segments.push_back(segment({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1));
  EXPECT_EQ(tessellate(scene, LineStyle::Cylinder, 1).positions.size(), 6u);  // at least a triangle
}

// ---------------------------------------------------------------- mesh files

struct Sample {
  Scene scene;
  TriangleMesh mesh;
  geometry::Palette palette;
  ModuleTypes types{{{"F", 4, nullptr}, {"Circle", 4, nullptr}, {"Sphere", 4, nullptr}, {"Polygon", 0, nullptr}}};
};

// A cylinder (colour 2, F at 12), a disc (colour 3, Circle at 14), a sphere
// (colour 3, Sphere at 20) and a triangle (colour 5, Polygon at 30), n = 8:
// 16 + 9 + 26 + 3 = 54 vertices, 16 + 8 + 48 + 1 = 73 triangles.
Sample sample() {
  Sample s;
  s.scene.segments.push_back(segment({0, 0, 0}, {0, 2, 0}, {0, 0, 1}, 1, 2, {12, 0}));
  Circle c;
  c.center = {3, 0, 0};
  c.normal = {0, 0, 1};
  c.color = 3;
  c.from = {14, 1};
  s.scene.circles.push_back(c);
  Sphere sphere;
  sphere.center = {0, 5, 0};
  sphere.radius = 0.5f;
  sphere.color = 3;
  sphere.from = {20, 2};
  s.scene.spheres.push_back(sphere);
  s.scene.add_triangles(geometry::TriangleGroup::Kind::Polygon, {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}},
                        {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, {0, 1, 2}, 5, {30, 3});
  s.mesh = tessellate(s.scene);
  s.palette.entries[2].diffuse = {0.2f, 0.6f, 0.1f};
  s.palette.entries[3].diffuse = {0.9f, 0.1f, 0.1f};
  s.palette.entries[3].transparency = 0.25f;
  s.palette.entries[3].emission = {0.5f, 0, 0};
  s.palette.entries[5].diffuse = {0.1f, 0.2f, 0.9f};
  s.palette.entries[5].shininess = 40;
  return s;
}

// Two pixel lines of colour 4: F at 1 and F at 3.
Sample line_sample() {
  Sample s;
  s.scene.segments.push_back(segment({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 1, 4, {1, 0}));
  s.scene.segments.push_back(segment({1, 0, 0}, {1, 1, 0}, {0, 0, 1}, 1, 4, {3, 0}));
  s.mesh = tessellate(s.scene, LineStyle::Pixel);
  s.palette.entries[4].diffuse = {1, 0.5f, 0};
  return s;
}

void collect_nodes(const aiNode* node, std::map<std::string, std::vector<unsigned>>& out) {
  for (unsigned k = 0; k < node->mNumMeshes; ++k) out[node->mName.C_Str()].push_back(node->mMeshes[k]);
  for (unsigned k = 0; k < node->mNumChildren; ++k) collect_nodes(node->mChildren[k], out);
}

std::string material_name(const aiScene* scene, unsigned mesh) {
  aiString name;
  scene->mMaterials[scene->mMeshes[mesh]->mMaterialIndex]->Get(AI_MATKEY_NAME, name);
  return name.C_Str();
}

const aiMaterial* find_material(const aiScene* scene, const std::string& name) {
  for (unsigned k = 0; k < scene->mNumMaterials; ++k) {
    aiString n;
    scene->mMaterials[k]->Get(AI_MATKEY_NAME, n);
    if (name == n.C_Str()) return scene->mMaterials[k];
  }
  return nullptr;
}

void expect_rgb(const aiMaterial* m, const char* key, unsigned type, unsigned index, geometry::Rgb rgb) {
  ASSERT_NE(m, nullptr);
  aiColor3D c;
  ASSERT_EQ(m->Get(key, type, index, c), aiReturn_SUCCESS) << key;
  EXPECT_NEAR(c.r, rgb.r, 1e-6);
  EXPECT_NEAR(c.g, rgb.g, 1e-6);
  EXPECT_NEAR(c.b, rgb.b, 1e-6);
}

std::vector<std::string> directory_listing(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(MeshObj, ReadsBackWithGroupsAndMaterials) {
  Sample s = sample();
  std::string dir = test::make_temp_dir("mesh-obj");
  std::string path = dir + "/plant.obj";
  io::write_obj(path, s.mesh, s.palette, s.types);
  EXPECT_EQ(directory_listing(dir), (std::vector<std::string>{"plant.mtl", "plant.obj"}));
  EXPECT_NE(test::read_text(path).find("mtllib plant.mtl\n"), std::string::npos);

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  std::size_t faces = 0;
  for (unsigned k = 0; k < scene->mNumMeshes; ++k) {
    faces += scene->mMeshes[k]->mNumFaces;
    ASSERT_TRUE(scene->mMeshes[k]->HasNormals());
    for (unsigned f = 0; f < scene->mMeshes[k]->mNumFaces; ++f) EXPECT_EQ(scene->mMeshes[k]->mFaces[f].mNumIndices, 3u);
  }
  EXPECT_EQ(faces, 73u);

  // One group per primitive, named Module_index, with the primitive's material.
  std::map<std::string, std::vector<unsigned>> nodes;
  collect_nodes(scene->mRootNode, nodes);
  std::map<std::string, std::pair<unsigned, std::string>> expected = {
      {"F_12", {16, "color_2"}}, {"Circle_14", {8, "color_3"}}, {"Sphere_20", {48, "color_3"}}, {"Polygon_30", {1, "color_5"}}};
  for (const auto& [group, what] : expected) {
    ASSERT_EQ(nodes[group].size(), 1u) << group;
    unsigned mesh = nodes[group][0];
    EXPECT_EQ(scene->mMeshes[mesh]->mNumFaces, what.first) << group;
    EXPECT_EQ(material_name(scene, mesh), what.second) << group;
  }

  const aiMaterial* red = find_material(scene, "color_3");
  expect_rgb(red, AI_MATKEY_COLOR_DIFFUSE, {0.9f, 0.1f, 0.1f});
  expect_rgb(red, AI_MATKEY_COLOR_EMISSIVE, {0.5f, 0, 0});
  expect_rgb(red, AI_MATKEY_COLOR_AMBIENT, {0.2f, 0.2f, 0.2f});
  float opacity = 0;
  ASSERT_EQ(red->Get(AI_MATKEY_OPACITY, opacity), aiReturn_SUCCESS);
  EXPECT_NEAR(opacity, 0.75f, 1e-6f);
  const aiMaterial* blue = find_material(scene, "color_5");
  expect_rgb(blue, AI_MATKEY_COLOR_DIFFUSE, {0.1f, 0.2f, 0.9f});
  float shininess = 0;
  ASSERT_EQ(blue->Get(AI_MATKEY_SHININESS, shininess), aiReturn_SUCCESS);
  EXPECT_FLOAT_EQ(shininess, 40);
  expect_rgb(find_material(scene, "color_2"), AI_MATKEY_COLOR_DIFFUSE, {0.2f, 0.6f, 0.1f});
  EXPECT_EQ(find_material(scene, "color_1"), nullptr);  // only colours in use
}

TEST(MeshObj, PixelLinesAreLineElements) {
  Sample s = line_sample();
  std::string dir = test::make_temp_dir("mesh-obj-lines");
  std::string path = dir + "/lines.obj";
  io::write_obj(path, s.mesh, s.palette, s.types);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  std::map<std::string, std::vector<unsigned>> nodes;
  collect_nodes(scene->mRootNode, nodes);
  for (const char* group : {"F_1", "F_3"}) {
    ASSERT_EQ(nodes[group].size(), 1u) << group;
    const aiMesh* mesh = scene->mMeshes[nodes[group][0]];
    ASSERT_EQ(mesh->mNumFaces, 1u);
    EXPECT_EQ(mesh->mFaces[0].mNumIndices, 2u);
    EXPECT_EQ(mesh->mPrimitiveTypes, unsigned{aiPrimitiveType_LINE});
    EXPECT_EQ(material_name(scene, nodes[group][0]), "color_4");
  }
  expect_rgb(find_material(scene, "color_4"), AI_MATKEY_COLOR_DIFFUSE, {1, 0.5f, 0});
}

// A binary PLY read by hand: assimp keeps no unknown face properties.
struct PlyFile {
  struct Property {
    std::string name, type, count_type;  // count_type: list properties only
  };
  struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
    std::vector<std::map<std::string, double>> records;
    std::vector<std::vector<std::int64_t>> lists;
  };
  std::vector<std::string> comments;
  std::vector<Element> elements;

  const Element* element(const std::string& name) const {
    for (const Element& e : elements)
      if (e.name == name) return &e;
    return nullptr;
  }

  static double read(std::istream& in, const std::string& type) {
    auto get = [&](auto value) {
      in.read(reinterpret_cast<char*>(&value), sizeof value);
      return static_cast<double>(value);
    };
    if (type == "uchar") return get(std::uint8_t{});
    if (type == "ushort") return get(std::uint16_t{});
    if (type == "int") return get(std::int32_t{});
    if (type == "uint") return get(std::uint32_t{});
    if (type == "float") return get(float{});
    ADD_FAILURE() << "unexpected PLY type " << type;
    return 0;
  }

  explicit PlyFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "ply");
    std::getline(in, line);
    EXPECT_EQ(line, "format binary_little_endian 1.0");
    while (std::getline(in, line) && line != "end_header") {
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      if (keyword == "comment") {
        comments.push_back(line.substr(8));
      } else if (keyword == "element") {
        elements.emplace_back();
        words >> elements.back().name >> elements.back().count;
      } else if (keyword == "property") {
        Property p;
        words >> p.type;
        if (p.type == "list") words >> p.count_type >> p.type;
        words >> p.name;
        elements.back().properties.push_back(p);
      }
    }
    for (Element& e : elements) {
      for (std::size_t r = 0; r < e.count; ++r) {
        std::map<std::string, double> record;
        std::vector<std::int64_t> list;
        for (const Property& p : e.properties) {
          if (p.count_type.empty()) {
            record[p.name] = read(in, p.type);
          } else {
            auto n = static_cast<std::size_t>(read(in, p.count_type));
            for (std::size_t k = 0; k < n; ++k) list.push_back(static_cast<std::int64_t>(read(in, p.type)));
          }
        }
        e.records.push_back(std::move(record));
        e.lists.push_back(std::move(list));
      }
    }
    EXPECT_TRUE(in.good());
    EXPECT_EQ(in.peek(), std::char_traits<char>::eof()) << "bytes after the last element";
  }
};

TEST(MeshPly, ReadsBackWithColoursAndFaceProvenance) {
  Sample s = sample();
  std::string dir = test::make_temp_dir("mesh-ply");
  std::string path = dir + "/plant.ply";
  io::write_ply(path, s.mesh, s.palette, s.types);

  PlyFile ply(path);
  const PlyFile::Element* vertices = ply.element("vertex");
  const PlyFile::Element* faces = ply.element("face");
  ASSERT_TRUE(vertices && faces);
  EXPECT_EQ(ply.element("edge"), nullptr);
  EXPECT_EQ(vertices->count, 54u);
  ASSERT_EQ(faces->count, 73u);
  // Faces in part order: 16 of F at 12, 8 of Circle at 14, 48 of Sphere at 20, 1 of Polygon at 30.
  for (std::size_t f = 0; f < 73; ++f) {
    auto [index, id] = f < 16 ? std::pair{12, 0} : f < 24 ? std::pair{14, 1} : f < 72 ? std::pair{20, 2} : std::pair{30, 3};
    EXPECT_EQ(faces->records[f].at("module_index"), index) << f;
    EXPECT_EQ(faces->records[f].at("module_id"), id) << f;
    ASSERT_EQ(faces->lists[f].size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(faces->lists[f][k], s.mesh.indices[3 * f + k]);
  }
  for (const char* comment : {"module 0 F", "module 1 Circle", "module 2 Sphere", "module 3 Polygon"})
    EXPECT_NE(std::find(ply.comments.begin(), ply.comments.end(), comment), ply.comments.end()) << comment;
  // The first vertex is the cylinder's: colour 2, seam at the turtle's left (-x).
  EXPECT_EQ(vertices->records[0].at("red"), std::lround(0.2 * 255));
  EXPECT_EQ(vertices->records[0].at("green"), std::lround(0.6 * 255));
  EXPECT_EQ(vertices->records[0].at("alpha"), 255);
  EXPECT_FLOAT_EQ(vertices->records[0].at("nx"), -1);

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  ASSERT_EQ(scene->mNumMeshes, 1u);
  const aiMesh* mesh = scene->mMeshes[0];
  EXPECT_EQ(mesh->mNumFaces, 73u);
  ASSERT_TRUE(mesh->HasNormals());
  ASSERT_TRUE(mesh->HasVertexColors(0));
  // Every corner of a face carries its part's colour and a unit normal.
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    geometry::Rgb rgb = f < 16 ? geometry::Rgb{0.2f, 0.6f, 0.1f} : f < 72 ? geometry::Rgb{0.9f, 0.1f, 0.1f} : geometry::Rgb{0.1f, 0.2f, 0.9f};
    float alpha = f >= 16 && f < 72 ? 0.75f : 1;
    for (unsigned k = 0; k < mesh->mFaces[f].mNumIndices; ++k) {
      unsigned v = mesh->mFaces[f].mIndices[k];
      const aiColor4D& c = mesh->mColors[0][v];
      EXPECT_NEAR(c.r, rgb.r, 1.0 / 255);
      EXPECT_NEAR(c.g, rgb.g, 1.0 / 255);
      EXPECT_NEAR(c.b, rgb.b, 1.0 / 255);
      EXPECT_NEAR(c.a, alpha, 1.0 / 255);
      EXPECT_NEAR(mesh->mNormals[v].Length(), 1, 1e-5);
    }
  }
}

TEST(MeshPly, PixelLinesAreEdges) {
  Sample s = line_sample();
  std::string path = test::make_temp_dir("mesh-ply-lines") + "/lines.ply";
  io::write_ply(path, s.mesh, s.palette, s.types);
  PlyFile ply(path);
  ASSERT_NE(ply.element("edge"), nullptr);
  const PlyFile::Element& edges = *ply.element("edge");
  ASSERT_EQ(edges.count, 2u);
  EXPECT_EQ(ply.element("face")->count, 0u);
  EXPECT_EQ(edges.records[0].at("module_index"), 1);
  EXPECT_EQ(edges.records[1].at("module_index"), 3);
  EXPECT_EQ(edges.records[1].at("vertex1"), 2);
  EXPECT_EQ(edges.records[1].at("vertex2"), 3);
  EXPECT_EQ(ply.element("vertex")->records[3].at("green"), std::lround(0.5 * 255));
}

double linear(double srgb) { return srgb <= 0.04045 ? srgb / 12.92 : std::pow((srgb + 0.055) / 1.055, 2.4); }

struct ProvenanceRecord {
  std::uint32_t first, count, module_index, module_id;
  bool operator==(const ProvenanceRecord&) const = default;
};

std::vector<ProvenanceRecord> provenance(const tinygltf::Model& model, const tinygltf::Primitive& primitive) {
  const tinygltf::Value& p = primitive.extras.Get("sylva_provenance");
  EXPECT_TRUE(p.IsObject());
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(p.Get("bufferView").GetNumberAsInt()));
  auto count = static_cast<std::size_t>(p.Get("count").GetNumberAsInt());
  EXPECT_EQ(view.byteLength, count * sizeof(ProvenanceRecord));
  std::vector<ProvenanceRecord> records(count);
  std::memcpy(records.data(), model.buffers.at(static_cast<std::size_t>(view.buffer)).data.data() + view.byteOffset,
              count * sizeof(ProvenanceRecord));
  return records;
}

std::size_t accessor_count(const tinygltf::Model& model, int accessor) {
  return model.accessors.at(static_cast<std::size_t>(accessor)).count;
}

tinygltf::Model load_glb(const std::string& path) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
  EXPECT_EQ(error, "");
  EXPECT_EQ(warning, "");
  return model;
}

TEST(MeshGlb, ReadsBackWithMaterialsAndProvenance) {
  Sample s = sample();
  std::string path = test::make_temp_dir("mesh-glb") + "/plant.glb";
  io::write_glb(path, s.mesh, s.palette, s.types);
  tinygltf::Model model = load_glb(path);

  ASSERT_EQ(model.materials.size(), 3u);
  std::map<std::string, const tinygltf::Material*> materials;
  for (const auto& m : model.materials) materials[m.name] = &m;
  ASSERT_TRUE(materials.count("color_2") && materials.count("color_3") && materials.count("color_5"));
  const auto& green = materials["color_2"]->pbrMetallicRoughness.baseColorFactor;
  ASSERT_EQ(green.size(), 4u);
  EXPECT_NEAR(green[0], linear(0.2f), 1e-6);
  EXPECT_NEAR(green[1], linear(0.6f), 1e-6);
  EXPECT_NEAR(green[2], linear(0.1f), 1e-6);
  EXPECT_EQ(green[3], 1);
  EXPECT_EQ(materials["color_2"]->alphaMode, "OPAQUE");
  const tinygltf::Material& red = *materials["color_3"];
  EXPECT_NEAR(red.pbrMetallicRoughness.baseColorFactor[3], 0.75, 1e-6);
  EXPECT_EQ(red.alphaMode, "BLEND");
  ASSERT_EQ(red.emissiveFactor.size(), 3u);
  EXPECT_NEAR(red.emissiveFactor[0], linear(0.5), 1e-6);
  EXPECT_EQ(red.emissiveFactor[1], 0);
  EXPECT_TRUE(red.doubleSided);

  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.nodes.size(), 1u);
  const tinygltf::Mesh& mesh = model.meshes[0];
  const tinygltf::Value& names = mesh.extras.Get("sylva_module_names");
  ASSERT_EQ(names.ArrayLen(), 4u);
  EXPECT_EQ(names.Get(1).Get<std::string>(), "Circle");
  EXPECT_EQ(names.Get(3).Get<std::string>(), "Polygon");

  // One primitive per colour, in colour order.
  ASSERT_EQ(mesh.primitives.size(), 3u);
  struct Expected {
    const char* material;
    std::size_t vertices, triangles;
    std::vector<ProvenanceRecord> records;
  };
  std::vector<Expected> expected = {
      {"color_2", 16, 16, {{0, 16, 12, 0}}},
      {"color_3", 9 + 26, 8 + 48, {{0, 8, 14, 1}, {8, 48, 20, 2}}},
      {"color_5", 3, 1, {{0, 1, 30, 3}}},
  };
  for (std::size_t k = 0; k < 3; ++k) {
    const tinygltf::Primitive& p = mesh.primitives[k];
    EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
    EXPECT_EQ(model.materials.at(static_cast<std::size_t>(p.material)).name, expected[k].material);
    EXPECT_EQ(accessor_count(model, p.attributes.at("POSITION")), expected[k].vertices);
    EXPECT_EQ(accessor_count(model, p.attributes.at("NORMAL")), expected[k].vertices);
    EXPECT_EQ(accessor_count(model, p.indices), 3 * expected[k].triangles);
    EXPECT_EQ(provenance(model, p), expected[k].records);
  }
  // The cylinder's bounds, as glTF requires them on positions.
  const tinygltf::Accessor& cylinder = model.accessors.at(static_cast<std::size_t>(mesh.primitives[0].attributes.at("POSITION")));
  ASSERT_EQ(cylinder.minValues.size(), 3u);
  EXPECT_NEAR(cylinder.minValues[0], -0.5, 1e-6);
  EXPECT_NEAR(cylinder.minValues[1], 0, 1e-6);
  EXPECT_NEAR(cylinder.maxValues[1], 2, 1e-6);
  EXPECT_NEAR(cylinder.maxValues[2], 0.5, 1e-6);

  // A second reader agrees on what is in the file.
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  std::size_t faces = 0, vertices = 0;
  for (unsigned k = 0; k < scene->mNumMeshes; ++k) {
    faces += scene->mMeshes[k]->mNumFaces;
    vertices += scene->mMeshes[k]->mNumVertices;
  }
  EXPECT_EQ(faces, 73u);
  EXPECT_EQ(vertices, 54u);
}

TEST(MeshGlb, PixelLinesAreLinePrimitives) {
  Sample s = line_sample();
  std::string path = test::make_temp_dir("mesh-glb-lines") + "/lines.glb";
  io::write_glb(path, s.mesh, s.palette, s.types);
  tinygltf::Model model = load_glb(path);
  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
  const tinygltf::Primitive& p = model.meshes[0].primitives[0];
  EXPECT_EQ(p.mode, TINYGLTF_MODE_LINE);
  EXPECT_EQ(accessor_count(model, p.indices), 4u);
  EXPECT_EQ(provenance(model, p), (std::vector<ProvenanceRecord>{{0, 1, 1, 0}, {1, 1, 3, 0}}));
}

TEST(MeshGlb, EmptyMeshIsAValidFile) {
  Sample s;
  std::string path = test::make_temp_dir("mesh-glb-empty") + "/empty.glb";
  io::write_glb(path, s.mesh, s.palette, s.types);
  tinygltf::Model model = load_glb(path);
  EXPECT_TRUE(model.meshes.empty());
  EXPECT_EQ(model.scenes.size(), 1u);
}

TEST(MeshWriters, UnwritablePathThrowsAndLeavesNoFile) {
  Sample s = sample();
  using Writer = void (*)(const std::string&, const TriangleMesh&, const geometry::Palette&, const ModuleTypes&);
  const Writer glb = [](const std::string& path, const TriangleMesh& mesh, const geometry::Palette& palette,
                        const ModuleTypes& types) { io::write_glb(path, mesh, palette, types); };
  for (auto [name, write] : {std::pair<const char*, Writer>{"obj", io::write_obj}, {"ply", io::write_ply}, {"glb", glb}}) {
    std::string dir = test::make_temp_dir(std::string("mesh-unwritable-") + name);
    // A missing directory, and a directory where the file should go.
    std::string missing = dir + "/missing/plant." + name;
    std::string blocked = dir + "/plant." + name;
    fs::create_directory(blocked);
    for (const std::string& path : {missing, blocked}) {
      try {
        write(path, s.mesh, s.palette, s.types);
        ADD_FAILURE() << "no error writing " << path;
      } catch (const ModelError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      }
      EXPECT_EQ(directory_listing(dir), (std::vector<std::string>{std::string("plant.") + name})) << path;
      EXPECT_TRUE(fs::is_empty(blocked));
    }
  }
}

// Thousands of primitives: one primitive per colour keeps the glTF's JSON
// small, and every part's provenance comes back.
TEST(MeshGlb, ManyPrimitivesStayCompact) {
  Sample s;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-10, 10);
  const int count = 20000;
  for (int k = 0; k < count; ++k) {
    Vec3 a{coordinate(random), coordinate(random), coordinate(random)};
    s.scene.segments.push_back(segment(a, a + Vec3{0, 1, 0}, {0, 0, 1}, 0.1f, 1 + k % 4,
                                       {static_cast<std::uint32_t>(2 * k), 0}));
  }
  s.mesh = tessellate(s.scene, LineStyle::Cylinder, 6);
  std::string path = test::make_temp_dir("mesh-glb-many") + "/many.glb";
  io::write_glb(path, s.mesh, s.palette, s.types);
  tinygltf::Model model = load_glb(path);
  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.meshes[0].primitives.size(), 4u);
  std::size_t records = 0, triangles = 0;
  for (const tinygltf::Primitive& p : model.meshes[0].primitives) {
    auto r = provenance(model, p);
    records += r.size();
    triangles += accessor_count(model, p.indices) / 3;
    for (std::size_t k = 0; k < r.size(); ++k) {
      EXPECT_EQ(r[k].first, 12 * k);
      EXPECT_EQ(r[k].count, 12u);
    }
  }
  EXPECT_EQ(records, static_cast<std::size_t>(count));
  EXPECT_EQ(triangles, 12u * count);
  // The JSON chunk's length, from the GLB header: no per-part JSON.
  std::ifstream in(path, std::ios::binary);
  std::uint32_t header[5];
  in.read(reinterpret_cast<char*>(header), sizeof header);
  EXPECT_LT(header[3], 16384u);
}

}  // namespace
}  // namespace sylva
