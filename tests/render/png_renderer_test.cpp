#include "render/png_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>

#include "geometry/camera.h"
#include "support/diagnostic.h"
#include "test_support.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace sylva {
namespace {

namespace fs = std::filesystem;
using geometry::Box;
using geometry::RenderMode;
using geometry::Rgb;
using geometry::Scene;
using geometry::Vec3;
using io::Image;
using io::ImageSettings;
using Pixel = std::array<std::uint8_t, 3>;

constexpr Pixel kBlack{0, 0, 0}, kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255};

// Black background; 2 red, 3 green, 4 blue, 5 white.
geometry::Palette test_palette() {
  geometry::Palette p = geometry::Palette::default_palette();
  auto set = [&](int i, Rgb c) {
    p.entries[static_cast<std::size_t>(i)].diffuse = p.entries[static_cast<std::size_t>(i)].ambient = c;
  };
  set(0, {0, 0, 0});
  set(2, {1, 0, 0});
  set(3, {0, 1, 0});
  set(4, {0, 0, 1});
  set(5, {1, 1, 1});
  return p;
}

// The default view (looking down -z) framing the box from -2 to 2.
geometry::ViewParameters test_view() {
  geometry::ViewParameters view;
  view.box = Box{{-2, -2, -2}, {2, 2, 2}};
  view.scale = 1;
  return view;
}

geometry::Provenance module(std::uint32_t index) { return {index, 0}; }

// A triangle in the plane z, counter-clockwise seen from +z, covering the
// centre of the view.
void add_triangle(Scene& scene, float z, int color, std::uint32_t index, float size = 1.5f) {
  scene.add_triangles(geometry::TriangleGroup::Kind::Triangle, {{-size, -size, z}, {size, -size, z}, {0, size, z}},
                      {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, {0, 1, 2}, color, module(index));
}

Image render(const Scene& scene, const ImageSettings& settings = {}, int width = 80, int height = 60,
             const geometry::ViewParameters& view = test_view()) {
  return io::render_image(scene, test_palette(), view, settings, width, height);
}

Pixel centre(const Image& image) { return image.pixel(image.width / 2, image.height / 2); }

int brightness(Pixel p) { return p[0] + p[1] + p[2]; }

int count_pixels(const Image& image, Pixel colour) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += image.pixel(x, y) == colour;
  return n;
}

TEST(PngRenderer, ImageHasTheRequestedSize) {
  Scene scene;
  scene.spheres.push_back({{0, 0, 0}, 1, 2, module(0)});
  for (auto [w, h] : {std::pair{1, 1}, {64, 48}, {33, 100}}) {
    Image image = render(scene, {}, w, h);
    EXPECT_EQ(image.width, w);
    EXPECT_EQ(image.height, h);
    EXPECT_EQ(image.rgb.size(), static_cast<std::size_t>(w * h * 3));
  }
}

TEST(PngRenderer, EmptySceneIsBackground) {
  geometry::Palette palette = test_palette();
  palette.entries[0].diffuse = {0, 0, 1};
  Image image = io::render_image(Scene{}, palette, test_view(), {}, 16, 8);
  EXPECT_EQ(count_pixels(image, kBlue), 16 * 8);
}

TEST(PngRenderer, RedDiscInTheMiddle) {
  Scene scene;
  scene.circles.push_back({{0, 0, 0}, {0, 0, 1}, 1, 0, false, 2, module(0)});
  Image image = render(scene);
  EXPECT_EQ(centre(image), kRed);
  EXPECT_EQ(image.pixel(0, 0), kBlack);
  EXPECT_EQ(image.pixel(image.width - 1, 0), kBlack);
  EXPECT_EQ(image.pixel(0, image.height - 1), kBlack);
  EXPECT_EQ(image.pixel(image.width - 1, image.height - 1), kBlack);
  // A disc of radius 1 in a view 4 units high is half the image's height across.
  EXPECT_NEAR(count_pixels(image, kRed), 3.14159 * 15 * 15, 3.14159 * 15 * 15 * 0.1);
}

TEST(PngRenderer, RedSegmentInTheMiddle) {
  Scene scene;
  geometry::Segment s;
  s.start = {-1, 0, 0}, s.end = {1, 0, 0}, s.up = {0, 0, 1};
  s.start_width = s.end_width = 3;
  s.color = 2;
  scene.segments.push_back(s);
  for (auto style : {geometry::LineStyle::Pixel, geometry::LineStyle::Polygon, geometry::LineStyle::Cylinder}) {
    ImageSettings settings;
    settings.render.line_style = style;
    // A polygon strip faces its up vector: the viewer here.
    scene.segments[0].up = style == geometry::LineStyle::Polygon ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
    Image image = render(scene, settings);
    EXPECT_EQ(centre(image), kRed) << static_cast<int>(style);
    EXPECT_EQ(image.pixel(0, 0), kBlack);
    EXPECT_EQ(image.pixel(image.width - 1, image.height - 1), kBlack);
  }
}

TEST(PngRenderer, PixelLinesAreTheirWidthInPixels) {
  Scene scene;
  geometry::Segment s;
  s.start = {-1, 0, 0}, s.end = {1, 0, 0}, s.color = 2;
  scene.segments.push_back(s);
  const int thin = count_pixels(render(scene), kRed);
  scene.segments[0].start_width = scene.segments[0].end_width = 5;
  const int wide = count_pixels(render(scene), kRed);
  EXPECT_GT(thin, 15);
  EXPECT_NEAR(wide, 5 * thin, thin);
}

TEST(PngRenderer, PixelWidthsDoNotWidenTheFrame) {
  Scene scene;
  geometry::Segment s;
  s.start = {-1, 0, 0}, s.end = {1, 0, 0}, s.color = 2;
  s.start_width = s.end_width = 20;  // pixels, not scene units
  scene.segments.push_back(s);
  geometry::ViewParameters view;
  view.scale = 0.5f;
  Image image = render(scene, {}, 100, 100, view);
  int left = image.width, right = -1;
  for (int x = 0; x < image.width; ++x)
    if (image.pixel(x, 50) == kRed) left = std::min(left, x), right = std::max(right, x);
  EXPECT_NEAR(right - left + 1, 50, 2);
  EXPECT_EQ(image.pixel(50, 50 - 8), kRed);
  EXPECT_EQ(image.pixel(50, 50 - 12), kBlack);
}

TEST(PngRenderer, SpheresAFewPixelsAcrossStillShow) {
  Scene scene;
  for (int i = 0; i < 5; ++i)
    scene.spheres.push_back(
        {{0.8f * static_cast<float>(i - 2), 0, 0}, 0.02f * static_cast<float>(i + 1), 3, module(i)});
  for (RenderMode mode : {RenderMode::Filled, RenderMode::Wireframe, RenderMode::Shaded}) {
    ImageSettings settings;
    settings.render.mode = mode;
    Image image = render(scene, settings, 200, 200);
    // 50 pixels per unit: radii of 1 to 5 pixels, areas of about 3 to 80.
    for (int i = 0; i < 5; ++i) {
      int drawn = 0;
      for (int y = 100 - 8; y < 100 + 8; ++y)
        for (int x = 20 + 40 * i - 8; x < 20 + 40 * i + 8; ++x) drawn += image.pixel(x, y) != kBlack;
      const double area = 3.14159 * (i + 1) * (i + 1);
      EXPECT_GE(drawn, area * 0.6) << i << " " << static_cast<int>(mode);
      EXPECT_LE(drawn, area * 1.4 + 2) << i << " " << static_cast<int>(mode);
    }
  }
  // A big one keeps all 16 sides: its outline is the 16-gon's.
  scene.spheres = {{{0, 0, 0}, 1.9f, 2, module(0)}};
  const double r = 1.9 * 50, area = 8 * std::sin(3.14159 / 8) * r * r;
  EXPECT_NEAR(count_pixels(render(scene, {}, 200, 200), kRed), area, 0.005 * area);
}

TEST(PngRenderer, ZBufferHidesTheFarTriangle) {
  Scene scene;
  add_triangle(scene, 1, 3, 0);   // near, green, drawn first
  add_triangle(scene, -1, 4, 1);  // far, blue, drawn last
  ImageSettings settings;
  settings.render.z_buffer = true;
  EXPECT_EQ(centre(render(scene, settings)), kGreen);
  // Without the z buffer the string's order decides: the later module shows.
  settings.render.z_buffer = false;
  EXPECT_EQ(centre(render(scene, settings)), kBlue);
}

TEST(PngRenderer, WithoutZBufferLinesAndTrianglesFollowTheString) {
  Scene scene;
  add_triangle(scene, 1, 3, 0);
  geometry::Segment s;
  s.start = {-1, 0, -1}, s.end = {1, 0, -1}, s.color = 2, s.start_width = 3, s.from = module(1);
  scene.segments.push_back(s);
  add_triangle(scene, 1.5f, 4, 2, 0.2f);  // a small blue one over the line's middle
  ImageSettings settings;
  Image painted = render(scene, settings);
  EXPECT_EQ(centre(painted), kBlue);
  EXPECT_EQ(painted.pixel(painted.width / 2 - 8, painted.height / 2), kRed);
  settings.render.z_buffer = true;
  Image hidden = render(scene, settings);
  EXPECT_EQ(hidden.pixel(hidden.width / 2 - 8, hidden.height / 2), kGreen);
}

TEST(PngRenderer, WireframeOutlinesTriangles) {
  Scene scene;
  add_triangle(scene, 0, 2, 0);
  ImageSettings settings;
  Image filled = render(scene, settings);
  settings.render.mode = RenderMode::Wireframe;
  Image wire = render(scene, settings);
  EXPECT_EQ(centre(filled), kRed);
  EXPECT_EQ(centre(wire), kBlack);
  const int outline = count_pixels(wire, kRed);
  EXPECT_GT(outline, 40);
  EXPECT_LT(outline, count_pixels(filled, kRed) / 3);
  settings.render.wireframe_line_width = 4;
  EXPECT_GT(count_pixels(render(scene, settings), kRed), 3 * outline);
}

TEST(PngRenderer, ShadedSphereIsBrighterOnTheLitSide) {
  Scene scene;
  scene.spheres.push_back({{0, 0, 0}, 1.5f, 5, module(0)});
  ImageSettings settings;
  settings.render.mode = RenderMode::Shaded;
  geometry::Light light;
  light.direction = {1, 0, 0};  // from screen right
  settings.lights = {light};
  Image image = render(scene, settings, 81, 61);
  const int y = 30;
  const int lit = brightness(image.pixel(40 + 12, y)), dark = brightness(image.pixel(40 - 12, y));
  EXPECT_GT(lit, dark + 200);
  EXPECT_GT(dark, 0);  // the ambient term
  EXPECT_EQ(image.pixel(0, 0), kBlack);

  // Filled mode ignores the light.
  settings.render.mode = RenderMode::Filled;
  Image flat = render(scene, settings, 81, 61);
  EXPECT_EQ(flat.pixel(40 + 12, y), flat.pixel(40 - 12, y));

  // A light moving with the camera, from the viewer's left.
  settings.render.mode = RenderMode::Shaded;
  settings.render.stationary_lights = false;
  settings.lights[0].direction = {-1, 0, 0};
  Image left = render(scene, settings, 81, 61);
  EXPECT_GT(brightness(left.pixel(40 - 12, y)), brightness(left.pixel(40 + 12, y)) + 200);
}

TEST(PngRenderer, PointAndSpotLights) {
  Scene scene;
  scene.spheres.push_back({{0, 0, 0}, 1.5f, 5, module(0)});
  ImageSettings settings;
  settings.render.mode = RenderMode::Shaded;
  settings.contour_sides = 32;
  geometry::Light point;
  point.kind = geometry::Light::Kind::Point;
  point.position = {-4, 0, 0};  // at screen left
  settings.lights = {point};
  Image image = render(scene, settings, 81, 61);
  EXPECT_GT(brightness(image.pixel(40 - 15, 30)), brightness(image.pixel(40 + 15, 30)) + 200);

  // A spotlight from the eye's side, narrow and aimed past the sphere, leaves
  // only the ambient term; aimed at it, it lights its middle.
  geometry::Light spot;
  spot.kind = geometry::Light::Kind::Spot;
  spot.position = {0, 0, 10};
  spot.direction = {1, 0, -1};
  spot.spot_cutoff = 10;
  settings.lights = {spot};
  const int away = brightness(render(scene, settings, 81, 61).pixel(40, 30));
  settings.lights[0].direction = {0, 0, -1};
  const int at = brightness(render(scene, settings, 81, 61).pixel(40, 30));
  EXPECT_GT(at, away + 300);
}

TEST(PngRenderer, TransparentMaterialsBlend) {
  Scene scene;
  add_triangle(scene, 0, 2, 0);
  geometry::Palette palette = test_palette();
  palette.entries[2].transparency = 0.5f;
  Image image = io::render_image(scene, palette, test_view(), {}, 80, 60);
  const Pixel c = centre(image);
  EXPECT_NEAR(c[0], 128, 2);
  EXPECT_EQ(c[1], 0);
}

TEST(PngRenderer, BackfaceCullingDropsTrianglesFacingAway) {
  Scene scene;
  scene.add_triangles(geometry::TriangleGroup::Kind::Triangle, {{-1.5f, -1.5f, 0}, {0, 1.5f, 0}, {1.5f, -1.5f, 0}},
                      {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}}, {0, 1, 2}, 2, module(0));  // clockwise as seen
  ImageSettings settings;
  EXPECT_EQ(centre(render(scene, settings)), kRed);
  settings.render.backface_culling = true;
  EXPECT_EQ(centre(render(scene, settings)), kBlack);
}

TEST(PngRenderer, MaterialsGiveSpecularHighlights) {
  Scene scene;
  scene.spheres.push_back({{0, 0, 0}, 1.5f, 2, module(0)});
  geometry::Palette palette = test_palette();
  palette.from_materials = true;
  palette.entries[2] = {{0.1f, 0, 0}, {0.5f, 0, 0}, {1, 1, 1}, {0, 0, 0}, 60, 0};
  ImageSettings settings;
  settings.render.mode = RenderMode::Shaded;
  Image image = io::render_image(scene, palette, test_view(), settings, 81, 61);
  // The default light shines from the eye: the highlight is in the middle.
  Pixel middle = image.pixel(40, 30);
  EXPECT_GT(middle[1], 200);
  EXPECT_GT(middle[0], 200);
  Pixel side = image.pixel(40 + 15, 30);
  EXPECT_LT(side[1], 50);
  EXPECT_GT(side[0], 20);
}

TEST(PngRenderer, ShadowsDarkenWhatTheLightCannotSee) {
  // A floor at y = 0, a ball above it, the light from up and to the right:
  // the ball's shadow falls to the left of it.
  Scene scene;
  scene.add_triangles(geometry::TriangleGroup::Kind::Polygon, {{-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4}},
                      {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}}, {0, 2, 1, 0, 3, 2}, 5, module(0));
  scene.spheres.push_back({{0, 1.5f, 0}, 0.6f, 2, module(1)});
  geometry::ViewParameters view;
  view.dir = {0, -1, -0.2f};
  view.up = {0, 0, -1};
  ImageSettings settings;
  settings.render.mode = RenderMode::Shadows;
  settings.contour_sides = 24;
  geometry::Light light;
  light.direction = {1, 1, 0};
  settings.lights = {light};
  const int w = 120, h = 120;
  Image image = io::render_image(scene, test_palette(), view, settings, w, h);
  const geometry::Camera camera(view, scene.bounds(), w, h);
  auto at = [&](Vec3 p) {
    Vec3 px = camera.to_pixels(p);
    return image.pixel(static_cast<int>(px.x), static_cast<int>(px.y));
  };
  const Pixel shadow = at({-1.5f, 0, 0}), open = at({1.5f, 0, 0}), far_open = at({-1.5f, 0, 2.5f});
  EXPECT_EQ(open, far_open);
  EXPECT_LT(brightness(shadow), brightness(open) / 2);
  // Multiplied by the shadow colour (0.2, 0.2, 0.4): bluish.
  EXPECT_GT(shadow[2], shadow[0]);

  settings.render.mode = RenderMode::Shaded;
  Image unshadowed = io::render_image(scene, test_palette(), view, settings, w, h);
  Vec3 px = camera.to_pixels({-1.5f, 0, 0});
  EXPECT_EQ(unshadowed.pixel(static_cast<int>(px.x), static_cast<int>(px.y)), open);
}

TEST(PngRenderer, AntialiasingBlendsEdges) {
  Scene scene;
  add_triangle(scene, 0, 2, 0);
  ImageSettings settings;
  auto colours = [](const Image& image) {
    std::set<Pixel> seen;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) seen.insert(image.pixel(x, y));
    return seen.size();
  };
  EXPECT_EQ(colours(render(scene, settings)), 2u);
  settings.render.antialiasing = 4;
  Image smooth = render(scene, settings);
  EXPECT_EQ(smooth.width, 80);
  EXPECT_GT(colours(smooth), 2u);
  EXPECT_EQ(centre(smooth), kRed);
}

TEST(PngRenderer, CirclesFacingTheViewerFaceIt) {
  Scene scene;
  scene.circles.push_back({{0, 0, 0}, {0, 0, 1}, 1, 0, true, 2, module(0)});
  geometry::ViewParameters view = test_view();
  view.dir = {-1, 0, 0};  // looking along the plane the circle would lie in
  EXPECT_GT(count_pixels(render(scene, {}, 80, 60, view), kRed), 400);
}

TEST(PngRenderer, RendersAgainAndAgainTheSame) {
  Scene scene;
  scene.spheres.push_back({{0, 0, 0}, 1, 3, module(0)});
  ImageSettings shaded;
  shaded.render.mode = RenderMode::Shaded;
  const Image first = render(scene, shaded);
  for (int i = 0; i < 20; ++i) {
    EXPECT_EQ(render(scene, i % 2 ? shaded : ImageSettings{}, 40 + i, 30).width, 40 + i);
  }
  EXPECT_EQ(render(scene, shaded).rgb, first.rgb);
}

TEST(PngRenderer, RejectsImpossibleSizes) {
  EXPECT_THROW(render(Scene{}, {}, 0, 10), ModelError);
  EXPECT_THROW(render(Scene{}, {}, 10, -1), ModelError);
  EXPECT_THROW(render(Scene{}, {}, 100000, 10), ModelError);
}

TEST(PngWriter, ReadsBackTheSamePixels) {
  Scene scene;
  add_triangle(scene, 0, 2, 0);
  scene.circles.push_back({{1, 1, 1}, {0, 0, 1}, 0.5f, 0, false, 3, module(1)});
  Image image = render(scene, {}, 37, 23);
  const std::string dir = test::make_temp_dir("png_writer");
  const std::string path = dir + "/plant.png";
  io::write_png(path, image);
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  ASSERT_NE(data, nullptr) << stbi_failure_reason();
  EXPECT_EQ(w, 37);
  EXPECT_EQ(h, 23);
  EXPECT_EQ(channels, 3);
  EXPECT_TRUE(std::equal(image.rgb.begin(), image.rgb.end(), data));
  EXPECT_EQ(data[(11 * 37 + 18) * 3], 255);  // the red centre
  stbi_image_free(data);
  // Nothing but the file itself is left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(PngWriter, UnwritablePathIsAnErrorNamingIt) {
  Image image{2, 2, std::vector<std::uint8_t>(12, 7)};
  const std::string dir = test::make_temp_dir("png_writer_bad");
  const std::string path = dir + "/missing/plant.png";
  try {
    io::write_png(path, image);
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  // An existing file is replaced whole.
  const std::string good = dir + "/plant.png";
  io::write_png(good, image);
  image.rgb.assign(12, 200);
  io::write_png(good, image);
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(good.c_str(), &w, &h, &channels, 3);
  ASSERT_NE(data, nullptr);
  EXPECT_EQ(data[0], 200);
  stbi_image_free(data);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(PngWriter, MalformedImageIsAnError) {
  const std::string dir = test::make_temp_dir("png_writer_malformed");
  EXPECT_THROW(io::write_png(dir + "/a.png", Image{}), ModelError);
  EXPECT_THROW(io::write_png(dir + "/b.png", Image{3, 3, std::vector<std::uint8_t>(5)}), ModelError);
  EXPECT_FALSE(fs::exists(dir + "/a.png"));
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

// A label's text starts at its projected position on the baseline (lpfg's
// and cpfg's renderText): its pixels, in its colour, lie right of and above
// the label's point and nowhere left of or below it (descenders aside).
TEST(PngRenderer, LabelsAreDrawnRightOfAndAboveTheirPosition) {
  Scene scene;
  scene.labels.push_back({{0, 0, 0}, "HHHH", 2, module(0)});
  ImageSettings settings;
  settings.label_font = geometry::LabelFont{"DejaVu Sans", 12, true, false};
  Image image = render(scene, settings, 80, 60);
  // The view is 4 units high in 60 pixels: the origin is at (40, 30).
  int red = 0, misplaced = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Pixel p = image.pixel(x, y);
      if (p == kBlack) continue;
      EXPECT_GT(p[0], p[1]) << x << "," << y;  // red, blended into black at the edges
      ++red;
      if (x < 40 || y > 30) ++misplaced;
    }
  EXPECT_GT(red, 40);
  EXPECT_EQ(misplaced, 0);
  // "HHHH" in 16 pixels: the capitals reach about 11 pixels above the baseline.
  bool high = false;
  for (int x = 40; x < 80; ++x) high = high || image.pixel(x, 21) != kBlack;
  EXPECT_TRUE(high);
}

}  // namespace
}  // namespace sylva
