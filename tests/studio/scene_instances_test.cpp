// A big scene's spheres and cylinders leave it as instances, in the binary
// form the page reads (scene_instances.h).
#include "studio/scene_instances.h"

#include <gtest/gtest.h>

#include <cstring>

namespace sylva::studio {
namespace {

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}
float f32(const std::string& bytes, std::size_t at) {
  float v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

geometry::Scene scene_of(int spheres, int segments) {
  geometry::Scene scene;
  for (int i = 0; i < spheres; ++i)
    scene.spheres.push_back({{float(i), 0, 0}, 0.5f, 2, {static_cast<std::uint32_t>(2 * i), 7}});
  for (int i = 0; i < segments; ++i) {
    geometry::Segment s;
    s.start = {0, float(i), 0};
    s.end = {0, float(i + 1), 0};
    s.start_width = 0.4f;
    s.end_width = 0.2f;
    s.from = {static_cast<std::uint32_t>(2 * i + 1), 3};
    scene.segments.push_back(s);
  }
  return scene;
}

TEST(SceneInstances, ASmallSceneStaysWhole) {
  geometry::Scene scene = scene_of(3, 3);
  EXPECT_EQ(take_instances(scene, geometry::Palette::default_palette(), {geometry::LineStyle::Cylinder, 8}, 10), "");
  EXPECT_EQ(scene.spheres.size(), 3u);
  EXPECT_EQ(scene.segments.size(), 3u);
}

TEST(SceneInstances, SpheresAndCylindersBecomeOneGroupEachPerColour) {
  geometry::Scene scene = scene_of(4, 3);
  const std::string bytes =
      take_instances(scene, geometry::Palette::default_palette(), {geometry::LineStyle::Cylinder, 8}, 5);
  EXPECT_TRUE(scene.spheres.empty());
  EXPECT_TRUE(scene.segments.empty());
  ASSERT_GE(bytes.size(), 12u);
  EXPECT_EQ(bytes.substr(0, 4), "SYLI");
  EXPECT_EQ(u32(bytes, 4), 1u);
  EXPECT_EQ(u32(bytes, 8), 2u);  // spheres in colour 2, cylinders in colour 1
  // The sphere group (shape 0 sorts first): 4 of 8 slices.
  std::size_t at = 12;
  EXPECT_EQ(u32(bytes, at), 0u);
  EXPECT_EQ(u32(bytes, at + 4), 4u);
  EXPECT_EQ(u32(bytes, at + 8), 8u);
  at += 28;
  EXPECT_EQ(f32(bytes, at + 16 * 3), 3.0f);     // the fourth sphere's x
  EXPECT_EQ(f32(bytes, at + 16 * 3 + 12), 0.5f);  // and radius
  at += 4 * 16;
  EXPECT_EQ(u32(bytes, at + 4 * 3), 6u);  // its module index
  EXPECT_EQ(u32(bytes, at + 16), 7u);     // the first one's module id
  at += 4 * 8;
  // The cylinders: frusta of radius half the turtle's widths.
  EXPECT_EQ(u32(bytes, at), 1u);
  EXPECT_EQ(u32(bytes, at + 4), 3u);
  at += 28;
  EXPECT_EQ(f32(bytes, at + 32 + 4), 1.0f);  // the second one starts at y = 1
  EXPECT_EQ(f32(bytes, at + 32 + 24), 0.2f);
  EXPECT_EQ(f32(bytes, at + 32 + 28), 0.1f);
  at += 3 * 32;
  EXPECT_EQ(u32(bytes, at + 4), 3u);  // the second one's module index
  EXPECT_EQ(at + 3 * 8, bytes.size());
}

TEST(SceneInstances, PixelLinesStayLines) {
  geometry::Scene scene = scene_of(0, 30);
  EXPECT_EQ(take_instances(scene, geometry::Palette::default_palette(), {geometry::LineStyle::Pixel, 8}, 5), "");
  EXPECT_EQ(scene.segments.size(), 30u);
}

}  // namespace
}  // namespace sylva::studio
