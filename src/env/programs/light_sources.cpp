#include "env/programs/light_sources.h"

#include <stdexcept>

namespace sylva::env::light {

void normalize_sources(std::vector<LightSource>& sources) {
  double total = 0;
  for (const LightSource& s : sources) total += s.intensity;
  if (!(total > 0)) throw std::invalid_argument("the light sources' intensities must add up to more than 0");
  for (LightSource& s : sources) {
    s.direction = normalized(s.direction);
    s.intensity /= total;
  }
}

int sky_sample_count(int requested) {
  int k = 1;
  while (8 * k * k * k * k < requested) ++k;
  return 8 * k * k * k * k;
}

std::vector<Vec3> sphere_directions(int samples) {
  int k = 1;
  while (8 * k * k * k * k < samples) ++k;
  const int n = k * k;  // parts per octahedron edge
  std::vector<Vec3> directions;
  directions.reserve(static_cast<std::size_t>(8) * n * n);
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (int sz : {1, -1}) {
        Vec3 a{double(sx), 0, 0}, b{0, double(sy), 0}, c{0, 0, double(sz)};
        // Point (i, j) of the face's triangular lattice.
        auto lattice = [&](int i, int j) { return (1.0 / n) * (double(i) * a + double(j) * b + double(n - i - j) * c); };
        auto add = [&](Vec3 p, Vec3 q, Vec3 r) { directions.push_back(normalized(p + q + r)); };
        for (int i = 0; i < n; ++i)
          for (int j = 0; i + j < n; ++j) {
            add(lattice(i, j), lattice(i + 1, j), lattice(i, j + 1));
            if (i + j + 2 <= n) add(lattice(i + 1, j), lattice(i, j + 1), lattice(i + 1, j + 1));
          }
      }
  return directions;
}

std::vector<LightSource> sky_sources(int samples, double lower_to_upper, bool cie_overcast) {
  std::vector<LightSource> sources;
  double upper_total = 0;
  int upper_count = 0;
  for (Vec3 d : sphere_directions(samples)) {
    double intensity = 0;
    if (d.y > 0) {
      intensity = cie_overcast ? (1 + 2 * d.y) / 3 : 1;
      upper_total += intensity;
      ++upper_count;
    }
    sources.push_back({d, intensity});
  }
  double lower = lower_to_upper * upper_total / upper_count;
  for (LightSource& s : sources)
    if (s.direction.y <= 0) s.intensity = lower;
  normalize_sources(sources);
  return sources;
}

}  // namespace sylva::env::light
