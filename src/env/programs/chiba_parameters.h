// The chiba specification file (EnviroManual 3.2.2; the Virtual Laboratory's
// ENVIRO/chiba), read as the real program reads it (vlab_spec_file.h), and
// the light directions it makes of it.
#pragma once

#include <array>
#include <filesystem>
#include <vector>

namespace sylva::env {

// A direction light comes from (unit length, +y up) and its share of the
// light, in float as the real program keeps them.
struct ChibaRay {
  std::array<float, 3> direction{};
  float intensity = 0;
};

struct ChibaSettings {
  std::array<int, 3> grid_size{1, 1, 1};  // voxels; the real default is one
  bool verbose = false;
  float lower_to_upper = 0.7f;
  float transmittance = 0.6f;
  float radius = 25;       // of a query whose first parameter is not above 0
  float beam_radius = 0;   // 1 with estimated intersection areas
  bool estimate_area = false;
  bool cie_sky = false;    // "use CIE formula: yes"
  int samples = 20;        // "number of samples:" as asked
  // "source direction:" lines (normalized) or, without them, the sampled sky.
  std::vector<ChibaRay> rays;
};

// Reads `path`; unknown keywords and values that are not numbers are warned
// about and passed over, as the real program passes over them. A grid or a
// number of samples the real program cannot allocate is an error at its line.
ChibaSettings read_chiba_settings(const std::filesystem::path& path);

// The sky as the real program samples it: an octahedron's faces subdivided
// into at least `samples` triangles (8·4^k, from Jon Leech's sphere
// program), one ray towards each centroid. Upward rays (y >= 0) share
// 1 / (1 + lower_to_upper) of the light, the others the rest; with `cie_sky`
// only rays above the horizon carry light, weighted by the CIE overcast sky
// of the real program's formula, and the weights are scaled to sum to 1.
std::vector<ChibaRay> chiba_sky(int samples, float lower_to_upper, bool cie_sky);

}  // namespace sylva::env
