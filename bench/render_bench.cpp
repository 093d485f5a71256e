// Rendering benchmarks (Google Benchmark), part of sylva_bench.
//
//   Render/plant/<line style>/<render mode>[/antialiasing_<n>]
//       A hand-built Scene shaped like a branching plant of about a million
//       modules: a binary tree 19 levels deep (524,287 internodes, each
//       branch rolled 90 degrees from its parent) with a bud, a sphere, on
//       each of its 262,144 tips. Rendered to a 1920 x 1080 image and written
//       as a PNG, with lpfg's defaults otherwise (16 contour sides, z buffer
//       off, one light). Pixel-style internodes are 1 to 8 pixels wide;
//       cylinders a tenth of their length.
//
// Counters:
//   render_s     render_image: tessellation, OpenGL drawing, reading back.
//   png_s        write_png: encoding and writing the file.
//   peak_RSS_MB  getrusage's ru_maxrss for the whole process: run one
//                benchmark per process (bench/run.sh does) to read it.
//   scene_RSS_MB the same once the Scene is built, before any rendering:
//                what rendering adds is the difference.
// The benchmark's own time is the two together.
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/material.h"
#include "geometry/scene.h"
#include "render/png_renderer.h"

namespace {

using sylva::geometry::Scene;
using sylva::geometry::Vec3;
using Clock = std::chrono::steady_clock;

constexpr int kDepth = 19;

// `v` turned by `angle` radians around the unit vector `axis`.
Vec3 rotate(Vec3 v, Vec3 axis, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return v * c + sylva::geometry::cross(axis, v) * s + axis * (sylva::geometry::dot(axis, v) * (1 - c));
}

Scene plant(bool pixel_widths) {
  struct Node {
    Vec3 base, heading, up;
    float length;
    int depth;
  };
  Scene scene;
  scene.segments.reserve((1u << kDepth) - 1);
  scene.spheres.reserve(1u << (kDepth - 1));
  std::uint32_t module = 0;
  std::vector<Node> stack{{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0f, 1}};
  while (!stack.empty()) {
    Node n = stack.back();
    stack.pop_back();
    sylva::geometry::Segment s;
    s.start = n.base;
    s.end = n.base + n.heading * n.length;
    s.up = n.up;
    s.start_width = pixel_widths ? std::max(1.0f, 8 * std::pow(0.85f, static_cast<float>(n.depth))) : n.length * 0.1f;
    s.end_width = s.start_width;
    s.color = 2;
    s.from = {module, 0};
    module += 2;  // each internode's F and the turn or bracket around it
    scene.segments.push_back(s);
    if (n.depth == kDepth) {
      scene.spheres.push_back({s.end, n.length * 0.4f, 3, {module++, 0}});
      continue;
    }
    const Vec3 left = sylva::geometry::cross(n.up, n.heading);
    for (float side : {-1.0f, 1.0f}) {
      Vec3 heading = rotate(n.heading, left, side * 0.45f);
      Vec3 up = rotate(rotate(n.up, left, side * 0.45f), heading, 1.5708f);
      stack.push_back(
          {s.end, sylva::geometry::normalized(heading), sylva::geometry::normalized(up), n.length * 0.8f, n.depth + 1});
    }
  }
  return scene;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

void render_plant(benchmark::State& state, sylva::geometry::LineStyle style, sylva::geometry::RenderMode mode,
                  int antialiasing) {
  const Scene scene = plant(style == sylva::geometry::LineStyle::Pixel);
  const double scene_rss_mb = peak_rss_mb();
  sylva::geometry::Palette palette = sylva::geometry::Palette::default_palette();
  palette.entries[0].diffuse = {1, 1, 1};
  palette.entries[2].diffuse = palette.entries[2].ambient = {0.45f, 0.3f, 0.15f};
  palette.entries[3].diffuse = palette.entries[3].ambient = {0.2f, 0.7f, 0.2f};
  // Scene::bounds() counts widths in scene units, which pixel-style widths
  // are not: frame the points the plant passes through instead.
  sylva::geometry::ViewParameters view;
  sylva::geometry::Box box;
  for (const auto& s : scene.segments) box.add(s.start), box.add(s.end);
  view.box = box;
  sylva::io::ImageSettings settings;
  settings.render.line_style = style;
  settings.render.mode = mode;
  settings.render.antialiasing = antialiasing;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("sylva-render-bench-" + std::to_string(getpid()) + ".png")).string();
  double render_s = 0, png_s = 0;
  for (auto _ : state) {
    auto t0 = Clock::now();
    sylva::io::Image image = sylva::io::render_image(scene, palette, view, settings, 1920, 1080);
    auto t1 = Clock::now();
    sylva::io::write_png(path, image);
    auto t2 = Clock::now();
    render_s += std::chrono::duration<double>(t1 - t0).count();
    png_s += std::chrono::duration<double>(t2 - t1).count();
    state.SetIterationTime(std::chrono::duration<double>(t2 - t0).count());
  }
  std::filesystem::remove(path);
  const auto n = static_cast<double>(state.iterations());
  state.counters["render_s"] = render_s / n;
  state.counters["png_s"] = png_s / n;
  state.counters["segments"] = static_cast<double>(scene.segments.size());
  state.counters["spheres"] = static_cast<double>(scene.spheres.size());
  state.counters["peak_RSS_MB"] = peak_rss_mb();
  state.counters["scene_RSS_MB"] = scene_rss_mb;
}

void register_render_benchmarks() {
  using sylva::geometry::LineStyle;
  using sylva::geometry::RenderMode;
  struct Case {
    const char* name;
    LineStyle style;
    RenderMode mode;
    int antialiasing;
  };
  const Case cases[] = {
      {"pixel/filled", LineStyle::Pixel, RenderMode::Filled, 0},
      {"pixel/shaded", LineStyle::Pixel, RenderMode::Shaded, 0},
      {"cylinder/shaded", LineStyle::Cylinder, RenderMode::Shaded, 0},
      {"cylinder/shadows", LineStyle::Cylinder, RenderMode::Shadows, 0},
      {"cylinder/shaded/antialiasing_4", LineStyle::Cylinder, RenderMode::Shaded, 4},
  };
  for (const Case& c : cases)
    benchmark::RegisterBenchmark((std::string("Render/plant/") + c.name).c_str(), render_plant, c.style, c.mode,
                                 c.antialiasing)
        ->UseManualTime()
        ->Iterations(3)
        ->Unit(benchmark::kMillisecond);
}

const bool registered = (register_render_benchmarks(), true);

}  // namespace
