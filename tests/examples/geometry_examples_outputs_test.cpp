// The geometric examples through the sylva program, every output read back
// by something other than the code that wrote it: PNG images with stb_image
// (size, background, where the model is, colours of the colormap), meshes
// with assimp (face counts against the Scene and against counts by hand),
// SVG and PostScript by parsing their text, PDF rasterized by pdftoppm,
// animation frames, and the turtle's trace. Expected numbers are worked out
// by hand in the comments; the Scene of the same run is the second method
// the mesh counts are compared with.
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "examples/geometry_examples.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace sylva::test::geometry_examples {
namespace {
namespace fs = std::filesystem;
using Rgb = std::array<int, 3>;

std::string test_dir() {
  return make_temp_dir(std::string("geoex-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

// `sylva run examples/<name>/<name>.l <inputs> <args>`; fails the test unless it succeeds.
ProcessResult run_example(const std::string& name, const std::vector<std::string>& args,
                          std::vector<std::string> inputs = {}) {
  if (inputs.empty()) inputs = inputs_of(name);
  std::vector<std::string> argv = {"run", model_of(name)};
  for (const std::string& input : inputs) argv.push_back(example_file(name, input));
  argv.insert(argv.end(), args.begin(), args.end());
  ProcessResult r = run_sylva(argv);
  EXPECT_EQ(r.exit_code, 0) << "sylva run " << name << ":\n" << r.err;
  return r;
}

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  Rgb at(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

Image read_png(const std::string& path) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  EXPECT_NE(data, nullptr) << path << ": " << stbi_failure_reason();
  if (!data) return image;
  image.rgb.assign(data, data + static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
  stbi_image_free(data);
  return image;
}

// The pixels that are not the background: how many, and their bounding box.
struct Drawn {
  int count = 0;
  int min_x = 1 << 30, min_y = 1 << 30, max_x = -1, max_y = -1;
};

Drawn drawn(const Image& image, Rgb background) {
  Drawn d;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y) != background) {
        ++d.count;
        d.min_x = std::min(d.min_x, x), d.max_x = std::max(d.max_x, x);
        d.min_y = std::min(d.min_y, y), d.max_y = std::max(d.max_y, y);
      }
  return d;
}

void expect_background_corners(const Image& image, Rgb background) {
  for (auto [x, y] : {std::pair{0, 0}, {image.width - 1, 0}, {0, image.height - 1}, {image.width - 1, image.height - 1}})
    EXPECT_EQ(image.at(x, y), background) << "corner (" << x << ", " << y << ")";
}

const Rgb kBlack{0, 0, 0};  // colour 0 of lpfg's default colours

// Parallel projection, the Scene's box framed to `scale` of the limiting
// dimension and centred (the view file's documented framing): the pixel
// box a world box of size w x h lands in.
struct PixelBox {
  double min_x, max_x, min_y, max_y;
};
PixelBox framed(double w, double h, int width, int height, double scale = 0.9) {
  const double ppu = std::min(scale * width / w, scale * height / h);
  return {width / 2.0 - ppu * w / 2, width / 2.0 + ppu * w / 2, height / 2.0 - ppu * h / 2, height / 2.0 + ppu * h / 2};
}

void expect_drawn_in(const Drawn& d, const PixelBox& box, double tolerance) {
  EXPECT_NEAR(d.min_x, box.min_x, tolerance);
  EXPECT_NEAR(d.max_x, box.max_x, tolerance);
  EXPECT_NEAR(d.min_y, box.min_y, tolerance);
  EXPECT_NEAR(d.max_y, box.max_y, tolerance);
}

// ---------------------------------------------------------------------------
// PNG images

// Every example at an image size that is not square: the file has that size,
// the corners are background, and the model covers a good part of it.
TEST(GeometryExampleImages, EveryExampleAtTheAskedSize) {
  const std::string dir = test_dir();
  for (const std::string name : {"snowflake", "ternary-tree", "query-height", "leaf", "stem", "colors"}) {
    SCOPED_TRACE(name);
    const std::string png = dir + "/" + name + ".png";
    run_example(name, {"-o", png, "--width", "240", "--height", "180"});
    const Image image = read_png(png);
    ASSERT_EQ(image.width, 240);
    ASSERT_EQ(image.height, 180);
    const Rgb background = name == "colors" ? Rgb{222, 235, 247} : kBlack;
    expect_background_corners(image, background);
    const Drawn d = drawn(image, background);
    EXPECT_GT(d.count, 200);
    // Framed to 0.9 of the limiting dimension: in parallel projection the
    // drawing spans that much of one of them; in perspective the box's
    // corners do, so the drawing itself less.
    const bool perspective = name == "ternary-tree" || name == "colors" || name == "stem";
    const double fill = perspective ? 0.5 : 0.85;
    EXPECT_TRUE(d.max_x - d.min_x > fill * 240 || d.max_y - d.min_y > fill * 180)
        << "drawn in x " << d.min_x << ".." << d.max_x << ", y " << d.min_y << ".." << d.max_y;
  }
}

// The snowflake after one step spans x in [-sqrt3/6, sqrt3/2] and y in
// [0, 1] (geometry_examples_test.cpp): 1.1547 x 1, framed to 0.9 of 200
// pixels across: 155.9 pixels per unit. Its middle, inside the curve, is
// background: a curve, not a filled shape.
TEST(GeometryExampleImages, SnowflakeFramedAsComputedByHand) {
  const std::string dir = test_dir();
  run_example("snowflake", {"--steps", "1", "-o", dir + "/s.png", "--width", "200", "--height", "200"});
  const Image image = read_png(dir + "/s.png");
  ASSERT_EQ(image.width, 200);
  const double r3 = std::sqrt(3.0);
  const Drawn d = drawn(image, kBlack);
  expect_drawn_in(d, framed(2 * r3 / 3, 1, 200, 200), 1.5);
  EXPECT_EQ(image.at(100, 100), kBlack);
  // Twelve lines 1 pixel wide: 12 * (155.9 / 3) pixels, give or take the ends.
  EXPECT_NEAR(d.count, 12 * 155.9 / 3, 0.15 * 12 * 155.9 / 3);
}

// Query height has no view file: lpfg's defaults (parallel, scale 0.9,
// white pixel lines on black). The plant spans x in [-5 sin 45, 0] (the
// branch from height 1) and y in [0, 3 + 3 sin 45] (the tip of the branch
// from height 3 is the highest point, above the main tip at 5). The main
// axis is the right edge, a vertical line 5 units long from the bottom.
TEST(GeometryExampleImages, QueryHeightMainAxisIsTheRightEdge) {
  const std::string dir = test_dir();
  run_example("query-height", {"-o", dir + "/q.png", "--width", "200", "--height", "200"});
  const Image image = read_png(dir + "/q.png");
  ASSERT_EQ(image.width, 200);
  const Drawn d = drawn(image, kBlack);
  const double r = std::sqrt(0.5), height = 3 + 3 * r;
  const PixelBox box = framed(5 * r, height, 200, 200);
  expect_drawn_in(d, box, 1.5);
  int column_run = 0;
  for (int y = 0; y < 200; ++y) column_run += image.at(d.max_x, y) != kBlack;
  EXPECT_NEAR(column_run, 5 * (box.max_y - box.min_y) / height, 2);
  EXPECT_EQ(image.at(d.max_x, (d.min_y + d.max_y) / 2), (Rgb{255, 255, 255}));
}

// The leaf is symmetric about x = 0 and 6.4 tall (tip of the terminal
// leaflet at 1.2 + 3 * 1.1 + 1.9) by about 2.9 wide: the height limits, and
// it is centred across. Its blades are colour 3, a green (hue 137.5).
TEST(GeometryExampleImages, LeafFillsTheHeightAndIsGreen) {
  const std::string dir = test_dir();
  run_example("leaf", {"-o", dir + "/leaf.png", "--width", "200", "--height", "200"});
  const Image image = read_png(dir + "/leaf.png");
  ASSERT_EQ(image.width, 200);
  const Drawn d = drawn(image, kBlack);
  EXPECT_NEAR(d.min_y, 10, 2);
  EXPECT_NEAR(d.max_y, 190, 2);
  EXPECT_NEAR((d.min_x + d.max_x) / 2.0, 100, 1.5);
  EXPECT_LT(d.max_x - d.min_x, 0.6 * 180);
  int green = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) {
      const Rgb c = image.at(x, y);
      if (c != kBlack) green += c[1] > c[0] + 20 && c[1] > c[2] + 20;
    }
  EXPECT_GT(green, d.count * 9 / 10);
  // A lateral leaflet's middle: the first pair's left leaflet has its middle
  // 0.75 along a heading 60 degrees left of up from (0, 1.2).
  const double ppu = 180 / (kPetiole + kPairs * kInternode + kTerminal + 0.03);  // box from y = -0.03
  const double wx = -0.75 * std::sin(radians(60)), wy = kPetiole + 0.75 * std::cos(radians(60));
  const int px = static_cast<int>(std::lround(100 + wx * ppu));
  const int py = static_cast<int>(std::lround(190 - (wy + 0.03) * ppu));
  EXPECT_NE(image.at(px, py), kBlack) << "at (" << px << ", " << py << ")";
}

// The stem: green, far taller than wide.
TEST(GeometryExampleImages, StemIsTallNarrowAndGreen) {
  const std::string dir = test_dir();
  run_example("stem", {"-o", dir + "/stem.png", "--width", "200", "--height", "200"});
  const Image image = read_png(dir + "/stem.png");
  ASSERT_EQ(image.width, 200);
  const Drawn d = drawn(image, kBlack);
  EXPECT_GT(d.max_y - d.min_y, 2 * (d.max_x - d.min_x));
  int green = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) {
      const Rgb c = image.at(x, y);
      if (c != kBlack) green += c[1] > c[0] && c[1] > c[2];
    }
  EXPECT_GT(green, d.count * 9 / 10);
}

// colors.map (examples/colors): 0 = (222, 235, 247), 1 = brown (101, 67,
// 33), 3 = green (60, 140, 50). The ternary tree draws its wood in colour 1
// and its apices in colour 3. Lit by white lights, a pixel keeps its
// colour's proportions: brown pixels have g/r = 67/101 and b/r = 33/101.
bool proportional(Rgb c, Rgb colour, double tolerance) {
  const int big = std::max({colour[0], colour[1], colour[2]});
  const int k = colour[0] == big ? 0 : colour[1] == big ? 1 : 2;
  if (c[k] < 40) return false;  // too dark to tell
  for (int j = 0; j < 3; ++j)
    if (std::fabs(double(c[j]) / c[k] - double(colour[j]) / colour[k]) > tolerance) return false;
  return true;
}

TEST(GeometryExampleImages, ColormapGivesTheTernaryTreeABrownTrunk) {
  const std::string dir = test_dir();
  for (const std::string name : {"ternary-tree", "colors"}) {
    SCOPED_TRACE(name);
    const std::string png = dir + "/" + name + ".png";
    std::vector<std::string> inputs = inputs_of(name);
    if (name == "ternary-tree") inputs.push_back("../colors/colors.map");
    run_example(name, {"-o", png, "--width", "300", "--height", "300"}, inputs);
    const Image image = read_png(png);
    ASSERT_EQ(image.width, 300);
    const Rgb sky{222, 235, 247};
    expect_background_corners(image, sky);
    int brown = 0, green = 0;
    for (int y = 0; y < 300; ++y)
      for (int x = 0; x < 300; ++x) {
        brown += proportional(image.at(x, y), {101, 67, 33}, 0.08);
        green += proportional(image.at(x, y), {60, 140, 50}, 0.08);
      }
    EXPECT_GT(brown, 300) << "trunk pixels";
    EXPECT_GT(green, 20) << "apex pixels";
    // Below the crown (which droops to about mid-height) only the trunk is
    // drawn: a narrow upright band, brown throughout.
    const Drawn all = drawn(image, sky);
    int trunk = 0, low = 300, high = -1;
    for (int y = all.min_y + (all.max_y - all.min_y) * 8 / 10; y < all.max_y - 2; ++y)
      for (int x = 0; x < 300; ++x) {
        if (image.at(x, y) == sky) continue;
        low = std::min(low, x), high = std::max(high, x);
        trunk += proportional(image.at(x, y), {101, 67, 33}, 0.08);
      }
    EXPECT_GT(trunk, 0);
    EXPECT_LT(high - low, 15) << "the lowest fifth is more than a trunk";
    EXPECT_NEAR((low + high) / 2.0, (all.min_x + all.max_x) / 2.0, 20);
  }
  // Without the colormap lpfg's colours apply: black background, no brown.
  run_example("ternary-tree", {"-o", dir + "/plain.png", "--width", "300", "--height", "300"});
  const Image plain = read_png(dir + "/plain.png");
  expect_background_corners(plain, kBlack);
}

// ---------------------------------------------------------------------------
// Meshes read back with assimp

struct FaceCount {
  std::size_t triangles = 0, lines = 0, other = 0;
};

FaceCount assimp_faces(const std::string& path) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, 0);
  FaceCount n;
  EXPECT_NE(scene, nullptr) << path << ": " << importer.GetErrorString();
  if (!scene) return n;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    for (unsigned f = 0; f < scene->mMeshes[m]->mNumFaces; ++f) {
      const unsigned k = scene->mMeshes[m]->mFaces[f].mNumIndices;
      (k == 3 ? n.triangles : k == 2 ? n.lines : n.other)++;
    }
  return n;
}

// What each example's mesh holds, by hand. These are L+C models, so the mesh
// is what lpfg's OBJ export makes whatever the view's line style: every
// segment a tube of 16 quads (32 triangles), a sphere `sides` slices (the
// view's contour sides) by (sides + 1) / 2 stacks with triangles at the poles:
//  - snowflake, 1 step: 12 segments * 32 = 384 triangles;
//  - query-height: 18 segments * 32 = 576 triangles;
//  - ternary tree, 2 steps: 2 * 9 - 1 = 17 segments * 32 + 9 spheres *
//    (8 + 2 * 8 * (4 - 2) + 8 = 48) = 544 + 432 = 976 triangles;
//  - leaf: 7 surfaces * 256 + 4 segments * 32 = 1920 triangles;
//  - stem: 12 bands * 32 sides * 2 = 768 triangles.
struct MeshCase {
  std::string name;
  std::vector<std::string> args;
  std::size_t triangles;
  int sides;  // contour sides in the view file
};

const std::vector<MeshCase>& mesh_cases() {
  static const std::vector<MeshCase> cases = {
      {"snowflake", {"--steps", "1"}, 384, 16},
      {"query-height", {}, 576, 16},
      {"ternary-tree", {"--steps", "2"}, 976, 8},
      {"leaf", {}, 1920, 8},
      {"stem", {}, 768, 16},
  };
  return cases;
}

// The same count from the Scene of the same model, through the API.
std::size_t triangles_from_scene(const MeshCase& c) {
  const int steps = c.args.empty() ? -1 : std::stoi(c.args[1]);
  auto sim = load(c.name, inputs_of(c.name), steps);
  const geometry::Scene scene = sim->scene();
  std::size_t n = 0;
  for (const auto& g : scene.groups) n += g.index_count / 3;
  n += scene.segments.size() * 2 * 16;
  const int stacks = (c.sides + 1) / 2;
  n += scene.spheres.size() * static_cast<std::size_t>(2 * c.sides * (stacks - 1));
  return n;
}

TEST(GeometryExampleMeshes, ObjPlyAndGlbReadBackWithAssimp) {
  const std::string dir = test_dir();
  for (const MeshCase& c : mesh_cases()) {
    SCOPED_TRACE(c.name);
    std::vector<std::string> args = c.args;
    for (const char* ext : {".obj", ".ply", ".glb"}) args.insert(args.end(), {"-o", dir + "/" + c.name + ext});
    run_example(c.name, args);
    EXPECT_EQ(triangles_from_scene(c), c.triangles);
    for (const char* ext : {".obj", ".ply", ".glb"}) {
      SCOPED_TRACE(ext);
      const std::string path = dir + "/" + c.name + ext;
      const FaceCount file = assimp_faces(path);
      EXPECT_EQ(file.triangles, c.triangles);
      EXPECT_EQ(file.lines, 0u);
      EXPECT_EQ(file.other, 0u);
      EXPECT_GT(file.triangles + file.lines, 0u);
    }
  }
}

// ---------------------------------------------------------------------------
// Vector drawings

int count_of(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// SVG elements, by hand: pixel lines are <line>s; a cylinder segment is a
// <line>, or a <polygon> when perspective makes its ends differ in width;
// spheres are <circle>s; triangles are <polygon>s, except those seen
// edge-on: the leaf's surfaces have their first and last rows of quads
// collapsed to the base and the tip, so 8 of each row's 16 triangles have no
// area: 2 patches * (128 - 16) = 224 per leaflet, 7 * 224 = 1568.
TEST(GeometryExampleDrawings, SvgElementsCountedByHand) {
  const std::string dir = test_dir();
  struct Case {
    std::string name;
    std::vector<std::string> args;
    int lines_and_polygons, polygons, circles;  // polygons < 0: not checked
  };
  const std::vector<Case> cases = {
      {"snowflake", {"--steps", "2"}, 48, 0, 0},
      {"query-height", {}, 18, 0, 0},
      {"ternary-tree", {"--steps", "2"}, 17, -1, 9},
      {"leaf", {}, 4 + 1568, 1568, 0},
      {"stem", {}, 768, 768, 0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"-o", dir + "/" + c.name + ".svg", "--width", "300", "--height", "200"});
    run_example(c.name, args);
    const std::string svg = read_text(dir + "/" + c.name + ".svg");
    EXPECT_EQ(svg.find("<?xml"), 0u);
    EXPECT_NE(svg.find("width=\"300\" height=\"200\""), std::string::npos);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    const int lines = count_of(svg, "<line "), polygons = count_of(svg, "<polygon "), paths = count_of(svg, "<path ");
    EXPECT_EQ(lines + polygons + paths, c.lines_and_polygons);
    if (c.polygons >= 0) {
      EXPECT_EQ(polygons + paths, c.polygons);
    }
    EXPECT_EQ(count_of(svg, "<circle "), c.circles);
  }
}

// The snowflake's 12 lines after one step end at the vertices computed by
// hand, projected with the framing worked out in
// SnowflakeFramedAsComputedByHand (here 200 x 150: the height limits,
// 135 pixels per unit, y down).
TEST(GeometryExampleDrawings, SvgSnowflakeLinesAtTheirProjectedEnds) {
  const std::string dir = test_dir();
  run_example("snowflake", {"--steps", "1", "-o", dir + "/s.svg", "--width", "200", "--height", "150"});
  const std::string svg = read_text(dir + "/s.svg");
  const std::regex line_re("<line x1=\"([-0-9.e]+)\" y1=\"([-0-9.e]+)\" x2=\"([-0-9.e]+)\" y2=\"([-0-9.e]+)\"");
  std::vector<Segment2> drawn_lines;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line_re); it != std::sregex_iterator(); ++it)
    drawn_lines.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4])});
  const std::vector<Segment2> walk = koch_snowflake(1);
  ASSERT_EQ(drawn_lines.size(), walk.size());
  const double r3 = std::sqrt(3.0), ppu = 0.9 * 150;
  const double cx = (-r3 / 6 + r3 / 2) / 2, cy = 0.5;  // the box's centre
  auto px = [&](double x) { return 100 + (x - cx) * ppu; };
  auto py = [&](double y) { return 75 - (y - cy) * ppu; };
  for (const Segment2& w : walk) {
    bool found = false;
    for (const Segment2& d : drawn_lines)
      found = found || (std::fabs(d.x0 - px(w.x0)) < 0.01 && std::fabs(d.y0 - py(w.y0)) < 0.01 &&
                        std::fabs(d.x1 - px(w.x1)) < 0.01 && std::fabs(d.y1 - py(w.y1)) < 0.01);
    EXPECT_TRUE(found) << "no line from (" << px(w.x0) << ", " << py(w.y0) << ") to (" << px(w.x1) << ", " << py(w.y1)
                       << ")";
  }
}

// PDF rasterized by poppler at 72 dpi (a point per pixel): the page has the
// asked size, background corners, and the snowflake's lines where the PNG
// has them; the leaf's blades green.
TEST(GeometryExampleDrawings, PdfRasterizedByPdftoppm) {
  const std::string dir = test_dir();
  run_example("snowflake", {"--steps", "1", "-o", dir + "/s.pdf", "--width", "200", "--height", "200"});
  run_example("leaf", {"-o", dir + "/leaf.pdf", "--width", "160", "--height", "200"});
  run_example("stem", {"-o", dir + "/stem.pdf", "--width", "160", "--height", "200"});
  EXPECT_EQ(read_text(dir + "/s.pdf").rfind("%PDF-", 0), 0u);
  for (const std::string name : {"s", "leaf", "stem"}) {
    ProcessResult r = run_process({"pdftoppm", "-png", "-r", "72", "-singlefile", dir + "/" + name + ".pdf", dir + "/" + name + "-page"});
    if (r.exit_code == -1) GTEST_SKIP() << "pdftoppm is not installed";
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const Image snow = read_png(dir + "/s-page.png");
  ASSERT_EQ(snow.width, 200);
  ASSERT_EQ(snow.height, 200);
  expect_background_corners(snow, kBlack);
  const Drawn d = drawn(snow, kBlack);
  expect_drawn_in(d, framed(2 * std::sqrt(3.0) / 3, 1, 200, 200), 2);
  EXPECT_EQ(snow.at(100, 100), kBlack);

  for (const std::string name : {"leaf", "stem"}) {
    SCOPED_TRACE(name);
    const Image page = read_png(dir + "/" + name + "-page.png");
    ASSERT_EQ(page.width, 160);
    ASSERT_EQ(page.height, 200);
    expect_background_corners(page, kBlack);
    const Drawn p = drawn(page, kBlack);
    EXPECT_GT(p.count, 500);
    EXPECT_GT(p.max_y - p.min_y, 0.8 * 200);  // both are taller than wide: the height limits
    int green = 0;
    for (int y = 0; y < page.height; ++y)
      for (int x = 0; x < page.width; ++x) {
        const Rgb c = page.at(x, y);
        green += c != kBlack && c[1] > c[0] && c[1] > c[2];
      }
    EXPECT_GT(green, p.count * 8 / 10);
  }
}

// PostScript and EPS as text: the header, the bounding box of the asked
// size, and for the snowflake after one step one lineto per segment (12);
// then the PostScript rasterized by ghostscript.
TEST(GeometryExampleDrawings, PostScriptAndEpsWellFormed) {
  const std::string dir = test_dir();
  run_example("snowflake", {"--steps", "1", "-o", dir + "/s.ps", "-o", dir + "/s.eps", "--width", "200", "--height", "150"});
  run_example("stem", {"-o", dir + "/stem.eps", "--width", "120", "--height", "300"});
  for (const std::string file : {"s.ps", "s.eps", "stem.eps"}) {
    SCOPED_TRACE(file);
    const std::string text = read_text(dir + "/" + file);
    const bool eps = file.ends_with(".eps");
    EXPECT_EQ(text.rfind(eps ? "%!PS-Adobe-3.0 EPSF-3.0" : "%!PS-Adobe-3.0", 0), 0u);
    EXPECT_NE(text.find(file == "stem.eps" ? "%%BoundingBox: 0 0 120 300" : "%%BoundingBox: 0 0 200 150"),
              std::string::npos);
    EXPECT_NE(text.find("%%EOF"), std::string::npos);
  }
  // Drawing operators after the prolog: each segment is "x y m x y l S".
  for (const std::string file : {"s.ps", "s.eps"}) {
    const std::string text = read_text(dir + "/" + file);
    std::istringstream body(text.substr(text.find("%%EndProlog")));
    std::string word;
    int linetos = 0;
    while (body >> word) linetos += word == "l";
    EXPECT_EQ(linetos, 12) << file;
  }
  // Rasterized by ghostscript, where there is one: as the PNG of the same
  // size, the lines within the box worked out by hand (200 x 150: the height
  // limits, 135 pixels per unit), the middle background.
  ProcessResult r = run_process({"gs", "-q", "-dSAFER", "-dBATCH", "-dNOPAUSE", "-sDEVICE=png16m", "-r72", "-g200x150",
                                 "-dFIXEDMEDIA", "-sOutputFile=" + dir + "/s-ps.png", dir + "/s.ps"});
  if (r.exit_code == -1) GTEST_SKIP() << "ghostscript is not installed";
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image page = read_png(dir + "/s-ps.png");
  ASSERT_EQ(page.width, 200);
  ASSERT_EQ(page.height, 150);
  expect_background_corners(page, kBlack);
  expect_drawn_in(drawn(page, kBlack), framed(2 * std::sqrt(3.0) / 3, 1, 200, 150), 2);
  EXPECT_EQ(page.at(100, 75), kBlack);
}

// ---------------------------------------------------------------------------
// Animation frames and the turtle's trace

// leaf.a: first frame 0, last frame 3, step 1: frames of steps 0, 1, 2, 3,
// each a PNG of the asked size. The camera holds still (framing the last
// frame), and each step adds a pair of leaflets: more of the image is drawn
// in every frame.
TEST(GeometryExampleFrames, LeafAnimationWritesFourGrowingFrames) {
  const std::string dir = test_dir();
  run_example("leaf", {"--frames", dir + "/frames", "--width", "120", "--height", "150"}, {"leaf.v", "leaf.a"});
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir + "/frames")) files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files, (std::vector<std::string>{"frame-0000.png", "frame-0001.png", "frame-0002.png", "frame-0003.png"}));
  int previous = 0;
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    const Image image = read_png(dir + "/frames/" + file);
    ASSERT_EQ(image.width, 120);
    ASSERT_EQ(image.height, 150);
    expect_background_corners(image, kBlack);
    const int count = drawn(image, kBlack).count;
    EXPECT_GT(count, previous);
    previous = count;
  }
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

int starting_with(const std::vector<std::string>& lines, const std::string& prefix) {
  return static_cast<int>(std::count_if(lines.begin(), lines.end(), [&](const std::string& l) { return l.rfind(prefix, 0) == 0; }));
}

// One line per module the turtle interprets (user modules are not turtle
// commands), counted by hand from each final string:
//  - snowflake, n steps: 3 * 4^n F and 3 * 4^n - 1 turns: 23 lines for n = 1;
//  - leaf: SetColor SetWidth F, 3 pairs of "SB Left Surface EB SB Right
//    Surface EB F" (9 each), and A(0) drawn as a Surface: 3 + 27 + 1 = 31;
//  - stem: SetColor RollR CurrentContour SetWidth StartGC (5), 11 steps of
//    "F SetWidth PointGC Left" (44) and the last "F SetWidth EndGC" (3): 52.
TEST(GeometryExampleTurtle, TraceHasOneLinePerTurtleCommand) {
  ProcessResult r = run_example("snowflake", {"--steps", "1", "--turtle", "-"});
  std::vector<std::string> lines = lines_of(r.out);
  EXPECT_EQ(lines.size(), 23u);
  EXPECT_EQ(starting_with(lines, "F("), 12);
  EXPECT_EQ(starting_with(lines, "Left(60)"), 6);
  EXPECT_EQ(starting_with(lines, "Right(120)"), 5);
  for (const std::string& l : lines) {
    if (l.rfind("F(", 0) == 0) {
      EXPECT_TRUE(l.find(" from ") != std::string::npos && l.find(" to ") != std::string::npos) << l;
    }
  }

  r = run_example("leaf", {"--turtle", "-"});
  lines = lines_of(r.out);
  EXPECT_EQ(lines.size(), 31u);
  EXPECT_EQ(starting_with(lines, "Surface(0,"), 7);
  EXPECT_EQ(starting_with(lines, "SB"), 6);
  EXPECT_EQ(starting_with(lines, "EB"), 6);

  r = run_example("stem", {"--turtle", "-"});
  lines = lines_of(r.out);
  EXPECT_EQ(lines.size(), 52u);
  EXPECT_EQ(starting_with(lines, "StartGC"), 1);
  EXPECT_EQ(starting_with(lines, "PointGC"), 11);
  EXPECT_EQ(starting_with(lines, "EndGC"), 1);
  EXPECT_EQ(starting_with(lines, "F("), 12);
}

}  // namespace
}  // namespace sylva::test::geometry_examples
