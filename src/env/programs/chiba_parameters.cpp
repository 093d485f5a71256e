#include "env/programs/chiba_parameters.h"

#include <cmath>

#include "env/programs/vlab_spec_file.h"
#include "support/diagnostic.h"

namespace sylva::env {
namespace {

constexpr const char* kProgram = "chiba";
// The real program cuts most values at "x" too ("32x32x32"), but not the
// ratio, the transmittance, the radii and a source's direction.
constexpr const char* kCounts = "x,; \t:\n";
constexpr const char* kValues = ",; \t:\n";
constexpr int kMaxSources = 100;

using Point = std::array<double, 3>;
using Triangle = std::array<Point, 3>;

Point normalized(Point p) {
  double magnitude = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
  if (magnitude != 0.0) {
    magnitude = 1.0 / std::sqrt(magnitude);
    for (double& c : p) c *= magnitude;
  }
  return p;
}

Point midpoint(const Point& a, const Point& b) {
  return {(a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, (a[2] + b[2]) * 0.5};
}

// The unit octahedron, each face's first and last vertex swapped (the
// sphere program's counterclockwise order), subdivided `level` - 1 times:
// each triangle [0,1,2] becomes [0,b,a], [b,1,c], [a,b,c], [a,c,2] with a, b, c
// the midpoints of 0-2, 0-1 and 1-2 pushed onto the sphere.
std::vector<Triangle> subdivided_octahedron(int level) {
  constexpr Point xp{1, 0, 0}, xm{-1, 0, 0}, yp{0, 1, 0}, ym{0, -1, 0}, zp{0, 0, 1}, zm{0, 0, -1};
  std::vector<Triangle> triangles = {{yp, zp, xp}, {xm, zp, yp}, {ym, zp, xm}, {xp, zp, ym},
                                     {zm, yp, xp}, {zm, xm, yp}, {zm, ym, xm}, {zm, xp, ym}};
  for (int k = 1; k < level; ++k) {
    std::vector<Triangle> finer;
    finer.reserve(triangles.size() * 4);
    for (const Triangle& t : triangles) {
      const Point a = normalized(midpoint(t[0], t[2]));
      const Point b = normalized(midpoint(t[0], t[1]));
      const Point c = normalized(midpoint(t[1], t[2]));
      finer.push_back({t[0], b, a});
      finer.push_back({b, t[1], c});
      finer.push_back({a, b, c});
      finer.push_back({a, c, t[2]});
    }
    triangles = std::move(finer);
  }
  return triangles;
}

// The real program's Normalize, in float.
void normalize(std::array<float, 3>& v) {
  const float length = static_cast<float>(std::sqrt(static_cast<double>(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])));
  if (length > 0)
    for (float& c : v) c /= length;
}

// The CIE overcast sky as the real program writes it: the cosine from the
// zenith taken in the x y plane only.
double overcast_sky(double cosine) { return (1 + cosine) / 3.0 * (8.6 * cosine + 0.123) / 0.203; }

}  // namespace

std::vector<ChibaRay> chiba_sky(int samples, float lower_to_upper, bool cie_sky) {
  // The least 8·4^k triangles not below `samples`; 1 or 2 samples give 2.
  const int level = static_cast<int>(std::ceil(std::log(static_cast<double>(samples) / 8.0) / std::log(4.0)) + 1);
  const int count = static_cast<int>(std::floor(0.5 + 8.0 * std::pow(4.0, static_cast<double>(level - 1))));
  const std::vector<Triangle> triangles = subdivided_octahedron(level);
  std::vector<ChibaRay> rays(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Triangle& t = triangles[i];
    for (int c = 0; c < 3; ++c) {
      // The vertices are kept in float, and their sum too.
      const float sum = static_cast<float>(t[0][c]) + static_cast<float>(t[1][c]) + static_cast<float>(t[2][c]);
      rays[i].direction[c] = static_cast<float>(sum / 3.0);
    }
    normalize(rays[i].direction);
  }
  if (cie_sky) {
    float total = 0;
    for (ChibaRay& ray : rays) {
      const std::array<float, 3>& d = ray.direction;
      if (d[1] <= 0) {
        ray.intensity = 0;
        continue;
      }
      ray.intensity = static_cast<float>(overcast_sky(d[1] / std::sqrt(static_cast<double>(d[0] * d[0] + d[1] * d[1]))));
      total += ray.intensity;
    }
    for (ChibaRay& ray : rays) ray.intensity /= total;
    return rays;
  }
  int up = 0;
  for (const ChibaRay& ray : rays) up += ray.direction[1] >= 0;
  const int down = count - up;
  for (ChibaRay& ray : rays)
    ray.intensity = ray.direction[1] >= 0
                        ? static_cast<float>(1.0 / static_cast<float>(up) / (1.0 + lower_to_upper))
                        : static_cast<float>(lower_to_upper / static_cast<float>(down) / (1.0 + lower_to_upper));
  return rays;
}

ChibaSettings read_chiba_settings(const std::filesystem::path& path) {
  ChibaSettings s;
  std::vector<ChibaRay> sources;
  auto fail = [&](int line, const std::string& message) {
    throw ModelError(SourceLocation{path.string(), line, 0}, std::string(kProgram) + ": " + message);
  };
  auto read_float = [](SpecLineTokens& line, const char* delimiters, float& value) {
    if (const std::optional<double> number = line.next_number(delimiters)) value = static_cast<float>(*number);
  };
  int samples_line = 0;
  read_vlab_spec_file(
      path, kProgram,
      {"grid size", "verbose", "lower to upper ratio", "transmittance", "number of samples", "radius", "beam radius",
       "source direction", "estimate intersection area", "use CIE formula"},
      [&](std::size_t keyword, SpecLineTokens& line) {
        switch (keyword) {
          case 0:
            for (int& size : s.grid_size) {
              const std::optional<double> value = line.next_number(kCounts);
              if (!value) break;
              if (!(*value >= 1 && *value < 1e6))
                fail(line.line(), "a grid of " + std::to_string(*value) + " voxels along an axis; expected 1 or more");
              size = static_cast<int>(*value);  // atof's value kept in an int
            }
            if (static_cast<double>(s.grid_size[0]) * s.grid_size[1] * s.grid_size[2] > 1e8)
              fail(line.line(), "a grid of more than 10^8 voxels is more than the program can hold");
            break;
          case 1: line.next_switch(kCounts, {"on"}, {"off"}, true, s.verbose); break;
          case 2: read_float(line, kValues, s.lower_to_upper); break;
          case 3: read_float(line, kValues, s.transmittance); break;
          case 4:
            if (const std::optional<int> samples = line.next_integer(kCounts)) {
              s.samples = *samples;
              samples_line = line.line();
            }
            break;
          case 5: read_float(line, kValues, s.radius); break;
          case 6: read_float(line, kValues, s.beam_radius); break;
          case 7: {
            if (sources.size() >= kMaxSources) {
              line.warn("more than 100 light sources; this one is ignored, as chiba ignores it");
              break;
            }
            // Three direction values and an intensity, or the line adds no source.
            ChibaRay source;
            bool complete = true;
            for (float& c : source.direction) {
              const std::optional<double> value = line.next_number(kValues);
              if (!value) {
                complete = false;
                break;
              }
              c = static_cast<float>(*value);
            }
            const std::optional<double> intensity = complete ? line.next_number(kCounts) : std::nullopt;
            if (!intensity) {
              line.warn("expected a direction and an intensity; the line adds no light source, as in chiba");
              break;
            }
            source.intensity = static_cast<float>(*intensity);
            sources.push_back(source);
            break;
          }
          case 8: line.next_switch(kCounts, {"on"}, {"off"}, true, s.estimate_area); break;
          case 9: line.next_switch(kCounts, {"yes"}, {"no"}, true, s.cie_sky); break;
        }
      });
  if (!sources.empty()) {
    float total = 0;
    for (const ChibaRay& source : sources) total += source.intensity;
    for (ChibaRay& source : sources) {
      source.intensity /= total;
      normalize(source.direction);
    }
    s.rays = std::move(sources);
  } else {
    // chiba cannot allocate its samples for fewer than one.
    if (s.samples < 1) fail(samples_line, "expected 1 or more samples of the sky, found " + std::to_string(s.samples));
    s.rays = chiba_sky(s.samples, s.lower_to_upper, s.cie_sky);
  }
  if (s.estimate_area) s.beam_radius = 1;
  return s;
}

}  // namespace sylva::env
