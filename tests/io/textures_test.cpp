// Textures (LPFG manual 5.9, 8.1.5; CPFG manual 6.7.4, 8.1.7): the view
// file's texture: commands, the texture coordinates the turtle gives
// cylinder lines, surfaces and cpfg's polygons, and the images in PNG
// renders and glTF files.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "export/mesh_writers.h"
#include "export/tiny_gltf_setup.h"
#include "geometry/patch_mesh.h"
#include "geometry/tessellation.h"
#include "inputs/view_file.h"
#include "io/texture_image.h"
#include "render/png_renderer.h"
#include "support/diagnostic.h"
#include "test_support.h"
#include "turtle/turtle_fixture.h"

namespace sylva::test {
namespace {

using geometry::Scene;
using geometry::TexCoord;
using geometry::Vec3;

void expect_texcoord(TexCoord actual, TexCoord expected) {
  EXPECT_NEAR(actual.u, expected.u, 1e-5f);
  EXPECT_NEAR(actual.v, expected.v, 1e-5f);
}

// A 2 x 1 texture: red on the left, green on the right.
io::TextureImage red_green() {
  io::TextureImage image;
  image.width = 2;
  image.height = 1;
  image.rgba = {255, 0, 0, 255, 0, 255, 0, 255};
  return image;
}

// lpfg's "texture: file" and cpfg's "texture: F: file E: ... H: ... L: ...",
// and cpfg's surface texture file, numbered after the texture: commands.
TEST(Textures, ViewFileTexturesInBothForms) {
  const std::string dir = make_temp_dir("textures-view");
  std::ofstream(dir + "/v.v") << "texture: bark.png\n"
                                 "texture: F: light.rgb H: l L: mll\n"
                                 "texture: E: decal F: leaf.rgb\n"
                                 "surface: l leaf.s 1.5 petal.rgb\n";
  const io::ViewFile view = io::read_view_file(dir + "/v.v", "", io::ViewDialect::Cpfg);
  ASSERT_EQ(view.textures.size(), 4u);
  EXPECT_EQ(view.textures[0], dir + "/bark.png");
  EXPECT_EQ(view.textures[1], dir + "/light.rgb");
  EXPECT_EQ(view.textures[2], dir + "/leaf.rgb");
  EXPECT_EQ(view.textures[3], dir + "/petal.rgb");
  ASSERT_EQ(view.surfaces.size(), 1u);
  EXPECT_EQ(view.surfaces[0].texture, 3);
  ASSERT_EQ(view.warnings.size(), 1u);  // E: decal is not used
  EXPECT_NE(view.warnings[0].find("E: decal ignored"), std::string::npos) << view.warnings[0];
}

// lpfg (gencyltrtl.cpp): a textured cylinder line's v runs from where the
// last one stopped by TextureVCoeff per unit, starting again below 1: F(2)
// with 0.25 covers 0 .. 0.5, F(3) 0.5 .. 1.25, the next starts at 0.25.
TEST(Textures, CylinderLinesCarryTheTexturesV) {
  Scene s = turtle_tests::draw("texture-v", "CurrentTexture(0) TextureVCoeff(0.25) F(2) F(3) F(1) CurrentTexture(-1) F(1)");
  ASSERT_EQ(s.segments.size(), 4u);
  EXPECT_EQ(s.segments[0].texture, 0);
  EXPECT_FLOAT_EQ(s.segments[0].texture_v0, 0);
  EXPECT_FLOAT_EQ(s.segments[0].texture_v1, 0.5f);
  EXPECT_FLOAT_EQ(s.segments[1].texture_v0, 0.5f);
  EXPECT_FLOAT_EQ(s.segments[1].texture_v1, 1.25f);
  EXPECT_FLOAT_EQ(s.segments[2].texture_v0, 0.25f);
  EXPECT_EQ(s.segments[3].texture, -1);
  // Tessellated with 4 sides: the seam twice (u = 0 and 1), 5 vertices a ring.
  Scene one;
  one.segments.push_back(s.segments[1]);
  geometry::TriangleMesh mesh = geometry::tessellate(one, {geometry::LineStyle::Cylinder, 4});
  ASSERT_EQ(mesh.positions.size(), 10u);
  ASSERT_EQ(mesh.texcoords.size(), 10u);
  expect_texcoord(mesh.texcoords[0], {0, 0.5f});
  expect_texcoord(mesh.texcoords[2], {0.5f, 0.5f});
  expect_texcoord(mesh.texcoords[4], {1, 0.5f});
  expect_texcoord(mesh.texcoords[9], {1, 1.25f});
  EXPECT_EQ(mesh.positions[0], mesh.positions[4]);
  ASSERT_EQ(mesh.parts.size(), 1u);
  EXPECT_EQ(mesh.parts[0].texture, 0);
}

// lpfg (patch.cpp) maps a texture once per patch at (v, 1 - u).
TEST(Textures, PatchesMapTheTextureOncePerPatch) {
  geometry::BezierPatch flat;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) flat.points[static_cast<std::size_t>(4 * r + c)] = {static_cast<float>(c), static_cast<float>(r), 0};
  Scene s;
  geometry::append_patch(s, flat, geometry::Placement{}, 2, 2, true);
  ASSERT_EQ(s.texcoords.size(), 9u);
  expect_texcoord(s.texcoords[0], {0, 1});    // u = 0, v = 0
  expect_texcoord(s.texcoords[2], {0, 0});    // u = 1, v = 0
  expect_texcoord(s.texcoords[6], {1, 1});    // u = 0, v = 1
  expect_texcoord(s.texcoords[4], {0.5f, 0.5f});
}

// cpfg (textures.c SetPolygonTextureParams): s along the first vertex's
// right, t along its heading, each over the polygon's extent. A square from
// the origin up 10 and right 10: (x, y) / 10.
TEST(Textures, CpfgPolygonsAcrossTheirExtent) {
  const std::string dir = make_temp_dir("textures-cpfg-polygon");
  std::ofstream(dir + "/p.l") << "Lsystem: 1\nderivation length: 0\nAxiom: @Tx(1){.f(10)-.f(10)-.f(10)-.f(10)-.}\nendlsystem\n";
  std::ofstream(dir + "/p.v") << "angle factor: 4\ntexture: F: t.rgb\n";
  build::BuildOptions build;
  build.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation sim(dir + "/p.l", SimulationOptions{build, {dir + "/p.v"}});
  sim.run(0);
  const Scene s = sim.scene();
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].texture, 0);  // @Tx(1): the first texture
  int checked = 0;
  for (std::uint32_t k = 0; k < s.positions.size(); ++k) {
    const Vec3 p = s.positions[k];
    expect_texcoord(s.texcoord(k), {p.x / 10, p.y / 10});
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

// A square textured red | green: its left half red, its right half green
// in the image (modulating white).
TEST(Textures, PngRendersTheTextureModulatingTheColour) {
  Scene s;
  s.add_triangles(geometry::TriangleGroup::Kind::Polygon, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
                  {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, {0, 1, 2, 0, 2, 3}, 1, {});
  s.groups[0].texture = 0;
  for (std::uint32_t k = 0; k < 4; ++k) s.set_texcoord(k, {k == 1 || k == 2 ? 1.0f : 0.0f, k >= 2 ? 1.0f : 0.0f});
  geometry::ViewParameters view;
  view.box = geometry::Box{{-1, -1, -1}, {1, 1, 1}};
  io::ImageSettings settings;
  settings.textures = {red_green()};
  const io::Image image = io::render_image(s, geometry::Palette::default_palette(), view, settings, 40, 40);
  EXPECT_EQ(image.pixel(12, 20), (std::array<std::uint8_t, 3>{255, 0, 0}));
  EXPECT_EQ(image.pixel(28, 20), (std::array<std::uint8_t, 3>{0, 255, 0}));
}

// glTF: the image embedded as PNG, the material's base colour texture, and
// TEXCOORD_0 with v turned to run down the image.
TEST(Textures, GlbEmbedsTheImageAndTexCoords) {
  Scene s;
  s.add_triangles(geometry::TriangleGroup::Kind::Polygon, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                  {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, {0, 1, 2}, 2, {});
  s.groups[0].texture = 0;
  s.set_texcoord(0, {0, 0});
  s.set_texcoord(1, {1, 0});
  s.set_texcoord(2, {0, 1});
  const geometry::TriangleMesh mesh = geometry::tessellate(s, {});
  const std::string path = make_temp_dir("textures-glb") + "/t.glb";
  ModuleTypes types{{{"Polygon", 0, nullptr}}};
  io::write_glb(path, mesh, geometry::Palette::default_palette(), types, {red_green()});
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  // The image bytes are checked below; nothing to decode here.
  loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                           void*) { return true; },
                        nullptr);
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
  ASSERT_EQ(model.images.size(), 1u);
  EXPECT_EQ(model.images[0].mimeType, "image/png");
  // The embedded bytes are the texture as PNG.
  const tinygltf::BufferView& image_view = model.bufferViews.at(static_cast<std::size_t>(model.images[0].bufferView));
  const auto* bytes = model.buffers[0].data.data() + image_view.byteOffset;
  const std::string png_path = make_temp_dir("textures-glb-image") + "/t.png";
  std::ofstream(png_path, std::ios::binary).write(reinterpret_cast<const char*>(bytes),
                                                  static_cast<std::streamsize>(image_view.byteLength));
  EXPECT_EQ(io::read_texture_image(png_path).rgba, red_green().rgba);
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(model.materials[0].pbrMetallicRoughness.baseColorTexture.index, 0);
  const tinygltf::Primitive& p = model.meshes.at(0).primitives.at(0);
  ASSERT_TRUE(p.attributes.count("TEXCOORD_0"));
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(p.attributes.at("TEXCOORD_0"))];
  const tinygltf::BufferView& v = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const auto* uv = reinterpret_cast<const float*>(model.buffers[0].data.data() + v.byteOffset + a.byteOffset);
  EXPECT_FLOAT_EQ(uv[1], 1);  // (0, 0) at the image's bottom: glTF's v = 1
  EXPECT_FLOAT_EQ(uv[5], 0);  // (0, 1) at its top
}

// SGI's .rgb (lpfg's and cpfg's usual texture format) and PNG, by content.
TEST(Textures, ReadsPngAndSgiImages) {
  const std::string dir = make_temp_dir("textures-read");
  const std::string png = io::encode_texture_png(red_green());
  std::ofstream(dir + "/t.png", std::ios::binary) << png;
  const io::TextureImage back = io::read_texture_image(dir + "/t.png");
  EXPECT_EQ(back.width, 2);
  EXPECT_EQ(back.rgba, red_green().rgba);
  // An uncompressed 2 x 1 SGI image (big-endian header: magic 474, verbatim,
  // 1 byte a channel, 3 dimensions, 2 x 1 x 3), channels stored one after another.
  std::string sgi(512, '\0');
  auto put16 = [&](std::size_t at, int v) { sgi[at] = static_cast<char>(v >> 8), sgi[at + 1] = static_cast<char>(v & 255); };
  put16(0, 474);
  sgi[2] = 0;  // verbatim
  sgi[3] = 1;  // bytes per channel
  put16(4, 3);
  put16(6, 2);
  put16(8, 1);
  put16(10, 3);
  sgi[19] = static_cast<char>(255);  // pixmax 255
  sgi += std::string{'\xff', '\x00'} + std::string{'\x00', '\xff'} + std::string{'\x00', '\x00'};
  std::ofstream(dir + "/t.rgb", std::ios::binary) << sgi;
  const io::TextureImage rgb = io::read_texture_image(dir + "/t.rgb");
  ASSERT_EQ(rgb.width, 2);
  ASSERT_EQ(rgb.height, 1);
  EXPECT_EQ(rgb.rgba, red_green().rgba);
  EXPECT_THROW(io::read_texture_image(dir + "/none.png"), ModelError);
}

}  // namespace
}  // namespace sylva::test
