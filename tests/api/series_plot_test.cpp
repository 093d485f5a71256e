// Plots of recorded series read back with stb_image, not with the cairo that
// drew them.
#include "api/series_plot.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "support/diagnostic.h"
#include "test_support.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace sylva {
namespace {

namespace fs = std::filesystem;
using Pixel = std::array<int, 3>;

// The plot palette's first four colours (Tableau's blue, orange, green and
// red): series 0 to 3.
constexpr Pixel kFirst{31, 119, 180}, kSecond{255, 127, 14}, kThird{44, 160, 44}, kFourth{214, 39, 40};

struct Png {
  int width = 0, height = 0;
  std::vector<Pixel> pixels;  // rows top to bottom
  const Pixel& at(int x, int y) const { return pixels[static_cast<std::size_t>(y * width + x)]; }
};

Png read_png(const std::string& path) {
  Png png;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
  if (!data) {
    ADD_FAILURE() << path << ": " << stbi_failure_reason();
    return {};
  }
  for (int i = 0; i < png.width * png.height; ++i)
    png.pixels.push_back({data[3 * i], data[3 * i + 1], data[3 * i + 2]});
  stbi_image_free(data);
  return png;
}

// Within rounding of `c`: only a dot's fully covered pixels are.
bool near(const Pixel& p, const Pixel& c) {
  return std::abs(p[0] - c[0]) <= 2 && std::abs(p[1] - c[1]) <= 2 && std::abs(p[2] - c[2]) <= 2;
}

// How many pixels of `c` lie in x0 <= x < x1, y0 <= y < y1.
int count(const Png& png, const Pixel& c, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) n += near(png.at(x, y), c);
  return n;
}
int count(const Png& png, const Pixel& c) { return count(png, c, 0, 0, png.width, png.height); }

// How many rows, top to bottom, lie between the first and the last with a
// pixel of `c` in x0 <= x < x1 (0 without any).
int rows_spanned(const Png& png, const Pixel& c, int x0, int x1) {
  int first = -1, last = -1;
  for (int y = 0; y < png.height; ++y)
    if (count(png, c, x0, y, x1, y + 1) > 0) {
      if (first < 0) first = y;
      last = y;
    }
  return first < 0 ? 0 : last - first + 1;
}

// Series 0 has one point, at the bottom left of series 1's points, which
// fill 0..10 both ways.
std::vector<PlotSeries> two_series(bool first_empty = false) {
  PlotSeries first{"Cell p1", {0}, {0}};
  if (first_empty) first = {"Cell p1", {}, {}};
  PlotSeries second{"Cell p2", {}, {}};
  for (int i = 1; i <= 10; ++i) {
    second.t.push_back(i);
    second.value.push_back(i % 2 ? 10 - i : i);
  }
  return {first, second};
}

// A ramp from 0 up to `scale` at t = 0..10.
PlotSeries ramp(const std::string& name, double scale) {
  PlotSeries s{name, {}, {}};
  for (int i = 0; i <= 10; ++i) {
    s.t.push_back(i);
    s.value.push_back(scale * i / 10);
  }
  return s;
}

TEST(SeriesPlot, DrawsAPngOfTheGivenSize) {
  const std::string path = test::make_temp_dir("series_plot_size") + "/plot.png";
  write_series_plot(path, two_series(), "Cell", 640, 400);
  const Png png = read_png(path);
  ASSERT_EQ(png.width, 640);
  ASSERT_EQ(png.height, 400);
  EXPECT_EQ(png.at(0, 0), (Pixel{255, 255, 255}));  // white paper
  std::set<Pixel> colours(png.pixels.begin(), png.pixels.end());
  EXPECT_GT(colours.size(), 10u);  // not blank: ink, grid, text's grey edges, dots
  EXPECT_GT(count(png, {0, 0, 0}), 500);  // the two frames alone are some 2800 pixels
}

TEST(SeriesPlot, EachSeriesHasAPanelOfItsOwnWithItsOwnRange) {
  // 0..1 and 0..1000: on one axis the first would be a flat line at the bottom.
  const std::string path = test::make_temp_dir("series_plot_panels") + "/plot.png";
  write_series_plot(path, {ramp("Cell p1", 1), ramp("Cell p2", 1000)}, "Cell", 900, 600);
  const Png png = read_png(path);
  ASSERT_EQ(png.width, 900);
  ASSERT_EQ(png.height, 600);
  // Series 0 (dots and name) in the top panel, series 1 in the bottom one.
  EXPECT_GT(count(png, kFirst, 0, 0, 900, 300), 0);
  EXPECT_EQ(count(png, kFirst, 0, 300, 900, 600), 0);
  EXPECT_GT(count(png, kSecond, 0, 300, 900, 600), 0);
  EXPECT_EQ(count(png, kSecond, 0, 0, 900, 300), 0);
  // Each ramp climbs through most of its panel of some 240 rows; in the
  // right half (t from about 5 on), away from the names, half of it.
  EXPECT_GT(rows_spanned(png, kFirst, 450, 900), 80);
  EXPECT_GT(rows_spanned(png, kSecond, 450, 900), 80);
}

TEST(SeriesPlot, EachSeriesHasItsColourWhereItsPointsAre) {
  const std::string dir = test::make_temp_dir("series_plot_colours");
  write_series_plot(dir + "/both.png", two_series(), "Cell", 900, 600);
  const Png both = read_png(dir + "/both.png");
  ASSERT_EQ(both.width, 900);
  // Series 0's one point, constant data, sits halfway up the top panel (rows
  // some 50 to 290) at its left edge, its name above that; the top right
  // stays clear of it.
  EXPECT_GT(count(both, kFirst, 0, 150, 450, 300), 0);
  EXPECT_EQ(count(both, kFirst, 450, 0, 900, 300), 0);
  EXPECT_EQ(count(both, kFirst, 0, 300, 900, 600), 0);
  EXPECT_GT(count(both, kSecond, 0, 300, 900, 600), 0);

  // A series without points gets no panel: the other one has the height.
  write_series_plot(dir + "/second.png", two_series(true), "Cell", 900, 600);
  const Png second = read_png(dir + "/second.png");
  ASSERT_EQ(second.width, 900);
  EXPECT_EQ(count(second, kFirst), 0);  // neither dot nor name
  EXPECT_GT(count(second, kSecond, 0, 0, 900, 150), 0);
  EXPECT_GT(count(second, kSecond, 0, 450, 900, 600), 0);
}

TEST(SeriesPlot, SeriesBeyondTheHeightAreCountedNotDrawn) {
  const std::string dir = test::make_temp_dir("series_plot_many");
  std::vector<PlotSeries> many;
  for (int k = 0; k < 10; ++k) many.push_back(ramp("M p" + std::to_string(k + 1), k + 1));
  // Some 200 rows of panels hold two at the least readable height.
  write_series_plot(dir + "/many.png", many, "M", 400, 300);
  const Png png = read_png(dir + "/many.png");
  ASSERT_EQ(png.height, 300);
  EXPECT_GT(count(png, kFirst), 0);
  EXPECT_GT(count(png, kSecond), 0);
  EXPECT_EQ(count(png, kThird), 0);
  EXPECT_EQ(count(png, kFourth), 0);
  // "+8 more series not shown" at the bottom left, where a plot without
  // hidden series has nothing.
  auto dark = [](const Png& p) {
    int n = 0;
    for (int y = p.height - 20; y < p.height; ++y)
      for (int x = 0; x < p.width / 3; ++x) n += p.at(x, y)[0] + p.at(x, y)[1] + p.at(x, y)[2] < 384;
    return n;
  };
  EXPECT_GT(dark(png), 20);
  write_series_plot(dir + "/two.png", {many[0], many[1]}, "M", 400, 300);
  EXPECT_EQ(dark(read_png(dir + "/two.png")), 0);
}

TEST(SeriesPlot, ConstantOrMissingDataStillMakesAPlot) {
  const std::string dir = test::make_temp_dir("series_plot_degenerate");
  write_series_plot(dir + "/constant.png", {{"A x", {0, 1, 2}, {3, 3, 3}}}, "", 400, 300);
  EXPECT_GT(count(read_png(dir + "/constant.png"), kFirst), 0);
  write_series_plot(dir + "/none.png", {}, "nothing recorded", 400, 300);
  EXPECT_EQ(read_png(dir + "/none.png").width, 400);
  write_series_plot(dir + "/nan.png", {{"A x", {0, 1}, {std::nan(""), 2}}}, "t", 400, 300);
  EXPECT_GT(count(read_png(dir + "/nan.png"), kFirst), 0);
}

TEST(SeriesPlot, BadPathOrSeriesIsAnErrorNamingThePath) {
  const std::string dir = test::make_temp_dir("series_plot_bad");
  const std::string path = dir + "/missing/plot.png";
  try {
    write_series_plot(path, two_series(), "Cell");
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));

  const std::string good = dir + "/plot.png";
  EXPECT_THROW(write_series_plot(good, {{"A x", {0, 1}, {2}}}, "Cell"), ModelError);
  EXPECT_THROW(write_series_plot(good, two_series(), "Cell", 10, 10), ModelError);
  EXPECT_FALSE(fs::exists(good));
}

}  // namespace
}  // namespace sylva
