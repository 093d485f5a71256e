// Text is placed from Courier's advance (0.6 em) rather than measured: the
// cairo plugin draws every text of a Drawing in Courier, and a monospaced font
// lets labels be centred and right-aligned without asking cairo here.
#include "api/series_plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

#include "geometry/material.h"
#include "geometry/vec3.h"
#include "io/output_file.h"
#include "render/vector_drawing.h"
#include "render/vector_writer.h"
#include "support/diagnostic.h"

namespace sylva {
namespace {

using geometry::Rgb;
using geometry::Vec2;
using io::Shape;

constexpr float kFontSize = 12;
constexpr float kCharWidth = 0.6f * kFontSize;
constexpr float kDotRadius = 1.8f;
constexpr float kTickLength = 5;
constexpr float kLegendRow = 18;
constexpr int kMinWidth = 320, kMinHeight = 200, kMaxSize = 16384;

constexpr Rgb rgb(int r, int g, int b) {
  return {static_cast<float>(r) / 255, static_cast<float>(g) / 255, static_cast<float>(b) / 255};
}

// Tableau's ten categorical colours: told apart by most eyes, and none of them
// the ink or grid grey of the axes.
constexpr std::array<Rgb, 10> kPalette = {rgb(31, 119, 180), rgb(255, 127, 14), rgb(44, 160, 44),  rgb(214, 39, 40),
                                          rgb(148, 103, 189), rgb(140, 86, 75),  rgb(227, 119, 194), rgb(127, 127, 127),
                                          rgb(188, 189, 34),  rgb(23, 190, 207)};
constexpr Rgb kInk = rgb(0, 0, 0);
constexpr Rgb kGrid = rgb(225, 225, 225);
constexpr Rgb kPaper = rgb(255, 255, 255);

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
};

// The data and 5% on either side, so that no dot sits on the frame.
Range padded(const Range& r) {
  if (r.empty()) return {0, 1};
  double pad = 0.05 * (r.hi - r.lo);
  if (!(pad > 1e-14 * std::max(std::abs(r.lo), std::abs(r.hi)))) pad = 0.5;  // constant, up to rounding
  Range out{r.lo - pad, r.hi + pad};
  // Beyond about 1e16 half a unit is lost to rounding; a relative pad is not.
  if (!(out.hi > out.lo)) out = {r.lo - std::abs(r.lo) * 1e-9, r.hi + std::abs(r.hi) * 1e-9};
  return out;
}

// The smallest of 1, 2, 5 x 10^k that cuts `span` into at most `most` parts.
double nice_step(double span, int most) {
  const double raw = span / most;
  const double unit = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * unit >= raw * (1 - 1e-9)) return m * unit;
  return 10 * unit;
}

std::string tick_label(double v, double step) {
  if (std::abs(v) < step * 1e-6) return "0";  // not -0 or 1e-17 from k * step
  const int step_exponent = static_cast<int>(std::floor(std::log10(step) + 1e-9));
  char buf[64];
  if (step_exponent >= -6 && std::abs(v) < 1e9) {
    std::snprintf(buf, sizeof buf, "%.*f", std::max(0, -step_exponent), v);
  } else {  // as many digits as tell neighbouring ticks apart
    const int digits = static_cast<int>(std::floor(std::log10(std::abs(v)))) - step_exponent + 1;
    std::snprintf(buf, sizeof buf, "%.*g", std::clamp(digits, 1, 15), v);
  }
  return buf;
}

struct Ticks {
  std::vector<double> at;
  std::vector<std::string> labels;
  std::size_t widest = 0;  // characters
};

// Ticks on an axis `pixels` long, as many as leave room between labels: side
// by side on a horizontal axis, one above another on a vertical one.
Ticks ticks_for(const Range& r, float pixels, bool horizontal) {
  const double span = r.hi - r.lo;
  for (int most = std::max(2, static_cast<int>(pixels / (horizontal ? 70 : 50)));; --most) {
    Ticks t;
    const double step = nice_step(span, most);
    if (!std::isfinite(step) || !(step > 0)) return t;
    const double first = std::ceil(r.lo / step - 1e-9), last = std::floor(r.hi / step + 1e-9);
    for (double k = first; k <= last && t.at.size() < 100; ++k) {
      t.at.push_back(k * step);
      t.labels.push_back(tick_label(k * step, step));
      t.widest = std::max(t.widest, t.labels.back().size());
    }
    const double gap = pixels * step / span;
    const double needed = horizontal ? static_cast<double>(t.widest) * kCharWidth + 12 : 1.5 * kFontSize;
    if (gap >= needed || most <= 1) return t;
  }
}

Shape line(Vec2 a, Vec2 b, Rgb color) {
  Shape s;
  s.kind = Shape::Kind::Line;
  s.points = {a, b};
  s.stroke = 1;
  s.color = color;
  return s;
}

Shape dot(Vec2 at, float radius, Rgb color) {
  Shape s;
  s.kind = Shape::Kind::Circle;
  s.points = {at};
  s.radius = radius;
  s.color = color;
  return s;
}

// `align` 0 puts the text's start at x, 0.5 its middle, 1 its end; y is the
// middle of its capitals.
Shape text(std::string words, float x, float y, float align = 0) {
  Shape s;
  s.kind = Shape::Kind::Text;
  s.points = {{x - align * static_cast<float>(words.size()) * kCharWidth, y + 0.35f * kFontSize}};
  s.text = std::move(words);
  s.color = kInk;
  return s;
}

std::string shortened(const std::string& name, std::size_t chars) {
  return name.size() <= chars ? name : name.substr(0, chars - 3) + "...";
}

bool finite_point(const PlotSeries& s, std::size_t i) { return std::isfinite(s.t[i]) && std::isfinite(s.value[i]); }

}  // namespace

void write_series_plot(const std::string& path, const std::vector<PlotSeries>& series, const std::string& title,
                       int width, int height) {
  const SourceLocation where{path, 0, 0};
  if (width < kMinWidth || height < kMinHeight || width > kMaxSize || height > kMaxSize)
    throw ModelError(where, "a plot of " + std::to_string(width) + " x " + std::to_string(height) +
                                " pixels: it takes 320 x 200 to 16384 x 16384");
  Range t_data, v_data;
  std::vector<std::size_t> shown;  // the series with points, in the legend
  for (std::size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    if (s.t.size() != s.value.size())
      throw ModelError(where, "series '" + s.name + "' has " + std::to_string(s.t.size()) + " times but " +
                                  std::to_string(s.value.size()) + " values");
    bool any = false;
    for (std::size_t i = 0; i < s.t.size(); ++i) {
      if (!finite_point(s, i)) continue;
      t_data.add(s.t[i]);
      v_data.add(s.value[i]);
      any = true;
    }
    if (any) shown.push_back(k);
  }
  const Range t_range = padded(t_data), v_range = padded(v_data);

  // Margins: the title above, the y labels' width on the left, the legend's
  // on the right, x labels and the axis' name below.
  const std::size_t legend_chars =
      std::clamp<std::size_t>(static_cast<std::size_t>((0.3f * static_cast<float>(width) - 40) / kCharWidth), 4, 40);
  std::size_t longest = 0;
  for (std::size_t k : shown) longest = std::max(longest, std::min(series[k].name.size(), legend_chars));
  const float top = title.empty() ? 16 : 40;
  const float bottom = static_cast<float>(height) - 46;
  const Ticks v_ticks = ticks_for(v_range, bottom - top, false);
  const float left = std::round(10 + static_cast<float>(v_ticks.widest) * kCharWidth + kTickLength + 6);
  const float right = static_cast<float>(width) -
                      (shown.empty() ? 20 : std::round(static_cast<float>(longest) * kCharWidth + 50));
  if (right - left < 40) throw ModelError(where, "no room for the plot's axes in " + std::to_string(width) + " pixels");
  const Ticks t_ticks = ticks_for(t_range, right - left, true);

  auto x_of = [&](double t) {
    return left + static_cast<float>((t - t_range.lo) / (t_range.hi - t_range.lo) * (right - left));
  };
  auto y_of = [&](double v) {
    return bottom - static_cast<float>((v - v_range.lo) / (v_range.hi - v_range.lo) * (bottom - top));
  };
  // One-pixel lines on pixel centres, so they stay sharp.
  auto crisp = [](float at) { return std::floor(at) + 0.5f; };

  io::Drawing d;
  d.width = width;
  d.height = height;
  d.background = kPaper;
  d.line_cap = io::LineCap::Butt;
  d.font_size = kFontSize;
  for (double t : t_ticks.at) d.shapes.push_back(line({crisp(x_of(t)), top}, {crisp(x_of(t)), bottom}, kGrid));
  for (double v : v_ticks.at) d.shapes.push_back(line({left, crisp(y_of(v))}, {right, crisp(y_of(v))}, kGrid));

  // Many modules put points on the same pixel; one dot per pixel and series
  // looks the same and keeps the drawing as small as the plot, not the data.
  const auto columns = static_cast<std::size_t>(right - left) + 1, rows = static_cast<std::size_t>(bottom - top) + 1;
  std::vector<bool> taken(columns * rows);
  for (std::size_t k : shown) {
    const PlotSeries& s = series[k];
    std::fill(taken.begin(), taken.end(), false);
    for (std::size_t i = 0; i < s.t.size(); ++i) {
      if (!finite_point(s, i)) continue;
      const Vec2 at{x_of(s.t[i]), y_of(s.value[i])};
      if (!std::isfinite(at.x) || !std::isfinite(at.y)) continue;
      const auto column = static_cast<std::size_t>(std::clamp(at.x - left, 0.0f, static_cast<float>(columns - 1)));
      const auto row = static_cast<std::size_t>(std::clamp(at.y - top, 0.0f, static_cast<float>(rows - 1)));
      if (taken[row * columns + column]) continue;
      taken[row * columns + column] = true;
      d.shapes.push_back(dot(at, kDotRadius, kPalette[k % kPalette.size()]));
    }
  }

  const float l = crisp(left), r = crisp(right), t = crisp(top), b = crisp(bottom);
  d.shapes.push_back(line({l, t}, {r, t}, kInk));
  d.shapes.push_back(line({r, t}, {r, b}, kInk));
  d.shapes.push_back(line({l, b}, {r, b}, kInk));
  d.shapes.push_back(line({l, t}, {l, b}, kInk));
  for (std::size_t i = 0; i < t_ticks.at.size(); ++i) {
    const float x = crisp(x_of(t_ticks.at[i]));
    d.shapes.push_back(line({x, b}, {x, b + kTickLength}, kInk));
    d.shapes.push_back(text(t_ticks.labels[i], x, b + kTickLength + 10, 0.5f));
  }
  for (std::size_t i = 0; i < v_ticks.at.size(); ++i) {
    const float y = crisp(y_of(v_ticks.at[i]));
    d.shapes.push_back(line({l - kTickLength, y}, {l, y}, kInk));
    d.shapes.push_back(text(v_ticks.labels[i], l - kTickLength - 4, y, 1));
  }
  d.shapes.push_back(text("t", (left + right) / 2, b + kTickLength + 30, 0.5f));

  // The legend beside the plot, as many rows as its height holds.
  const std::size_t fit = std::max<std::size_t>(1, static_cast<std::size_t>((bottom - top) / kLegendRow));
  const std::size_t listed = shown.size() <= fit ? shown.size() : fit - 1;
  for (std::size_t i = 0; i < listed; ++i) {
    const float y = top + 8 + static_cast<float>(i) * kLegendRow;
    d.shapes.push_back(dot({right + 20, y}, 4, kPalette[shown[i] % kPalette.size()]));
    d.shapes.push_back(text(shortened(series[shown[i]].name, legend_chars), right + 30, y));
  }
  if (listed < shown.size())
    d.shapes.push_back(text("+" + std::to_string(shown.size() - listed) + " more", right + 14,
                            top + 8 + static_cast<float>(listed) * kLegendRow));

  if (!title.empty()) {  // centred over the plot, unless that pushes it off the left edge
    const float half = static_cast<float>(title.size()) * kCharWidth / 2;
    d.shapes.push_back(text(title, std::max(4 + half, (left + right) / 2), top / 2, 0.5f));
  }

  io::write_output_file(path, io::drawing_png(d, path));
}

}  // namespace sylva
