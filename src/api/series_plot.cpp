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
// Each panel: the series' name in a row of its own, the framed plot, a gap
// to the next; kMinPanel is the least of all three that still reads.
constexpr float kNameRow = 18, kPanelGap = 8, kMinPanel = 80;
constexpr float kNoticeRow = 18;  // "+N more series not shown"
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
// by side on a horizontal axis, one above another on a vertical one. A short
// vertical axis (a panel among many) starts from three parts, so that it
// mostly gets two labels, not one, to read its scale from.
Ticks ticks_for(const Range& r, float pixels, bool horizontal) {
  const double span = r.hi - r.lo;
  for (int most = std::max(horizontal ? 2 : 3, static_cast<int>(pixels / (horizontal ? 70 : 50)));; --most) {
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
Shape text(std::string words, float x, float y, float align = 0, Rgb color = kInk) {
  Shape s;
  s.kind = Shape::Kind::Text;
  s.points = {{x - align * static_cast<float>(words.size()) * kCharWidth, y + 0.35f * kFontSize}};
  s.text = std::move(words);
  s.color = color;
  return s;
}

std::string shortened(const std::string& name, std::size_t chars) {
  return name.size() <= chars ? name : name.substr(0, chars - 3) + "...";
}

bool finite_point(const PlotSeries& s, std::size_t i) { return std::isfinite(s.t[i]) && std::isfinite(s.value[i]); }

}  // namespace

void write_series_plot(const std::string& path, const std::vector<PlotSeries>& series, const std::string& title,
                       int width, int height, const std::string& x_label) {
  const SourceLocation where{path, 0, 0};
  if (width < kMinWidth || height < kMinHeight || width > kMaxSize || height > kMaxSize)
    throw ModelError(where, "a plot of " + std::to_string(width) + " x " + std::to_string(height) +
                                " pixels: it takes 320 x 200 to 16384 x 16384");
  std::vector<std::size_t> shown;  // the series with points, one panel each
  std::vector<Range> v_data(series.size());
  for (std::size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    if (s.t.size() != s.value.size())
      throw ModelError(where, "series '" + s.name + "' has " + std::to_string(s.t.size()) + " times but " +
                                  std::to_string(s.value.size()) + " values");
    for (std::size_t i = 0; i < s.t.size(); ++i)
      if (finite_point(s, i)) v_data[k].add(s.value[i]);
    if (!v_data[k].empty()) shown.push_back(k);
  }

  // The title above, x labels and the axis' name below, and between them as
  // many panels as fit at kMinPanel; the rest are counted on a line of their
  // own at the very bottom.
  const float top = title.empty() ? 6 : 32;
  auto panels_fitting = [&](float bottom) {
    return std::max<std::size_t>(1, static_cast<std::size_t>((bottom - top + kPanelGap) / kMinPanel));
  };
  float bottom = static_cast<float>(height) - 46;
  std::size_t drawn = std::min(shown.size(), panels_fitting(bottom));
  if (drawn < shown.size()) {
    bottom -= kNoticeRow;
    drawn = std::min(drawn, panels_fitting(bottom));
  }
  const std::size_t panels = std::max<std::size_t>(1, drawn);  // an empty one without data
  const float slot = (bottom - top + kPanelGap) / static_cast<float>(panels);
  struct Panel {
    std::size_t series = 0;  // index into `series`, for panels with data
    float top = 0, bottom = 0;
    Range range;
    Ticks ticks;
  };
  std::vector<Panel> layout(panels);
  Range t_data;
  std::size_t widest = 0;
  for (std::size_t p = 0; p < panels; ++p) {
    Panel& pane = layout[p];
    pane.top = std::round(top + static_cast<float>(p) * slot + kNameRow);
    pane.bottom = std::round(top + static_cast<float>(p + 1) * slot - kPanelGap);
    pane.range = padded(p < drawn ? v_data[shown[p]] : Range{});
    pane.ticks = ticks_for(pane.range, pane.bottom - pane.top, false);
    widest = std::max(widest, pane.ticks.widest);
    if (p >= drawn) continue;
    pane.series = shown[p];
    const PlotSeries& s = series[pane.series];
    for (std::size_t i = 0; i < s.t.size(); ++i)
      if (finite_point(s, i)) t_data.add(s.t[i]);
  }
  const Range t_range = padded(t_data);
  // One left edge for all panels, wide enough for the widest y labels.
  const float left = std::round(10 + static_cast<float>(widest) * kCharWidth + kTickLength + 6);
  const float right = static_cast<float>(width) - 20;
  if (right - left < 40) throw ModelError(where, "no room for the plot's axes in " + std::to_string(width) + " pixels");
  const Ticks t_ticks = ticks_for(t_range, right - left, true);

  auto x_of = [&](double t) {
    return left + static_cast<float>((t - t_range.lo) / (t_range.hi - t_range.lo) * (right - left));
  };
  // One-pixel lines on pixel centres, so they stay sharp.
  auto crisp = [](float at) { return std::floor(at) + 0.5f; };

  io::Drawing d;
  d.width = width;
  d.height = height;
  d.background = kPaper;
  d.line_cap = io::LineCap::Butt;
  d.font_size = kFontSize;
  const float l = crisp(left), r = crisp(right);
  const auto name_chars = static_cast<std::size_t>((right - left) / kCharWidth);
  std::vector<bool> taken;
  for (std::size_t p = 0; p < panels; ++p) {
    const Panel& pane = layout[p];
    auto y_of = [&](double v) {
      const double share = (v - pane.range.lo) / (pane.range.hi - pane.range.lo);
      return pane.bottom - static_cast<float>(share * (pane.bottom - pane.top));
    };
    for (double t : t_ticks.at)
      d.shapes.push_back(line({crisp(x_of(t)), pane.top}, {crisp(x_of(t)), pane.bottom}, kGrid));
    for (double v : pane.ticks.at) d.shapes.push_back(line({left, crisp(y_of(v))}, {right, crisp(y_of(v))}, kGrid));

    if (p < drawn) {
      // Many modules put points on the same pixel; one dot per pixel looks
      // the same and keeps the drawing as small as the plot, not the data.
      const PlotSeries& s = series[pane.series];
      const Rgb colour = kPalette[pane.series % kPalette.size()];
      const auto columns = static_cast<std::size_t>(right - left) + 1;
      const auto rows = static_cast<std::size_t>(pane.bottom - pane.top) + 1;
      taken.assign(columns * rows, false);
      for (std::size_t i = 0; i < s.t.size(); ++i) {
        if (!finite_point(s, i)) continue;
        const Vec2 at{x_of(s.t[i]), y_of(s.value[i])};
        if (!std::isfinite(at.x) || !std::isfinite(at.y)) continue;
        const auto column = static_cast<std::size_t>(std::clamp(at.x - left, 0.0f, static_cast<float>(columns - 1)));
        const auto row = static_cast<std::size_t>(std::clamp(at.y - pane.top, 0.0f, static_cast<float>(rows - 1)));
        if (taken[row * columns + column]) continue;
        taken[row * columns + column] = true;
        d.shapes.push_back(dot(at, kDotRadius, colour));
      }
      d.shapes.push_back(text(shortened(s.name, std::max<std::size_t>(4, name_chars)), left,
                              pane.top - kNameRow / 2 - 1, 0, colour));
    }

    const float t = crisp(pane.top), b = crisp(pane.bottom);
    d.shapes.push_back(line({l, t}, {r, t}, kInk));
    d.shapes.push_back(line({r, t}, {r, b}, kInk));
    d.shapes.push_back(line({l, b}, {r, b}, kInk));
    d.shapes.push_back(line({l, t}, {l, b}, kInk));
    for (std::size_t i = 0; i < pane.ticks.at.size(); ++i) {
      const float y = crisp(y_of(pane.ticks.at[i]));
      d.shapes.push_back(line({l - kTickLength, y}, {l, y}, kInk));
      d.shapes.push_back(text(pane.ticks.labels[i], l - kTickLength - 4, y, 1));
    }
  }

  // The shared t axis, labelled under the bottom panel only.
  const float b = crisp(layout.back().bottom);
  for (std::size_t i = 0; i < t_ticks.at.size(); ++i) {
    const float x = crisp(x_of(t_ticks.at[i]));
    d.shapes.push_back(line({x, b}, {x, b + kTickLength}, kInk));
    d.shapes.push_back(text(t_ticks.labels[i], x, b + kTickLength + 10, 0.5f));
  }
  d.shapes.push_back(text(x_label, (left + right) / 2, b + kTickLength + 30, 0.5f));
  if (drawn < shown.size())
    d.shapes.push_back(text("+" + std::to_string(shown.size() - drawn) + " more series not shown", left,
                            static_cast<float>(height) - kNoticeRow / 2 - 2));

  if (!title.empty()) {  // centred over the plot, unless that pushes it off the left edge
    const float half = static_cast<float>(title.size()) * kCharWidth / 2;
    d.shapes.push_back(text(title, std::max(4 + half, (left + right) / 2), top / 2, 0.5f));
  }

  io::write_output_file(path, io::drawing_png(d, path));
}

}  // namespace sylva
