// Vector drawings read back: SVG parsed, PDF and PostScript rasterized by
// poppler and ghostscript.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/camera.h"
#include "render/vector_writer.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;
using geometry::Box;
using geometry::Camera;
using geometry::Scene;
using geometry::Vec3;
using geometry::ViewParameters;

Box square_box(float half, float depth = 0) { return Box{{-half, -half, -depth}, {half, half, depth}}; }

geometry::Palette test_palette() {
  geometry::Palette palette;
  palette.entries[0].diffuse = {1, 1, 0.8f};  // background
  palette.entries[1].diffuse = {1, 0, 0};
  palette.entries[2].diffuse = {0, 0.5f, 0};
  palette.entries[3].diffuse = {0, 0, 1};
  return palette;
}

const ModuleTypes& test_types() {
  static const ModuleTypes types({{"Axiom", 0, nullptr}, {"F", 0, nullptr}, {"+", 0, nullptr}, {"-", 0, nullptr}});
  return types;
}

// The Koch curve after two steps (F -> F+F--F+F, 60 degrees) from (0,0) to
// (1,0), one segment per F, coloured 1 and 2 in turn.
Scene koch_scene(std::string* word = nullptr) {
  std::string s = "F";
  for (int step = 0; step < 2; ++step) {
    std::string next;
    for (char c : s) next += c == 'F' ? std::string("F+F--F+F") : std::string(1, c);
    s = next;
  }
  Scene scene;
  Vec3 at{0, 0, 0};
  float angle = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '+') angle += 60;
    if (s[i] == '-') angle -= 60;
    if (s[i] != 'F') continue;
    float a = angle * std::numbers::pi_v<float> / 180;
    Vec3 to = at + Vec3{std::cos(a), std::sin(a), 0} / 9;
    geometry::Segment seg;
    seg.start = at, seg.end = to, seg.up = {0, 0, 1};
    seg.start_width = seg.end_width = 0.01f;
    seg.color = scene.segments.size() % 2 ? 2 : 1;
    seg.from = {static_cast<std::uint32_t>(i), 1};
    scene.segments.push_back(seg);
    at = to;
  }
  if (word) *word = s;
  return scene;
}

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::map<std::string, std::string> group;  // of the enclosing <g>
  std::string text;
};

// Enough of XML for what the writer produces: elements, attributes, text.
std::vector<Element> parse_svg(const std::string& svg) {
  std::vector<Element> out;
  std::map<std::string, std::string> group;
  static const std::regex attribute(R"(([\w:-]+)="([^"]*)\")");
  for (std::size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
    std::size_t end = svg.find('>', at);
    std::string tag = svg.substr(at + 1, end - at - 1);
    if (tag[0] == '?' || tag[0] == '/') {
      if (tag == "/g") group.clear();
      continue;
    }
    Element e;
    e.name = tag.substr(0, tag.find_first_of(" />"));
    for (std::sregex_iterator it(tag.begin(), tag.end(), attribute), stop; it != stop; ++it)
      e.attributes[(*it)[1]] = (*it)[2];
    if (e.name == "g") {
      group = e.attributes;
      continue;
    }
    e.group = group;
    if (tag.back() != '/' && e.name != "svg") e.text = svg.substr(end + 1, svg.find('<', end) - end - 1);
    out.push_back(e);
  }
  return out;
}

std::vector<Element> only(const std::vector<Element>& elements, const std::string& name) {
  std::vector<Element> out;
  for (const auto& e : elements)
    if (e.name == name) out.push_back(e);
  return out;
}

float attr(const Element& e, const std::string& name) { return std::stof(e.attributes.at(name)); }

std::vector<std::pair<float, float>> polygon_points(const Element& e) {
  std::vector<std::pair<float, float>> out;
  std::istringstream in(e.attributes.at("points"));
  float x, y;
  char comma;
  while (in >> x >> comma >> y) out.emplace_back(x, y);
  return out;
}

std::string svg_of(const Scene& scene, const ViewParameters& view, geometry::LineStyle style, int width, int height,
                   const std::string& name) {
  std::string path = test::make_temp_dir(name) + "/drawing.svg";
  io::write_vector_drawing(path, scene, test_palette(), view, style, width, height, &test_types());
  return test::read_text(path);
}

TEST(SvgTest, KochCurveReadsBack) {
  std::string word;
  Scene scene = koch_scene(&word);
  ViewParameters view;
  const std::string svg = svg_of(scene, view, geometry::LineStyle::Cylinder, 300, 200, "svg-koch");
  ASSERT_EQ(svg.rfind("<?xml", 0), 0u);
  ASSERT_NE(svg.find("</svg>"), std::string::npos);
  auto elements = parse_svg(svg);

  const auto& root = elements.at(0);
  EXPECT_EQ(root.name, "svg");
  EXPECT_EQ(root.attributes.at("width"), "300");
  EXPECT_EQ(root.attributes.at("height"), "200");
  auto rects = only(elements, "rect");
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_EQ(rects[0].attributes.at("fill"), "#ffffcc");

  const Camera camera(view, scene.bounds(), 300, 200);
  auto lines = only(elements, "line");
  ASSERT_EQ(lines.size(), 16u);
  ASSERT_EQ(scene.segments.size(), 16u);
  float top = 1e9f;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Element& line = lines[i];
    const auto& seg = scene.segments[i];  // all at one depth: in string order
    EXPECT_EQ(line.group.at("data-module"), "F");
    EXPECT_EQ(line.group.at("data-module-id"), "1");
    EXPECT_EQ(line.group.at("data-index"), std::to_string(seg.from.module_index));
    EXPECT_EQ(word[seg.from.module_index], 'F');
    Vec3 a = camera.to_pixels(seg.start), b = camera.to_pixels(seg.end);
    EXPECT_NEAR(attr(line, "x1"), a.x, 2e-3);
    EXPECT_NEAR(attr(line, "y1"), a.y, 2e-3);
    EXPECT_NEAR(attr(line, "x2"), b.x, 2e-3);
    EXPECT_NEAR(attr(line, "y2"), b.y, 2e-3);
    EXPECT_NEAR(attr(line, "stroke-width"), 0.01f * camera.pixels_per_unit(), 2e-3);
    EXPECT_EQ(line.attributes.at("stroke"), i % 2 ? "#008000" : "#ff0000");
    EXPECT_EQ(line.attributes.at("stroke-linecap"), "round");
    top = std::min({top, attr(line, "y1"), attr(line, "y2")});
  }
  // The curve starts at the bottom left and its peak, at (1/2, sqrt(3)/6), is on top.
  EXPECT_NEAR(top, camera.to_pixels({0.5f, std::sqrt(3.0f) / 6, 0}).y, 1e-2);
  EXPECT_LT(top, attr(lines.front(), "y1"));
  EXPECT_LT(attr(lines.front(), "x1"), attr(lines.back(), "x2"));
  // The curve, widths included, fills 0.9 of the image's width.
  float left = attr(lines.front(), "x1"), right = attr(lines.back(), "x2");
  float width = (right - left) + 0.01f * camera.pixels_per_unit();
  EXPECT_NEAR(width, 0.9f * 300, 0.1);
}

TEST(SvgTest, EveryKindOfPrimitive) {
  Scene scene;
  geometry::Sphere sphere;
  sphere.center = {2, 2, 0}, sphere.radius = 0.5f, sphere.color = 3, sphere.from = {1, 1};
  scene.spheres.push_back(sphere);
  geometry::Circle disc;
  disc.center = {-2, 2, 0}, disc.normal = {0, 0, 1}, disc.radius = 0.5f, disc.from = {2, 1};
  scene.circles.push_back(disc);
  geometry::Circle tilted = disc;  // normal at 45 degrees to the view: an ellipse half as tall as wide
  tilted.center = {-2, -2, 0}, tilted.normal = {0, 1, 1}, tilted.from = {3, 1};
  scene.circles.push_back(tilted);
  geometry::Circle ring = disc;
  ring.center = {2, -2, 0}, ring.outline = 0.1f, ring.from = {4, 1};
  scene.circles.push_back(ring);
  geometry::Label label;
  label.position = {0, 2, 0}, label.text = "a<b & c", label.color = 2, label.from = {5, 1};
  scene.labels.push_back(label);
  // A square polygon as two triangles sharing a diagonal, and a mesh of two.
  std::vector<Vec3> square{{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
  scene.add_triangles(geometry::TriangleGroup::Kind::Polygon, square, {}, {0, 1, 2, 0, 2, 3}, 2, {6, 1});
  std::vector<Vec3> shifted;
  for (Vec3 p : square) shifted.push_back(p + Vec3{0, -2, 0});
  scene.add_triangles(geometry::TriangleGroup::Kind::Surface, shifted, {}, {0, 1, 2, 0, 2, 3}, 1, {7, 1});
  geometry::Segment taper;
  taper.start = {-3, 0, 0}, taper.end = {-1, 0, 0}, taper.start_width = 0.4f, taper.end_width = 0.1f;
  taper.from = {8, 1};
  scene.segments.push_back(taper);

  ViewParameters view;
  view.scale = 1;
  view.box = square_box(4);
  auto elements = parse_svg(svg_of(scene, view, geometry::LineStyle::Cylinder, 400, 400, "svg-kinds"));
  // 50 pixels per unit, (0,0) at (200,200).
  auto circles = only(elements, "circle");
  ASSERT_EQ(circles.size(), 3u);
  std::map<std::string, Element> by_index;
  for (const auto& e : elements)
    if (!e.group.empty()) by_index[e.group.at("data-index")] = e;
  const Element& s = by_index.at("1");
  EXPECT_EQ(s.name, "circle");
  EXPECT_FLOAT_EQ(attr(s, "cx"), 300);
  EXPECT_FLOAT_EQ(attr(s, "cy"), 100);
  EXPECT_FLOAT_EQ(attr(s, "r"), 25);
  EXPECT_EQ(s.attributes.at("fill"), "#0000ff");
  EXPECT_EQ(by_index.at("2").name, "circle");
  EXPECT_EQ(by_index.at("4").name, "circle");
  EXPECT_EQ(by_index.at("4").attributes.at("fill"), "none");
  EXPECT_FLOAT_EQ(attr(by_index.at("4"), "stroke-width"), 5);

  const Element& ellipse = by_index.at("3");
  ASSERT_EQ(ellipse.name, "polygon");
  float x0 = 1e9f, x1 = -1e9f, y0 = 1e9f, y1 = -1e9f;
  for (auto [x, y] : polygon_points(ellipse)) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  EXPECT_NEAR(x1 - x0, 50, 0.5);
  EXPECT_NEAR(y1 - y0, 50 / std::numbers::sqrt2, 0.5);
  EXPECT_NEAR((y0 + y1) / 2, 300, 0.5);

  const Element& text = by_index.at("5");
  EXPECT_EQ(text.name, "text");
  EXPECT_EQ(text.text, "a&lt;b &amp; c");
  EXPECT_EQ(text.attributes.at("fill"), "#008000");

  const Element& polygon = by_index.at("6");
  ASSERT_EQ(polygon.name, "polygon");
  auto corners = polygon_points(polygon);
  ASSERT_EQ(corners.size(), 4u);  // the outline, not the two triangles
  for (auto [x, y] : corners) {
    EXPECT_NEAR(std::fabs(x - 200), 25, 1e-3);
    EXPECT_NEAR(std::fabs(y - 200), 25, 1e-3);
  }
  EXPECT_EQ(polygon.attributes.count("stroke"), 0u);
  int surface_triangles = 0;
  for (const auto& e : elements)
    if (!e.group.empty() && e.group.at("data-index") == "7") {
      ++surface_triangles;
      EXPECT_EQ(polygon_points(e).size(), 3u);
      EXPECT_EQ(e.attributes.at("stroke"), "#ff0000");  // hides the seam between them
    }
  EXPECT_EQ(surface_triangles, 2);

  const Element& tapered = by_index.at("8");
  ASSERT_EQ(tapered.name, "polygon");
  x0 = 1e9f, x1 = -1e9f, y0 = 1e9f, y1 = -1e9f;
  for (auto [x, y] : polygon_points(tapered)) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  EXPECT_NEAR(x0, 50 - 10, 0.1);  // round caps of radius 10 and 2.5 pixels
  EXPECT_NEAR(x1, 150 + 2.5, 0.1);
  EXPECT_NEAR(y1 - y0, 20, 0.1);
}

TEST(SvgTest, PaintsFarBeforeNearThenInStringOrder) {
  Scene scene;
  geometry::Sphere near, far;
  near.center = {0, 0, 5}, near.from = {1, 1};
  far.center = {0.5f, 0, -5}, far.from = {2, 1};
  scene.spheres = {near, far};
  geometry::Segment later, earlier;  // at one depth, the later module covers the earlier
  later.start = {-1, 0, 0}, later.end = {1, 0, 0}, later.from = {9, 1};
  earlier.start = {0, -1, 0}, earlier.end = {0, 1, 0}, earlier.from = {4, 1};
  scene.segments = {later, earlier};
  auto elements = parse_svg(svg_of(scene, ViewParameters{}, geometry::LineStyle::Pixel, 100, 100, "svg-order"));
  std::vector<std::string> order;
  for (const auto& e : elements)
    if (!e.group.empty()) order.push_back(e.group.at("data-index"));
  EXPECT_EQ(order, (std::vector<std::string>{"2", "4", "9", "1"}));
}

TEST(SvgTest, PixelLinesAreTheTurtlesWidthInPixels) {
  Scene scene = koch_scene();
  scene.segments[0].start_width = 3;
  scene.segments[1].start_width = 0.5f;  // glLineWidth draws at least one pixel
  scene.segments[1].end_width = 7;       // and one width per line
  auto lines = only(parse_svg(svg_of(scene, ViewParameters{}, geometry::LineStyle::Pixel, 300, 200, "svg-pixel")), "line");
  ASSERT_EQ(lines.size(), 16u);
  EXPECT_EQ(lines[0].attributes.at("stroke-width"), "3");
  EXPECT_EQ(lines[1].attributes.at("stroke-width"), "1");
  EXPECT_EQ(lines[2].attributes.at("stroke-width"), "1");
}

TEST(SvgTest, PolygonLineStyleFacesTheTurtlesUp) {
  Scene scene;
  geometry::Segment seg;
  seg.start = {0, 0, 0}, seg.end = {0, 1, 0}, seg.up = {0, 0, 1}, seg.start_width = seg.end_width = 0.2f;
  scene.segments.push_back(seg);
  ViewParameters view;
  view.scale = 1;
  view.box = Box{{-0.5f, 0, 0}, {0.5f, 1, 0}};
  auto polygons = only(parse_svg(svg_of(scene, view, geometry::LineStyle::Polygon, 100, 100, "svg-polygon")), "polygon");
  ASSERT_EQ(polygons.size(), 1u);
  auto corners = polygon_points(polygons[0]);
  ASSERT_EQ(corners.size(), 4u);
  for (auto [x, y] : corners) {
    EXPECT_NEAR(std::fabs(x - 50), 10, 1e-3);  // no caps: a strip of width 0.2 along y
    EXPECT_TRUE(std::fabs(y) < 1e-3 || std::fabs(y - 100) < 1e-3);
  }
  // Seen edge-on (up in the screen plane), the strip vanishes as in lpfg.
  scene.segments[0].up = {1, 0, 0};
  polygons = only(parse_svg(svg_of(scene, view, geometry::LineStyle::Polygon, 100, 100, "svg-polygon")), "polygon");
  ASSERT_EQ(polygons.size(), 1u);
  for (auto [x, y] : polygon_points(polygons[0])) EXPECT_NEAR(x, 50, 1e-3);
}

TEST(SvgTest, PolygonWithHoleIsOnePath) {
  // A square ring: four outer and four inner corners, two triangles per side.
  std::vector<Vec3> corners{{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  std::vector<std::uint32_t> triangles;
  for (std::uint32_t i = 0; i < 4; ++i) {
    std::uint32_t j = (i + 1) % 4;
    triangles.insert(triangles.end(), {i, j, 4 + j, i, 4 + j, 4 + i});
  }
  Scene scene;
  scene.add_triangles(geometry::TriangleGroup::Kind::Polygon, corners, {}, triangles, 1, {3, 1});
  ViewParameters view;
  view.scale = 1;
  auto elements = parse_svg(svg_of(scene, view, geometry::LineStyle::Pixel, 100, 100, "svg-hole"));
  ASSERT_EQ(elements.size(), 3u);
  const Element& path = elements[2];
  ASSERT_EQ(path.name, "path");
  EXPECT_EQ(path.attributes.at("fill-rule"), "evenodd");
  const std::string& d = path.attributes.at("d");
  EXPECT_EQ(std::count(d.begin(), d.end(), 'M'), 2);
  EXPECT_EQ(std::count(d.begin(), d.end(), 'L'), 6);
  EXPECT_EQ(std::count(d.begin(), d.end(), 'Z'), 2);
  EXPECT_NE(d.find("25 75"), std::string::npos) << d;  // the inner corner (-1,-1)
}

// --- PDF and PostScript, rasterized -------------------------------------------

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  std::array<int, 3> at(int x, int y) const {
    std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

// Binary PPM (P6), as pdftoppm and ghostscript write it: no PNG decoder needed.
Image read_ppm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  // Header fields, skipping the comments ghostscript puts between them.
  auto field = [&] {
    std::string word;
    while (in >> word && word[0] == '#') std::getline(in, word);
    return word;
  };
  Image image;
  std::string magic = field();
  image.width = std::stoi(field());
  image.height = std::stoi(field());
  int maxval = std::stoi(field());
  in.get();
  EXPECT_EQ(magic, "P6");
  EXPECT_EQ(maxval, 255);
  image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
  in.read(reinterpret_cast<char*>(image.rgb.data()), static_cast<std::streamsize>(image.rgb.size()));
  return image;
}

// A red bar across the top half, a green one down the lower left, a blue ball
// at the lower right, in a 200 x 200 drawing of the box [-1,1]^2: 100 pixels per unit.
Scene raster_scene() {
  Scene scene;
  geometry::Segment bar;
  bar.start = {-0.8f, 0.5f, 0}, bar.end = {0.8f, 0.5f, 0}, bar.start_width = bar.end_width = 0.1f, bar.color = 1;
  scene.segments.push_back(bar);
  bar.start = {-0.5f, -0.8f, 0}, bar.end = {-0.5f, 0, 0}, bar.color = 2, bar.from.module_index = 1;
  scene.segments.push_back(bar);
  geometry::Sphere ball;
  ball.center = {0.5f, -0.5f, 0}, ball.radius = 0.2f, ball.color = 3, ball.from.module_index = 2;
  scene.spheres.push_back(ball);
  return scene;
}

ViewParameters raster_view() {
  ViewParameters view;
  view.scale = 1;
  view.box = square_box(1);
  return view;
}

void expect_color(const Image& image, int x, int y, std::array<int, 3> expected) {
  auto c = image.at(x, y);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], expected[k], 8) << "channel " << k << " at (" << x << "," << y << ")";
}

void check_raster(const Image& image) {
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  const std::array<int, 3> background{255, 255, 204}, red{255, 0, 0}, green{0, 128, 0}, blue{0, 0, 255};
  expect_color(image, 100, 50, red);    // the bar's middle
  expect_color(image, 25, 50, red);     // near its left end
  expect_color(image, 100, 46, red);    // 5 pixels thick each side
  expect_color(image, 100, 40, background);
  expect_color(image, 100, 60, background);
  expect_color(image, 5, 50, background);  // past the end and its cap
  expect_color(image, 50, 150, green);
  expect_color(image, 50, 110, green);
  expect_color(image, 50, 192, background);
  expect_color(image, 150, 150, blue);
  expect_color(image, 150 + 17, 150, blue);
  expect_color(image, 150 + 23, 150, background);
  expect_color(image, 150, 100, background);
  expect_color(image, 100, 150, background);
  int marked = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) marked += image.at(x, y) != background;
  // The bars (160 x 10 and 80 x 10, plus caps of radius 5) and the ball (radius
  // 20); antialiasing (poppler) or ghostscript's any-part-of-a-pixel rule adds
  // some of the pixels the outlines cross.
  const double area = 160 * 10 + 80 * 10 + std::numbers::pi * (2 * 5 * 5 + 20 * 20);
  EXPECT_GT(marked, area - 50);
  EXPECT_LT(marked, area + 400);
}

TEST(PdfTest, RasterizedShowsTheLinesAndNothingElse) {
  std::string dir = test::make_temp_dir("pdf-raster");
  std::string pdf = dir + "/drawing.pdf";
  io::write_vector_drawing(pdf, raster_scene(), test_palette(), raster_view(), geometry::LineStyle::Cylinder, 200, 200);
  EXPECT_EQ(test::read_text(pdf).rfind("%PDF-", 0), 0u);
  auto result = run_process({"pdftoppm", "-r", "72", "-singlefile", pdf, dir + "/page"});
  if (result.exit_code == -1) GTEST_SKIP() << "pdftoppm is not installed";
  ASSERT_EQ(result.exit_code, 0) << result.err;
  check_raster(read_ppm(dir + "/page.ppm"));
}

TEST(VectorPostScriptTest, WellFormedAndRasterized) {
  std::string dir = test::make_temp_dir("ps-raster");
  std::string ps = dir + "/drawing.ps";
  io::write_vector_drawing(ps, raster_scene(), test_palette(), raster_view(), geometry::LineStyle::Cylinder, 200, 200);
  std::string text = test::read_text(ps);
  EXPECT_EQ(text.rfind("%!PS-Adobe-3.0", 0), 0u);
  EXPECT_NE(text.find("showpage"), std::string::npos);
  EXPECT_NE(text.find("%%EOF"), std::string::npos);

  std::string eps = dir + "/drawing.eps";
  io::write_vector_drawing(eps, raster_scene(), test_palette(), raster_view(), geometry::LineStyle::Cylinder, 200, 200);
  text = test::read_text(eps);
  EXPECT_EQ(text.rfind("%!PS-Adobe-3.0 EPSF-3.0", 0), 0u);
  EXPECT_NE(text.find("%%BoundingBox: 0 0 200 200"), std::string::npos);

  auto result = run_process({"gs", "-q", "-dSAFER", "-dBATCH", "-dNOPAUSE", "-sDEVICE=ppmraw", "-r72", "-g200x200",
                             "-dFIXEDMEDIA", "-sOutputFile=" + dir + "/page.ppm", ps});
  if (result.exit_code == -1) GTEST_SKIP() << "ghostscript is not installed";
  ASSERT_EQ(result.exit_code, 0) << result.err;
  check_raster(read_ppm(dir + "/page.ppm"));
}

TEST(VectorWriterTest, FailedWritesLeaveNoFile) {
  std::string dir = test::make_temp_dir("vector-fail");
  for (const char* name : {"/missing/drawing.svg", "/missing/drawing.pdf", "/missing/drawing.eps", "/drawing.txt"}) {
    std::string path = dir + name;
    try {
      io::write_vector_drawing(path, koch_scene(), test_palette(), ViewParameters{}, geometry::LineStyle::Pixel, 100, 100);
      ADD_FAILURE() << "no error for " << path;
    } catch (const ModelError& e) {
      EXPECT_EQ(e.where().file, path);
    }
    EXPECT_FALSE(fs::exists(path));
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(VectorWriterTest, EmptySceneIsJustTheBackground) {
  std::string dir = test::make_temp_dir("vector-empty");
  io::write_vector_drawing(dir + "/empty.svg", Scene{}, test_palette(), ViewParameters{}, geometry::LineStyle::Pixel, 64, 48);
  auto elements = parse_svg(test::read_text(dir + "/empty.svg"));
  ASSERT_EQ(elements.size(), 2u);
  EXPECT_EQ(elements[1].name, "rect");
  io::write_vector_drawing(dir + "/empty.pdf", Scene{}, test_palette(), ViewParameters{}, geometry::LineStyle::Pixel, 64, 48);
  EXPECT_EQ(test::read_text(dir + "/empty.pdf").rfind("%PDF-", 0), 0u);
}

}  // namespace
}  // namespace sylva
